/**
 * @class   vtkRadiosityView
 * @brief   Draws a radiosity solution as tone-mapped HDR radiance.
 *
 * Two display paths, both drawing the radiance L = B / pi times Exposure with
 * no lighting and no clamping into the float framebuffer of a
 * vtkToneMappingPass, which maps the HDR values to the displayable range
 * (Reinhard by default). The background is black.
 *
 * - Interpolants: when the input has the cell array `QuadraticInterpolant`
 *   (Hardt & Teller's per-triangle quadratic irradiance, SPEC.md), the drawn
 *   array is the default `Radiosity` and InterpolantRendering is on (the
 *   default), a vtkQuadraticInterpolantMapper evaluates the interpolant per
 *   pixel, B = Emission + Reflectance * R(s,t), from the cell arrays
 *   `QuadraticInterpolant`, `Reflectance` and `Emission`.
 * - Gouraud: otherwise VTK's own polydata mapper draws the point array
 *   ArrayName (3 components, W/m^2; `Radiosity`, B, by default), linearly
 *   interpolated across each triangle. The array reaches the shaders as a
 *   float vertex attribute (MapDataArrayToVertexAttribute) and a shader
 *   replacement writes it to the fragment colour.
 *
 * - Splats: when a meshless Shepard field is given (SetShepardField, the
 *   port 1 of vtkRadiosityFilter with Method Meshless), the drawn array is `Radiosity` and
 *   InterpolantRendering is on, a vtkShepardSplatMapper evaluates the field
 *   per pixel on the input's polygons (Lehtinen et al. 2007, section 6.2).
 *   It takes precedence over the interpolant path.
 *
 * - Vector irradiance: when the input has the point array `IrradianceVector`
 *   (9 components, face cluster radiosity's), the drawn array is `Radiosity`
 *   and InterpolantRendering is on, a vtkVectorIrradianceMapper shades every
 *   pixel with eq. 10 of Gobbetti et al. 2003 (glossy where the input has
 *   `Specular`).
 *
 * - Irradiance samples: when the input has the cell array
 *   `IrradianceSamples` (12 components: each element's irradiance at its
 *   corners and centroid, written for the progressive and hierarchical
 *   methods), the drawn array is `Radiosity` and InterpolantRendering is
 *   on, a vtkIrradianceSamplesMapper draws every element from its own
 *   samples per pixel (Coombe et al.'s texel display). The interpolant,
 *   splat and vector paths take precedence.
 *
 * InterpolantRenderingOff forces the Gouraud path (for side-by-side
 * comparisons of the same solution); UsesInterpolantMapper tells which path
 * the next render takes.
 *
 * Typical use:
 * @code
 * vtkNew<vtkRadiosityView> view;
 * view->SetInputData(solvedPolyData);
 * view->SetSize(800, 600);
 * view->SetExposure(2.0);
 * view->WritePNG("image.png");
 * @endcode
 *
 * Without SetCamera the camera is reset to frame the input at the first render.
 * Invalid input (no point array of that name, wrong component count; on the
 * interpolant path a wrong `QuadraticInterpolant` or a cell that is not a
 * triangle) is refused with an error naming the array or the cell: Render()
 * and WritePNG() return false.
 */

#ifndef vtkRadiosityView_h
#define vtkRadiosityView_h

#include "RadiosityRenderingModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For members
#include <string> // For CanOpenWindow

class vtkActor;
class vtkPolyData;
class vtkIrradianceSamplesMapper;
class vtkPolyDataMapper;
class vtkQuadraticInterpolantMapper;
class vtkShepardSplatMapper;
class vtkVectorIrradianceMapper;
class vtkRenderWindow;
class vtkRenderer;
class vtkToneMappingPass;

