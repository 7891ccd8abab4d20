// Progressive refinement radiosity against exact answers: closed enclosures,
// energy balance on an open scene, scale invariance.
#include "Radiosity/Common/ClosedFormFactors.h"
#include "Radiosity/Progressive/ProgressiveRadiosity.h"
#include "Radiosity/Scenes/SceneGenerators.h"
#include "Radiosity/Common/SolutionMesh.h"

#include <gtest/gtest.h>

#include <iostream>

#include <cmath>

using namespace radiosity;

namespace
{
double MaxRelativeError(const SolutionMesh& s, double exact)
{
  double err = 0.0;
  for (const RGB& b : s.CellRadiosity)
  {
    for (int c = 0; c < 3; ++c)
    {
      err = std::max(err, std::fabs(b[c] - exact) / exact);
    }
  }
  return err;
}
}

class ClosedCube : public ::testing::TestWithParam<double>
{
};

TEST_P(ClosedCube, UniformRadiosityIsEOverOneMinusRho)
{
  const double rho = GetParam();
  const Scene cube = MakeClosedCube(1.0, 2, rho, 1.0);
  ProgressiveOptions options;
  options.Tolerance = 1e-4;
  options.MaxTimeSeconds = 120;
  options.ShooterElementSize = 0.4;
  options.InitialElementSize = 0.2;
  ProgressiveRadiosity solver(cube, options);
  const SolverStatistics stats = solver.Solve();
  EXPECT_EQ(stats.Stop, StopReason::Converged) << ToString(stats.Stop);
  const SolutionMesh s = ExtractSolution(solver.Mesh());
  const double exact = 1.0 / (1.0 - rho);
  std::cout << "closed cube rho " << rho << ": max error " << MaxRelativeError(s, exact) << "\n";
  // Measured 5.7e-6 (rho 0.5), 1.6e-5 (0.9), 1.7e-6 (0.99), 7.6e-7 (0.999).
  EXPECT_LT(MaxRelativeError(s, exact), 5e-5) << "rho = " << rho << ", iterations "
                                              << stats.Iterations;
  // A convex enclosure: nothing can occlude, so no ray is cast.
  EXPECT_EQ(stats.Occluders, 0u);
  EXPECT_EQ(stats.RaysCast, 0u);
}

INSTANTIATE_TEST_SUITE_P(Reflectance, ClosedCube, ::testing::Values(0.5, 0.9, 0.99, 0.999));

TEST(ProgressiveRadiosity, OvershootingShortensHighReflectanceRooms)
{
  const Scene cube = MakeClosedCube(1.0, 2, 0.99, 1.0);
  ProgressiveOptions options;
  options.Tolerance = 1e-3;
  options.MaxIterations = 20000;
  options.ShooterElementSize = 0.4;
  options.InitialElementSize = 0.2;
  ProgressiveRadiosity fast(cube, options);
  const SolverStatistics accelerated = fast.Solve();
  ASSERT_EQ(accelerated.Stop, StopReason::Converged);
  // Without the acceleration, four times as many shots are not enough.
  options.Overshooting = false;
  options.MaxIterations = 4 * accelerated.Iterations;
  ProgressiveRadiosity slow(cube, options);
  const SolverStatistics plain = slow.Solve();
  EXPECT_EQ(plain.Stop, StopReason::IterationLimit);
  std::cout << "unshot without / with overshooting: " << plain.UnshotPowerW / accelerated.UnshotPowerW
            << " after " << accelerated.Iterations << " shots\n";
  EXPECT_GT(plain.UnshotPowerW, 220 * accelerated.UnshotPowerW); // measured 670 times
}

