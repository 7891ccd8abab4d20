// Relighting (Lehtinen et al. 2007, section 6.5): a relit field against the
// solve of the same lighting, a fresh solve of the new lighting, and the
// analytic light cases; surfaces that changed are refused.
#include "Radiosity/Common/ErrorMetrics.h"
#include "Radiosity/Meshless/MeshlessMethod.h"
#include "Radiosity/Meshless/MeshlessRadiosity.h"
#include "Radiosity/Reference/AnalyticReference.h"
#include "Radiosity/Scenes/LightScenes.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <gtest/gtest.h>

#include <iostream>
#include <memory>

namespace
{
using namespace radiosity;

std::vector<Probe> TriangleCentroids(const Scene& scene)
{
  std::vector<Probe> probes;
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    probes.push_back({ scene.Centroid(t), scene.Normal(t) });
  }
  return probes;
}

MeshlessOptions FourLevels()
{
  MeshlessOptions options;
  options.Placement.Levels = 4;
  return options;
}

/// The Cornell box with its ceiling lamp off and a point light in the left
/// half of the box instead: light moved, not only rescaled.
Scene CornellWithPointLight(const Scene& box)
{
  Scene lit = box;
  Vec3 low, high;
  box.BoundingBox(low, high);
  Light bulb;
  bulb.Position = low + Vec3(0.25, 0.5, 0.5) * (high - low);
  bulb.Intensity = RGB(4.0, 3.0, 2.0);
  lit.Lighting.Lights.push_back(bulb);
  for (Material& m : lit.Materials)
  {
    m.Emission = RGB(0.0);
  }
  return lit;
}

ErrorFigures RelitAgainstFresh(MeshlessMethod& relit, const std::shared_ptr<const Scene>& lit,
  const MeshlessOptions& options, const char* what)
{
  const SolverStatistics stats = relit.Relight(lit, {});
  EXPECT_EQ(stats.Stop, StopReason::Converged) << what;
  MeshlessMethod fresh(lit, options);
  fresh.Solve({});
  const std::vector<Probe> probes = TriangleCentroids(*lit);
  const ErrorFigures e = RelativeErrors(relit.EvaluateProbes(probes), fresh.EvaluateProbes(probes));
  const MeshlessStatistics& t = relit.GetInstance().Statistics();
  std::cout << what << ": relit against a fresh solve, max " << e.Max << " RMS " << e.Rms << " of the peak; relight "
            << t.RelightDirectSeconds << " s direct + " << t.RelightIndirectSeconds << " s transfer, "
            << t.RelightBounces << " bounces, " << t.RelightRowsAdded << " receivers added\n";
  return e;
}
}

TEST(MeshlessRelighting, TheSolvedLightingGivesTheSolveBack)
{
  // Relit with the lighting it was solved with, the field is the solve's:
  // the same direct light, the same receivers chosen by the same oracle at
  // every bounce, the same gathers (the transfer's rows hold the solve's
  // weights in float). Measured (4 levels): max 1.9e-9, RMS 5.3e-10 of the
  // peak. (When every receiver of the transfer was computed at every
  // bounce, it was 1.05% off the solve: the oracle's choice is part of the
  // answer a fresh solve gives.)
  const auto box = std::make_shared<const Scene>(MakeCornellBox());
  MeshlessMethod method(box, FourLevels());
  method.Solve({});
  const std::vector<Probe> probes = TriangleCentroids(*box);
  const std::vector<RGB> solved = method.EvaluateProbes(probes);
  ASSERT_TRUE(method.PrecomputeRelighting({}));
  const MeshlessStatistics& t = method.GetInstance().Statistics();
  std::cout << "transfer: " << t.TransferReceivers << " receivers of " << t.SamplesGenerated << " points, "
            << t.TransferEntries << " entries, " << t.TransferBytes / 1048576.0 << " MiB, " << t.TransferSeconds
            << " s\n";
  EXPECT_GT(t.TransferEntries, t.TransferReceivers);
  method.Relight(std::make_shared<const Scene>(*box), {});
  const ErrorFigures e = RelativeErrors(method.EvaluateProbes(probes), solved);
  std::cout << "same lighting: max " << e.Max << " RMS " << e.Rms << " of the peak\n";
  EXPECT_EQ(e.NotFinite, 0u);
  EXPECT_LT(e.Max, 1e-7);
}