class RADIOSITYRENDERING_EXPORT vtkRadiosityView : public vtkObject
{
public:
  static vtkRadiosityView* New();
  vtkTypeMacro(vtkRadiosityView, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Tone mapping operators, the values of vtkToneMappingPass.
  enum ToneMappingTypes
  {
    Clamp = 0,
    Reinhard = 1,
    Exponential = 2,
    GenericFilmic = 3
  };

  ///@{
  /**
   * The polydata to draw. It must carry the point array ArrayName with 3
   * components (RGB radiant exitance, W/m^2).
   */
  void SetInputData(vtkPolyData* input);
  vtkPolyData* GetInputData();
  ///@}

  ///@{
  /**
   * Name of the point array drawn by the Gouraud path (default "Radiosity").
   * The interpolant path draws radiosity, so it is taken only while this is
   * "Radiosity".
   */
  vtkSetStringMacro(ArrayName);
  vtkGetStringMacro(ArrayName);
  ///@}

  ///@{
  /**
   * Whether an input with the cell array `QuadraticInterpolant` is drawn by
   * evaluating the interpolants per pixel (default on). Off draws the point
   * array ArrayName with Gouraud interpolation whatever the input.
   */
  vtkSetMacro(InterpolantRendering, bool);
  vtkGetMacro(InterpolantRendering, bool);
  vtkBooleanMacro(InterpolantRendering, bool);
  ///@}

  ///@{
  /**
   * A meshless multilevel Shepard field of the input's solution (the output
   * of vtkRadiosityFilter with Method Meshless), drawn per pixel on the input's polygons by
   * vtkShepardSplatMapper; nullptr (the default) for none.
   */
  void SetShepardField(vtkPolyData* field);
  vtkPolyData* GetShepardField();
  ///@}

  /**
   * Whether the next render splats the Shepard field: a field set,
   * InterpolantRendering on and ArrayName "Radiosity".
   */
  bool UsesSplatMapper();

  /**
   * Whether the next render shades the irradiance vectors per pixel: the
   * point array `IrradianceVector`, InterpolantRendering on, ArrayName
   * "Radiosity", no Shepard field and no `QuadraticInterpolant`.
   */
  bool UsesVectorIrradianceMapper();

  /**
   * Whether the next render draws the interpolants per pixel: an input with
   * the cell array `QuadraticInterpolant`, InterpolantRendering on,
   * ArrayName "Radiosity" and no Shepard field.
   */
  bool UsesInterpolantMapper();

  /**
   * Whether the next render draws the elements' own samples per pixel: the
   * cell array `IrradianceSamples`, InterpolantRendering on, ArrayName
   * "Radiosity", and none of the other per-pixel paths.
   */
  bool UsesIrradianceSamplesMapper();

  ///@{
  /**
   * Scale applied to the radiance B/pi before tone mapping (default 1).
   * Clamped to [0, 1e12].
   */
  vtkSetClampMacro(Exposure, double, 0.0, 1e12);
  vtkGetMacro(Exposure, double);
  ///@}

  ///@{
  /**
   * Tone mapping operator, one of ToneMappingTypes (default Reinhard).
   */
  vtkSetClampMacro(ToneMappingType, int, Clamp, GenericFilmic);
  vtkGetMacro(ToneMappingType, int);
  void SetToneMappingTypeToClamp() { this->SetToneMappingType(Clamp); }
  void SetToneMappingTypeToReinhard() { this->SetToneMappingType(Reinhard); }
  void SetToneMappingTypeToExponential() { this->SetToneMappingType(Exponential); }
  void SetToneMappingTypeToGenericFilmic() { this->SetToneMappingType(GenericFilmic); }
  ///@}

  ///@{
  /**
   * Image size in pixels (default 640 x 480), each clamped to [1, 16384].
   */
  void SetSize(int width, int height);
  void SetSize(const int size[2]) { this->SetSize(size[0], size[1]); }
  vtkGetVector2Macro(Size, int);
  ///@}

  ///@{
  /**
   * Whether a window created by this view renders offscreen (default on).
   * Has no effect on a window given with SetRenderWindow.
   */
  vtkSetMacro(OffScreen, bool);
  vtkGetMacro(OffScreen, bool);
  vtkBooleanMacro(OffScreen, bool);
  ///@}

  /**
   * Places the camera; without a call the camera frames the input at the
   * first render. viewAngle is the vertical view angle in degrees.
   */
  void SetCamera(const double position[3], const double focalPoint[3], const double viewUp[3],
    double viewAngle);

  /**
   * Frames the input again at the next render (undoes SetCamera).
   */
  void ResetCamera();

  /**
   * The renderer, whose active camera may be set directly.
   */
  vtkRenderer* GetRenderer();

  ///@{
  /**
   * The render window. Unless one is set, GetRenderWindow creates one
   * (offscreen when OffScreen is on). Setting a window adds the renderer to it.
   */
  vtkRenderWindow* GetRenderWindow();
  void SetRenderWindow(vtkRenderWindow* window);
  ///@}

  /**
   * Renders the input. Returns false (with an error) on invalid input, or
   * when no window can be opened (see CanOpenWindow).
   */
  bool Render();

  /**
   * Whether this process can open a render window: false, with `why`
   * naming DISPLAY and the way out (xvfb-run), when VTK's window is an X
   * window and no X display can be opened (VTK would abort).
   */
  static bool CanOpenWindow(std::string& why);

  /**
   * Renders and writes the image as PNG. Returns false (with an error) on
   * invalid input or when the file cannot be written.
   */
  bool WritePNG(const char* fileName);

protected:
  vtkRadiosityView();
  ~vtkRadiosityView() override;

  /// Checks the input and its array; reports an error naming the array.
  bool CheckInput();
  /// (Re)configures mapper, shaders and passes from the current properties.
  void UpdatePipeline();

  char* ArrayName = nullptr;
  bool InterpolantRendering = true;
  double Exposure = 1.0;
  int ToneMappingType = Reinhard;
  int Size[2] = { 640, 480 };
  bool OffScreen = true;
  bool CameraSet = false;

  vtkSmartPointer<vtkPolyData> Input;
  // Gouraud path: the plain mapper with the shader replacements on its actor.
  vtkSmartPointer<vtkPolyDataMapper> Mapper;
  vtkSmartPointer<vtkActor> Actor;
  // Interpolant path: an actor of its own, free of those replacements.
  vtkSmartPointer<vtkQuadraticInterpolantMapper> InterpolantMapper;
  vtkSmartPointer<vtkActor> InterpolantActor;
  // Splat path: the input's polygons with the Shepard field.
  vtkSmartPointer<vtkPolyData> ShepardField;
  vtkSmartPointer<vtkShepardSplatMapper> SplatMapper;
  vtkSmartPointer<vtkActor> SplatActor;
  // Vector irradiance path.
  vtkSmartPointer<vtkVectorIrradianceMapper> VectorMapper;
  vtkSmartPointer<vtkActor> VectorActor;
  // Irradiance samples path.
  vtkSmartPointer<vtkIrradianceSamplesMapper> SamplesMapper;
  vtkSmartPointer<vtkActor> SamplesActor;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkRenderWindow> RenderWindow;
  vtkSmartPointer<vtkToneMappingPass> ToneMappingPass;

private:
  vtkRadiosityView(const vtkRadiosityView&) = delete;
  void operator=(const vtkRadiosityView&) = delete;
};

#endif
