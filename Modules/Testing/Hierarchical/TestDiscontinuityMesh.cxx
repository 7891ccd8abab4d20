// Hardt & Teller: quadratic interpolants, exact point irradiance through
// blockers (backprojection), and the discontinuity mesh on the exact
// penumbra scene against the analytic answer and a uniform mesh.
#include "Radiosity/Reference/AnalyticReference.h"
#include "Radiosity/Hierarchical/Backprojection.h"
#include "Radiosity/Hierarchical/DiscontinuityMesher.h"
#include "Radiosity/Common/ErrorMetrics.h"
#include "Radiosity/Common/FormFactor.h"
#include "Radiosity/Hierarchical/HierarchicalRadiosity.h"
#include "Radiosity/Hierarchical/QuadraticInterpolant.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

using namespace radiosity;

TEST(QuadraticInterpolant, ReproducesSamplesAndQuadratics)
{
  // An arbitrary quadratic per channel is reproduced everywhere.
  auto f = [](double s, double t) {
    return RGB(1 + 2 * s - 3 * t + 4 * s * s - 5 * s * t + 6 * t * t, 7 - s * s, 0.5 * s * t + t);
  };
  const double at[6][2] = { { 0, 0 }, { 0.5, 0 }, { 1, 0 }, { 0.5, 0.5 }, { 0, 1 }, { 0, 0.5 } };
  std::array<RGB, 6> r;
  for (int k = 0; k < 6; ++k)
  {
    r[k] = f(at[k][0], at[k][1]);
  }
  const QuadraticInterpolant q = QuadraticInterpolant::FromSamples(r);
  for (int k = 0; k < 6; ++k)
  {
    EXPECT_NEAR(glm::length(q.Evaluate(at[k][0], at[k][1]) - r[k]), 0.0, 1e-12) << "sample " << k;
  }
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < 100; ++i)
  {
    double s = u(rng), t = u(rng);
    if (s + t > 1)
    {
      s = 1 - s;
      t = 1 - t;
    }
    EXPECT_NEAR(glm::length(q.Evaluate(s, t) - f(s, t)), 0.0, 1e-12);
  }
  // The area mean of x^2 over the reference triangle is 1/6 / (1/2) ... check
  // against a fine midpoint sum.
  RGB sum(0.0);
  const int n = 400;
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; i + j < n; ++j)
    {
      sum += q.Evaluate((i + 1.0 / 3) / n, (j + 1.0 / 3) / n);
      if (i + j < n - 1)
      {
        sum += q.Evaluate((i + 2.0 / 3) / n, (j + 2.0 / 3) / n);
      }
    }
  }
  std::cout << "interpolant mean against the sum: " << glm::length(q.Mean() - sum / double(n * n)) << "\n";
  EXPECT_NEAR(glm::length(q.Mean() - sum / double(n * n)), 0.0, 1.3e-5); // measured 4.4e-6 (the sum's own error)
}

TEST(Backprojection, AgreesWithTheAnalyticPenumbra)
{
  const TriangleCorners light[2] = { { Vec3(-0.25, -0.25, 1), Vec3(-0.25, 0.25, 1), Vec3(0.25, 0.25, 1) },
    { Vec3(-0.25, -0.25, 1), Vec3(0.25, 0.25, 1), Vec3(0.25, -0.25, 1) } };
  const Vec3 b0(-0.05, -0.2, 0.5), b1(0.35, -0.2, 0.5), b2(0.35, 0.2, 0.5), b3(-0.05, 0.2, 0.5);
  const TriangleCorners blockers[2] = { { b0, b1, b2 }, { b0, b2, b3 } };
  const Scene scene = MakeShadowScene(1, 1.0);
  const std::vector<Vec3> square = { b0, b1, b2, b3 };
  const Vec3 up(0, 0, 1);
  for (double x = -0.6; x <= 1.1; x += 0.01)
  {
    for (double y : { 0.0, 0.17, 0.4 })
    {
      const Vec3 p(x, y, 0.0);
      double f = 0.0;
      bool exact = false;
      for (const TriangleCorners& l : light)
      {
        f += VisibleFormFactor(p, up, l, blockers, 2, &exact);
        EXPECT_TRUE(exact);
      }
      const double reference = DirectIrradiance(scene, p, up, square).x;
      EXPECT_NEAR(f, reference, 1e-9 + 1e-7 * reference) << "at " << x << ", " << y;
    }
  }
}

