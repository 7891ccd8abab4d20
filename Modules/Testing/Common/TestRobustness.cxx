// Every method on the inputs that used to crash it: a scene without emitters
// (the documented zero solution, returned at once) and a solve aborted
// before its first phase. The surface solution and the probes must then be
// zero, not a null dereference.
#include "Radiosity/FaceCluster/FaceClusterRadiosity.h"
#include "Radiosity/Hierarchical/DiscontinuityMesher.h"
#include "Radiosity/Common/ElementMesh.h"
#include "Radiosity/Hierarchical/HierarchicalRadiosity.h"
#include "Radiosity/Common/MemoryBudget.h"
#include "Radiosity/Meshless/MeshlessPoints.h"
#include "Radiosity/Meshless/MeshlessRadiosity.h"
#include "Radiosity/Progressive/ProgressiveRadiosity.h"
#include "Radiosity/Scenes/SceneGenerators.h"
#include "Radiosity/Common/SolutionMesh.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <functional>
#include <cmath>
#include <iostream>

using namespace radiosity;

namespace
{
std::vector<Probe> TwoProbes()
{
  return { { Vec3(0.5, 0.5, 0.01), Vec3(0, 0, 1) }, { Vec3(0.5, 0.5, 0.99), Vec3(0, 0, -1) } };
}

void ExpectZero(const SolutionMesh& s, const std::string& what)
{
  ASSERT_FALSE(s.CellIrradiance.empty()) << what << ": the zero solution still has its cells";
  for (const RGB& e : s.CellIrradiance)
  {
    EXPECT_EQ(MaxComponent(e), 0.0) << what;
  }
  for (const RGB& e : s.PointIrradiance)
  {
    EXPECT_EQ(MaxComponent(e), 0.0) << what;
  }
}

void ExpectZero(const std::vector<RGB>& values, const std::string& what)
{
  ASSERT_EQ(values.size(), 2u) << what;
  for (const RGB& e : values)
  {
    EXPECT_EQ(MaxComponent(e), 0.0) << what;
  }
}
}

TEST(Robustness, MeshlessWithoutEmittersIsZero)
{
  // Used to segfault: Surface() and Evaluate() read a field never built.
  const Scene dark = MakeClosedCube(1.0, 2, 0.5, 0.0);
  MeshlessRadiosity solver(dark, MeshlessOptions());
  EXPECT_EQ(solver.Solve().Stop, StopReason::NoEmitters);
  ExpectZero(solver.Surface(), "meshless surface");
  ExpectZero(solver.Evaluate(TwoProbes()), "meshless probes");
}

TEST(Robustness, MeshlessAbortedBeforePlacementIsZero)
{
  const Scene lit = MakeClosedCube(1.0, 2, 0.5, 1.0);
  MeshlessRadiosity solver(lit, MeshlessOptions());
  EXPECT_EQ(solver.Solve([](const ProgressStatus&) { return false; }).Stop, StopReason::Aborted);
  ExpectZero(solver.Surface(), "aborted meshless surface");
  ExpectZero(solver.Evaluate(TwoProbes()), "aborted meshless probes");
}

TEST(Robustness, FaceClusterWithoutEmittersIsZero)
{
  const Scene dark = MakeClosedCube(1.0, 2, 0.5, 0.0);
  FaceClusterRadiosity solver(dark, FaceClusterSettings());
  EXPECT_EQ(solver.Solve().Stop, StopReason::NoEmitters);
  ExpectZero(solver.Surface(), "face cluster surface");
  ExpectZero(solver.Evaluate(TwoProbes()), "face cluster probes");
  // The vertex vectors too (what --output writes for the display): no
  // element to read, all zero (a halved-triangle branch once read
  // element -1 here: the corpus's unlit glossy files crashed).
  for (const auto& v : solver.VertexIrradianceVectors())
  {
    for (double x : v)
    {
      EXPECT_EQ(x, 0.0);
    }
  }
}

TEST(Robustness, HierarchicalAndProgressiveWithoutEmittersAreZero)
{
  const Scene dark = MakeClosedCube(1.0, 2, 0.5, 0.0);
  HierarchicalRadiosity hierarchical(dark, HierarchicalOptions());
  EXPECT_EQ(hierarchical.Solve().Stop, StopReason::NoEmitters);
  ExpectZero(ExtractSolution(hierarchical.Mesh()), "hierarchical");
  ProgressiveRadiosity progressive(dark, ProgressiveOptions());
  EXPECT_EQ(progressive.Solve().Stop, StopReason::NoEmitters);
  ExpectZero(ExtractSolution(progressive.Mesh()), "progressive");
}

