// Convergence that tells the truth (Divergence.h, issue 53): a series of
// bounce powers or an unshot power that grows is reported as diverged, with
// what grew, and a solve whose transfers create energy stops as Diverged
// instead of "converged" (the atrium's face clusters went 0.67, 39, 160,
// 1100 and were reported solved with a residual of 0).
#include "Radiosity/Common/Divergence.h"
#include "Radiosity/FaceCluster/FaceClusterMethod.h"
#include "Radiosity/Progressive/ProgressiveMethod.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <gtest/gtest.h>

#include <limits>

using namespace radiosity;

TEST(Divergence, BouncePowersThatShrinkAreNotDivergence)
{
  SolverStatistics stats;
  std::vector<double> powers;
  // A closed scene of reflectance 0.999 with rounding wobbles of 1e-4.
  double p = 1.0;
  for (int i = 0; i < 200; ++i)
  {
    p *= (i % 2 ? 0.999 : 1.0001);
    powers.push_back(p);
    EXPECT_FALSE(SeriesDiverges(powers, "test", stats)) << i;
  }
  EXPECT_EQ(stats.Stop, StopReason::Converged);
  EXPECT_TRUE(stats.StopDetail.empty());
}

TEST(Divergence, GrowthIsDivergence)
{
  {
    // The atrium's face clusters: 0.67 then 39.
    SolverStatistics stats;
    EXPECT_FALSE(SeriesDiverges({ 0.67 }, "bounce power", stats));
    EXPECT_TRUE(SeriesDiverges({ 0.67, 39.0 }, "bounce power", stats));
    EXPECT_EQ(stats.Stop, StopReason::Diverged);
    EXPECT_NE(stats.StopDetail.find("bounce power grew from 0.67 W to 39 W at iteration 2"), std::string::npos)
      << stats.StopDetail;
  }
  {
    // A slow growth: three bounces in a row above 1 + DivergenceSlack; two are not enough.
    SolverStatistics stats;
    EXPECT_FALSE(SeriesDiverges({ 1.0, 0.8, 0.9, 1.0 }, "p", stats));
    EXPECT_FALSE(SeriesDiverges({ 1.0, 1.0005, 1.001, 1.0015 }, "p", stats));
    EXPECT_TRUE(SeriesDiverges({ 1.0, 0.8, 0.9, 1.0, 1.1 }, "p", stats));
    EXPECT_NE(stats.StopDetail.find("grew 3 iterations in a row, from 0.8 W at iteration 2 to 1.1 W at iteration 5"),
      std::string::npos)
      << stats.StopDetail;
  }
  {
    // Near convergence, far below the largest bounce: a wobble, not divergence.
    SolverStatistics stats;
    EXPECT_FALSE(SeriesDiverges({ 2800.0, 100.0, 0.023, 0.059 }, "p", stats));
    EXPECT_FALSE(SeriesDiverges({ 2800.0, 1.0, 2.0, 3.0, 4.0 }, "p", stats));
    EXPECT_TRUE(SeriesDiverges({ 2800.0, 1.0, 2.0, 3.0, 29.0 }, "p", stats));
  }
  {
    SolverStatistics stats;
    EXPECT_TRUE(SeriesDiverges({ 1.0, std::numeric_limits<double>::quiet_NaN() }, "p", stats));
    EXPECT_NE(stats.StopDetail.find("not finite at iteration 2"), std::string::npos) << stats.StopDetail;
  }
}

TEST(Divergence, AResidualRisingAboveItsLowestIsDivergence)
{
  SolverStatistics stats;
  double lowest = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(ResidualRoseAboveItsLowest(100.0, lowest, 100.0, 0, "unshot", stats));
  EXPECT_FALSE(ResidualRoseAboveItsLowest(-10.0, lowest, 100.0, 1, "unshot", stats));
  EXPECT_FALSE(ResidualRoseAboveItsLowest(39.0, lowest, 100.0, 2, "unshot", stats)); // 49 W above
  EXPECT_EQ(lowest, -10.0);
  EXPECT_EQ(stats.Stop, StopReason::Converged);
  EXPECT_TRUE(ResidualRoseAboveItsLowest(41.0, lowest, 100.0, 3, "unshot", stats));
  EXPECT_EQ(stats.Stop, StopReason::Diverged);
  EXPECT_NE(stats.StopDetail.find("unshot rose to 41 W at iteration 3, 51 W above the lowest it reached (-10 W): "
                                  "more than 0.5 of the emitted 100 W"),
    std::string::npos)
    << stats.StopDetail;
}

namespace
{
// A closed cube whose walls send on more than they receive (reflectance
// 1.2, which ValidateScene refuses: here it stands for transfers that create
// energy, as form factors summing above 1 do).
std::shared_ptr<const Scene> EnergyCreatingCube(double reflectance)
{
  return std::make_shared<const Scene>(MakeClosedCube(1.0, 2, reflectance, 1.0));
}
}

TEST(Divergence, FaceClusterSolveThatCreatesEnergyStopsAsDiverged)
{
  FaceClusterSettings settings;
  settings.MaxIterations = 200;
  FaceClusterMethod grows(EnergyCreatingCube(1.2), settings);
  const SolverStatistics stats = grows.Solve({});
  EXPECT_EQ(stats.Stop, StopReason::Diverged) << ToString(stats.Stop) << " after " << stats.Iterations;
  EXPECT_NE(stats.StopDetail.find("face cluster radiosity's bounce power grew"), std::string::npos) << stats.StopDetail;
  EXPECT_LT(stats.Iterations, 10);
  // The same cube at reflectance 0.9 converges.
  FaceClusterMethod shrinks(EnergyCreatingCube(0.9), settings);
  EXPECT_EQ(shrinks.Solve({}).Stop, StopReason::Converged);
}

TEST(Divergence, ProgressiveSolveThatCreatesEnergyStopsAsDiverged)
{
  // Without overshooting: its ambient term extrapolates to the linear
  // system's solution E / (1 - rho), which for rho > 1 is finite (and
  // negative), so this stand-in for energy-creating transfers would not grow.
  ProgressiveOptions options;
  options.MaxIterations = 5000;
  options.Overshooting = false;
  ProgressiveMethod grows(EnergyCreatingCube(1.2), options);
  const SolverStatistics stats = grows.Solve({});
  EXPECT_EQ(stats.Stop, StopReason::Diverged) << ToString(stats.Stop) << " after " << stats.Iterations;
  EXPECT_NE(stats.StopDetail.find("progressive refinement's signed unshot power rose to"), std::string::npos)
    << stats.StopDetail;
  // The same cube at reflectance 0.9, with overshooting (the default),
  // whose negative shots raise the unshot power for a while, converges.
  ProgressiveMethod shrinks(EnergyCreatingCube(0.9), ProgressiveOptions());
  const SolverStatistics fine = shrinks.Solve({});
  EXPECT_EQ(fine.Stop, StopReason::Converged) << fine.StopDetail;

}