TEST(ProgressiveRadiosity, EnergyBalanceOnOpenScene)
{
  // Emitter below a reflecting square, open to the sky: emitted = absorbed + escaped.
  const Scene s = MakeParallelSquares(1.0, 0.5, 4, 0.8, 10.0);
  ProgressiveOptions options;
  options.Tolerance = 1e-7;
  ProgressiveRadiosity solver(s, options);
  const SolverStatistics stats = solver.Solve();
  ASSERT_EQ(stats.Stop, StopReason::Converged);
  const double emitted = stats.EmittedPowerW;
  EXPECT_NEAR(emitted, 10.0, 1e-9);
  const double balance =
    (emitted - stats.AbsorbedPowerW - stats.EscapedPowerW - 0.0) / emitted;
  std::cout << "balance " << balance << "\n";
  EXPECT_LT(std::fabs(balance), 3e-4) << "absorbed " // measured 1.0e-4 << stats.AbsorbedPowerW << " escaped "
                                      << stats.EscapedPowerW;
  // The receiver absorbs (1 - rho) of what reaches it from the uniform
  // emitter (which reflects nothing back): E A F12 (1 - rho), F12 in closed form.
  const SolutionMesh sol = ExtractSolution(solver.Mesh());
  double receiverAbsorbed = 0.0;
  for (std::size_t t = 0; t < sol.Triangles.size(); ++t)
  {
    if (s.ObjectIds[sol.SourceTriangle[t]] == 1)
    {
      const auto& v = sol.Triangles[t].V;
      const double a =
        glm::length(AreaVector(sol.Points[v[0]], sol.Points[v[1]], sol.Points[v[2]]));
      receiverAbsorbed += 0.2 * Luminance(sol.CellIrradiance[t]) * a;
    }
  }
  const double f12 = closedform::ParallelRectangles(1.0, 1.0, 0.5);
  std::cout << "receiver absorbed " << receiverAbsorbed / (10.0 * f12 * 0.2) - 1 << " off\n";
  EXPECT_NEAR(receiverAbsorbed, 10.0 * f12 * 0.2, 1.9e-6 * 10.0 * f12 * 0.2); // measured 6.3e-7
}

TEST(ProgressiveRadiosity, ScaleInvariance)
{
  // The same scene at 1e-4 m and 1e4 m gives the same radiosity.
  const Scene unit = MakeCornellBox();
  std::vector<double> results;
  for (double scale : { 1e-4, 1e4 })
  {
    Scene scaled = unit;
    for (Vec3& p : scaled.Points)
    {
      p *= scale;
    }
    ProgressiveOptions options;
    options.Tolerance = 1e-2;
    ProgressiveRadiosity solver(scaled, options);
    const SolverStatistics stats = solver.Solve();
    ASSERT_EQ(stats.Stop, StopReason::Converged);
    const SolutionMesh sol = ExtractSolution(solver.Mesh());
    double weighted = 0.0, area = 0.0;
    for (std::size_t t = 0; t < sol.Triangles.size(); ++t)
    {
      const auto& v = sol.Triangles[t].V;
      const double a =
        glm::length(AreaVector(sol.Points[v[0]], sol.Points[v[1]], sol.Points[v[2]]));
      weighted += Luminance(sol.CellRadiosity[t]) * a;
      area += a;
    }
    results.push_back(weighted / area);
  }
  // Embree's single-precision rays round differently at the two scales, so a
  // few grazing visibility rays may flip: 1e-5 of the mean radiosity. A self-
  // intersection offset that did not scale would show errors of order 1.
  // Measured 1.3e-6; the bound stays at 1e-5 because which rays flip depends
  // on the platform's float rounding (Embree's SIMD width).
  std::cout << "scales: " << results[1] / results[0] - 1 << "\n";
  EXPECT_NEAR(results[0], results[1], 1e-5 * results[0]);
}

TEST(ProgressiveRadiosity, NoEmittersReturnsZeroAtOnce)
{
  const Scene cube = MakeClosedCube(1.0, 2, 0.5, 0.0);
  ProgressiveRadiosity solver(cube, ProgressiveOptions());
  const SolverStatistics stats = solver.Solve();
  EXPECT_EQ(stats.Stop, StopReason::NoEmitters);
  EXPECT_EQ(stats.Iterations, 0);
  const SolutionMesh s = ExtractSolution(solver.Mesh());
  for (const RGB& b : s.CellRadiosity)
  {
    EXPECT_EQ(MaxComponent(b), 0.0);
  }
}