TEST(Robustness, ProgressFractionIsFiniteAtToleranceOne)
{
  // Tolerance 1 made the fraction log(r) / log(1): 0/0 at residual 1.
  for (double tolerance : { 1.0, 1e-3 })
  {
    for (double residual : { 2.0, 1.0, 0.5, 1e-4, 0.0, std::nan("") })
    {
      double fraction = -1.0;
      ReportProgress([&](const ProgressStatus& s) { fraction = s.Fraction; return true; }, "test", 1,
        residual, tolerance);
      EXPECT_TRUE(fraction >= 0.0 && fraction <= 1.0)
        << "tolerance " << tolerance << " residual " << residual << ": " << fraction;
    }
  }
  double atOne = -1.0;
  ReportProgress([&](const ProgressStatus& s) { atOne = s.Fraction; return true; }, "test", 1, 1.0, 1.0);
  EXPECT_EQ(atOne, 1.0); // residual at the tolerance: done
}

TEST(MemoryBudget, FacingPairsAreTheInitialLinks)
{
  // Exact (up to 2,000 triangles): hierarchical radiosity with no refinement
  // makes exactly one link per facing ordered pair of input triangles.
  const Scene box = MakeCornellBox();
  HierarchicalOptions options;
  options.LinkTolerance = 1e30; // no link is ever split
  options.MaxRefinementRounds = 0;
  options.MaxIterations = 1;
  HierarchicalRadiosity solver(box, options);
  const SolverStatistics stats = solver.Solve();
  EXPECT_EQ(static_cast<double>(stats.Links), FacingTrianglePairs(box));
  EXPECT_GT(stats.Links, 100u);
}

TEST(MemoryBudget, SampledFacingPairsWithinATenthOfAPercent)
{
  // Beyond 2,000 triangles the count is sampled. Inside a sphere every pair
  // faces; in a closed cube each triangle faces the five other walls.
  const Scene sphere = MakeSphereInterior(1.0, 4, 0.5, RGB(1.0)); // 5,120 triangles
  const double n = static_cast<double>(sphere.Triangles.size());
  ASSERT_GT(n, 2000);
  EXPECT_NEAR(FacingTrianglePairs(sphere) / (n * (n - 1)), 1.0, 1e-12);
  const Scene cube = MakeClosedCube(1.0, 24, 0.5, 1.0);
  const double m = static_cast<double>(cube.Triangles.size());
  ASSERT_GT(m, 2000);
  const double exact = m * (5.0 / 6.0 * m);
  const double sampled = FacingTrianglePairs(cube);
  std::cout << "closed cube of " << m << " triangles: facing pairs sampled " << sampled << ", exact " << exact
            << " (" << (sampled / exact - 1) * 100 << "%)\n";
  EXPECT_NEAR(sampled / exact, 1.0, 1.5e-4); // measured 5.0e-5
}

