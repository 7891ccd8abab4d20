// The face cluster hierarchy (Gobbetti et al. 2003, 3.1; Garland et al. 2001):
// greedy dual-graph contraction merges planar regions first, one root per
// object, and each cluster's box, area samples, convexity and materials
// bound and describe its triangles.
#include "Radiosity/FaceCluster/FaceClusterHierarchy.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

using namespace radiosity;

namespace
{
// A (2n x n)-cell grid folded by 90 degrees along x = 1: the half x < 1 lies in
// z = 0 facing +z, the other half rises (`up`, a concave fold: the halves see
// each other) or drops (convex). One object, shared points.
Scene MakeFold(int n, bool up)
{
  Scene scene;
  auto point = [&](int i, int j) {
    const double u = static_cast<double>(i) / n, v = static_cast<double>(j) / n;
    return u <= 1.0 ? Vec3(u, v, 0.0) : Vec3(1.0, v, (up ? 1.0 : -1.0) * (u - 1.0));
  };
  for (int i = 0; i <= 2 * n; ++i)
  {
    for (int j = 0; j <= n; ++j)
    {
      scene.Points.push_back(point(i, j));
    }
  }
  auto id = [n](int i, int j) { return static_cast<std::uint32_t>(i * (n + 1) + j); };
  for (int i = 0; i < 2 * n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      // Counter-clockwise seen from +z on the flat half.
      scene.Triangles.push_back({ { id(i, j), id(i + 1, j), id(i + 1, j + 1) } });
      scene.Triangles.push_back({ { id(i, j), id(i + 1, j + 1), id(i, j + 1) } });
    }
  }
  scene.Materials.assign(scene.Triangles.size(), Material());
  scene.ObjectIds.assign(scene.Triangles.size(), 0);
  scene.ObjectNames = { "fold" };
  return scene;
}

// The triangles of cluster `id`, from its range.
std::set<std::uint32_t> TrianglesOf(const FaceClusterHierarchy& h, std::uint32_t id)
{
  const FaceCluster c = h.Cluster(id);
  return std::set<std::uint32_t>(
    h.TriangleOrder().begin() + c.First, h.TriangleOrder().begin() + c.First + c.Count);
}

bool OnFlatHalf(const Scene& scene, std::uint32_t t)
{
  return std::abs(scene.Normal(t).z) > 0.5;
}
}

TEST(FaceClusterHierarchy, ConcaveFoldSplitsIntoItsTwoPlanesLast)
{
  const Scene scene = MakeFold(6, true);
  const FaceClusterHierarchy h(scene);
  ASSERT_EQ(h.Roots().size(), 1u);
  EXPECT_EQ(h.NumberOfClusters(), 2 * scene.Triangles.size() - 1);
  const FaceCluster root = h.Cluster(h.Roots()[0]);
  EXPECT_EQ(root.Count, scene.Triangles.size());
  // The planar halves are contracted before they are joined.
  for (std::uint32_t child : root.Child)
  {
    const std::set<std::uint32_t> tris = TrianglesOf(h, child);
    EXPECT_EQ(tris.size(), scene.Triangles.size() / 2);
    const bool flat = OnFlatHalf(scene, *tris.begin());
    for (std::uint32_t t : tris)
    {
      EXPECT_EQ(OnFlatHalf(scene, t), flat);
    }
    EXPECT_TRUE(h.Cluster(child).Convex);
    EXPECT_EQ(h.Cluster(child).SelfFormFactorUpper(), 0.0);
  }
  // The halves see each other: not convex, and the self form factor bound is
  // 1 - |A1 n1 + A2 n2| / (A1 + A2) = 1 - sqrt(2) / 2.
  EXPECT_FALSE(root.Convex);
  EXPECT_NEAR(root.SelfFormFactorUpper(), 1.0 - std::sqrt(0.5), 1e-6);
  EXPECT_NEAR(root.Area, 2.0, 1e-6);
}

