// Higher-order face cluster radiosity (Gobbetti et al. 2003) against exact
// answers: closed rooms of uniform reflectance (H = E / (1 - rho)), the
// inside of a sphere with cap emission, and the constant bases reproducing
// plain face cluster radiosity (one irradiance vector per element).
#include "Radiosity/Reference/AnalyticReference.h"
#include "Radiosity/Common/ErrorMetrics.h"
#include "Radiosity/FaceCluster/FaceClusterMethod.h"
#include "Radiosity/FaceCluster/FaceClusterRadiosity.h"
#include "Radiosity/Scenes/SceneGenerators.h"
#include "Radiosity/Scenes/StandardScenes.h"

#include <gtest/gtest.h>

#include <iostream>
#include <memory>

using namespace radiosity;

namespace
{
// Largest relative error of the irradiance at every `stride`th triangle's
// centroid against `exact`.
double WorstCentroidError(
  const FaceClusterRadiosity& solver, const std::function<RGB(std::size_t)>& exact, std::size_t stride = 1)
{
  const Scene& scene = solver.GetScene();
  double worst = 0.0;
  for (std::size_t t = 0; t < scene.Triangles.size(); t += stride)
  {
    const RGB e = solver.IrradianceAt(static_cast<std::uint32_t>(t), scene.Centroid(t), scene.Normal(t));
    const RGB reference = exact(t);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_TRUE(std::isfinite(e[c]));
      worst = std::max(worst, std::abs(e[c] - reference[c]) / reference[c]);
    }
  }
  return worst;
}

/// The largest departure of `values` from the reference (red channel),
/// relative to the reference's peak, and the ratio of their sums.
void WorstAndMean(const std::vector<RGB>& values, const AnalyticReference& reference, double& worst, double& mean)
{
  double peak = 0.0, sum = 0.0, exactSum = 0.0;
  for (const RGB& e : reference.Irradiance)
  {
    peak = std::max(peak, e.r);
  }
  worst = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    worst = std::max(worst, std::abs(values[i].r - reference.Irradiance[i].r) / peak);
    sum += values[i].r;
    exactSum += reference.Irradiance[i].r;
  }
  mean = sum / exactSum;
}

/// A probe at every triangle's centroid, facing as it does, and the closed
/// form's irradiance there.
/// The scene and its probes scaled by `scale` about the origin.
void ScaleSceneAndProbes(double scale, Scene& scene, std::vector<Probe>& probes)
{
  for (Vec3& p : scene.Points)
  {
    p *= scale;
  }
  for (Probe& p : probes)
  {
    p.Position *= scale;
  }
}

AnalyticReference CentroidReference(const Scene& scene, std::vector<Probe>& probes)
{
  probes.clear();
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    probes.push_back({ scene.Centroid(t), scene.Normal(t) });
  }
  AnalyticReference reference;
  std::string why;
  EXPECT_TRUE(ComputeAnalyticReference(scene, probes, reference, why)) << why;
  return reference;
}
}

TEST(FaceClusterRadiosity, ClosedRoomsWithinOnePercent)
{
  for (double rho : { 0.5, 0.9, 0.99, 0.999 })
  {
    const Scene scene = MakeClosedCube(1.0, 4, rho, 1.0);
    FaceClusterRadiosity solver(scene, FaceClusterSettings());
    const SolverStatistics stats = solver.Solve();
    EXPECT_EQ(stats.Stop, StopReason::Converged);
    const double worst = WorstCentroidError(solver, [&](std::size_t) { return RGB(1.0 / (1.0 - rho)); });
    std::cout << "closed room rho " << rho << ": " << stats.Iterations << " iterations, "
              << solver.Statistics().LeafElements << " leaves, " << solver.Statistics().Transfers
              << " transfers, worst " << worst << "\n";
    // Measured 1.8e-4 (0.5), 2.4e-7 (0.9), 9.5e-7 (0.99), 1.3e-5 (0.999)
    // with each bounce balanced (the room is enclosed); 7.7e-4, 2.0e-4,
    // 7.0e-4 (0.999 not run) before.
    EXPECT_LT(worst, 5e-4) << "rho " << rho;
    // The vertex output: n . E at every point (the faces have points of
    // their own), including the corners.
    const std::vector<std::array<double, 9>> vertices = solver.VertexIrradianceVectors();
    ASSERT_EQ(vertices.size(), scene.Points.size());
    double vertexWorst = 0.0;
    for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
    {
      const Vec3 n = scene.Normal(t);
      for (int k = 0; k < 3; ++k)
      {
        const auto& e = vertices[scene.Triangles[t].V[k]];
        const double h = n.x * e[0] + n.y * e[1] + n.z * e[2];
        vertexWorst = std::max(vertexWorst, std::abs(h * (1.0 - rho) - 1.0));
      }
    }
    std::cout << "  vertex worst " << vertexWorst << "\n";
    EXPECT_LT(vertexWorst, 2.5e-3) << "rho " << rho; // measured 1.3e-3 (0.5), 2.4e-7, 9.5e-7, 1.3e-5
  }
}