TEST(MemoryBudget, HierarchicalSphereOf20kTrianglesIsRefusedAtOnce)
{
  // Used to grow past 24 GB and be killed: 20,480 triangles all facing each
  // other make 419 million initial links (about 47 GB). With the budget of a
  // 24 GB machine (18 GB) the constructor refuses before allocating them.
  // Unclustered only: clustered (the default above 2048 triangles) the
  // sphere is solved (ClusteredHierarchical.SphereOf20kTriangles).
  const Scene sphere = MakeSphereInterior(1.0, 5, 0.9, RGB(10.0));
  ASSERT_EQ(sphere.Triangles.size(), 20480u);
  HierarchicalOptions options;
  options.Clustering = HierarchicalClustering::Off;
  options.MemoryBudgetBytes = 18e9;
  const auto start = std::chrono::steady_clock::now();
  try
  {
    HierarchicalRadiosity solver(sphere, options);
    ADD_FAILURE() << "not refused";
  }
  catch (const MemoryBudgetExceeded& e)
  {
    const std::string message = e.what();
    std::cout << message << "\n";
    EXPECT_NE(message.find("20480 input triangles"), std::string::npos) << message;
    EXPECT_NE(message.find("419 million links"), std::string::npos) << message;
    EXPECT_NE(message.find("need about 47 GB"), std::string::npos) << message; // the README's figure
    EXPECT_NE(message.find("--method facecluster"), std::string::npos) << message;
    EXPECT_NE(message.find("--max-memory"), std::string::npos) << message;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "refused in " << seconds << " s\n";
  // The README's "in under a second" is this figure (0.54 s measured on a
  // loaded 2-core machine); speed is not asserted in tests (DESIGN: benchmarks).
}

TEST(MemoryBudget, RefinementPastTheBudgetIsRefused)
{
  // What the estimate cannot know (how far the links refine) is guarded
  // while it grows: the Cornell box with a tiny link tolerance and minimum
  // element size, 2 MB allowed.
  const Scene box = MakeCornellBox();
  HierarchicalOptions options;
  options.RelativeLinkTolerance = 1e-6;
  options.MinElementSize = 1e-4;
  options.MemoryBudgetBytes = 2e6;
  HierarchicalRadiosity solver(box, options); // the initial links fit
  try
  {
    solver.Solve();
    ADD_FAILURE() << "not refused";
  }
  catch (const MemoryBudgetExceeded& e)
  {
    const std::string message = e.what();
    EXPECT_NE(message.find("refining to"), std::string::npos) << message;
    EXPECT_NE(message.find("--link-tolerance"), std::string::npos) << message;
  }
}

TEST(MemoryBudget, EstimatesOfTheOtherMethods)
{
  const Scene box = MakeCornellBox();
  // Progressive: the initial mesh is the uniform quadtree the estimate counts.
  const double diagonal = box.Diagonal();
  for (double size : { 1.0 / 8, 1.0 / 16, 1.0 / 40 })
  {
    const ElementMesh mesh(box, 0.25 * diagonal, size * diagonal, 12);
    EXPECT_EQ(static_cast<double>(mesh.NumberOfLeaves()), UniformQuadtreeLeaves(box, size * diagonal, 12))
      << "element size " << size;
  }
  ProgressiveOptions progressive;
  progressive.InitialElementSize = 1e-6;
  progressive.MemoryBudgetBytes = 16e9; // 537 million initial elements: about 230 GB
  EXPECT_THROW(ProgressiveRadiosity(box, progressive), MemoryBudgetExceeded);
  // Meshless: the hexagonal packing bound holds the points placed.
  MeshlessOptions meshless;
  meshless.Placement.Levels = 3;
  MeshlessRadiosity solver(box, meshless);
  solver.Solve();
  const double placed = static_cast<double>(solver.Statistics().SamplesGenerated);
  const double bound = MaxPoissonDiskPoints(box, meshless.Placement);
  std::cout << "meshless: " << placed << " points placed, bound " << bound << "\n";
  EXPECT_LE(placed, bound);
  EXPECT_GT(placed, bound / 4.0); // measured: 2,212 points, bound 5,082
  meshless.Placement.InitialRadius = 1e-6;
  meshless.MemoryBudgetBytes = 16e9;
  MeshlessRadiosity tooFine(box, meshless);
  EXPECT_THROW(tooFine.Solve(), MemoryBudgetExceeded);
  // Face cluster: elements are guarded as they are made.
  FaceClusterSettings faceCluster;
  faceCluster.MemoryBudgetBytes = 1e5;
  FaceClusterRadiosity clusters(box, faceCluster);
  EXPECT_THROW(clusters.Solve(), MemoryBudgetExceeded);
}

// The floor's irradiance power with 575 links' blockers cut over that with
// none cut: measured 1 - 2.7e-4 (before the cut links took their rays'
// passing fraction: 1 + 2.4e-3, light through the gaps between the kept blockers).
constexpr double CutFloorPowerBound = 1e-3;

TEST(Robustness, LinksWithTooManyBlockersAreCounted)
{
  // The exact-penumbra scene with its blocker split into 12 x 12 quads (288
  // triangles): the links from the emitter to the floor behind it have more
  // candidate blockers than the 64 kept per link. Those used to be cut
  // without a word; they are counted now, and none are with room for all.
  Scene scene = MakeShadowScene(2, 10.0);
  Scene fine;
  Material black;
  black.Reflectance = RGB(0.0);
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    const Vec3 c = scene.Centroid(t);
    if (std::fabs(c.z - 0.5) > 1e-9) // keep the emitter and the floor
    {
      const std::uint32_t base = static_cast<std::uint32_t>(fine.Points.size());
      for (int k = 0; k < 3; ++k)
      {
        fine.Points.push_back(scene.Vertex(t, k));
      }
      fine.Triangles.push_back({ { base, base + 1, base + 2 } });
      fine.Materials.push_back(scene.Materials[t]);
      fine.ObjectIds.push_back(scene.ObjectIds[t]);
      fine.SourceCells.push_back(static_cast<long long>(t));
    }
  }
  fine.ObjectNames = scene.ObjectNames;
  // The blocker, facing down towards the floor and up towards the light: both sides.
  const double x0 = -0.2 + 0.15, x1 = 0.2 + 0.15, y0 = -0.2, y1 = 0.2;
  AppendQuad(fine, Vec3(x0, y0, 0.5), Vec3(x0, y1, 0.5), Vec3(x1, y1, 0.5), Vec3(x1, y0, 0.5), black, 12, "down");
  AppendQuad(fine, Vec3(x0, y0, 0.5), Vec3(x1, y0, 0.5), Vec3(x1, y1, 0.5), Vec3(x0, y1, 0.5), black, 12, "up");
  ASSERT_NO_THROW(ValidateScene(fine));
  HierarchicalOptions options;
  options.MaxRefinementRounds = 0;
  HierarchicalRadiosity cut(fine, options);
  const SolverStatistics few = cut.Solve();
  std::cout << few.LinksWithBlockersCut << " of " << few.Links << " links had their blockers cut\n";
  EXPECT_GT(few.LinksWithBlockersCut, 0u);
  options.MaxBlockersPerLink = 1000;
  HierarchicalRadiosity all(fine, options);
  EXPECT_EQ(all.Solve().LinksWithBlockersCut, 0u);
  // The light on the floor with the blockers cut is the light with all of
  // them: a cut link's visibility is its rays' passing fraction, not the few
  // blockers those rays met (through whose gaps the light leaked).
  auto floorPower = [&](const HierarchicalRadiosity& s) {
    double power = 0.0;
    for (std::uint32_t e : s.Mesh().Leaves())
    {
      const TriangleCorners p = s.Corners(e);
      if (std::fabs(p[0].z) < 1e-9 && std::fabs(p[1].z) < 1e-9 && std::fabs(p[2].z) < 1e-9)
      {
        power += 0.5 * glm::length(glm::cross(p[1] - p[0], p[2] - p[0])) * Luminance(s.Irradiance(e));
      }
    }
    return power;
  };
  const double cutPower = floorPower(cut), allPower = floorPower(all);
  std::cout << "floor power: blockers cut " << cutPower << ", all blockers " << allPower << "\n";
  EXPECT_NEAR(cutPower / allPower, 1.0, CutFloorPowerBound);
}

