// The vector irradiance at the face cluster solver's output vertices
// (VertexIrradianceVectors: what vtkVectorIrradianceMapper shades, section
// 3.5 of Gobbetti et al. 2003) against a dense gather of the converged
// radiosity (VectorIrradianceReference.h: every emitter's and reflector's
// exact vector form factor, weighted by its visible fraction): magnitude
// error relative to the peak, direction error where the reference is above
// 5% of its peak, and vertices whose own normal sees a negative irradiance
// (n . E < 0: the black specks of issue 20's glossy statue).
#include "Radiosity/Common/ClosedFormFactors.h"
#include "Radiosity/FaceCluster/FaceClusterRadiosity.h"
#include "Radiosity/Reference/VectorIrradianceReference.h"
#include "Radiosity/Scenes/BunnyScene.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace radiosity;

namespace
{
struct VectorErrors
{
  std::size_t Vertices = 0;  ///< compared (smooth) vertices
  std::size_t Creases = 0;   ///< left out: incident normals more than 30 degrees apart
  std::size_t Directions = 0; ///< channel vectors above 5% of the peak
  double MaxMagnitude = 0.0, RmsMagnitude = 0.0; ///< |E - E_ref| / peak |E_ref|
  double MaxAngle = 0.0, RmsAngle = 0.0, Angle99 = 0.0; ///< degrees
  std::size_t BelowZero = 0;     ///< vertices with n . E_c < 0 in some channel
  double LowestRelative = 0.0;   ///< min over vertices of n . E_c / peak
  std::size_t ReferenceBelowZero = 0;
};

std::ostream& operator<<(std::ostream& os, const VectorErrors& e)
{
  return os << e.Vertices << " vertices (" << e.Creases << " creases left out): magnitude max "
            << e.MaxMagnitude << " RMS " << e.RmsMagnitude << " of the peak; direction max " << e.MaxAngle
            << " deg, 99th percentile " << e.Angle99 << ", RMS " << e.RmsAngle << " over "
            << e.Directions << " channel vectors; " << e.BelowZero << " vertices below zero (lowest n.E "
            << e.LowestRelative << " of the peak), reference " << e.ReferenceBelowZero;
}

/// The solver's vertex output against the dense gather of its own
/// converged radiosity (each element split 3 x 3), at every smooth vertex;
/// `part`: the same figures for the points from `firstPoint` on.
VectorErrors CompareWithDenseGather(
  const FaceClusterRadiosity& solver, std::size_t firstPoint = 0, VectorErrors* part = nullptr)
{
  const Scene& scene = solver.GetScene();
  const std::size_t np = scene.Points.size();
  std::vector<Vec3> normal(np, Vec3(0.0));
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    const Vec3 area = scene.Area(t) * scene.Normal(t);
    for (int k = 0; k < 3; ++k)
    {
      normal[scene.Triangles[t].V[k]] += area;
    }
  }
  std::vector<char> smooth(np, 0);
  for (std::size_t p = 0; p < np; ++p)
  {
    const double l = glm::length(normal[p]);
    if (l > 0.0)
    {
      normal[p] /= l;
      smooth[p] = 1;
    }
  }
  std::size_t creases[2] = { 0, 0 };
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t p = scene.Triangles[t].V[k];
      if (smooth[p] && glm::dot(normal[p], scene.Normal(t)) < std::cos(Pi / 6.0))
      {
        smooth[p] = 0;
        ++creases[0];
        creases[1] += p >= firstPoint ? 1 : 0;
      }
    }
  }
  std::vector<Vec3> points, normals;
  std::vector<std::size_t> index;
  for (std::size_t p = 0; p < np; ++p)
  {
    if (smooth[p])
    {
      points.push_back(scene.Points[p]);
      normals.push_back(normal[p]);
      index.push_back(p);
    }
  }
  const std::vector<RadiantTriangle> sources = RadiantTrianglesOf(scene, solver.Surface(), 3);
  const std::vector<std::array<Vec3, 3>> reference = GatherVectorIrradiance(scene, sources, points, normals);
  const std::vector<std::array<double, 9>> output = solver.VertexIrradianceVectors();
  double peak[3] = { 0.0, 0.0, 0.0 };
  for (const auto& e : reference)
  {
    for (int c = 0; c < 3; ++c)
    {
      peak[c] = std::max(peak[c], glm::length(e[c]));
    }
  }
  // The figures over the smooth points from `first` on, against the peaks
  // over all of them.
  auto figures = [&](std::size_t first) {
    VectorErrors errors;
    std::vector<double> angles;
    double squares = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      if (index[i] < first)
      {
        continue;
      }
      ++errors.Vertices;
      const auto& o = output[index[i]];
      bool below = false, referenceBelow = false;
      for (int c = 0; c < 3; ++c)
      {
        const Vec3 e(o[3 * c], o[3 * c + 1], o[3 * c + 2]);
        const Vec3& r = reference[i][c];
        const double magnitude = glm::length(e - r) / peak[c];
        errors.MaxMagnitude = std::max(errors.MaxMagnitude, magnitude);
        squares += magnitude * magnitude;
        // Below zero beyond rounding (the output's projection leaves n . E
        // within a few ulps of zero).
        const double h = glm::dot(normals[i], e);
        below = below || h < -1e-12 * peak[c];
        referenceBelow = referenceBelow || glm::dot(normals[i], r) < -1e-12 * peak[c];
        errors.LowestRelative = std::min(errors.LowestRelative, h / peak[c]);
        if (glm::length(r) > 0.05 * peak[c])
        {
          const double cosine = glm::dot(e, r) / std::max(glm::length(e) * glm::length(r), 1e-300);
          angles.push_back(std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / Pi);
        }
      }
      errors.BelowZero += below ? 1 : 0;
      errors.ReferenceBelowZero += referenceBelow ? 1 : 0;
    }
    errors.RmsMagnitude = std::sqrt(squares / std::max<double>(3.0 * errors.Vertices, 1.0));
    errors.Directions = angles.size();
    if (!angles.empty())
    {
      double sum = 0.0;
      for (double a : angles)
      {
        sum += a * a;
      }
      errors.RmsAngle = std::sqrt(sum / angles.size());
      std::sort(angles.begin(), angles.end());
      errors.MaxAngle = angles.back();
      errors.Angle99 = angles[static_cast<std::size_t>(0.99 * (angles.size() - 1))];
    }
    return errors;
  };
  VectorErrors all = figures(0);
  all.Creases = creases[0];
  if (part)
  {
    *part = figures(firstPoint);
    part->Creases = creases[1];
  }
  return all;
}