TEST(FaceClusterHierarchy, ConvexFoldHasNoSelfTransfer)
{
  const Scene scene = MakeFold(4, false);
  const FaceClusterHierarchy h(scene);
  ASSERT_EQ(h.Roots().size(), 1u);
  const FaceCluster root = h.Cluster(h.Roots()[0]);
  EXPECT_TRUE(root.Convex);
  EXPECT_EQ(root.SelfFormFactorUpper(), 0.0);
  EXPECT_EQ(root.SelfFormFactorLower(), 0.0);
}

TEST(FaceClusterHierarchy, ClustersBoundAndDescribeTheirTriangles)
{
  const Scene scene = MakeSphereInterior(1.0, 2, 0.6, RGB(4.0, 2.0, 1.0));
  const FaceClusterHierarchy h(scene);
  std::mt19937 random(7);
  std::normal_distribution<double> gauss;
  std::vector<Vec3> directions;
  for (int i = 0; i < 24; ++i)
  {
    directions.push_back(glm::normalize(Vec3(gauss(random), gauss(random), gauss(random))));
  }
  for (std::uint32_t id = 0; id < h.NumberOfClusters(); ++id)
  {
    const FaceCluster c = h.Cluster(id);
    ASSERT_GE(c.Count, 1u);
    // Axes orthonormal and right-handed, z along the area vector.
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        EXPECT_NEAR(glm::dot(c.Axis[i], c.Axis[j]), i == j ? 1.0 : 0.0, 1e-5);
      }
    }
    EXPECT_NEAR(glm::dot(glm::cross(c.Axis[0], c.Axis[1]), c.Axis[2]), 1.0, 1e-5);
    EXPECT_GE(glm::dot(Vec3(c.AreaVector), Vec3(c.Axis[2])), -1e-6);
    double area = 0.0;
    Vec3 areaVector(0.0);
    for (std::uint32_t k = c.First; k < c.First + c.Count; ++k)
    {
      const std::uint32_t t = h.TriangleOrder()[k];
      area += scene.Area(t);
      areaVector += scene.Area(t) * scene.Normal(t);
      // The box holds every vertex.
      for (int v = 0; v < 3; ++v)
      {
        const Vec3 d = scene.Vertex(t, v) - Vec3(c.Centre);
        for (int j = 0; j < 3; ++j)
        {
          EXPECT_LE(std::abs(glm::dot(d, Vec3(c.Axis[j]))), c.HalfSize[j] + 1e-5);
        }
      }
      EXPECT_EQ(h.AncestorAtDepth(t, c.Depth), id);
    }
    EXPECT_NEAR(c.Area, area, 1e-5 * area);
    EXPECT_NEAR(glm::length(Vec3(c.AreaVector) - areaVector), 0.0, 1e-5 * area);
    // Willmott's projected-area bounds hold the front-facing area sum.
    for (const Vec3& r : directions)
    {
      double front = 0.0;
      for (std::uint32_t k = c.First; k < c.First + c.Count; ++k)
      {
        const std::uint32_t t = h.TriangleOrder()[k];
        front += scene.Area(t) * std::max(glm::dot(scene.Normal(t), r), 0.0);
      }
      EXPECT_LE(c.MinProjectedArea(r), front + 1e-5 * area);
      EXPECT_GE(c.MaxProjectedArea(r), front - 1e-5 * area);
    }
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_LE(c.EmissionMin[k], c.EmissionMean[k] + 1e-6f);
      EXPECT_LE(c.EmissionMean[k], c.EmissionMax[k] + 1e-6f);
    }
    if (!c.IsLeaf())
    {
      EXPECT_EQ(h.Cluster(c.Child[0]).Parent, id);
      EXPECT_EQ(h.Cluster(c.Child[0]).Count + h.Cluster(c.Child[1]).Count, c.Count);
    }
  }
  // The closed sphere: one root, its area vector vanishes, its self form
  // factor bound is 1, the cap's emission is its maximum and the mean is
  // the area-weighted one.
  ASSERT_EQ(h.Roots().size(), 1u);
  const FaceCluster root = h.Cluster(h.Roots()[0]);
  EXPECT_FALSE(root.Convex);
  EXPECT_NEAR(root.SelfFormFactorUpper(), 1.0, 1e-5);
  EXPECT_FLOAT_EQ(root.EmissionMax.x, 4.0f);
  EXPECT_FLOAT_EQ(root.EmissionMin.x, 0.0f);
  double emitted = 0.0, total = 0.0;
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    emitted += scene.Area(t) * scene.Materials[t].Emission.x;
    total += scene.Area(t);
  }
  EXPECT_NEAR(root.EmissionMean.x, emitted / total, 1e-5);
}