TEST(Robustness, ThreadLimitIsScopedToTheSolve)
{
  // Threads = 1 used to set a tbb::global_control: while the solve ran, every
  // TBB user of the process (a ParaView session, another filter) was capped
  // at one thread. The solve's own loops see one thread now, the rest of the
  // process TBB's default.
  const int all = tbb::this_task_arena::max_concurrency();
  if (all < 2)
  {
    GTEST_SKIP() << "one core: a limit of 1 cannot be told from the default";
  }
  const Scene box = MakeClosedCube(1.0, 2, 0.5, 1.0);
  ProgressiveOptions options;
  options.Threads = 1;
  ProgressiveRadiosity solver(box, options);
  int inside = 0;
  std::size_t outside = 0;
  solver.Solve([&](const ProgressStatus&) {
    inside = tbb::this_task_arena::max_concurrency();
    outside = tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
    return true;
  });
  EXPECT_EQ(inside, 1);
  EXPECT_GE(outside, static_cast<std::size_t>(all)) << "the process-wide limit was set";
}

namespace
{
/// A progress callback that says stop once `after` seconds have passed, and
/// remembers when it first did.
struct AbortAfter
{
  explicit AbortAfter(double after)
    : After(after)
  {
  }
  using Clock = std::chrono::steady_clock;
  double After;
  Clock::time_point Start = Clock::now();
  Clock::time_point Stopped{};
  bool Asked = false;
  bool operator()(const ProgressStatus&)
  {
    const auto now = Clock::now();
    if (std::chrono::duration<double>(now - this->Start).count() < this->After)
    {
      return true;
    }
    if (!this->Asked)
    {
      this->Asked = true;
      this->Stopped = now;
    }
    return false;
  }
  double SecondsSinceStop() const
  {
    return std::chrono::duration<double>(Clock::now() - this->Stopped).count();
  }
};
}