#ifdef RADIOSITY_BUNNY_JS
/// TestGlossyBunnyCornell's scene: the Cornell box without its blocks, every
/// triangle split in 16, and the bunny 0.25 m high on the middle of the
/// floor, subdivided `levels` times (the image's statue: 1; here 0, 3674
/// triangles, to keep the dense gather quick). `firstBunnyPoint`: its first point.
Scene GlossyStatue(int levels, std::size_t& firstBunnyPoint)
{
  return MakeGlossyStatueCornell(ReadNpmBunny(RADIOSITY_BUNNY_JS), levels, &firstBunnyPoint);
}
#endif
}

TEST(VectorIrradianceReference, ExactUnderASquareEmitterWithAndWithoutABlocker)
{
  // A unit square emitter (exitance 2) facing down at height 1 over a point
  // below its centre: E = 2 * 4 F(0.5, 0.5, 1), straight up. A blocker of
  // side 0.25 at height 0.5 hides the central 0.5 x 0.5 of the emitter.
  Scene scene;
  scene.Points = { Vec3(-0.5, 1.0, -0.5), Vec3(0.5, 1.0, -0.5), Vec3(0.5, 1.0, 0.5), Vec3(-0.5, 1.0, 0.5) };
  scene.Triangles = { { { 0, 1, 2 } }, { { 0, 2, 3 } } };
  scene.Materials.assign(2, Material());
  std::vector<RadiantTriangle> sources;
  for (const Triangle& t : scene.Triangles)
  {
    sources.push_back({ { scene.Points[t.V[0]], scene.Points[t.V[1]], scene.Points[t.V[2]] }, RGB(2.0) });
  }
  const std::vector<Vec3> points = { Vec3(0.0) }, normals = { Vec3(0.0, 1.0, 0.0) };
  const double open = 2.0 * 4.0 * closedform::PointToParallelRectangleCorner(0.5, 0.5, 1.0);
  const auto free = GatherVectorIrradiance(scene, sources, points, normals);
  EXPECT_NEAR(free[0][1].y, open, 1e-12 * open);
  EXPECT_NEAR(glm::length(free[0][1] - Vec3(0.0, free[0][1].y, 0.0)), 0.0, 1e-12 * open);
  const double b = 0.125;
  const std::uint32_t o = 4;
  scene.Points.insert(scene.Points.end(), { Vec3(-b, 0.5, -b), Vec3(b, 0.5, -b), Vec3(b, 0.5, b), Vec3(-b, 0.5, b) });
  scene.Triangles.push_back({ { o, o + 2, o + 1 } });
  scene.Triangles.push_back({ { o, o + 3, o + 2 } });
  scene.Materials.assign(4, Material());
  // Strata of a quarter of each leg: the shadow's edges fall on theirs.
  VectorGatherOptions options;
  options.MaxStrataPerEdge = 4;
  const auto shaded = GatherVectorIrradiance(scene, sources, points, normals, options);
  const double hidden = 2.0 * 4.0 * closedform::PointToParallelRectangleCorner(0.25, 0.25, 1.0);
  EXPECT_NEAR(shaded[0][0].y, open - hidden, 1e-9 * open);
  EXPECT_NEAR(glm::length(shaded[0][0] - Vec3(0.0, shaded[0][0].y, 0.0)), 0.0, 1e-9 * open);
  // Behind the point's horizon nothing arrives.
  const auto behind = GatherVectorIrradiance(scene, sources, points, { Vec3(0.0, -1.0, 0.0) });
  EXPECT_EQ(glm::length(behind[0][2]), 0.0);
}

