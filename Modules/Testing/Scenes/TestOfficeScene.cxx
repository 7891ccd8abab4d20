// The built-in office (SPEC "Lights and sky"): the daylight factor on the
// working plane under the CIE overcast sky, each method against the path
// tracer, and the unobstructed horizontal irradiance of that sky exactly.
#include "Radiosity/Common/ErrorMetrics.h"
#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/FaceCluster/FaceClusterMethod.h"
#include "Radiosity/Hierarchical/HierarchicalMethod.h"
#include "Radiosity/Meshless/MeshlessMethod.h"
#include "Radiosity/Progressive/ProgressiveMethod.h"
#include "Radiosity/Reference/PathTracer.h"
#include "Radiosity/Scenes/OfficeScene.h"

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <iostream>

using namespace radiosity;

TEST(OfficeScene, UnobstructedIrradianceOfTheOvercastSky)
{
  const Scene scene = MakeOfficeScene();
  const RGB e = UnobstructedHorizontalIrradiance(scene.Lighting.SkyLight);
  // 7/9 pi L_z: the integral of L_z (1 + 2 cos) / 3 cos over the hemisphere.
  EXPECT_NEAR(e.r, 7.0 / 9.0 * Pi * office::SkyZenithRadiance, 1e-9);
  ValidateScene(scene);
  EXPECT_FALSE(scene.HasEmitters());
  EXPECT_TRUE(scene.IsLit());
  ASSERT_EQ(scene.Lighting.Lights.size(), 1u);
  EXPECT_EQ(scene.Lighting.Lights[0].Type, LightType::Spot);
}

namespace
{
// What leaves through the window, of what the sky brings: measured 0.0613
// (progressive) and 0.0622 (hierarchical); 0 in both while hierarchical
// counted the sky's direct light as sent by the surfaces (it reported minus
// the absorbed power).
constexpr double EscapedShare = 0.04;
// |emitted - absorbed - escaped| / emitted: measured 2.7e-4 (progressive)
// and 0 (hierarchical, whose escaped power is the balance's rest).
constexpr double BalanceBound = 2e-3;
/// Daylight only (the lamp off): the daylight factor E / E_unobstructed on
/// every third sensor of the working-plane grid (0.75 m above the floor, in
/// the air: every method gathers them from its surface solution), against
/// the path tracer (262144 paths a sensor: a standard error of 0.3 to 0.8%
/// of the daylight factor). Checks the worst sensor's error in standard
/// errors and relative to the traced value.
void CheckDaylightFactor(const char* name,
  const std::function<std::unique_ptr<RadiositySolver>(std::shared_ptr<const Scene>)>& make,
  double sigmaBound, double relativeBound)
{
  auto scene = std::make_shared<const Scene>(MakeOfficeScene(false, true));
  std::vector<Probe> probes;
  const std::vector<Probe> grid = OfficeSensorGrid();
  for (std::size_t i = 0; i < grid.size(); i += 3)
  {
    probes.push_back(grid[i]);
  }
  const double unobstructed = Luminance(UnobstructedHorizontalIrradiance(scene->Lighting.SkyLight));
  PathTracerOptions traced;
  traced.SamplesPerProbe = 262144;
  const std::vector<ReferenceValue> reference = PathTracer(*scene, traced).Irradiance(probes);

  const auto clock = std::chrono::steady_clock::now();
  std::unique_ptr<RadiositySolver> solver = make(scene);
  const SolverStatistics stats = solver->Solve({});
  std::size_t gathered = 0;
  const std::vector<RGB> values = solver->EvaluateProbes(probes, &gathered);
  double worstSigma = 0.0, worstRelative = 0.0, meanDf = 0.0;
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    const double df = Luminance(values[i]) / unobstructed;
    const double dfTraced = Luminance(reference[i].Value) / unobstructed;
    const double se = Luminance(reference[i].StandardError) / unobstructed;
    worstSigma = std::max(worstSigma, std::fabs(df - dfTraced) / se);
    worstRelative = std::max(worstRelative, std::fabs(df - dfTraced) / dfTraced);
    meanDf += df / static_cast<double>(probes.size());
  }
  std::cout << name << ": mean daylight factor " << meanDf << ", worst sensor " << worstRelative
            << " relative (" << worstSigma << " standard errors) over " << probes.size() << " sensors ("
            << gathered << " gathered), "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count() << " s\n";
  // The power balance (SPEC report): what the lights and the sky bring is
  // absorbed or leaves through the window; none of it is created.
  std::cout << name << ": emitted " << stats.EmittedPowerW << " W, absorbed " << stats.AbsorbedPowerW
            << " W, escaped " << stats.EscapedPowerW << " W; absorbed by its surface "
            << AbsorbedPower(solver->Surface(), *scene) << " W\n";
  if (stats.AbsorbedPowerW > 0.0)
  {
    EXPECT_GT(stats.EscapedPowerW, EscapedShare * stats.EmittedPowerW) << name;
    EXPECT_NEAR(stats.AbsorbedPowerW + stats.EscapedPowerW, stats.EmittedPowerW, BalanceBound * stats.EmittedPowerW)
      << name;
  }
  EXPECT_EQ(gathered, probes.size()) << name;
  EXPECT_GT(meanDf, 0.01) << name;
  EXPECT_LT(worstSigma, sigmaBound) << name;
  EXPECT_LT(worstRelative, relativeBound) << name;
}
}

// Each method at its defaults; the bound is 3 standard errors.
// Measured: progressive 1.66 (0.96%; 7.4% before the lights' shot integrated
// each element's light over its quarters and split two levels deeper, 2.4
// before the rays of its corner samples started inside the element),
// face cluster 1.66 (1.1%), hierarchical 1.62 (0.97%, in 40 s; 11.5 and 9%
// at the back of the room while its nodes' edges on the walls saw the sky
// through them: DirectLighting::VisibilityPoint).
TEST(OfficeScene, DaylightFactorProgressive)
{
  CheckDaylightFactor("progressive",
    [](std::shared_ptr<const Scene> scene) { return std::make_unique<ProgressiveMethod>(scene, ProgressiveOptions()); },
    3.0, 0.025);
}

TEST(OfficeScene, DaylightFactorFaceCluster)
{
  CheckDaylightFactor("facecluster",
    [](std::shared_ptr<const Scene> scene) { return std::make_unique<FaceClusterMethod>(scene, FaceClusterSettings()); },
    3.0, 0.015);
}

// Meshless: 2.48 standard errors (1.88%; 1.84% while the sensors in the air
// gathered a surface with the lights exact at its samples; 3.2 and
// 2.4% while its Aitken tail was added after a bounce ratio held for one
// bounce, at bounce 3, not two). Its sensors gather its Shepard field's
// surface (MeshlessMethod::EvaluateProbes); what remains low is reflected light:
// against hierarchical and progressive (which agree to 0.1% at every sensor)
// the ceiling's mean irradiance is 1.8% under, the walls' 0.4 to 1.3%.
TEST(OfficeScene, DaylightFactorMeshless)
{
  CheckDaylightFactor("meshless",
    [](std::shared_ptr<const Scene> scene) { return std::make_unique<MeshlessMethod>(scene, MeshlessOptions()); },
    3.0, 0.025);
}

TEST(OfficeScene, DaylightFactorHierarchical)
{
  CheckDaylightFactor("hierarchical",
    [](std::shared_ptr<const Scene> scene) { return std::make_unique<HierarchicalMethod>(scene, HierarchicalOptions(), DiscontinuityMeshOptions()); },
    3.0, 0.025);
}
