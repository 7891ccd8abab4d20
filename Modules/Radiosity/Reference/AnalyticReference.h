// Exact irradiance for the scenes that have a closed form (the analytic
// references of the error harness):
// - "direct": every surface black (reflectance 0), so irradiance is the direct
//   light of the polygonal Lambertian emitters, E F(point -> emitter) by
//   Lambert's contour formula; unoccluded, or with one convex planar blocker
//   parallel to the emitters, where the visible part of each emitter is the
//   emitter minus the blocker projected from the point onto its plane (exact
//   penumbrae);
// - "closed uniform enclosure": a watertight enclosure of uniform reflectance
//   and emission: B = E / (1 - rho) everywhere, H = B;
// - "sphere interior": a watertight sphere of uniform reflectance: every area
//   element sees every other alike (F = dA / (4 pi R^2)), so irradiance is the
//   area-mean radiosity, mean(E) / (1 - rho), for any distribution of emission.
// Scenes with lights (scene.Lighting, SPEC "Lights and sky"; AnalyticLights.h
// has the formulas, Scenes/LightScenes.h the scenes):
// - "sphere interior with lights": point and spot lights inside such a
//   sphere: H = E0(x) + rho P / ((1 - rho) A) (+ mean(E) / (1 - rho));
// - "direct light of lights[ and sky][ with convex blocker]": every surface
//   black, or one plane: the punctual lights' closed forms, each hidden or
//   not by at most one convex planar blocker (an exact segment test: hard
//   shadows), a uniform sky less the part of it the blocker hides (Lambert's
//   contour formula), an unobstructed CIE overcast sky on probes facing up
//   (7/9 pi L_z); emitters as above.
#ifndef Radiosity_AnalyticReference_h
#define Radiosity_AnalyticReference_h

#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Common/Scene.h"

#include <string>
#include <vector>

namespace radiosity
{
struct AnalyticReference
{
  std::string Kind;
  std::vector<RGB> Irradiance; ///< per probe
};

/// False with `why` set when the scene is none of the cases above.
bool ComputeAnalyticReference(const Scene& scene, const std::vector<Probe>& probes,
  AnalyticReference& reference, std::string& why);

/// Irradiance at (p, n) from the emitters of `scene`, with the emitters
/// clipped by a convex planar `blocker` (its vertices in order, may be empty).
RGB DirectIrradiance(
  const Scene& scene, const Vec3& p, const Vec3& n, const std::vector<Vec3>& blocker);
} // namespace radiosity

#endif