TEST(FaceClusterVectorIrradiance, CornellBoxAgainstTheDenseGather)
{
  // The box as given (32 triangles) with the default linear and the
  // quadratic irradiance basis, and split in 16 (the glossy statue's room)
  // with the quadratic one. Measured (magnitude max / RMS of the peak,
  // direction max / RMS in degrees, vertices below zero):
  //                     before the fixes               after
  //   32, linear        0.266 / 0.079, 66 / 16, 1      0.265 / 0.080, 66 / 16, 0
  //   32, quadratic     0.491 / 0.169, 162 / 70, 7     0.440 / 0.083, 43 / 14, 0
  //   512, quadratic    0.336 / 0.071, 180 / 53, 27    0.103 / 0.025, 56 / 13, 0
  // (the same with and without ClusterFaces' fix, to 3 digits). With the
  // triangles halved where their fits cannot follow the light they receive
  // (MaxBisections 5, the default since), a vertex takes the parts' light
  // fitted over its whole input triangle (WholeTriangleExpansion: what the
  // display interpolates across it):
  //   32, linear        0.299 / 0.089, 64 / 23.6, 0
  //   32, quadratic     0.439 / 0.088, 60 / 21.6, 0
  //   512, quadratic    0.099 / 0.024, 46 / 12.5, 0
  // The vertex values of the parts in the triangles' corners were nearer
  // the gather at the vertex (0.081 / 0.033, 45 / 17.5 on the 32 linear),
  // but interpolated across a wall they lit the Cornell box's back wall by
  // the side walls' colours, the lamp's light missing from its middle
  // (TestRadiosityRepresentations' image): the vertex of a coarse triangle
  // stands for the whole triangle. The RMS direction on the 32 triangles is
  // 5 to 7 degrees worse than unhalved: the whole-triangle fit of halved
  // light is a different linear function than the unhalved fit. With the
  // lamp's direct light shown exactly (FaceClusterExactEmitters), the rest
  // fitted:
  //   32, linear        0.151 / 0.043, 45 / 19.6, 0
  //   32, quadratic     0.122 / 0.047, 50 / 22.6, 0
  //   512, quadratic    0.098 / 0.023, 46 / 12.6, 0
  struct Case
  {
    int Levels;
    BasisKind Basis;
    double Magnitude, Rms, Angle, AngleRms;
  };
  const Case cases[] = { { 0, BasisKind::Linear, 0.17, 0.05, 50.0, 21.5 },
    { 0, BasisKind::Quadratic, 0.14, 0.053, 55.0, 24.5 }, { 2, BasisKind::Quadratic, 0.11, 0.026, 50.0, 13.5 } };
  for (const Case& c : cases)
  {
    const Scene box = SubdividedScene(MakeCornellBox(), c.Levels);
    FaceClusterSettings settings;
    settings.IrradianceBasis = c.Basis;
    FaceClusterRadiosity solver(box, settings);
    solver.Solve();
    const VectorErrors errors = CompareWithDenseGather(solver);
    std::cout << "Cornell box, " << box.Triangles.size() << " triangles, " << static_cast<int>(c.Basis)
              << " irradiance functions: " << errors << "\n";
    EXPECT_EQ(errors.ReferenceBelowZero, 0u);
    EXPECT_EQ(errors.BelowZero, 0u);
    EXPECT_LT(errors.MaxMagnitude, c.Magnitude);
    EXPECT_LT(errors.RmsMagnitude, c.Rms);
    EXPECT_LT(errors.MaxAngle, c.Angle);
    EXPECT_LT(errors.RmsAngle, c.AngleRms);
  }
}

