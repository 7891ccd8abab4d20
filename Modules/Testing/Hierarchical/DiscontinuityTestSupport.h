// What the tests of the discontinuity-meshing kernels share: a check that a
// triangulation covers its domain validly, and geometric measures.
#ifndef Radiosity_DiscontinuityTestSupport_h
#define Radiosity_DiscontinuityTestSupport_h

#include "Radiosity/Hierarchical/ConstrainedTriangulation.h"
#include "Radiosity/Hierarchical/CriticalSurfaces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <utility>

using radiosity::BlockerEdge;
using radiosity::DiscontinuitySegment;
using radiosity::FindCriticalSegments;
using radiosity::PlanarTriangulation;
using radiosity::TriangulateWithConstraints;
using radiosity::Vec3;
using Domain = std::array<Vec3, 3>;
using Segments = std::vector<std::array<Vec3, 2>>;

namespace discontinuity_test
{
inline double TriangleArea(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return 0.5 * glm::length(glm::cross(b - a, c - a));
}

inline double DomainScale(const Domain& d)
{
  return std::max(
    { glm::length(d[1] - d[0]), glm::length(d[2] - d[1]), glm::length(d[0] - d[2]) });
}

/// Distance from p to the segment ab.
inline double PointSegmentDistance(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return glm::length(p - (a + t * ab));
}

/// Everything a valid triangulation of the domain must satisfy: the first
/// points are the corners, all points lie in the domain, every triangle has
/// positive area and the domain's orientation, the areas sum to the domain's,
/// and the mesh is conforming: every directed edge is used once, an edge
/// without a twin lies on the domain boundary.
inline void ExpectValidTriangulation(const Domain& domain, const PlanarTriangulation& t)
{
  // Output points are doubles: their rounding is relative to their magnitude.
  const double scale = DomainScale(domain);
  const double eps = 1e-12 * std::max(scale, glm::length(domain[0]));
  const Vec3 n = glm::cross(domain[1] - domain[0], domain[2] - domain[0]);
  const Vec3 unitN = glm::normalize(n);
  const double domainArea = 0.5 * glm::length(n);
  ASSERT_GE(t.Points.size(), 3u);
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_EQ(t.Points[i], domain[i]) << "corner " << i;
  }
  for (const Vec3& p : t.Points)
  {
    ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    EXPECT_LE(std::abs(glm::dot(p - domain[0], unitN)), eps) << "off the plane";
    // Barycentric coordinates >= 0 (up to rounding).
    for (int e = 0; e < 3; ++e)
    {
      const Vec3& a = domain[e];
      const Vec3& b = domain[(e + 1) % 3];
      EXPECT_GE(glm::dot(glm::cross(b - a, p - a), unitN) / glm::length(b - a), -eps)
        << "outside the domain";
    }
  }
  ASSERT_FALSE(t.Triangles.empty());
  double area = 0.0, edgeLength = 0.0;
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& tri : t.Triangles)
  {
    for (std::uint32_t v : tri)
    {
      ASSERT_LT(v, t.Points.size());
    }
    const Vec3& a = t.Points[tri[0]];
    const Vec3& b = t.Points[tri[1]];
    const Vec3& c = t.Points[tri[2]];
    const double signedArea = 0.5 * glm::dot(glm::cross(b - a, c - a), unitN);
    EXPECT_GT(signedArea, 0.0) << "triangle flipped or degenerate";
    area += signedArea;
    edgeLength += glm::length(b - a) + glm::length(c - b) + glm::length(a - c);
    for (int e = 0; e < 3; ++e)
    {
      ++directed[{ tri[e], tri[(e + 1) % 3] }];
    }
  }
  // Moving the points by eps changes the areas by about eps times the edges' length.
  EXPECT_NEAR(area, domainArea, 1e-12 * domainArea + eps * edgeLength);
  for (const auto& [edge, count] : directed)
  {
    EXPECT_EQ(count, 1) << "directed edge used twice";
    if (directed.count({ edge.second, edge.first }) == 0)
    {
      const Vec3& a = t.Points[edge.first];
      const Vec3& b = t.Points[edge.second];
      bool onBoundary = false;
      for (int e = 0; e < 3; ++e)
      {
        onBoundary = onBoundary ||
          (PointSegmentDistance(a, domain[e], domain[(e + 1) % 3]) <= eps &&
            PointSegmentDistance(b, domain[e], domain[(e + 1) % 3]) <= eps);
      }
      EXPECT_TRUE(onBoundary) << "a hole in the mesh: edge " << edge.first << "-" << edge.second;
    }
  }
}

/// Index of the mesh vertex at p, or -1.
inline int FindVertex(const PlanarTriangulation& t, const Vec3& p, double tol)
{
  for (std::size_t i = 0; i < t.Points.size(); ++i)
  {
    if (glm::length(t.Points[i] - p) <= tol)
    {
      return static_cast<int>(i);
    }
  }
  return -1;
}

/// The total length of the mesh edges lying on the segment ab: equal to |ab|
/// exactly when ab is a union of mesh edges.
inline double LengthOfEdgesOn(const PlanarTriangulation& t, const Vec3& a, const Vec3& b, double tol)
{
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const auto& tri : t.Triangles)
  {
    for (int e = 0; e < 3; ++e)
    {
      edges.insert(std::minmax(tri[e], tri[(e + 1) % 3]));
    }
  }
  double length = 0.0;
  for (const auto& [i, j] : edges)
  {
    if (PointSegmentDistance(t.Points[i], a, b) <= tol &&
      PointSegmentDistance(t.Points[j], a, b) <= tol)
    {
      length += glm::length(t.Points[j] - t.Points[i]);
    }
  }
  return length;
}

const Domain kUnitDomain = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0) };
} // namespace discontinuity_test

using namespace discontinuity_test;

#endif