TEST(FaceClusterHierarchy, OneRootPerObjectDisconnectedPiecesChained)
{
  Scene scene;
  Material m;
  AppendQuad(scene, Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), m, 3, "a");
  AppendQuad(scene, Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(3, 1, 0), Vec3(2, 1, 0), m, 3, "b");
  AppendQuad(scene, Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1), m, 2, "c");
  // Quads "a" and "b" become one object of two disconnected pieces.
  const std::size_t quadA = 18;
  for (std::size_t t = quadA; t < 2 * quadA; ++t)
  {
    scene.ObjectIds[t] = scene.ObjectIds[0];
  }
  const FaceClusterHierarchy h(scene);
  ASSERT_EQ(h.Roots().size(), 2u);
  EXPECT_EQ(h.NumberOfClusters(), 2 * scene.Triangles.size() - 2);
  std::set<std::size_t> counts;
  for (std::uint32_t r : h.Roots())
  {
    counts.insert(h.Cluster(r).Count);
    const std::set<std::uint32_t> tris = TrianglesOf(h, r);
    const int object = scene.ObjectIds[*tris.begin()];
    for (std::uint32_t t : tris)
    {
      EXPECT_EQ(scene.ObjectIds[t], object);
    }
  }
  EXPECT_EQ(counts, (std::set<std::size_t>{ 2 * quadA, 8 }));
}

TEST(FaceClusterHierarchy, SharedHierarchyIsBuiltOncePerScene)
{
  Scene scene = MakeFold(3, true);
  const auto first = FaceClusterHierarchy::Shared(scene);
  const auto second = FaceClusterHierarchy::Shared(scene);
  EXPECT_EQ(first.get(), second.get());
  scene.Materials[0].Reflectance = RGB(0.9);
  const auto changed = FaceClusterHierarchy::Shared(scene);
  EXPECT_NE(first.get(), changed.get());
  EXPECT_NE(first->Fingerprint(), changed->Fingerprint());
}

TEST(FaceClusterHierarchy, ContractionDoesNotDependOnScale)
{
  // Scaling by powers of two is exact, so the costs scale exactly: the trees
  // must be identical if the cost is scale-free.
  const Scene base = MakeSphereInterior(1.0, 2, 0.5, RGB(1.0));
  const FaceClusterHierarchy reference(base);
  for (double scale : { std::ldexp(1.0, -14), std::ldexp(1.0, 14) })
  {
    Scene scaled = base;
    for (Vec3& p : scaled.Points)
    {
      p *= scale;
    }
    const FaceClusterHierarchy h(scaled);
    ASSERT_EQ(h.NumberOfClusters(), reference.NumberOfClusters());
    for (std::uint32_t id = static_cast<std::uint32_t>(h.NumberOfTriangles());
         id < h.NumberOfClusters(); ++id)
    {
      ASSERT_EQ(h.Cluster(id).Child[0], reference.Cluster(id).Child[0]) << "scale " << scale;
      ASSERT_EQ(h.Cluster(id).Child[1], reference.Cluster(id).Child[1]) << "scale " << scale;
    }
  }
}

TEST(FaceClusterHierarchy, ProgressCanAbortTheBuild)
{
  // 81,920 triangles: the progress callback is called after 65,536 merges.
  const Scene scene = MakeSphereInterior(1.0, 6, 0.5, RGB(1.0));
  int calls = 0;
  auto stop = [&calls](const ProgressStatus& status) {
    ++calls;
    EXPECT_GT(status.Fraction, 0.0);
    return false;
  };
  EXPECT_THROW(FaceClusterHierarchy(scene, {}, stop), FaceClusterBuildAborted);
  EXPECT_EQ(calls, 1);
}
