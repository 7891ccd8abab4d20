/**
 * @class   vtkRadiosityTriangleFieldMapper
 * @brief   base of the mappers that evaluate a per-triangle irradiance field
 *          at the exact barycentrics of every pixel
 *
 * A solution stored per triangle as a few RGB vectors (Hardt & Teller's
 * quadratic coefficients, an element's irradiance samples) is drawn by
 * evaluating it per pixel at the barycentrics (s, t) of the visible point,
 * with B = Emission + Reflectance * irradiance(s, t) written as the radiance
 * of vtkRadiosityCellTexelMapper. A subclass names the cell array and its
 * layout (FieldArrayName, FieldComponent) and gives the GLSL of its
 * irradiance (FieldIrradianceGLSL); this class does the rest:
 *
 * - Barycentrics (Hardt & Teller section 2.5: texture coordinates (0,0),
 *   (1,0), (0,1) issued per triangle and interpolated perspective-correctly
 *   by the rasteriser). When the input changes, an unshared-vertex copy of it
 *   is built: three points of its own per triangle, in the cell's order, with
 *   a two-component point array holding (0,0), (1,0), (0,1). The copy is what
 *   the OpenGL polydata machinery draws; the array reaches the vertex shader
 *   as the generic attribute `fieldST` and the fragment shader as a smooth
 *   (perspective-correct) varying, so (s,t) at a pixel are exact barycentrics
 *   of the visible point, whatever the camera. A shared-vertex mesh cannot
 *   carry them, since a point belongs to several triangles with a different
 *   (s,t) in each.
 * - Field and materials. The field's RGB vectors, then Reflectance and
 *   Emission, sit per triangle in the float texture buffer of
 *   vtkRadiosityCellTexelMapper (3 (FieldVectors + 2) floats rounded up to a
 *   whole RGBA texel), read by texelFetch at the OpenGL primitive; the
 *   buffer is laid out per primitive, so the wireframe and points
 *   representations show the field along the edges and at the corners too.
 *
 * The input is triangles (any other cell is refused with an error naming it)
 * with the field's cell array and, optionally, the cell arrays `Reflectance`
 * (3; 0.5 grey when absent) and `Emission` (3, W/m^2; none when absent),
 * each absence warned about once. Negative irradiance, which a fit may give
 * near a steep drop, is drawn as 0. The actor's lighting, colour, scalar
 * colouring and textures are ignored. The shaders are
 * vtkOpenGLPolyDataMapper's with replacements, so clipping planes,
 * coincident topology, depth peeling, hardware picking of cells and surface
 * edges (drawn in the property's edge colour) keep working. Cell ids seen by
 * the picker are the input's; point ids are those of the copy.
 *
 * @sa vtkQuadraticInterpolantMapper, vtkIrradianceSamplesMapper
 */
#ifndef vtkRadiosityTriangleFieldMapper_h
#define vtkRadiosityTriangleFieldMapper_h

#include "RadiosityRenderingModule.h" // For export macro
#include "vtkNew.h"                   // For members
#include "vtkRadiosityCellTexelMapper.h"

#include <string> // For members

class vtkPolyData;

class RADIOSITYRENDERING_EXPORT vtkRadiosityTriangleFieldMapper : public vtkRadiosityCellTexelMapper
{
public:
  vtkAbstractTypeMacro(vtkRadiosityTriangleFieldMapper, vtkRadiosityCellTexelMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Names of the optional material cell arrays (SPEC.md).
  static const char* GetReflectanceArrayName() { return "Reflectance"; }
  static const char* GetEmissionArrayName() { return "Emission"; }
  ///@}

protected:
  /**
   * `arrayName`: the field's cell array, of `vectors` RGB vectors
   * (3 x vectors components) described to the user as `layout`; `mapper`
   * names the subclass in messages; `what` names the texels (see the base).
   */
  vtkRadiosityTriangleFieldMapper(const char* arrayName, int vectors, const char* layout,
    const char* mapper, const char* what);
  ~vtkRadiosityTriangleFieldMapper() override;

  /**
   * Whether `input` can be drawn with a field array `arrayName` of
   * 3 x `vectors` components: triangles only, the array numeric on the cells
   * with a tuple per cell, `Reflectance` and `Emission`, when present, numeric
   * with 3 components. When it cannot, `message` (if given) names the array
   * (and its component count) or the cell. An input without cells is valid.
   */
  static bool ValidateField(vtkPolyData* input, const char* arrayName, int vectors,
    const char* layout, const char* mapper, std::string* message);

  /// The component of the field array holding channel `channel` of vector `vector`.
  virtual int FieldComponent(int vector, int channel) const = 0;

  /**
   * GLSL statements that declare `vec3 irradiance` from the field's vectors
   * `field0` ... (in vector order) and the barycentrics `float s, t` (the
   * point p0 + s (p1 - p0) + t (p2 - p0) of the cell's points).
   */
  virtual std::string FieldIrradianceGLSL() const = 0;

  /**
   * vtkOpenGLPolyDataMapper::RenderPiece calls this after updating the input
   * and before drawing: here the input is checked (an error, and nothing
   * drawn, when it is refused) and the copy replaces it as CurrentInput.
   */
  void UpdateCameraShiftScale(vtkRenderer* ren, vtkActor* act) override;

  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderLight(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;

  const std::string FieldArrayName;
  const int FieldVectors;
  const std::string FieldLayout;
  const std::string MapperName;

private:
  vtkRadiosityTriangleFieldMapper(const vtkRadiosityTriangleFieldMapper&) = delete;
  void operator=(const vtkRadiosityTriangleFieldMapper&) = delete;

  /**
   * Rebuilds the unshared-vertex copy and the per-triangle texels when the
   * input changed; false (with an error) when the input is refused.
   */
  bool UpdateTriangles(vtkPolyData* input);

  // The unshared-vertex copy of the input that the superclass draws, and the
  // input state it was built from.
  vtkNew<vtkPolyData> Triangles;
  vtkPolyData* TrianglesSource = nullptr; // not referenced: compared only
  vtkMTimeType TrianglesSourceTime = 0;
  bool InputValid = false;
  std::string InputError;
  bool WarnedNoReflectance = false;
  bool WarnedNoEmission = false;
};

#endif