TEST(MeshlessRelighting, EqualsAFreshSolveOfTheNewLighting)
{
  // The lamp recoloured and brighter, then replaced by a point light in
  // the left half of the box. Measured (4 levels): max 1.9e-9 (a colour and
  // scale leave the oracle's choices as they were, no receiver added) and
  // 3.4e-9 of the peak: the point light's oracle wants receivers
  // the solved lighting did not, and they are gathered and added as rows
  // (0.0046 of the peak when they were left out). Bound 1e-7 for both, as
  // for the solved lighting.
  const auto box = std::make_shared<const Scene>(MakeCornellBox());
  const MeshlessOptions options = FourLevels();
  MeshlessMethod method(box, options);
  method.Solve({});
  ASSERT_TRUE(method.PrecomputeRelighting({}));

  auto recoloured = std::make_shared<Scene>(*box);
  for (Material& m : recoloured->Materials)
  {
    m.Emission *= RGB(2.0, 1.0, 0.5);
  }
  const ErrorFigures a = RelitAgainstFresh(method, recoloured, options, "lamp recoloured");
  EXPECT_EQ(a.NotFinite, 0u);
  EXPECT_LT(a.Max, 1e-7);
  EXPECT_EQ(method.GetInstance().Statistics().RelightRowsAdded, 0u);

  const std::size_t before = method.GetInstance().Statistics().TransferReceivers;
  const auto moved = std::make_shared<const Scene>(CornellWithPointLight(*box));
  const ErrorFigures b = RelitAgainstFresh(method, moved, options, "point light instead");
  EXPECT_EQ(b.NotFinite, 0u);
  EXPECT_LT(b.Max, 1e-7);
  const std::size_t added = method.GetInstance().Statistics().RelightRowsAdded;
  EXPECT_GT(added, 0u);
  EXPECT_EQ(method.GetInstance().Statistics().TransferReceivers, before + added);
  // The rows are kept: the same lighting again adds none.
  const ErrorFigures c = RelitAgainstFresh(method, moved, options, "point light again");
  EXPECT_LT(c.Max, 1e-7);
  EXPECT_EQ(method.GetInstance().Statistics().RelightRowsAdded, 0u);
  EXPECT_EQ(&method.GetScene(), moved.get());
}

TEST(MeshlessRelighting, GathersPastTheirTimeWaitForTheNextRelights)
{
  // With a microsecond for gathers a relight adds one batch of the
  // receivers the point light wants (8, the batch that measures their
  // cost) and leaves the rest to the coarser rows' fit; the relights after
  // it under the same lighting gather the rest, until the answer is the
  // fresh solve's. Measured: the first relight 4.6e-3 of the peak (8
  // added, 182 deferred), all gathered by the 26th relight, then 3.4e-9
  // (bound 1e-7, and the first at least 100 times worse).
  const auto box = std::make_shared<const Scene>(MakeCornellBox());
  MeshlessOptions options = FourLevels();
  options.RelightGatherSeconds = 1e-6;
  MeshlessMethod method(box, options);
  method.Solve({});
  ASSERT_TRUE(method.PrecomputeRelighting({}));
  const auto moved = std::make_shared<const Scene>(CornellWithPointLight(*box));
  const MeshlessStatistics& t = method.GetInstance().Statistics();
  const ErrorFigures first = RelitAgainstFresh(method, moved, options, "point light, 1 us of gathers");
  const std::size_t deferred = t.RelightRowsDeferred;
  std::cout << "  " << deferred << " receivers deferred\n";
  EXPECT_EQ(first.NotFinite, 0u);
  EXPECT_LE(t.RelightRowsAdded, 8u);
  EXPECT_GT(deferred, 0u);
  int relights = 1;
  while (t.RelightRowsDeferred > 0 && relights < 400)
  {
    method.Relight(moved, {});
    ++relights;
  }
  std::cout << "  all gathered after " << relights << " relights\n";
  EXPECT_EQ(t.RelightRowsDeferred, 0u);
  const ErrorFigures last = RelitAgainstFresh(method, moved, options, "point light, gathered over relights");
  EXPECT_LT(last.Max, 1e-7);
  EXPECT_GT(first.Max, 100.0 * last.Max);
}