TEST(Backprojection, CoplanarPairsMergedCastTheSameShadow)
{
  // The Cornell box's blocks (10 triangles each, five quads) seen from
  // points on the floor and the walls through the ceiling light: the
  // merged quads give the triangles' form factor, with half the blockers.
  const Scene scene = MakeCornellBox();
  std::vector<TriangleCorners> corners;
  std::vector<std::array<std::uint32_t, 3>> ids;
  std::vector<std::uint32_t> light;
  for (std::uint32_t t = 0; t < scene.Triangles.size(); ++t)
  {
    if (MaxComponent(scene.Materials[t].Emission) > 0)
    {
      light.push_back(t);
    }
    else if (scene.ObjectNames[scene.ObjectIds[t]].find("block") != std::string::npos)
    {
      corners.push_back({ scene.Vertex(t, 0), scene.Vertex(t, 1), scene.Vertex(t, 2) });
      ids.push_back(scene.Triangles[t].V);
    }
  }
  ASSERT_EQ(corners.size(), 20u);
  const std::vector<BlockerPolygon> merged = MergeCoplanarPairs(corners, ids);
  EXPECT_EQ(merged.size(), 10u);
  double worst = 0.0, largest = 0.0, brighter = 0.0;
  for (int i = 0; i <= 20; ++i)
  {
    for (int j = 0; j <= 20; ++j)
    {
      // The floor (y = 0, facing up) and the back wall (z = 0.5592 m, facing -z).
      const double u = 0.01 + 0.0265 * i, v = 0.01 + 0.0265 * j;
      const std::pair<Vec3, Vec3> points[2] = { { Vec3(u, 1e-6, v), Vec3(0, 1, 0) },
        { Vec3(u, v, 0.5592 - 1e-6), Vec3(0, 0, -1) } };
      for (const auto& [p, n] : points)
      {
        for (std::uint32_t t : light)
        {
          const TriangleCorners l = { scene.Vertex(t, 0), scene.Vertex(t, 1), scene.Vertex(t, 2) };
          const double triangles = VisibleFormFactor(p, n, l, corners.data(), corners.size());
          const double quads = VisibleFormFactor(p, n, l, merged.data(), merged.size());
          brighter = std::max(brighter, quads - triangles);
          worst = std::max(worst, std::fabs(triangles - quads));
          largest = std::max(largest, triangles);
        }
      }
    }
  }
  std::cout << "merged quads against triangles: " << worst << ", quads brighter by " << brighter
            << " (largest form factor " << largest << ")\n";
  // Measured 9.8e-10 both ways (quads brighter by at most 4.0e-10): the
  // backprojection's own rounding, which agrees with the closed form to
  // 1e-7 of the value (AgreesWithTheAnalyticPenumbra); in the umbrae the
  // triangles let up to 2e-10 through slivers along their shared diagonals,
  // the quads nothing.
  EXPECT_GT(largest, 1e-3);
  EXPECT_LT(worst, 2e-9);
}

