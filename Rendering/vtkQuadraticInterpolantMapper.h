/**
 * @class   vtkQuadraticInterpolantMapper
 * @brief   Draws Hardt & Teller's quadratic irradiance interpolants per pixel.
 *
 * The input is a vtkPolyData of triangles (polys with three points; any other
 * cell is refused with an error naming it) carrying the cell arrays of
 * SPEC.md:
 *
 * - `QuadraticInterpolant`, 18 components per triangle, channel-major:
 *   components 6c+0 .. 6c+5 of channel c (R, G, B) are the stored coefficients
 *   (A, 2B, 2C, D, 2E, F) of the irradiance, in W/m^2,
 *   R(s,t) = A s^2 + 2B st + 2C s + D t^2 + 2E t + F,
 *   where the cell's point ids (p0, p1, p2), in cell order, give the
 *   barycentric frame x = p0 + s (p1 - p0) + t (p2 - p0);
 * - `Reflectance` (3) and `Emission` (3, W/m^2): the materials. Without
 *   `Reflectance` the triangles are drawn with reflectance 0.5 grey, without
 *   `Emission` with no emission; each absence is warned about once.
 *
 * Every fragment evaluates R(s,t) of its triangle for each colour channel (eq. 1
 * of the paper: eight multiplies and five adds), forms the radiosity
 * B = Emission + Reflectance * R and writes the displayed radiance
 * L = B / pi * Exposure, unclamped, to the colour output. There is no
 * Gouraud interpolation of shading and no lighting: the actor's lighting,
 * colour, scalar colouring and textures are ignored.
 *
 * The output is meant for the float framebuffer of a vtkToneMappingPass,
 * which maps the HDR radiance to the displayable range. That pass decodes
 * its input with pow(c, 2.2) before its operator (it takes the colour for
 * gamma-encoded), so the fragment colour is L^(1/Gamma) with Gamma 2.2 by
 * default: the operator then sees L itself. Negative values, which a
 * quadratic fit may produce near a steep drop, are drawn as 0.
 *
 * How it works (paper section 2.5: texture coordinates (0,0), (1,0), (0,1)
 * issued per triangle and interpolated perspective-correctly by the
 * rasteriser):
 *
 * - Barycentrics. When the input changes, the mapper builds once an
 *   unshared-vertex copy of it: three points of its own per triangle, in the
 *   triangle's cell order, with a two-component point array holding
 *   (0,0), (1,0), (0,1). The copy is what the OpenGL polydata machinery
 *   draws; the array reaches the vertex shader as the generic attribute
 *   `interpolantST` and the fragment shader as a smooth (perspective-correct)
 *   varying, so (s,t) at a pixel are exact barycentrics of the visible point,
 *   whatever the camera. A shared-vertex mesh cannot carry them, since a
 *   point belongs to several triangles with a different (s,t) in each. The
 *   copy costs three points and six floats per triangle; a geometry shader
 *   could issue the coordinates instead, but would have to be merged with
 *   the ones VTK itself uses for surface edges and wide lines.
 * - Coefficients and materials. The 24 floats of each triangle (the six
 *   coefficient triples, reflectance, emission) sit in a float texture buffer
 *   (vtkTextureObject::CreateTextureBuffer over a vtkOpenGLBufferObject,
 *   six RGBA32F texels per triangle, coefficient-major: A.rgb, 2B.rgb, 2C.rgb,
 *   D.rgb, 2E.rgb, F.rgb, Reflectance.rgb, Emission.rgb) which the fragment
 *   shader reads with texelFetch at gl_PrimitiveID + PrimitiveIDOffset, as
 *   vtkOpenGLPolyDataMapper does for cell scalars. The buffer is laid out per
 *   OpenGL primitive through the superclass's cell-to-cell map, so the
 *   wireframe and points representations show the interpolants along the
 *   edges and at the corners too.
 *
 * The shaders are vtkOpenGLPolyDataMapper's with replacements, so clipping
 * planes, coincident topology, depth peeling, hardware picking of cells and
 * surface edges (drawn in the property's edge colour) keep working. Cell ids
 * seen by the picker are the input's (the copy keeps the cell order); point
 * ids are those of the copy (3 per triangle).
 *
 * Typical use, in a renderer whose pass is a vtkToneMappingPass:
 * @code
 * vtkNew<vtkQuadraticInterpolantMapper> mapper;
 * mapper->SetInputData(meshWithInterpolants);
 * mapper->SetExposure(2.0);
 * actor->SetMapper(mapper);
 * @endcode
 *
 * @sa vtkRadiosityView, vtkToneMappingPass
 */

#ifndef vtkQuadraticInterpolantMapper_h
#define vtkQuadraticInterpolantMapper_h

#include "RadiosityRenderingModule.h" // For export macro
#include "vtkNew.h"                   // For members
#include "vtkRadiosityCellTexelMapper.h"

#include <string> // For ValidateInput

class vtkPolyData;

class RADIOSITYRENDERING_EXPORT vtkQuadraticInterpolantMapper : public vtkRadiosityCellTexelMapper
{
public:
  static vtkQuadraticInterpolantMapper* New();
  vtkTypeMacro(vtkQuadraticInterpolantMapper, vtkRadiosityCellTexelMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Names of the cell arrays read (SPEC.md): "QuadraticInterpolant"
   * (18 components), "Reflectance" (3) and "Emission" (3).
   */
  static const char* GetInterpolantArrayName() { return "QuadraticInterpolant"; }
  static const char* GetReflectanceArrayName() { return "Reflectance"; }
  static const char* GetEmissionArrayName() { return "Emission"; }
  ///@}

  /**
   * Whether `input` can be drawn: triangles only, a numeric cell array
   * `QuadraticInterpolant` with 18 components and a tuple per cell, and
   * `Reflectance` and `Emission`, when present, numeric with 3 components.
   * When it cannot, and `message` is given, `message` tells why, naming the
   * array (and its component count) or the cell. An input without cells is
   * valid (nothing is drawn).
   */
  static bool ValidateInput(vtkPolyData* input, std::string* message);

protected:
  vtkQuadraticInterpolantMapper();
  ~vtkQuadraticInterpolantMapper() override;

  /**
   * Rebuilds the unshared-vertex copy and the per-triangle texel data when
   * the input changed; false (with an error) when the input is refused.
   */
  bool UpdateTriangles(vtkPolyData* input);

  /**
   * vtkOpenGLPolyDataMapper::RenderPiece calls this after updating the input
   * and before drawing: here the input is checked (an error, and nothing
   * drawn, when ValidateInput refuses it) and the copy replaces it as
   * CurrentInput.
   */
  void UpdateCameraShiftScale(vtkRenderer* ren, vtkActor* act) override;

  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderLight(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;


  // The unshared-vertex copy of the input that the superclass draws, and the
  // input state it was built from.
  vtkNew<vtkPolyData> Triangles;
  vtkPolyData* TrianglesSource = nullptr; // not referenced: compared only
  vtkMTimeType TrianglesSourceTime = 0;
  bool InputValid = false;
  std::string InputError;
  bool WarnedNoReflectance = false;
  bool WarnedNoEmission = false;

  // CellTexels: 24 floats per triangle (see the class description).

private:
  vtkQuadraticInterpolantMapper(const vtkQuadraticInterpolantMapper&) = delete;
  void operator=(const vtkQuadraticInterpolantMapper&) = delete;
};

#endif