TEST(MeshlessRelighting, AnalyticLightCases)
{
  // Each light case solved under other lights (intensities and sky scaled
  // by (0.3, 0.6, 1), point and spot lights moved by a tenth of the scene),
  // then relit with its own: against the closed forms. The meshless solve
  // itself is within 2% of the peak on these (LightCases.Meshless).
  for (const LightCase& c : AnalyticLightCases(1.0))
  {
    AnalyticReference exact;
    std::string why;
    ASSERT_TRUE(ComputeAnalyticReference(c.Geometry, c.Probes, exact, why)) << c.Name << ": " << why;
    const auto other = std::make_shared<const Scene>(WithOtherLighting(c.Geometry));
    MeshlessMethod method(other, MeshlessOptions());
    method.Solve({});
    ASSERT_TRUE(method.PrecomputeRelighting({})) << c.Name;
    method.Relight(std::make_shared<const Scene>(c.Geometry), {});
    const ErrorFigures e = RelativeErrors(method.EvaluateProbes(c.Probes), exact.Irradiance);
    MeshlessMethod fresh(std::make_shared<const Scene>(c.Geometry), MeshlessOptions());
    fresh.Solve({});
    const ErrorFigures f = RelativeErrors(fresh.EvaluateProbes(c.Probes), exact.Irradiance);
    std::cout << "  " << c.Name << ": relit max " << e.Max << " RMS " << e.Rms << ", a fresh solve max " << f.Max
              << " RMS " << f.Rms << " of the peak\n";
    EXPECT_EQ(e.NotFinite, 0u) << c.Name;
    // Measured: the relit field equals a fresh solve on every case; 1.2e-3
    // of the peak in the sphere (its indirect light), 2.1e-3 beside the wall
    // (the sky quadrature's own limit), below 2e-6 elsewhere. The issue's
    // bound: 1%.
    EXPECT_LT(e.Max, 0.01) << c.Name;
  }
}

TEST(MeshlessRelighting, ChangedSurfacesAreRefusedAndNamed)
{
  const auto box = std::make_shared<const Scene>(MakeCornellBox());
  MeshlessOptions options;
  options.Placement.Levels = 3;
  MeshlessMethod method(box, options);
  EXPECT_THROW(method.PrecomputeRelighting({}), SceneError); // before a solve: nothing to precompute on
  method.Solve({});
  EXPECT_THROW(method.Relight(box, {}), SceneError);         // before the precomputation
  ASSERT_TRUE(method.PrecomputeRelighting({}));

  auto painted = std::make_shared<Scene>(*box);
  painted->Materials[5].Reflectance = RGB(0.1, 0.2, 0.3);
  try
  {
    method.Relight(painted, {});
    ADD_FAILURE() << "a changed reflectance was relit";
  }
  catch (const SceneError& e)
  {
    const std::string message = e.what();
    EXPECT_NE(message.find("reflectance of triangle 5"), std::string::npos) << message;
  }
  auto moved = std::make_shared<Scene>(*box);
  moved->Points[7].y += 0.01;
  try
  {
    method.Relight(moved, {});
    ADD_FAILURE() << "a moved point was relit";
  }
  catch (const SceneError& e)
  {
    const std::string message = e.what();
    EXPECT_NE(message.find("point 7 moved"), std::string::npos) << message;
  }
  // Refused, the solver keeps its scene and still relights.
  EXPECT_EQ(&method.GetScene(), box.get());
  const SolverStatistics stats = method.Relight(std::make_shared<const Scene>(*box), {});
  EXPECT_EQ(stats.Stop, StopReason::Converged);

  auto dark = std::make_shared<Scene>(*box);
  for (Material& m : dark->Materials)
  {
    m.Emission = RGB(0.0);
  }
  EXPECT_EQ(method.Relight(dark, {}).Stop, StopReason::NoEmitters);
  for (const RGB& v : method.EvaluateProbes(TriangleCentroids(*dark)))
  {
    EXPECT_EQ(MaxComponent(v), 0.0); // no light: zero, not the last lighting's answer
  }
}