TEST(Backprojection, BlockersThatCannotShadowChangeNothing)
{
  const TriangleCorners light = { Vec3(-0.5, -0.5, 1), Vec3(-0.5, 0.5, 1), Vec3(0.5, 0.5, 1) };
  const Vec3 p(0.1, -0.1, 0.0), n(0, 0, 1);
  const double free = PointToPolygonFormFactor(p, n, light.data(), 3);
  const TriangleCorners away[3] = {
    { Vec3(-1, -1, 2), Vec3(1, -1, 2), Vec3(0, 1, 2) },       // behind the light
    { Vec3(-1, -1, -1), Vec3(1, -1, -1), Vec3(0, 1, -1) },    // below the receiver
    { Vec3(5, 5, 0.5), Vec3(6, 5, 0.5), Vec3(5, 6, 0.5) },    // outside the pyramid
  };
  EXPECT_NEAR(VisibleFormFactor(p, n, light, away, 3), free, 1e-14);
  // A blocker covering the whole pyramid hides everything; two halves as well.
  const TriangleCorners cover[2] = { { Vec3(-3, -3, 0.5), Vec3(3, -3, 0.5), Vec3(3, 3, 0.5) },
    { Vec3(-3, -3, 0.5), Vec3(3, 3, 0.5), Vec3(-3, 3, 0.5) } };
  EXPECT_NEAR(VisibleFormFactor(p, n, light, cover, 2), 0.0, 1e-12);
  // Overlapping blockers are not subtracted twice.
  const TriangleCorners overlap[2] = { { Vec3(-3, -3, 0.5), Vec3(3, -3, 0.5), Vec3(3, 3, 0.5) },
    { Vec3(-3, -3, 0.6), Vec3(3, -3, 0.6), Vec3(3, 3, 0.6) } };
  const double one = VisibleFormFactor(p, n, light, overlap, 1);
  EXPECT_NEAR(VisibleFormFactor(p, n, light, overlap, 2), one, 1e-12);
  EXPECT_GT(one, 0.0);
  EXPECT_LT(one, free);
}

// A receiver on the Cornell box's left wall, h above the floor at the back
// corner, sees the floor's back triangle past the two boxes standing on it.
// The boxes hide floor that the receiver sees at a grazing angle, so what
// they take is h times a constant as h -> 0 (the cosine at the floor). The
// fragment subtraction cut the whole triangle along the shadows' edges, whose
// lines pass through the foot of the receiver, and lost 1e-3 of the form
// factor at h = 1e-8 (2e5 times the shadows' share); the samples on the
// mesh's contact lines lie 1e-7 of a leaf above the neighbouring plane.
TEST(Backprojection, NearTheSourcesPlaneTheShadowsFadeLinearly)
{
  const double faces[5][4][3] = { { { 0.24, 0.165, 0.272 }, { 0.24, 0, 0.272 }, { 0.29, 0, 0.114 }, { 0.29, 0.165, 0.114 } },
    { { 0.29, 0.165, 0.114 }, { 0.29, 0, 0.114 }, { 0.13, 0, 0.065 }, { 0.13, 0.165, 0.065 } },
    { { 0.472, 0.33, 0.406 }, { 0.472, 0, 0.406 }, { 0.423, 0, 0.247 }, { 0.423, 0.33, 0.247 } },
    { { 0.314, 0.33, 0.456 }, { 0.314, 0, 0.456 }, { 0.472, 0, 0.406 }, { 0.472, 0.33, 0.406 } },
    { { 0.314, 0, 0.456 }, { 0.314, 0.33, 0.456 }, { 0.265, 0.33, 0.296 }, { 0.265, 0, 0.296 } } };
  for (const double scale : { 1e-4, 1.0, 1e4 })
  {
    const TriangleCorners floor = { scale * Vec3(0.5528, 0, 0), scale * Vec3(0, 0, 0.5592),
      scale * Vec3(0.5496, 0, 0.5592) };
    std::vector<BlockerPolygon> boxes(5);
    for (int b = 0; b < 5; ++b)
    {
      boxes[b].Size = 4;
      for (int k = 0; k < 4; ++k)
      {
        boxes[b].Corners[k] = scale * Vec3(faces[b][k][0], faces[b][k][1], faces[b][k][2]);
      }
    }
    const PreparedVisibleFormFactor prepared(floor, boxes.data(), boxes.size());
    double reference = 0.0;
    for (const double h : { 1e-3, 1e-5, 1e-7, 1e-8, 1e-9 })
    {
      const Vec3 x = scale * Vec3(0, h, 0.5592), n(1, 0, 0);
      const double free = PointToPolygonFormFactor(x, n, floor.data(), 3);
      const double visible = VisibleFormFactor(x, n, floor, boxes.data(), boxes.size());
      EXPECT_EQ(prepared(x, n), visible) << "scale " << scale << " h " << h;
      const double perHeight = (free - visible) / h;
      if (h == 1e-3)
      {
        reference = perHeight;
        EXPECT_GT(reference, 0.1); // measured 0.17198
        continue;
      }
      // Measured: within 3.1e-5 of the h = 1e-3 value down to 1e-8 and
      // 3.9e-4 at 1e-9, the same at every scale (before: 1.3e6 times it at
      // 1e-8, and at the scale 1e4 a shadow projected behind the point).
      EXPECT_NEAR(perHeight / reference, 1.0, 1e-3) << "scale " << scale << " h " << h;
    }
  }
}

