/**
 * @class   vtkIrradianceSamplesMapper
 * @brief   Draws each solution element from its own irradiance samples, per
 *          pixel: the element's texel, as Coombe et al. display it
 *
 * Progressive radiosity (Cohen et al. 1988; on the GPU, Coombe, Harris &
 * Lastra 2004) keeps per element the irradiance gathered at its three
 * corners and its centroid. Coombe et al. display the solution by rendering
 * every leaf of the quadtree with its own radiosity texture (section 4.3),
 * so every pixel shows its element's values, interpolated, never an average
 * across elements. This mapper does the same for triangular elements: every
 * fragment evaluates
 *
 *   H(u, s, t) = u H0 + s H1 + t H2 + 27 u s t (Hc - (H0 + H1 + H2) / 3),
 *   u = 1 - s - t,
 *
 * linear through the corner samples H0, H1, H2 plus the cubic bubble that
 * also passes through the centroid sample Hc, at the exact (perspective-
 * correct) barycentrics of the visible point, and writes
 * B = Emission + Reflectance * H as radiance. It is the interpolation the
 * probes of `vtkradiosity --probe-output` report (radiosity::
 * InterpolateSamples), so the picture shows what the probes measure. Unlike
 * the Gouraud path it keeps a centroid sample (a spot of light or a shadow
 * inside an element) and does not average corners across elements. Where an
 * element meets two smaller ones (a T-junction of the adaptive subdivision)
 * each side shows its own samples, so a step may show along that edge: the
 * "t-vertex" artifact of the paper's figure 5, as large as the light's
 * curvature the subdivision criterion let through.
 *
 * The input is triangles with the cell array `IrradianceSamples`
 * (12 components, sample-major: H0.rgb, H1.rgb, H2.rgb at the cell's points
 * in order, then Hc.rgb at the centroid, W/m^2), as vtkRadiosityFilter
 * writes for the progressive, GPU progressive and hierarchical (without
 * discontinuity meshing) methods, and the optional `Reflectance` and
 * `Emission`; see vtkRadiosityTriangleFieldMapper for how it is drawn and
 * what is refused.
 *
 * @sa vtkRadiosityTriangleFieldMapper, vtkQuadraticInterpolantMapper, vtkRadiosityView
 */
#ifndef vtkIrradianceSamplesMapper_h
#define vtkIrradianceSamplesMapper_h

#include "RadiosityRenderingModule.h" // For export macro
#include "vtkRadiosityTriangleFieldMapper.h"

#include <string> // For ValidateInput

class vtkPolyData;

class RADIOSITYRENDERING_EXPORT vtkIrradianceSamplesMapper : public vtkRadiosityTriangleFieldMapper
{
public:
  static vtkIrradianceSamplesMapper* New();
  vtkTypeMacro(vtkIrradianceSamplesMapper, vtkRadiosityTriangleFieldMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Name of the cell array read: "IrradianceSamples" (12 components).
  static const char* GetSamplesArrayName() { return "IrradianceSamples"; }

  /**
   * Whether `input` can be drawn: triangles only, a numeric cell array
   * `IrradianceSamples` with 12 components and a tuple per cell, and
   * `Reflectance` and `Emission`, when present, numeric with 3 components.
   * When it cannot, and `message` is given, `message` tells why, naming the
   * array (and its component count) or the cell.
   */
  static bool ValidateInput(vtkPolyData* input, std::string* message);

protected:
  vtkIrradianceSamplesMapper();
  ~vtkIrradianceSamplesMapper() override;

  /// Sample k's channel c is the array's component 3k + c (sample-major).
  int FieldComponent(int vector, int channel) const override { return 3 * vector + channel; }
  /// Linear through the corners plus the cubic bubble through the centroid.
  std::string FieldIrradianceGLSL() const override;

private:
  vtkIrradianceSamplesMapper(const vtkIrradianceSamplesMapper&) = delete;
  void operator=(const vtkIrradianceSamplesMapper&) = delete;
};

#endif
