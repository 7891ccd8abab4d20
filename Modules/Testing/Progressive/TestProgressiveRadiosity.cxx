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

TEST(ProgressiveRadiosity, SplitsAfterTheLightsShotKeepTheLight)
{
  // A sunlit wall (y = 1, facing -y) behind a small box 0.2 m in front of
  // it, on a floor; reflectance 0.8, the sun travelling along (0, 0.6, -0.8)
  // at 1 W/m^2. The box's shadow falls on the floor (it ends 0.15 m behind
  // the box, 0.05 m short of the wall): every point of the wall receives
  // 0.6 W/m^2 from the sun, and more from the floor and the box. Receivers
  // split by a later element shot (near the box) gather their history
  // again; that history once left out the lights' shot, and those children
  // lost their sunlight (dark triangles on the wall behind the box: 0.31 of
  // 1.4 W/m^2 at a corner in TestRadiosityPassAssembly's scene).
  Scene s;
  Material white;
  white.Reflectance = RGB(0.8);
  AppendQuad(s, Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0), white, 4, "floor");
  const std::size_t firstWall = s.Triangles.size();
  AppendQuad(s, Vec3(-1, 1, 0), Vec3(1, 1, 0), Vec3(1, 1, 1.5), Vec3(-1, 1, 1.5), white, 3, "wall");
  const std::size_t endWall = s.Triangles.size();
  AppendQuad(s, Vec3(-0.1, 0.6, 0.2), Vec3(0.1, 0.6, 0.2), Vec3(0.1, 0.8, 0.2), Vec3(-0.1, 0.8, 0.2), white, 1, "box top");
  AppendQuad(s, Vec3(-0.1, 0.6, 0), Vec3(0.1, 0.6, 0), Vec3(0.1, 0.6, 0.2), Vec3(-0.1, 0.6, 0.2), white, 1, "box front");
  AppendQuad(s, Vec3(0.1, 0.8, 0), Vec3(-0.1, 0.8, 0), Vec3(-0.1, 0.8, 0.2), Vec3(0.1, 0.8, 0.2), white, 1, "box back");
  AppendQuad(s, Vec3(-0.1, 0.8, 0), Vec3(-0.1, 0.6, 0), Vec3(-0.1, 0.6, 0.2), Vec3(-0.1, 0.8, 0.2), white, 1, "box left");
  AppendQuad(s, Vec3(0.1, 0.6, 0), Vec3(0.1, 0.8, 0), Vec3(0.1, 0.8, 0.2), Vec3(0.1, 0.6, 0.2), white, 1, "box right");
  Light sun;
  sun.Type = LightType::Directional;
  sun.Direction = Vec3(0.0, 0.6, -0.8);
  sun.Intensity = RGB(1.0);
  s.Lighting.Lights.push_back(sun);
  ProgressiveOptions options;
  options.Threads = 2;
  // A finer gradient criterion than the default 0.1, so that the box's
  // shots split the wall behind it (at 0.1 nothing splits there).
  options.SubdivisionThreshold = 0.03;
  ProgressiveRadiosity solver(s, options);
  const SolverStatistics stats = solver.Solve();
  ASSERT_EQ(stats.Stop, StopReason::Converged) << ToString(stats.Stop);
  const ElementMesh& mesh = solver.Mesh();

  double lowest = 1e300;
  std::size_t wallLeaves = 0;
  for (std::uint32_t e : mesh.Leaves())
  {
    if (mesh[e].Source < firstWall || mesh[e].Source >= endWall)
    {
      continue;
    }
    ++wallLeaves;
    const ElementSamples& h = mesh[e].Irradiance;
    for (const RGB& v : { h.Corner[0], h.Corner[1], h.Corner[2], h.Centre })
    {
      lowest = std::min({ lowest, v.r, v.g, v.b });
    }
  }
  std::cout << "wall: " << wallLeaves << " leaves (" << stats.Subdivisions
            << " subdivisions), lowest sample " << lowest << " W/m^2 (the sun alone 0.6)\n";
  // Measured 0.659 (1,260 leaves); 0.18 before the fix.
  EXPECT_GE(lowest, 0.6);
}