// The prepared form gives VisibleFormFactor's value to the last bit.
TEST(Backprojection, PreparedEqualsThePerPointForm)
{
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial)
  {
    TriangleCorners source = { Vec3(u(random), u(random), 1.0), Vec3(u(random), u(random), 1.0),
      Vec3(u(random), u(random), 1.0) };
    if (glm::cross(source[1] - source[0], source[2] - source[0]).z > 0)
    {
      std::swap(source[1], source[2]); // facing the receivers below
    }
    std::vector<BlockerPolygon> blockers(1 + trial % 5);
    for (BlockerPolygon& b : blockers)
    {
      b.Size = 3 + trial % 2;
      const double z = trial % 3 == 0 ? 0.9 + 0.2 * u(random) : 0.2 + 0.6 * u(random);
      const double cx = 1.4 * u(random) - 0.2, cy = 1.4 * u(random) - 0.2, r = 0.1 + 0.5 * u(random);
      for (int k = 0; k < b.Size; ++k)
      {
        const double a = 2.0 * 3.141592653589793 * (k + 0.3 * u(random)) / b.Size;
        b.Corners[k] = Vec3(cx + r * std::cos(a), cy + r * std::sin(a), z + 0.05 * u(random));
      }
    }
    const PreparedVisibleFormFactor prepared(source, blockers.data(), blockers.size());
    const double height = trial % 4 == 0 ? 1.0 - 1e-6 * u(random) : 0.0;
    const Vec3 x(u(random), u(random), height);
    const Vec3 n = glm::normalize(Vec3(u(random) - 0.5, u(random) - 0.5, 1.0));
    ASSERT_EQ(prepared(x, n), VisibleFormFactor(x, n, source, blockers.data(), blockers.size())) << trial;
  }
}