TEST(FaceClusterRadiosity, SphereWithNonUniformEmission)
{
  // 1280 facets: the reference is the smooth sphere (every point sees the
  // area-mean radiosity), from which the facets' own direct light departs by
  // up to 1.7% (measured for the meshless test).
  const Scene sphere = MakeSphereInterior(1.0, 3, 0.7, RGB(3.0, 2.0, 1.0));
  std::vector<Probe> probes;
  const AnalyticReference reference = CentroidReference(sphere, probes);
  ASSERT_EQ(reference.Irradiance.size(), probes.size());
  FaceClusterRadiosity solver(sphere, FaceClusterSettings());
  const SolverStatistics stats = solver.Solve();
  EXPECT_EQ(stats.Stop, StopReason::Converged);
  const double worst = WorstCentroidError(solver, [&](std::size_t t) { return reference.Irradiance[t]; });
  std::cout << "sphere: " << stats.Iterations << " iterations, " << solver.Statistics().LeafElements
            << " leaves, " << solver.Statistics().Transfers << " transfers, worst " << worst << " in "
            << stats.SolveSeconds << " s\n";
  // Measured 0.0109 with the 5 x 5 control points on flat clusters (0.0097
  // before them, 0.0088 with 3 x 3), 0.0077 since the leaks of
  // StiffSphereConservesEnergy were closed: all within the reference's own
  // departure from the facets' answer (up to 1.7%), so the bound is that
  // measurement's, 0.012.
  EXPECT_LT(worst, 0.012);
}

TEST(FaceClusterRadiosity, StiffSphereConservesEnergy)
{
  // The inside of a 320-facet sphere with cap emission at reflectance 0.99
  // and 0.999, default settings: light is amplified 100 and 1000 times, so
  // a leak of 0.1% per bounce is a 10% or 50% error. Two leaks were found
  // this way (FaceClusterTransport.cxx): a leaf cluster's own light dropped
  // by the paper's (1 - F_ii), and a subdivided element's light between its
  // children never sent; and the tail of the series was added once the
  // infinity norm's ratio was steady to 1% (0.987 where the decay was
  // 0.99). With 1280 facets at transfer tolerance 1e-4 and reflectance
  // 0.99 the mean irradiance was 0.784 of the exact before the three
  // fixes, 0.910 after (the rest is the transfers' own error, amplified).
  // Measured here: worst 9.2e-4 (0.99) and 1.4e-3 (0.999) of the peak over
  // every facet, mean 1.0001 and 1.0006 of the exact; with the facets halved
  // where the light they receive curves (MaxBisections 5, the default
  // since): worst 2.7e-3 and 2.5e-3, mean 0.99998 and 1.0000; bound 3.5e-3.
  for (double rho : { 0.99, 0.999 })
  {
    const Scene sphere = MakeSphereInterior(1.0, 2, rho, RGB(1.0));
    std::vector<Probe> probes;
    const AnalyticReference reference = CentroidReference(sphere, probes);
    ASSERT_EQ(reference.Irradiance.size(), probes.size());
    FaceClusterRadiosity solver(sphere, FaceClusterSettings());
    const SolverStatistics stats = solver.Solve();
    EXPECT_EQ(stats.Stop, StopReason::Converged) << "rho " << rho;
    const std::vector<RGB> values = solver.Evaluate(probes);
    double worst = 0.0, mean = 0.0;
    WorstAndMean(values, reference, worst, mean);
    std::cout << "sphere rho " << rho << ": " << stats.Iterations << " iterations, worst " << worst
              << " of the peak, mean " << mean << " of the exact\n";
    EXPECT_LT(worst, 3.5e-3) << "rho " << rho;
  }
}

