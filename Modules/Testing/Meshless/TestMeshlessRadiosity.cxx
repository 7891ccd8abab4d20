// Meshless hierarchical radiosity (Lehtinen et al. 2007, section 6.3)
// against exact answers: closed uniform rooms, the inside of a sphere with
// non-uniform emission, the exact penumbra; and the Cornell box against the
// path tracer.
#include "Radiosity/Reference/AnalyticReference.h"
#include "Radiosity/Common/ErrorMetrics.h"
#include "Radiosity/Meshless/MeshlessRadiosity.h"
#include "Radiosity/Reference/PathTracer.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

using namespace radiosity;

namespace
{
std::vector<Probe> Centroids(const Scene& scene, std::size_t stride)
{
  std::vector<Probe> probes;
  for (std::size_t t = 0; t < scene.Triangles.size(); t += stride)
  {
    probes.push_back({ scene.Centroid(t), scene.Normal(t) });
  }
  return probes;
}

ErrorFigures SolveAgainstAnalytic(const Scene& scene, const std::vector<Probe>& probes,
  const MeshlessOptions& options, MeshlessStatistics* table = nullptr)
{
  AnalyticReference ref;
  std::string why;
  EXPECT_TRUE(ComputeAnalyticReference(scene, probes, ref, why)) << why;
  MeshlessRadiosity solver(scene, options);
  const SolverStatistics stats = solver.Solve();
  EXPECT_EQ(stats.Stop, StopReason::Converged);
  const std::vector<RGB> values = solver.Evaluate(probes);
  for (const RGB& v : values)
  {
    EXPECT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
  }
  if (table)
  {
    *table = solver.Statistics();
  }
  return RelativeErrors(values, ref.Irradiance);
}
}

TEST(MeshlessRadiosity, ClosedRoomsWithinOnePercent)
{
  for (double rho : { 0.5, 0.9, 0.99 })
  {
    const Scene cube = MakeClosedCube(1.0, 2, rho, 1.0);
    MeshlessOptions options;
    options.Placement.Levels = 3;
    const ErrorFigures e = SolveAgainstAnalytic(cube, Centroids(cube, 3), options);
    // Exact up to rounding: measured 4.4e-16 (rho 0.5), 1.7e-14 (0.9), 1.0e-12 (0.99).
    EXPECT_LT(e.Max, 3e-12) << "rho " << rho;
    EXPECT_EQ(e.Counted, Centroids(cube, 3).size());
    std::cout << "closed room rho " << rho << ": max error " << e.Max << "\n";
  }
}

TEST(MeshlessRadiosity, SphereWithNonUniformEmission)
{
  // 5120 facets: the reference is the smooth sphere, and the facets' own
  // direct light departs from it by up to 1.7% at 1280 facets (exact
  // contour integrals at the centroids), 0.4% at 5120.
  const Scene sphere = MakeSphereInterior(1.0, 4, 0.7, RGB(3.0, 2.0, 1.0));
  MeshlessOptions options;
  options.Placement.Levels = 3;
  MeshlessStatistics table;
  const ErrorFigures e = SolveAgainstAnalytic(sphere, Centroids(sphere, 29), options, &table);
  EXPECT_LT(e.Max, 0.01); // measured 0.0067 of the peak
  EXPECT_GT(table.SamplesGenerated, table.CoarsestSamples);
  EXPECT_GT(table.SamplesGatheredTo, 0u);
  std::cout << "sphere: max error " << e.Max << ", " << table.SamplesGenerated << " samples, "
            << table.SamplesGatheredTo << " gathered to, " << table.VisibilityRays << " rays\n";
}

TEST(MeshlessRadiosity, CornellBoxAgainstThePathTracer)
{
  const Scene box = MakeCornellBox();
  const std::vector<Probe> probes = Centroids(box, 1);
  PathTracerOptions pto;
  pto.SamplesPerProbe = 16384;
  PathTracer tracer(box, pto);
  std::vector<RGB> reference;
  for (const ReferenceValue& r : tracer.Irradiance(probes))
  {
    reference.push_back(r.Value);
  }
  MeshlessRadiosity solver(box, MeshlessOptions());
  const SolverStatistics stats = solver.Solve();
  EXPECT_EQ(stats.Stop, StopReason::Converged);
  const ErrorFigures e = RelativeErrors(solver.Evaluate(probes), reference);
  const MeshlessStatistics& t = solver.Statistics();
  std::cout << "Cornell box: RMS " << e.Rms << ", max " << e.Max << " in " << stats.SolveSeconds
            << " s; " << t.SamplesGenerated << " samples, " << t.SamplesGatheredTo
            << " gathered to, " << t.VisibilityRays << " rays, " << t.Levels << " levels, "
            << t.CoarsestSamples << " coarsest\n";
  // Against a path tracer of 16384 paths per probe (its noise is part of
  // the figure): measured RMS 0.0203, max 0.0887 of the peak.
  EXPECT_EQ(e.Counted, probes.size());
  EXPECT_EQ(e.NotFinite, 0u);
  EXPECT_LT(e.Rms, 0.06);
  EXPECT_LT(e.Max, 0.26);
}