#ifdef RADIOSITY_BUNNY_JS
TEST(FaceClusterVectorIrradiance, GlossyStatueAgainstTheDenseGather)
{
  // TestGlossyBunnyCornell's scene with the bunny unsubdivided (3,866
  // triangles), quadratic irradiance basis as the image's right half.
  // Measured over the 1,809 smooth vertices (180 creases of the bunny left
  // out; the bunny's own figures are within a few percent of these):
  //   before: magnitude max 0.830 RMS 0.127 of the peak; direction max
  //   179.8 deg, 99th percentile 178.5, RMS 29.6; 33 vertices below zero
  //   (down to -0.19 of the peak: the light's vertices, see the Cornell
  //   box test), 6 of them on the bunny (-0.044);
  //   with MakeSurfaceRule's fix: 0.675 / 0.079; 164.8, 89.4, 17.9; 5
  //   below zero (-0.065: the ceiling above the light, the floor and the
  //   bunny's underside at their contact);
  //   with VertexIrradianceVectors' projection too: 0.675 / 0.079; 128.8,
  //   89.4, 17.7; none below zero;
  //   with ClusterFaces' fix too (the light was culled from curved clusters
  //   of the bunny whose upper faces it lights: a vertex under the ear got
  //   0.105 W/m^2 upward against 1.71 gathered, the light wholly visible):
  //   0.625 / 0.062; 125.3, 69.2, 14.0; none below zero.
  // What is left is the fit's: the worst vertices are in crevices and at
  // the bunny's contact with the floor, where a leaf's expansion leans the
  // wrong way (directions above 90 degrees, at under 10% of the peak), and
  // lit vertices of leaves whose nodes are shadowed (0.62 of the peak):
  // issue 20's refinement items.
  //   with the lamp's direct light shown exactly (FaceClusterExactEmitters,
  //   the rest fitted): 0.255 / 0.038; 98.1, 45.8, 11.4; none below zero
  //   (with the fit of it, on the same build: 0.627 / 0.062; 125.4, 69.4,
  //   14.6).
  std::size_t firstBunnyPoint = 0;
  const Scene scene = GlossyStatue(0, firstBunnyPoint);
  FaceClusterSettings settings;
  settings.IrradianceBasis = BasisKind::Quadratic;
  FaceClusterRadiosity solver(scene, settings);
  const SolverStatistics stats = solver.Solve();
  VectorErrors bunny;
  const VectorErrors all = CompareWithDenseGather(solver, firstBunnyPoint, &bunny);
  std::cout << "glossy statue (" << scene.Triangles.size() << " triangles, quadratic, solve " << stats.SolveSeconds
            << " s)\n  all: " << all << "\n  bunny: " << bunny << "\n";
  EXPECT_EQ(all.ReferenceBelowZero, 0u);
  EXPECT_EQ(all.BelowZero, 0u);
  EXPECT_LT(all.MaxAngle, 120.0);
  EXPECT_LT(all.Angle99, 52.0);
  EXPECT_LT(all.RmsAngle, 13.0);
  EXPECT_LT(all.MaxMagnitude, 0.3);
  EXPECT_LT(all.RmsMagnitude, 0.043);
}
#else
TEST(FaceClusterVectorIrradiance, GlossyStatueAgainstTheDenseGather)
{
  GTEST_SKIP() << "no bunny data: run scripts/fetch-data.sh and reconfigure";
}
#endif