TEST(FaceClusterRadiosity, StiffSphereTheSameAtEveryScale)
{
  // The 320-facet sphere at reflectance 0.8 and 0.99 scaled to 1e-3 m and
  // 1e3 m with the same emission (inside a sphere the irradiance does not
  // depend on its radius): against the unit sphere's exact answer.
  // Measured: reflectance 0.8 8.2e-3 / 7.8e-3 of the peak at worst, 0.99
  // 2.7e-3 / 1.8e-3 (at 1 m 2.7e-3); mean 0.9997 and 0.99998. With the
  // facets' direct light shown exactly (ExactEmitters: every facet emits,
  // 320 lamps) 9.7e-3 / 9.7e-3 and 2.7e-3 / 1.8e-3, mean 1.0000 and
  // 0.999997: the rest, fitted, is the uniform answer less the direct
  // light, less smooth than the whole. Bound 1.2e-2 at 0.8, 1e-2 at 0.99
  // (the issue asks for 2% at these scales, 1% at high reflectance).
  for (double rho : { 0.8, 0.99 })
  {
    const Scene unit = MakeSphereInterior(1.0, 2, rho, RGB(1.0));
    std::vector<Probe> unitProbes;
    const AnalyticReference reference = CentroidReference(unit, unitProbes);
    for (double scale : { 1e-3, 1e3 })
    {
      Scene sphere = unit;
      std::vector<Probe> probes = unitProbes;
      ScaleSceneAndProbes(scale, sphere, probes);
      FaceClusterRadiosity solver(sphere, FaceClusterSettings());
      EXPECT_EQ(solver.Solve().Stop, StopReason::Converged);
      double worst = 0.0, mean = 0.0;
      WorstAndMean(solver.Evaluate(probes), reference, worst, mean);
      std::cout << "sphere rho " << rho << " at " << scale << " m: worst " << worst << " of the peak, mean "
                << mean << " of the exact\n";
      EXPECT_LT(worst, rho < 0.9 ? 1.2e-2 : 1e-2) << "rho " << rho << " at " << scale << " m";
      EXPECT_LT(std::abs(mean - 1.0), 1e-3);
    }
  }
}

TEST(FaceClusterRadiosity, EnclosedSphereBalancesEachBounce)
{
  // 1280 facets at reflectance 0.999: the transfers' own errors lost 3e-4
  // of the light per bounce (scale 1.00031 to balance), which the
  // thousand bounces made a mean of 0.765 of the exact (worst 24% of the
  // peak) without the balance (BalanceEnclosedScenes). Measured with it: worst 2.5e-3 of the
  // peak, mean 0.99987; bounds 3.5e-3 and 5e-4.
  const Scene sphere = MakeSphereInterior(1.0, 3, 0.999, RGB(1.0));
  std::vector<Probe> probes;
  const AnalyticReference reference = CentroidReference(sphere, probes);
  ASSERT_EQ(reference.Irradiance.size(), probes.size());
  FaceClusterRadiosity solver(sphere, FaceClusterSettings());
  const SolverStatistics stats = solver.Solve();
  EXPECT_EQ(stats.Stop, StopReason::Converged);
  EXPECT_TRUE(solver.Statistics().Enclosed);
  EXPECT_GT(solver.Statistics().EnergyScaleMax, 1.0);
  EXPECT_LT(solver.Statistics().EnergyScaleMax, 1.002);
  const std::vector<RGB> values = solver.Evaluate(probes);
  double worst = 0.0, mean = 0.0;
  WorstAndMean(values, reference, worst, mean);
  std::cout << "1280-facet sphere rho 0.999: worst " << worst << ", mean " << mean << ", scale "
            << solver.Statistics().EnergyScaleMin << " to " << solver.Statistics().EnergyScaleMax << "\n";
  EXPECT_LT(worst, 3.5e-3);
  EXPECT_LT(std::abs(mean - 1.0), 5e-4);

  // An open scene (the Cornell box) is left as its transfers make it.
  FaceClusterSettings leaves;
  leaves.MaxBisections = 0;
  FaceClusterRadiosity open(MakeCornellBox(), leaves);
  open.Solve();
  EXPECT_FALSE(open.Statistics().Enclosed);
  EXPECT_EQ(open.Statistics().EnergyScaleMin, 1.0);
  EXPECT_EQ(open.Statistics().EnergyScaleMax, 1.0);
}