TEST(DiscontinuityMesh, ExactPenumbraWithFewTriangles)
{
  const double emission = 1.0;
  const Scene scene = MakeShadowScene(4, emission);
  HierarchicalOptions options;
  HierarchicalRadiosity solver(scene, options);
  const SolverStatistics stats = solver.Solve();
  ASSERT_EQ(stats.Stop, StopReason::Converged);
  const DiscontinuityMesh mesh = BuildDiscontinuityMesh(solver, DiscontinuityMeshOptions());
  ASSERT_FALSE(mesh.Triangles.empty());
  EXPECT_GT(mesh.LeavesMeshed, 0u);
  EXPECT_GT(mesh.SegmentsKept, 0u);

  // Irradiance along a line across both penumbrae and the umbra (y = 0).
  const Vec3 b0(-0.05, -0.2, 0.5), b1(0.35, -0.2, 0.5), b2(0.35, 0.2, 0.5), b3(-0.05, 0.2, 0.5);
  const std::vector<Vec3> square = { b0, b1, b2, b3 };
  std::vector<Probe> line;
  std::vector<double> exact;
  double peak = 0.0;
  for (int i = 0; i <= 340; ++i)
  {
    const Vec3 p(-0.6 + 1.58 * i / 340.0, 0.013, 0.0);
    line.push_back({ p, Vec3(0, 0, 1) });
    exact.push_back(DirectIrradiance(scene, p, Vec3(0, 0, 1), square).x);
    peak = std::max(peak, exact.back());
  }
  const std::vector<RGB> values = EvaluateInterpolants(mesh, line, 1e-9);
  double worst = 0.0;
  for (std::size_t i = 0; i < line.size(); ++i)
  {
    ASSERT_TRUE(std::isfinite(values[i].x)) << "probe " << i << " not on the mesh";
    worst = std::max(worst, std::fabs(values[i].x - exact[i]) / peak);
  }
  EXPECT_LT(worst, 0.0042); // measured 0.00141 of the peak
  std::size_t floorTriangles = 0;
  for (std::size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    floorTriangles += scene.ObjectNames[scene.ObjectIds[mesh.SourceTriangle[t]]] == "floor";
  }

  // A uniform mesh of the 2 x 2 floor with exact vertex values, linear in
  // each triangle (what Gouraud shading of a perfect uniform solution shows):
  // the coarsest one that reaches the same error along the line.
  std::size_t uniformTriangles = 0;
  double uniformError = 0.0;
  for (int n = 8; n <= 1024; n *= 2)
  {
    const double h = 2.0 / n;
    double err = 0.0;
    for (std::size_t i = 0; i < line.size(); ++i)
    {
      const Vec3& p = line[i].Position;
      const double gx = (p.x + 1) / h, gy = (p.y + 1) / h;
      const double ix = std::floor(gx), iy = std::floor(gy);
      const double fx = gx - ix, fy = gy - iy;
      auto at = [&](double a, double b) {
        return DirectIrradiance(scene, Vec3(-1 + a * h, -1 + b * h, 0), Vec3(0, 0, 1), square).x;
      };
      // Cells split along their diagonal, as AppendQuad splits them.
      double v;
      if (fx >= fy)
      {
        v = (1 - fx) * at(ix, iy) + (fx - fy) * at(ix + 1, iy) + fy * at(ix + 1, iy + 1);
      }
      else
      {
        v = (1 - fy) * at(ix, iy) + (fy - fx) * at(ix, iy + 1) + fx * at(ix + 1, iy + 1);
      }
      err = std::max(err, std::fabs(v - exact[i]) / peak);
    }
    uniformTriangles = 2u * n * n;
    uniformError = err;
    if (err <= worst)
    {
      break;
    }
  }
  std::cout << "discontinuity mesh: max error " << worst << " of the peak with " << floorTriangles
            << " floor triangles (" << mesh.Triangles.size() << " in all, " << mesh.SegmentsKept
            << " segments kept of " << mesh.SegmentsFound << "); uniform mesh with exact vertex values: "
            << uniformError << " with " << uniformTriangles << " triangles\n";
  EXPECT_LE(uniformError, worst * 1.0001);
  // Measured: 854 floor triangles against 524,288 uniform ones (614 times as
  // many). The uniform counts step by 4 (2 n^2, n doubling), so the uniform
  // bound is the step below the measured one.
  EXPECT_LE(floorTriangles, 2560u);
  EXPECT_GE(uniformTriangles, 131072u);
  EXPECT_GT(uniformTriangles, 200 * floorTriangles);
}

TEST(DiscontinuityMesh, WithoutDiscontinuitiesOneTrianglePerLeaf)
{
  const Scene scene = MakeShadowScene(4, 1.0);
  HierarchicalRadiosity solver(scene, HierarchicalOptions());
  solver.Solve();
  DiscontinuityMeshOptions options;
  options.Discontinuities = false;
  options.Conforming = false;
  const DiscontinuityMesh mesh = BuildDiscontinuityMesh(solver, options);
  EXPECT_EQ(mesh.Triangles.size(), solver.Mesh().NumberOfLeaves());
  EXPECT_EQ(mesh.LeavesMeshed, 0u);
  // A weight threshold above every discontinuity leaves the mesh alone too.
  DiscontinuityMeshOptions strict;
  strict.MinWeight = 1e9;
  strict.Conforming = false;
  EXPECT_EQ(BuildDiscontinuityMesh(solver, strict).Triangles.size(), mesh.Triangles.size());
}

