/**
 * @class   vtkVectorIrradianceMapper
 * @brief   Draws a vector irradiance solution with view-dependent glossy
 *          reflection, per pixel (Gobbetti, Spano & Agus 2003, eq. 10).
 *
 * The input is a vtkPolyData of polygons with
 * - the point array `IrradianceVector` (9 components: the irradiance vector
 *   of the red, green and blue channels, x y z each, W/m^2), as face cluster
 *   radiosity writes it;
 * - optional point `Normals` (3; otherwise area-weighted vertex normals of the
 *   polygons are used);
 * - optional cell arrays `Reflectance` (3, diffuse; 0.5 grey without),
 *   `Emission` (3, W/m^2), `Specular` (3) and `Shininess` (1, the Phong
 *   exponent).
 *
 * Every fragment evaluates eq. 10 of the paper, the paper's future work of a
 * fragment rather than a vertex program: the radiance toward the eye is the
 * emitted radiance plus the modified Phong BRDF (Lewis 1994) lit by the single
 * dominant direction of each colour channel,
 *
 *   L_c = Emission_c / pi + (n . E_c)_+ (rho_d,c / pi
 *         + rho_s,c (q + 2) / (2 pi) max(0, r . E_c / |E_c|)^q),
 *
 * with E_c the irradiance vector interpolated from the vertices, n the
 * interpolated normal, r the mirror direction of the view about n and q the
 * shininess. A diffuse-only input (no `Specular`, or all zero) compiles the
 * shader without the glossy term. The fragment writes L * Exposure encoded
 * with 1/Gamma for a vtkToneMappingPass (see vtkQuadraticInterpolantMapper).
 *
 * Bad input (a non-polygon cell, an array with the wrong number of
 * components) is refused with an error naming it, and nothing is drawn.
 *
 * @sa vtkToneMappingPass, vtkRadiosityView
 */
#ifndef vtkVectorIrradianceMapper_h
#define vtkVectorIrradianceMapper_h

#include "RadiosityRenderingModule.h" // For export macro
#include "vtkNew.h"                   // For members
#include "vtkRadiosityCellTexelMapper.h"

#include <string> // For ValidateInput

class vtkPolyData;

class RADIOSITYRENDERING_EXPORT vtkVectorIrradianceMapper : public vtkRadiosityCellTexelMapper
{
public:
  static vtkVectorIrradianceMapper* New();
  vtkTypeMacro(vtkVectorIrradianceMapper, vtkRadiosityCellTexelMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Whether `input` can be drawn: polygons only, the point array
   * `IrradianceVector` with 9 components, and the optional arrays with the
   * component counts above. Otherwise false with `message` naming the cell
   * or the array.
   */
  static bool ValidateInput(vtkPolyData* input, std::string* message);

  /// Whether the last drawn input had a non-zero Specular (the glossy path).
  bool GetGlossy() const { return this->Glossy; }

protected:
  vtkVectorIrradianceMapper();
  ~vtkVectorIrradianceMapper() override;

  /// Checks the input and swaps in the copy with split attribute arrays.
  void UpdateCameraShiftScale(vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderLight(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;


private:
  vtkVectorIrradianceMapper(const vtkVectorIrradianceMapper&) = delete;
  void operator=(const vtkVectorIrradianceMapper&) = delete;

  bool UpdateCopy(vtkPolyData* input);

  vtkNew<vtkPolyData> Copy; // the input with the vectors and normals split
  vtkPolyData* CopySource = nullptr; // compared only
  vtkMTimeType CopySourceTime = 0;
  bool InputValid = false;
  bool Glossy = false;
  bool ShaderGlossy = false;
  std::string InputError;
  // CellTexels per cell: (Reflectance, Shininess), (Specular, 0), (Emission, 0).
};

#endif