TEST(FaceClusterRadiosity, LargeSheetsMissingTheirBoxFitFromQuantileNodes)
{
  // Inside a 20480-facet sphere lit by its cap, every point receives the
  // same irradiance. Its clusters are sheets whose triangles cover about
  // half of their boxes: a 40-triangle one had 2 of its 9 nodes on its
  // surface (the linear fit's gradient a guess: a leaf below it got 16%
  // less direct light at one edge), a 30-triangle one 3 (the fit exactly
  // determined, its departures unseen at the nodes). With nodes at the area
  // quantiles wherever a sheet of more than 9 triangles misses nodes
  // (MakeSurfaceRule), measured:
  //   direct light (reflectance 0): worst 4.3e-2 of the exact, mean 0.99955
  //     (5.3e-2 with quantile nodes on the 2-node sheets alone); bound 5.5e-2;
  //   reflectance 0.99: worst 7.2e-3, mean 0.99956 (1.6e-2 before, 59% with
  //     neither); the 1%: bound 1e-2.
  const Scene direct = MakeSphereInterior(1.0, 5, 0.0, RGB(1.0));
  std::vector<Probe> probes;
  const AnalyticReference reference = CentroidReference(direct, probes);
  ASSERT_EQ(reference.Irradiance.size(), probes.size());
  FaceClusterRadiosity solver(direct, FaceClusterSettings());
  solver.Solve();
  double worst = 0.0, mean = 0.0;
  WorstAndMean(solver.Evaluate(probes), reference, worst, mean);
  std::cout << "20480-facet sphere, direct light: worst " << worst << ", mean " << mean << "\n";
  EXPECT_LT(worst, 5.5e-2);
  EXPECT_LT(std::abs(mean - 1.0), 2e-3);

  const Scene stiff = MakeSphereInterior(1.0, 5, 0.99, RGB(1.0));
  std::vector<Probe> stiffProbes;
  const AnalyticReference stiffReference = CentroidReference(stiff, stiffProbes);
  FaceClusterRadiosity stiffSolver(stiff, FaceClusterSettings());
  stiffSolver.Solve();
  WorstAndMean(stiffSolver.Evaluate(stiffProbes), stiffReference, worst, mean);
  std::cout << "20480-facet sphere, reflectance 0.99: worst " << worst << ", mean " << mean << "\n";
  EXPECT_LT(worst, 1e-2);
  EXPECT_LT(std::abs(mean - 1.0), 1e-3);
}

