// A point light's hard shadow through hierarchical radiosity with
// discontinuity meshing (SPEC "Lights and sky"; Hardt & Teller 4.1: the D0
// boundaries, the projections of the blocker's silhouette from the light,
// inserted into the leaves' triangulations): along a line across both
// shadow edges the quadratic interpolants follow the exact step, where the
// progressive method's elements blur it.
#include "Radiosity/Common/SolutionMesh.h"
#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Hierarchical/DiscontinuityMesher.h"
#include "Radiosity/Hierarchical/HierarchicalRadiosity.h"
#include "Radiosity/Progressive/ProgressiveRadiosity.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

using namespace radiosity;

namespace
{
constexpr double PlateZ = 0.5, PlateHalf = 0.4;
const Vec3 LampAt(0.3, 0.1, 1.5);
constexpr double Intensity = 10.0;

/// A black floor [-2, 2]^2 of 4 x 4 quads (32 triangles: coarse input), a
/// black two-sided square plate above it, a point light above the plate.
Scene HardShadowScene()
{
  Scene scene;
  Material black;
  black.Reflectance = RGB(0.0);
  AppendQuad(scene, Vec3(-2, -2, 0), Vec3(2, -2, 0), Vec3(2, 2, 0), Vec3(-2, 2, 0), black, 4, "floor");
  const double h = PlateHalf;
  AppendQuad(scene, Vec3(-h, -h, PlateZ), Vec3(h, -h, PlateZ), Vec3(h, h, PlateZ), Vec3(-h, h, PlateZ), black, 1,
    "plate top");
  AppendQuad(scene, Vec3(-h, -h, PlateZ), Vec3(-h, h, PlateZ), Vec3(h, h, PlateZ), Vec3(h, -h, PlateZ), black, 1,
    "plate bottom");
  Light lamp;
  lamp.Type = LightType::Point;
  lamp.Position = LampAt;
  lamp.Intensity = RGB(Intensity);
  scene.Lighting.Lights.push_back(lamp);
  return scene;
}

/// Exact: I h / d^3 where the segment to the lamp misses the plate, else 0.
double ExactIrradiance(const Vec3& x)
{
  const Vec3 crossing = x + (LampAt - x) * (PlateZ / LampAt.z);
  if (std::fabs(crossing.x) <= PlateHalf && std::fabs(crossing.y) <= PlateHalf)
  {
    return 0.0;
  }
  const double d = glm::length(LampAt - x);
  return Intensity * LampAt.z / (d * d * d);
}

/// Probes along y = 0 from x = -1.5 to 1.5; the shadow's edges on it are at
/// x = 0.3 + 1.5 (+-0.4 - 0.3): -0.75 and 0.45. Probes within 1e-3 of an
/// edge are left out (the value on the edge itself is either side's).
std::vector<Probe> LineAcrossTheEdges()
{
  std::vector<Probe> probes;
  for (int i = 0; i <= 600; ++i)
  {
    const double x = -1.5 + 3.0 * i / 600.0;
    if (std::fabs(x + 0.75) < 1e-3 || std::fabs(x - 0.45) < 1e-3)
    {
      continue;
    }
    probes.push_back({ Vec3(x, 0.0, 0.0), Vec3(0, 0, 1) });
  }
  return probes;
}

double MaxErrorOverPeak(const std::vector<RGB>& values, const std::vector<Probe>& probes)
{
  double peak = 0.0, worst = 0.0;
  for (const Probe& p : probes)
  {
    peak = std::max(peak, ExactIrradiance(p.Position));
  }
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    const double e = std::fabs(values[i].x - ExactIrradiance(probes[i].Position));
    worst = std::max(worst, std::isfinite(e) ? e : std::numeric_limits<double>::infinity());
  }
  return worst / peak;
}
}

TEST(HardShadow, DiscontinuityMeshFollowsThePointLightsStep)
{
  const Scene scene = HardShadowScene();
  const std::vector<Probe> probes = LineAcrossTheEdges();

  HierarchicalRadiosity hr(scene, HierarchicalOptions{});
  const SolverStatistics stats = hr.Solve();
  EXPECT_GT(stats.LightPowerW, 0.0);
  EXPECT_GT(hr.NumberOfLightLinks(), 0u);
  const DiscontinuityMesh dm = BuildDiscontinuityMesh(hr, DiscontinuityMeshOptions{});
  const std::vector<RGB> values = EvaluateInterpolants(dm, probes, 1e-6 * scene.Diagonal());
  const double dmError = MaxErrorOverPeak(values, probes);
  // And along the shadow's left edge, 5e-3 inside the shadow and outside it:
  // the edge runs along leaf boundaries there, through leaf corners that
  // touch it at one point (a shared sample there was lit for the triangles
  // inside the shadow: 0.78 of the peak before the punctual light was taken
  // per triangle).
  std::vector<Probe> alongEdge;
  for (int i = 0; i <= 200; ++i)
  {
    for (double x : { -0.755, -0.745 })
    {
      alongEdge.push_back({ Vec3(x, -0.6 + 1.1 * i / 200.0, 0.0), Vec3(0, 0, 1) });
    }
  }
  const std::vector<RGB> alongValues = EvaluateInterpolants(dm, alongEdge, 1e-6 * scene.Diagonal());
  const double alongError = MaxErrorOverPeak(alongValues, alongEdge);
  ProgressiveRadiosity progressive(scene, ProgressiveOptions{});
  progressive.Solve();
  const SolutionMesh surface = ExtractSolution(progressive.Mesh());
  // The elements' interpolation as the Gouraud display draws it (without the
  // sensors' exact punctual light, which would make any mesh exact here).
  ProbeEvaluator evaluator(surface, scene);
  evaluator.SetExactPunctualLight(false);
  const double progressiveError = MaxErrorOverPeak(evaluator.Evaluate(probes), probes);

  std::cout << "hard shadow: discontinuity mesh " << dm.Triangles.size() << " triangles ("
            << dm.LeavesMeshed << " leaves meshed, " << dm.SegmentsKept << " segments), max error "
            << dmError << " of peak (along an edge " << alongError << "); progressive " << surface.Triangles.size()
            << " elements, max error " << progressiveError << std::endl;
  // Measured: 4.7e-6 across and 6.0e-6 along, of the peak, with 8,036 triangles (the issue asks for
  // below 1%). A uniform linear mesh would need elements below 2e-3 m (the
  // probes come within 1e-3 of the edges, and a step across an element is
  // wrong by half its height there): about 8 million triangles on this floor.
  EXPECT_LT(dmError, 2e-5);
  EXPECT_LT(alongError, 2e-5);
  EXPECT_LT(dm.Triangles.size(), 20000u);
  EXPECT_GT(dm.LeavesMeshed, 0u);
  // The progressive elements straddling the edges blur the step (measured
  // 0.48 of the peak with 2184 elements; 0.72 with 891 before the lights' shot
  // could split two levels deeper).
  EXPECT_GT(progressiveError, 0.3);
}
