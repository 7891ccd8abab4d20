// Sensor values from a solution (SPEC: --probes): the irradiance a user would
// see at a point with a normal, reconstructed from the solution itself.
#ifndef Radiosity_ProbeEvaluator_h
#define Radiosity_ProbeEvaluator_h

#include "Radiosity/Common/SolutionMesh.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace radiosity
{
class Visibility;
class DirectLighting;

struct Probe
{
  Vec3 Position{ 0.0 };
  Vec3 Normal{ 0.0, 0.0, 1.0 };
};

/**
 * For each probe, `at` on the input triangle nearest to it among those
 * facing its normal (the distance to the triangle's plane plus the distance
 * from the foot to the triangle): how the methods whose solution lives on
 * the input triangles (meshless, face cluster) answer probes. NaN where no
 * triangle faces the probe. The search is an Embree point query over
 * `allTriangles` (a Visibility built over every triangle of `scene`; built
 * here when null), not a loop over the triangles.
 */
std::vector<RGB> EvaluateOnNearestTriangles(const Scene& scene, const std::vector<Probe>& probes,
  const std::function<RGB(std::uint32_t triangle, const Vec3& x, const Vec3& n)>& at,
  const Visibility* allTriangles = nullptr);

class ProbeEvaluator;

/**
 * Sensors of a method whose solution lives on the input triangles (meshless,
 * face cluster): a sensor on a surface (ProbeEvaluator's rule, over the
 * input triangles) takes `onTriangles` (the method's own nearest-triangle
 * evaluation), a sensor in the air (a working plane) is gathered from the
 * solution's surface (ProbeEvaluator), which `surface` makes only when some
 * sensor needs it. `gathered`: how many were.
 */
std::vector<RGB> EvaluateSensorsOnInputTriangles(const std::function<SolutionMesh()>& surface, const Scene& scene,
  const std::vector<Probe>& probes,
  const std::function<std::vector<RGB>(const std::vector<Probe>&)>& onTriangles, std::size_t* gathered);

class ProbeEvaluator
{
public:
  explicit ProbeEvaluator(const SolutionMesh& solution, const Scene& scene);
  ~ProbeEvaluator();

  /**
   * On a surface (within 1e-6 of the scene size, normals within 25 degrees),
   * the element's own interpolant (corner and centre samples); elsewhere, a
   * gather of the solution's radiosity with exact point-to-polygon form
   * factors and one visibility ray per element, plus the lights and the sky
   * the sensor sees directly (DirectLighting: they are not surfaces).
   */
  std::vector<RGB> Evaluate(const std::vector<Probe>& probes) const;

  /// The value of a method whose solution lives on the input triangles, at
  /// x with normal n on input triangle `source` (SolutionMesh::SourceTriangle).
  using SurfaceValue = std::function<RGB(std::uint32_t source, const Vec3& x, const Vec3& n)>;
  /**
   * As Evaluate, but a sensor on a surface takes `onSurface` there (the
   * meshless Shepard field, the face cluster bases); a sensor in the air
   * (a working plane) is gathered from the solution's elements as above.
   */
  std::vector<RGB> Evaluate(const std::vector<Probe>& probes, const SurfaceValue& onSurface) const;

  /**
   * On (the default for sensors): on a surface, the punctual lights' direct
   * light is taken exactly at the sensor (DirectLighting::Punctual: the
   * closed form and one shadow ray per light), and the element's interpolant
   * carries the rest: its samples less the punctual light at the sample
   * points, so that a hard shadow edge or a spot's cone edge inside an
   * element is where it is, not where the interpolation smears it
   * (Lehtinen et al. 2007, figure 1, and section 6.5: direct light per
   * pixel, the finite elements for what is smooth). Off: the interpolant
   * alone, as the Gouraud display draws it.
   */
  void SetExactPunctualLight(bool on) { this->ExactPunctual = on; }

  /// How many of the last probes were gathered rather than interpolated.
  std::size_t GatheredCount() const { return this->Gathered; }

private:
  RGB Gather(const Probe& probe) const;
  const SolutionMesh& Solution;
  const Scene& SourceScene;
  std::unique_ptr<Visibility> Rays;
  std::unique_ptr<DirectLighting> Lights; ///< what a gathering sensor sees of the lights and sky
  double Tolerance = 0.0;
  bool ExactPunctual = true;
  mutable std::size_t Gathered = 0;
};
} // namespace radiosity

#endif