TEST(FaceClusterRadiosity, PenumbraFromTheEmittersVisibleFraction)
{
  // The exact-penumbra scene of the benchmarks (a square lamp, a blocker, a
  // black floor: direct light only) with the receivers halved up to 4
  // times: an emitter hidden in part from a receiver triangle takes its
  // visible fraction exactly, by backprojecting the blockers in the shaft
  // between them (FaceClusterTransfer.cxx, ExactFractionBlockers), not from
  // its 9 rule nodes. Measured: 1.85% of the peak at worst, 0.56% RMS
  // (9.7% and 3.6% with the rule nodes, 3.8% and 1.1% from ~64 stratified
  // points); bound 2.5% and 0.8%. The solver's fit, not the output's
  // exact display of the lamp (ExactEmitterTriangles off here; with it,
  // 4.2e-16 of the peak: CoarseInputHalvedWithinTwoPercentAtEveryScale).
  for (const StandardScene& standard : StandardScenes())
  {
    if (standard.Name != "shadow")
    {
      continue;
    }
    const Scene scene = standard.Make();
    const std::vector<Probe> probes = standard.Probes ? standard.Probes(scene) : CentroidSample(scene);
    bool analytic = false;
    const AnalyticReference reference = StandardReference(scene, probes, 4096, &analytic);
    ASSERT_TRUE(analytic);
    FaceClusterSettings settings;
    settings.MaxBisections = 4;
    settings.ExactEmitterTriangles = 0;
    FaceClusterRadiosity solver(scene, settings);
    solver.Solve();
    const auto errors = RelativeErrors(solver.Evaluate(probes), reference.Irradiance);
    std::cout << "penumbra: worst " << errors.Max << " RMS " << errors.Rms << " of the peak\n";
    EXPECT_LT(errors.Max, 0.025);
    EXPECT_LT(errors.Rms, 0.008);
    return;
  }
  FAIL() << "no shadow scene among the standard scenes";
}

TEST(FaceClusterRadiosity, CoarseInputHalvedWithinTwoPercentAtEveryScale)
{
  // The coarse standard scenes (the Cornell box's 32 triangles against the
  // path tracer; the exact penumbra and the contact edge against their
  // closed forms) at default settings: receivers halved up to 5 times where
  // their basis cannot follow the light they receive (SubdivisionTolerance)
  // and halved emitters sending from their parts, at 1e-3 m, 1 m and 1e3 m
  // (the same emission: the same irradiance). Without halving: 11.8%, 21.8%
  // and 5.9% of the peak. Measured (worst over the probes, every scale):
  // Cornell 1.69% (1.71% with the lamp's light fitted); bound 2% (the
  // issue's). The penumbra and the contact edge are lit by the lamp alone,
  // which the output shows exactly (FaceClusterExactEmitters): 6.5e-16 and
  // 1.8e-16 of the peak at worst, bound 1e-12 (with the fit: 1.82% and
  // 0.12%). The three scales agree to 1e-5 of the peak at worst.
  for (const StandardScene& standard : StandardScenes())
  {
    if (standard.Name != "cornell" && standard.Name != "shadow" && standard.Name != "contact")
    {
      continue;
    }
    const Scene unit = standard.Make();
    const std::vector<Probe> unitProbes = standard.Probes ? standard.Probes(unit) : CentroidSample(unit);
    const AnalyticReference reference = StandardReference(unit, unitProbes, 16384);
    for (double scale : { 1e-3, 1.0, 1e3 })
    {
      Scene scene = unit;
      std::vector<Probe> probes = unitProbes;
      ScaleSceneAndProbes(scale, scene, probes);
      FaceClusterRadiosity solver(scene, FaceClusterSettings());
      EXPECT_EQ(solver.Solve().Stop, StopReason::Converged);
      const auto errors = RelativeErrors(solver.Evaluate(probes), reference.Irradiance);
      std::cout << standard.Name << " at " << scale << " m: " << solver.Statistics().LeafElements
                << " leaves, worst " << errors.Max << " RMS " << errors.Rms << " of the peak\n";
      EXPECT_LT(errors.Max, standard.Name == "cornell" ? 0.02 : 1e-12) << standard.Name << " at " << scale;
    }
  }
}