TEST(Robustness, AbortDuringMeshlessPointPlacementWithinASecond)
{
  // Placement used to ask for progress only before it began: fine radii made
  // it minutes long and deaf to an abort.
  const Scene box = MakeCornellBox();
  MeshlessOptions options;
  options.Placement.InitialRadius = 0.004;
  options.Placement.Levels = 4;
  MeshlessRadiosity solver(box, options);
  AbortAfter abort(0.3);
  const SolverStatistics stats = solver.Solve(std::ref(abort));
  ASSERT_TRUE(abort.Asked);
  const double late = abort.SecondsSinceStop();
  std::cout << "meshless placement stopped " << late << " s after the abort\n";
  EXPECT_EQ(stats.Stop, StopReason::Aborted);
  EXPECT_LT(late, 1.0); // wall clock: measured 1.9 ms; 1 s is the promise, the margin a loaded machine
  ExpectZero(solver.Surface(), "meshless aborted during placement");
}

TEST(Robustness, AbortDuringHierarchicalLinkingWithinASecond)
{
  // 1.64 million initial links inside a sphere of 1,280 triangles: several
  // seconds of linking, which used to ask for progress only before it began.
  const Scene sphere = MakeSphereInterior(1.0, 3, 0.9, RGB(10.0));
  HierarchicalRadiosity solver(sphere, HierarchicalOptions());
  AbortAfter abort(0.2);
  const SolverStatistics stats = solver.Solve(std::ref(abort));
  ASSERT_TRUE(abort.Asked);
  const double late = abort.SecondsSinceStop();
  std::cout << "hierarchical linking stopped " << late << " s after the abort\n";
  EXPECT_EQ(stats.Stop, StopReason::Aborted);
  EXPECT_EQ(stats.Iterations, 0) << "the abort came during linking, before any sweep";
  EXPECT_LT(late, 1.0); // wall clock: measured 0.1 ms; 1 s is the promise, the margin a loaded machine
}

namespace
{
struct MeshingAbort
{
  bool Asked = false;
  std::string Phase; ///< of the last progress report
  double Late = 0.0; ///< seconds from the abort to the mesher's return
  bool Empty = false; ///< no interpolant made
};

/// The Cornell box solved, then meshed with an abort asked `after` seconds
/// from the first report that `from` accepts (and every one after it).
MeshingAbort AbortCornellMeshing(const std::function<bool(const ProgressStatus&)>& from, double after)
{
  const Scene box = MakeCornellBox();
  HierarchicalRadiosity solver(box, HierarchicalOptions());
  EXPECT_EQ(solver.Solve().Stop, StopReason::Converged);
  AbortAfter abort(after);
  MeshingAbort out;
  bool started = false;
  const DiscontinuityMesh mesh = BuildDiscontinuityMesh(solver, DiscontinuityMeshOptions(),
    [&](const ProgressStatus& status) {
      out.Phase = status.Phase;
      started = started || from(status);
      return started ? abort(status) : true;
    });
  out.Asked = abort.Asked;
  out.Late = abort.SecondsSinceStop();
  out.Empty = mesh.Interpolants.empty();
  std::cout << "meshing stopped in phase '" << out.Phase << "' " << out.Late << " s after the abort\n";
  return out;
}
} // namespace

TEST(Robustness, AbortDuringTheFirstMeshingPhaseWithinASecond)
{
  // The discontinuities and triangulations of every leaf (phase 1) used to
  // run to their end before the first progress report.
  const MeshingAbort r = AbortCornellMeshing([](const ProgressStatus&) { return true; }, 0.1);
  ASSERT_TRUE(r.Asked);
  EXPECT_EQ(r.Phase, "finding discontinuities");
  EXPECT_TRUE(r.Empty);
  EXPECT_LT(r.Late, 1.0); // wall clock: measured 0.14 ms; 1 s is the promise, the margin a loaded machine
}

TEST(Robustness, AbortDuringTheMeshingSamplesWithinASecond)
{
  // The accurate point irradiance of every sample (phase 3) runs in blocks
  // of leaves with a progress report between them: an abort asked once the
  // samples have begun stops it before the interpolants. Past the first
  // block of samples (the Cornell box has about seven):
  const MeshingAbort r = AbortCornellMeshing(
    [](const ProgressStatus& status) { return status.Phase == "sampling" && status.Fraction > 0.35; }, 0.0);
  ASSERT_TRUE(r.Asked);
  EXPECT_EQ(r.Phase, "sampling");
  EXPECT_TRUE(r.Empty);
  EXPECT_LT(r.Late, 1.0); // wall clock: measured 2.6 ms; 1 s is the promise, the margin a loaded machine
}