TEST(DiscontinuityMesh, ConformingMeshHasNoTJunctions)
{
  // Every vertex lying inside another triangle's edge is a T-junction, where
  // rasterisation leaves cracks; the conforming mesh has none, the paper's
  // hybrid mesh (leaves of different levels, segments ending on leaf edges) has.
  const Scene scene = MakeShadowScene(4, 1.0);
  HierarchicalRadiosity solver(scene, HierarchicalOptions());
  solver.Solve();
  // Only vertices of triangles facing the same way count: the blocker's two
  // faces lie back to back in one plane, and their meshes never meet on screen.
  auto junctions = [](const DiscontinuityMesh& m) {
    std::vector<std::vector<std::size_t>> users(m.Points.size());
    for (std::size_t t = 0; t < m.Triangles.size(); ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        users[m.Triangles[t].V[k]].push_back(t);
      }
    }
    std::size_t count = 0;
    for (std::size_t t = 0; t < m.Triangles.size(); ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        const Vec3& a = m.Points[m.Triangles[t].V[k]];
        const Vec3& b = m.Points[m.Triangles[t].V[(k + 1) % 3]];
        const double len = glm::length(b - a);
        for (std::size_t i = 0; i < m.Points.size(); ++i)
        {
          const Vec3& p = m.Points[i];
          const double s = glm::dot(p - a, b - a) / (len * len);
          if (!(s > 1e-6 && s < 1 - 1e-6 && glm::length(p - (a + s * (b - a))) < 1e-9 * len))
          {
            continue;
          }
          for (std::size_t u : users[i])
          {
            if (glm::dot(m.Normals[u], m.Normals[t]) > 0.99)
            {
              ++count;
              break;
            }
          }
        }
      }
    }
    return count;
  };
  DiscontinuityMeshOptions hybrid;
  hybrid.Conforming = false;
  const DiscontinuityMesh paper = BuildDiscontinuityMesh(solver, hybrid);
  const DiscontinuityMesh conforming = BuildDiscontinuityMesh(solver, DiscontinuityMeshOptions());
  EXPECT_GT(junctions(paper), 0u);
  EXPECT_EQ(junctions(conforming), 0u);
  EXPECT_GT(conforming.LeavesConformed, 0u);
  EXPECT_EQ(conforming.LeavesMeshed, paper.LeavesMeshed);
}

TEST(DiscontinuityMesh, PastItsTimeLimitEveryLeafIsStillMeshed)
{
  // The exact penumbra scene, meshed with no time at all: no leaf is searched
  // for discontinuities (one interpolant each) and the partially visible
  // links bring their solve's mean to the samples instead of the exact
  // backprojection. Every leaf still has its interpolant, every value is
  // finite and non-negative, and the probes lie between the constant leaves
  // and the full mesh.
  const Scene scene = MakeShadowScene(4, 10.0);
  std::vector<Probe> probes;
  for (int i = 0; i <= 30; ++i)
  {
    probes.push_back(Probe{ Vec3(-0.6 + 0.05 * i, 0.03, 0.0), Vec3(0, 0, 1) });
  }
  AnalyticReference reference;
  std::string why;
  ASSERT_TRUE(ComputeAnalyticReference(scene, probes, reference, why)) << why;
  HierarchicalOptions options;
  options.ErrorProbes = probes;
  options.ErrorReference = reference.Irradiance;
  HierarchicalRadiosity solver(scene, options);
  const SolverStatistics stats = solver.Solve();
  DiscontinuityMeshOptions limited;
  limited.MaxSeconds = 1e-9;
  const DiscontinuityMesh mesh = BuildDiscontinuityMesh(solver, limited);
  const DiscontinuityMesh full = BuildDiscontinuityMesh(solver, DiscontinuityMeshOptions());
  const std::size_t leaves = solver.Mesh().NumberOfLeaves();
  EXPECT_EQ(mesh.LeavesPastTimeLimit, leaves);
  EXPECT_EQ(mesh.LeavesMeshed, 0u);
  EXPECT_GT(mesh.LeavesSampledPastTimeLimit, 0u);
  EXPECT_EQ(full.LeavesPastTimeLimit + full.LeavesSampledPastTimeLimit, 0u);
  ASSERT_EQ(mesh.Interpolants.size(), mesh.Triangles.size());
  for (const RGB& h : mesh.PointIrradiance)
  {
    ASSERT_TRUE(std::isfinite(h.x) && h.x >= 0.0 && h.y >= 0.0 && h.z >= 0.0);
  }
  const double tolerance = 1e-6 * scene.Diagonal();
  const ErrorFigures fast = RelativeErrors(EvaluateInterpolants(mesh, probes, tolerance), reference.Irradiance);
  const ErrorFigures exact = RelativeErrors(EvaluateInterpolants(full, probes, tolerance), reference.Irradiance);
  const double leavesRms = stats.History.Rows.back().RmsError;
  std::cout << "penumbra scene: " << leaves << " leaves, " << mesh.LeavesSampledPastTimeLimit
            << " sampled past the limit; RMS against the closed form: constant leaves " << leavesRms
            << ", past the limit " << fast.Rms << ", full mesh " << exact.Rms << "\n";
  // Measured: 752 leaves, 566 sampled past the limit; RMS 0.109 constant
  // leaves, 0.033 past the limit, 3.6e-4 the full mesh.
  EXPECT_EQ(fast.NotFinite, 0u);
  EXPECT_LT(exact.Rms, fast.Rms);
  EXPECT_LT(fast.Rms, leavesRms);
}