TEST(FaceClusterRadiosity, ConstantBasesArePlainFaceClusterRadiosity)
{
  const Scene scene = MakeClosedCube(1.0, 4, 0.5, 1.0);
  // Plain face cluster radiosity (Willmott et al.) keeps the input triangles
  // as its finest elements: no halving below them, for both bases.
  FaceClusterSettings settings;
  settings.MaxBisections = 0;
  settings.IrradianceBasis = BasisKind::Constant;
  FaceClusterRadiosity solver(scene, settings);
  solver.Solve();
  // One irradiance vector per leaf element: the same at every point of it.
  std::size_t leaves = 0;
  for (const FaceClusterElement& e : solver.Elements())
  {
    if (!e.IsLeaf() || !e.IsTriangle())
    {
      continue;
    }
    ++leaves;
    const Vec3 centre = (e.Corners[0] + e.Corners[1] + e.Corners[2]) / 3.0;
    const IrradianceVector b = solver.IrradianceVectorAt(e.Cluster, centre);
    for (const Vec3& corner : e.Corners)
    {
      const IrradianceVector a = solver.IrradianceVectorAt(e.Cluster, corner + 1e-3 * (centre - corner));
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(glm::length(a[c] - b[c]), 0.0, 1e-12);
      }
    }
  }
  EXPECT_GT(leaves, 0u);
  // Plain face cluster radiosity is coarser than the linear basis on the
  // same elements: the floor next to an emitting wall (exact direct light;
  // a closed room's uniform field is exact with either basis).
  const Scene contact = MakeContactScene(4, 0.0, 10.0);
  std::vector<Probe> probes;
  for (double x = 0.05; x < 2.0; x += 0.1)
  {
    probes.push_back({ Vec3(x, 0.4, 0.0), Vec3(0, 0, 1) });
  }
  AnalyticReference reference;
  std::string why;
  ASSERT_TRUE(ComputeAnalyticReference(contact, probes, reference, why)) << why;
  double errors[2];
  // The bases' fits of the direct light, not its exact display (both 0).
  settings.ExactEmitterTriangles = 0;
  for (BasisKind basis : { BasisKind::Constant, BasisKind::Linear })
  {
    settings.IrradianceBasis = basis;
    FaceClusterRadiosity onFloor(contact, settings);
    onFloor.Solve();
    errors[basis == BasisKind::Linear] = RelativeErrors(onFloor.Evaluate(probes), reference.Irradiance).Rms;
  }
  std::cout << "floor by a wall: constant bases " << errors[0] << " RMS, linear irradiance " << errors[1] << "\n";
  EXPECT_LT(errors[0], 0.18);              // measured 0.062 of the peak
  EXPECT_LT(errors[1], 0.019);             // measured 0.0064
  EXPECT_LT(errors[1], 0.3 * errors[0]);   // measured 0.10 times
}

TEST(FaceClusterRadiosity, SameAnswerAtEveryScale)
{
  // A 1 m square emitter (1 W/m^2) 1 m above a 2 m floor of 32 x 32 cells
  // (reflectance 0.5), scaled to 1e-4 m, 0.9 m, 1e3 m and 1e4 m with the
  // same exitance: the irradiance at probes across the floor, beside and
  // under the emitter's edge, must be the scale-1 answer. Scales other than
  // powers of two round the greedy contraction's costs differently, so the
  // hierarchy differs; before a 5 x 5 grid of control points on flat
  // clusters (FaceClusterQuadrature) the answer then moved by 6% of the
  // peak at 1e-3 m, 9% at 0.9 and 1e3 m, 7.1% at 1e4 m (a 3 x 3 grid still
  // left 7.1% at 1e4 m). Powers of two give the scale-1 answer bit for bit.
  // Measured now: 2.0e-3 (1e-4 m), 1.3e-3 (0.9), 2.4e-3 (1e3), 2.6e-3 (1e4)
  // of the peak; bound 5e-3. That is the solver's fit of the lamp's light
  // (ExactEmitterTriangles 0); the output's exact display of it
  // (FaceClusterExactEmitters) differs by 2.3e-16 at most, bound 1e-12.
  Scene unit;
  Material floor, lamp;
  floor.Reflectance = RGB(0.5);
  lamp.Reflectance = RGB(0.0);
  lamp.Emission = RGB(1.0);
  AppendQuad(unit, Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0), floor, 32, "floor");
  AppendQuad(unit, Vec3(-0.5, -0.5, 1), Vec3(-0.5, 0.5, 1), Vec3(0.5, 0.5, 1), Vec3(0.5, -0.5, 1), lamp, 1, "lamp");
  std::vector<Probe> probes;
  for (int i = 0; i < 7; ++i)
  {
    probes.push_back({ Vec3(-0.9 + 0.3 * i, 0.1, 0.0), Vec3(0, 0, 1) });
  }
  FaceClusterSettings settings;
  const auto solve = [&](double scale)
  {
    Scene s = unit;
    for (Vec3& p : s.Points)
    {
      p *= scale;
    }
    std::vector<Probe> scaled = probes;
    for (Probe& p : scaled)
    {
      p.Position *= scale;
    }
    FaceClusterMethod method(std::make_shared<const Scene>(s), settings);
    EXPECT_EQ(method.Solve({}).Stop, StopReason::Converged) << "scale " << scale;
    return method.EvaluateProbes(scaled);
  };
  for (int exact : { 0, 1 })
  {
    settings.ExactEmitterTriangles = exact ? FaceClusterSettings().ExactEmitterTriangles : 0;
    const std::vector<RGB> reference = solve(1.0);
    double peak = 0.0;
    for (const RGB& e : reference)
    {
      peak = std::max(peak, e.r);
    }
    for (double scale : { 1e-4, 0.9, 1e3, 1e4 })
    {
      const std::vector<RGB> values = solve(scale);
      double worst = 0.0;
      for (std::size_t i = 0; i < values.size(); ++i)
      {
        worst = std::max(worst, std::fabs(values[i].r - reference[i].r) / peak);
      }
      std::cout << (exact ? "lamp shown exactly" : "lamp fitted") << ", scale " << scale << ": largest difference "
                << worst << " of the peak " << peak << "\n";
      EXPECT_LT(worst, exact ? 1e-12 : 5e-3) << "scale " << scale;
    }
  }
}

