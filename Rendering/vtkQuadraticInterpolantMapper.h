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
 * rasteriser): see vtkRadiosityTriangleFieldMapper, which builds the
 * unshared-vertex copy carrying the barycentrics and lays the 24 floats of
 * each triangle (the six coefficient triples, reflectance, emission) out in
 * a float texture buffer, six RGBA32F texels per triangle, coefficient-major:
 * A.rgb, 2B.rgb, 2C.rgb, D.rgb, 2E.rgb, F.rgb, Reflectance.rgb,
 * Emission.rgb. The copy costs three points and six floats per triangle; a
 * geometry shader could issue the coordinates instead, but would have to be
 * merged with the ones VTK itself uses for surface edges and wide lines.
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
#include "vtkRadiosityTriangleFieldMapper.h"

#include <string> // For ValidateInput

class vtkPolyData;

class RADIOSITYRENDERING_EXPORT vtkQuadraticInterpolantMapper : public vtkRadiosityTriangleFieldMapper
{
public:
  static vtkQuadraticInterpolantMapper* New();
  vtkTypeMacro(vtkQuadraticInterpolantMapper, vtkRadiosityTriangleFieldMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Name of the cell array read (SPEC.md): "QuadraticInterpolant"
   * (18 components); with the base's "Reflectance" (3) and "Emission" (3).
   */
  static const char* GetInterpolantArrayName() { return "QuadraticInterpolant"; }

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

  /// Coefficient k of channel c is the array's component 6c + k (channel-major).
  int FieldComponent(int vector, int channel) const override { return 6 * channel + vector; }
  /// Hardt & Teller eq. 1: eight multiplies and five adds per channel.
  std::string FieldIrradianceGLSL() const override;

private:
  vtkQuadraticInterpolantMapper(const vtkQuadraticInterpolantMapper&) = delete;
  void operator=(const vtkQuadraticInterpolantMapper&) = delete;
};

#endif