TEST(MeshlessRadiosity, SurfaceOfKeptTrianglesIsTheWholeSurfacesThere)
{
  // An MPI rank evaluates the output of its own triangles only
  // (Surface(&keep)): there it is the whole surface's, tile for tile
  // (SampledSurface tiles the elements to evaluate, not all of them);
  // elsewhere it is left zero.
  const Scene box = MakeCornellBox();
  MeshlessOptions options;
  options.Placement.Levels = 3;
  MeshlessRadiosity solver(box, options);
  solver.Solve();
  std::vector<char> keep(box.Triangles.size(), 0);
  for (std::size_t t = 0; t < keep.size(); t += 3)
  {
    keep[t] = 1;
  }
  const SolutionMesh whole = solver.Surface(), part = solver.Surface(&keep);
  ASSERT_EQ(whole.Triangles.size(), part.Triangles.size());
  std::size_t kept = 0, zero = 0;
  for (std::size_t e = 0; e < whole.Triangles.size(); ++e)
  {
    const double peak = std::max(1.0, MaxComponent(whole.Samples[e].Mean()));
    if (keep[whole.SourceTriangle[e]])
    {
      ++kept;
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_LT(MaxComponent(glm::abs(part.Samples[e].Corner[k] - whole.Samples[e].Corner[k])), 1e-12 * peak);
      }
      EXPECT_LT(MaxComponent(glm::abs(part.Samples[e].Centre - whole.Samples[e].Centre)), 1e-12 * peak);
    }
    else if (MaxComponent(part.Samples[e].Mean()) == 0.0)
    {
      ++zero;
    }
  }
  EXPECT_GT(kept, 0u);
  EXPECT_GT(zero, 0u); // elements of neither a kept triangle nor its neighbours
}

TEST(MeshlessRadiosity, TimeLimitStopsRefiningInsideABounce)
{
  // A limit already past when the solve starts: the direct light and the
  // first bounce keep their coarsest level only (always whole), every finer
  // wave is left at that fit, and the solve stops after the bounce with the
  // time limit. A whole bounce of a large scene had taken 30 s past a 5 s limit.
  const Scene box = MakeCornellBox();
  MeshlessOptions options;
  options.MaxTimeSeconds = 1e-9;
  MeshlessRadiosity limited(box, options);
  const SolverStatistics stats = limited.Solve();
  const MeshlessStatistics& t = limited.Statistics();
  EXPECT_EQ(stats.Stop, StopReason::TimeLimit);
  EXPECT_EQ(stats.Iterations, 1);
  EXPECT_EQ(t.GatherOperations, 2 * t.CoarsestSamples) << t.CoarsestSamples << " coarsest samples";
  MeshlessOptions oneBounce; // the same bounces, every level refined
  oneBounce.MaxBounces = 1;
  MeshlessRadiosity whole(box, oneBounce);
  whole.Solve();
  EXPECT_GT(whole.Statistics().GatherOperations, 4 * t.GatherOperations);
  // The coarse answer is an answer: finite, non-negative, and near the
  // refined solve of as many bounces on average.
  const std::vector<Probe> probes = Centroids(box, 1);
  const std::vector<RGB> coarse = limited.Evaluate(probes), fine = whole.Evaluate(probes);
  double sumCoarse = 0.0, sumFine = 0.0;
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    ASSERT_TRUE(std::isfinite(Luminance(coarse[i])) && MaxComponent(-coarse[i]) <= 0.0) << "probe " << i;
    sumCoarse += Luminance(coarse[i]);
    sumFine += Luminance(fine[i]);
  }
  std::cout << "Cornell box past the time limit: " << t.GatherOperations << " gathers (whole: "
            << whole.Statistics().GatherOperations << "), mean probe irradiance " << sumCoarse / sumFine
            << " of the whole solve's\n";
  // Measured: 368 gathers against 6,016, mean 0.908 of the refined solve's.
  EXPECT_NEAR(sumCoarse / sumFine, 1.0, 0.15);
}