TEST(FaceClusterRadiosity, ScenesSharingAHierarchyKeepTheirOwnLights)
{
  // Two scenes of the same surfaces share one hierarchy
  // (FaceClusterHierarchy::Shared); each solve must take its own scene's
  // lights, not the hierarchy's scene's. Measured: the right bulb's solve
  // beside the left bulb's is the right bulb's alone (0 difference) and
  // differs from the left bulb's by 0.995 of the peak vector component.
  // Before the fix every solve on the hierarchy took the lights of the
  // scene that built it: the left bulb's solve gave the right bulb's answer
  // (0 difference).
  Scene left = MakeCornellBox(), right = left;
  Vec3 low, high;
  left.BoundingBox(low, high);
  Light bulb;
  bulb.Intensity = RGB(4.0, 3.0, 2.0);
  bulb.Position = low + Vec3(0.25, 0.5, 0.5) * (high - low);
  left.Lighting.Lights.push_back(bulb);
  bulb.Position = low + Vec3(0.75, 0.5, 0.5) * (high - low);
  right.Lighting.Lights.push_back(bulb);
  auto difference = [](const FaceClusterRadiosity& a, const FaceClusterRadiosity& b) {
    const auto u = a.VertexIrradianceVectors(), v = b.VertexIrradianceVectors();
    double peak = 0.0, worst = 0.0;
    for (std::size_t p = 0; p < u.size(); ++p)
    {
      for (int k = 0; k < 9; ++k)
      {
        peak = std::max(peak, std::abs(v[p][k]));
        worst = std::max(worst, std::abs(u[p][k] - v[p][k]));
      }
    }
    return worst / peak;
  };
  std::unique_ptr<FaceClusterRadiosity> alone;
  {
    alone = std::make_unique<FaceClusterRadiosity>(right, FaceClusterSettings());
    alone->Solve();
  }
  FaceClusterRadiosity first(left, FaceClusterSettings());
  first.Solve();
  FaceClusterRadiosity second(right, FaceClusterSettings(), first.SharedHierarchy());
  second.Solve();
  const double same = difference(second, *alone), other = difference(second, first);
  std::cout << "right bulb beside a left-bulb solve: " << same << " of the peak from a solve alone, " << other
            << " from the left bulb's\n";
  EXPECT_LE(same, 1e-12);
  EXPECT_GT(other, 0.1);
}