// w_min is relative to the brightest emitter; a scene lit by lights alone has
// none, and w_min is then relative to the brightest surface's radiosity (it
// was 0 there: every discontinuity kept whatever --min-discontinuity-weight
// said). A lamp lights a white wall, whose light reaches the floor past a
// plate: partial links, discontinuities on the floor.
TEST(DiscontinuityMesh, MinimumWeightAppliesInASceneLitByLightsAlone)
{
  Scene scene;
  Material grey, white, black;
  grey.Reflectance = RGB(0.5);
  white.Reflectance = RGB(0.8);
  black.Reflectance = RGB(0.0);
  AppendQuad(scene, Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0), grey, 4, "floor");
  AppendQuad(scene, Vec3(-1, -1, 0), Vec3(-1, 1, 0), Vec3(-1, 1, 1.5), Vec3(-1, -1, 1.5), white, 2, "wall");
  const Vec3 p0(-0.8, -0.3, 0.3), p1(-0.4, -0.3, 0.3), p2(-0.4, 0.3, 0.3), p3(-0.8, 0.3, 0.3);
  AppendQuad(scene, p0, p1, p2, p3, black, 1, "plate top");
  AppendQuad(scene, p0, p3, p2, p1, black, 1, "plate bottom");
  Light lamp;
  lamp.Type = LightType::Point;
  lamp.Position = Vec3(0.5, 0.0, 1.2);
  lamp.Intensity = RGB(10.0);
  scene.Lighting.Lights.push_back(lamp);
  ASSERT_FALSE(scene.HasEmitters());
  HierarchicalRadiosity solver(scene, HierarchicalOptions());
  solver.Solve();
  DiscontinuityMeshOptions options;
  options.Conforming = false;
  const DiscontinuityMesh mesh = BuildDiscontinuityMesh(solver, options);
  DiscontinuityMeshOptions all = options, strict = options, stricter = options;
  all.MinWeight = 0.0;
  strict.MinWeight = 1e9;
  stricter.MinWeight = 1e12;
  const DiscontinuityMesh every = BuildDiscontinuityMesh(solver, all);
  const DiscontinuityMesh few = BuildDiscontinuityMesh(solver, strict);
  const DiscontinuityMesh fewer = BuildDiscontinuityMesh(solver, stricter);
  std::cout << "segments found at w_min 0, 0.05, 1e9: " << every.SegmentsFound << ", " << mesh.SegmentsFound << ", "
            << few.SegmentsFound << "\n";
  // Measured: 10,099, 10,099 and 332 (the same 10,099 at every w_min before):
  // the wall's weakest surfaces lie above 0.05 of the floor's brightest
  // radiosity; above every weight only the lamp's hard shadow edges (D0,
  // which no w_min drops) are left.
  EXPECT_GT(mesh.SegmentsKept, 0u);
  EXPECT_LE(mesh.SegmentsFound, every.SegmentsFound);
  EXPECT_LT(few.SegmentsFound, every.SegmentsFound / 10);
  EXPECT_EQ(fewer.SegmentsFound, few.SegmentsFound);
  EXPECT_LT(few.Triangles.size(), mesh.Triangles.size());
}
