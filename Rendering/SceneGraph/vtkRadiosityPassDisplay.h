/**
 * @class   vtkRadiosityPassDisplay
 * @brief   the private actors with which vtkRadiosityPass draws a solution
 *
 * One actor per display path, as vtkRadiosityView chooses them: the
 * discontinuity mesh's quadratic interpolants (vtkQuadraticInterpolantMapper
 * on the product with `QuadraticInterpolant`), the Shepard field splatted on
 * the surface (vtkShepardSplatMapper, a product of points), the vector
 * irradiance (vtkVectorIrradianceMapper, the surface's point array
 * `IrradianceVector`, glossy with the scene's `Specular` and `Shininess`),
 * each element's own irradiance samples (vtkIrradianceSamplesMapper, the
 * surface's cell array `IrradianceSamples` of the progressive and
 * hierarchical methods), and otherwise the point array `Radiosity` interpolated across each
 * triangle (a vtkOpenGLPolyDataMapper with shader replacements). All write
 * the radiance B / pi x Exposure with the tone mapping operator ToneMapping
 * and the 1/2.2 encoding of the project's mappers. The actors cull back
 * faces: a two-sided surface is two coincident triangles, each drawn from
 * its own side.
 */
#ifndef vtkRadiosityPassDisplay_h
#define vtkRadiosityPassDisplay_h

#include "RadiosityRenderingSceneGraphModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for members

#include <string> // for std::string

class vtkActor;
class vtkIrradianceSamplesMapper;
class vtkOpenGLPolyDataMapper;
class vtkPolyData;
class vtkQuadraticInterpolantMapper;
class vtkShepardSplatMapper;
class vtkVectorIrradianceMapper;
class vtkWindow;

class RADIOSITYRENDERINGSCENEGRAPH_EXPORT vtkRadiosityPassDisplay : public vtkObject
{
public:
  static vtkRadiosityPassDisplay* New();
  vtkTypeMacro(vtkRadiosityPassDisplay, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Chooses the path for a solution: the filter's `surface` (port 0) and
   * `product` (port 1), and the scene polydata `materials`
   * (vtkRadiositySceneConverter::FromScene) whose cells are the surface's
   * when the method solves on the input triangles. Returns false with
   * `error` when the chosen mapper refuses its input.
   */
  bool SetSolution(vtkPolyData* surface, vtkPolyData* product, vtkPolyData* materials,
    std::string& error);
  /// No solution: GetActor() is null.
  void Clear();

  /// The actor that draws the solution, or null.
  vtkActor* GetActor();

  /// The meshless path's mapper (its Evaluation, TexelSpacing and
  /// MaximumTexels are the user's to set; the others are the pass's).
  vtkShepardSplatMapper* GetSplatMapper();

  /// Which path: "interpolants", "splats", "vector irradiance", "irradiance samples",
  /// "radiosity per vertex" or "none".
  const char* GetPathName() const;

  ///@{
  /// Applied at every draw (Update).
  vtkSetClampMacro(Exposure, double, 0.0, 1e12);
  vtkGetMacro(Exposure, double);
  vtkSetClampMacro(ToneMapping, int, 0, 2);
  vtkGetMacro(ToneMapping, int);
  ///@}

  /// Sets Exposure and ToneMapping on the active path before a draw.
  void Update();

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkRadiosityPassDisplay();
  ~vtkRadiosityPassDisplay() override;

  double Exposure = 1.0;
  int ToneMapping = 0;

private:
  vtkRadiosityPassDisplay(const vtkRadiosityPassDisplay&) = delete;
  void operator=(const vtkRadiosityPassDisplay&) = delete;

  enum Path
  {
    None,
    Interpolants,
    Splats,
    Vectors,
    Samples,
    Vertices
  };
  int Active = None;
  vtkSmartPointer<vtkQuadraticInterpolantMapper> InterpolantMapper;
  vtkSmartPointer<vtkShepardSplatMapper> SplatMapper;
  vtkSmartPointer<vtkVectorIrradianceMapper> VectorMapper;
  vtkSmartPointer<vtkIrradianceSamplesMapper> SamplesMapper;
  vtkSmartPointer<vtkOpenGLPolyDataMapper> VertexMapper;
  vtkSmartPointer<vtkActor> Actors[6];
};

#endif
