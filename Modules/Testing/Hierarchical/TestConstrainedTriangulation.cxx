// The constrained Delaunay triangulation of a leaf (Hardt & Teller, section
// 2.1): coverage, constraints as mesh edges, crossings, orientation,
// degenerate input and extreme scales.
#include "DiscontinuityTestSupport.h"

TEST(ConstrainedTriangulation, NoConstraintsGivesTheDomain)
{
  const Domain d = { Vec3(0.3, -1, 2), Vec3(1, 0.5, 2.5), Vec3(-0.2, 0.7, 1) };
  const PlanarTriangulation t = TriangulateWithConstraints(d, {});
  ASSERT_EQ(t.Points.size(), 3u);
  ASSERT_EQ(t.Triangles.size(), 1u);
  EXPECT_EQ(t.Points[0], d[0]);
  EXPECT_EQ(t.Points[1], d[1]);
  EXPECT_EQ(t.Points[2], d[2]);
  EXPECT_EQ(t.Triangles[0], (std::array<std::uint32_t, 3>{ 0, 1, 2 }));
}

TEST(ConstrainedTriangulation, SegmentAcrossIsMeshEdges)
{
  // A tilted domain, so the 2D frame is exercised.
  const Domain d = { Vec3(1, 2, 3), Vec3(4, 2.5, 2), Vec3(2, 5, 4) };
  const Vec3 a = 0.5 * (d[0] + d[1]);                // on an edge
  const Vec3 b = 0.6 * d[2] + 0.2 * d[0] + 0.2 * d[1]; // inside
  const PlanarTriangulation t = TriangulateWithConstraints(d, { { a, b } });
  ExpectValidTriangulation(d, t);
  const double tol = 1e-12 * DomainScale(d);
  EXPECT_GE(FindVertex(t, a, tol), 3);
  EXPECT_GE(FindVertex(t, b, tol), 3);
  EXPECT_NEAR(LengthOfEdgesOn(t, a, b, tol), glm::length(b - a), 1e-12 * glm::length(b - a));
}

TEST(ConstrainedTriangulation, CrossingSegmentsMeetAtAVertex)
{
  const Domain d = { Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0) };
  // Two crossing segments; the first runs from edge to edge, the second
  // pokes out of the domain.
  const Vec3 a0(0.0, 0.2, 0.0), a1(1.2, 0.8, 0.0);
  const Vec3 b0(0.8, 0.2, 0.0), b1(-0.4, 1.0, 0.0);
  const PlanarTriangulation t = TriangulateWithConstraints(d, { { a0, a1 }, { b0, b1 } });
  ExpectValidTriangulation(d, t);
  // Crossing point: a0 + s (a1 - a0) = b0 + r (b1 - b0): s = 8/21, r = 2/7.
  const Vec3 x = a0 + (8.0 / 21.0) * (a1 - a0);
  const double tol = 1e-12 * DomainScale(d);
  EXPECT_GE(FindVertex(t, x, tol), 3) << "crossing point is no vertex";
  // The second one is clipped at x = 0: its end is the point (0, 0.4667) on the edge.
  const Vec3 clipped(0.0, 0.2 + 0.8 * (2.0 / 3.0), 0.0);
  EXPECT_GE(FindVertex(t, clipped, tol), 3);
  EXPECT_NEAR(LengthOfEdgesOn(t, a0, a1, tol), glm::length(a1 - a0), 1e-12);
  EXPECT_NEAR(LengthOfEdgesOn(t, b0, clipped, tol), glm::length(clipped - b0), 1e-12);
}

TEST(ConstrainedTriangulation, OrientationFollowsTheDomain)
{
  // Domain whose normal is -z: every output triangle must face -z.
  const Domain d = { Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(1, 0, 0) };
  const PlanarTriangulation t = TriangulateWithConstraints(
    d, { { Vec3(0.1, 0.1, 0), Vec3(0.5, 0.4, 0) }, { Vec3(0.6, 0.0, 0), Vec3(0.0, 0.7, 0) } });
  ExpectValidTriangulation(d, t);
  EXPECT_GT(t.Triangles.size(), 3u);
  for (const auto& tri : t.Triangles)
  {
    const Vec3 n =
      glm::cross(t.Points[tri[1]] - t.Points[tri[0]], t.Points[tri[2]] - t.Points[tri[0]]);
    EXPECT_LT(n.z, 0.0);
  }
}

TEST(ConstrainedTriangulation, SegmentsOffThePlaneAreProjected)
{
  const PlanarTriangulation t =
    TriangulateWithConstraints(kUnitDomain, { { Vec3(0.1, 0.1, 0.5), Vec3(0.6, 0.3, -2.0) } });
  ExpectValidTriangulation(kUnitDomain, t);
  EXPECT_GE(FindVertex(t, Vec3(0.1, 0.1, 0), 1e-14), 3);
  EXPECT_GE(FindVertex(t, Vec3(0.6, 0.3, 0), 1e-14), 3);
}

TEST(ConstrainedTriangulation, DegenerateInputGivesAValidMesh)
{
  const Domain& d = kUnitDomain;
  // Nothing usable: zero-length, outside, along an edge, tiny, non-finite.
  const Segments unusable = {
    { Vec3(0.2, 0.2, 0), Vec3(0.2, 0.2, 0) },
    { Vec3(2, 2, 0), Vec3(3, 1, 0) },
    { Vec3(-1, -1, 0), Vec3(-0.5, 2, 0) },
    { Vec3(0.1, 0, 0), Vec3(0.7, 0, 0) },          // on edge 0
    { Vec3(-0.5, 0, 0), Vec3(2, 0, 0) },           // along edge 0, beyond it
    { Vec3(0.2, 0.8, 0), Vec3(0.7, 0.3, 0) },      // on the hypotenuse
    { Vec3(0.3, 1e-13, 0), Vec3(0.6, -1e-13, 0) }, // along edge 0 within the tolerance
    { Vec3(0.3, 0.3, 0), Vec3(0.3 + 1e-12, 0.3, 0) },
    { Vec3(NAN, 0.3, 0), Vec3(0.5, 0.3, 0) },
    { Vec3(0.1, 0.1, 0), Vec3(INFINITY, 0.3, 0) },
  };
  for (const auto& s : unusable)
  {
    const PlanarTriangulation t = TriangulateWithConstraints(d, { s });
    ASSERT_EQ(t.Triangles.size(), 1u) << s[0].x << "," << s[0].y << " " << s[1].x << "," << s[1].y;
    ExpectValidTriangulation(d, t);
  }
  {
    const PlanarTriangulation t = TriangulateWithConstraints(d, unusable);
    ASSERT_EQ(t.Triangles.size(), 1u);
  }
  // Usable ones mixed with duplicates, reversed duplicates, overlapping
  // collinear pieces, a segment from a corner, and near-corner endpoints.
  const Segments messy = {
    { Vec3(0.1, 0.1, 0), Vec3(0.5, 0.3, 0) },
    { Vec3(0.1, 0.1, 0), Vec3(0.5, 0.3, 0) },
    { Vec3(0.5, 0.3, 0), Vec3(0.1, 0.1, 0) },
    { Vec3(0.3, 0.2, 0), Vec3(0.7, 0.4, 0) }, // overlaps the first, runs out through the hypotenuse
    { Vec3(0, 0, 0), Vec3(0.4, 0.4, 0) },     // from a corner, crossing the others
    { Vec3(1e-13, 1 - 1e-13, 0), Vec3(0.2, 0.05, 0) },
    { Vec3(0.25, 0.5, 1e-3), Vec3(0.25, 0.5 + 1e-12, 0) }, // tiny after projection
    { Vec3(0.3, 1e-11, 0), Vec3(0.3, 0.6, 0) },            // endpoint snapped onto edge 0
    { Vec3(0.3, 0.6, 0), Vec3(0.3, 0.2, 0) },              // overlaps the previous one
  };
  const PlanarTriangulation t = TriangulateWithConstraints(d, messy);
  ExpectValidTriangulation(d, t);
  EXPECT_GE(FindVertex(t, Vec3(0.3, 0.0, 0), 1e-14), 3) << "endpoint not snapped onto the edge";
  EXPECT_EQ(FindVertex(t, Vec3(0.3, 1e-11, 0), 1e-14), -1);
  EXPECT_EQ(FindVertex(t, Vec3(1e-13, 1 - 1e-13, 0), 1e-14), -1) << "near-corner endpoint kept";
  // No needle triangle along the boundary: none thinner than the snapping tolerance.
  for (const auto& tri : t.Triangles)
  {
    const Vec3& a = t.Points[tri[0]];
    const Vec3& b = t.Points[tri[1]];
    const Vec3& c = t.Points[tri[2]];
    const double longest = std::max({ glm::length(b - a), glm::length(c - b), glm::length(a - c) });
    EXPECT_GT(2.0 * TriangleArea(a, b, c) / longest, 1e-9);
  }
  // Degenerate domain: returned as is, no crash.
  const Domain flat = { Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2) };
  const PlanarTriangulation f = TriangulateWithConstraints(flat, messy);
  EXPECT_EQ(f.Points.size(), 3u);
  EXPECT_EQ(f.Triangles.size(), 1u);
}

TEST(ConstrainedTriangulation, ManyCrossingSegments)
{
  // A fan of chords crossing one another: every pairwise crossing inside the
  // domain must become a vertex, and the mesh must stay valid.
  const Domain d = { Vec3(-1, -1, 0.5), Vec3(3, -1, 0.5), Vec3(-1, 3, 0.5) };
  Segments s;
  for (int i = 0; i < 12; ++i)
  {
    const double a = 0.3 * i + 0.1;
    s.push_back({ Vec3(-1.5 + 0.2 * i, -1.5, 0.5), Vec3(-1.0 + std::cos(a), 2.0 * std::sin(a), 0.5) });
  }
  const PlanarTriangulation t = TriangulateWithConstraints(d, s);
  ExpectValidTriangulation(d, t);
  EXPECT_GT(t.Triangles.size(), 24u);
}

TEST(ConstrainedTriangulation, ExtremeScales)
{
  for (const double scale : { 1e4, 1e-4 })
  {
    for (const double offset : { 0.0, 1e4 })
    {
      const Vec3 o(offset, -offset, 0.5 * offset);
      const Domain d = { o + scale * Vec3(0, 0, 0), o + scale * Vec3(1, 0.2, 0.1),
        o + scale * Vec3(0.3, 1, -0.4) };
      const Vec3 a = 0.5 * (d[0] + d[1]);
      const Vec3 b = 0.5 * (d[1] + d[2]);
      const Vec3 c = 0.5 * (d[2] + d[0]);
      const Vec3 g = (d[0] + d[1] + d[2]) / 3.0;
      const PlanarTriangulation t =
        TriangulateWithConstraints(d, { { a, b }, { b, c }, { c, a }, { d[0], b }, { g, d[2] } });
      SCOPED_TRACE(testing::Message() << "scale " << scale << " offset " << offset);
      ExpectValidTriangulation(d, t);
      // The positional tolerance is relative to the coordinates' magnitude.
      const double tol = 1e-12 * std::max(DomainScale(d), glm::length(o));
      EXPECT_GE(FindVertex(t, a, tol), 3);
      EXPECT_GE(FindVertex(t, b, tol), 3);
      EXPECT_GE(FindVertex(t, c, tol), 3);
      EXPECT_GE(FindVertex(t, g, tol), 3);
    }
  }
}

TEST(ConstrainedTriangulation, RandomNearDegenerateInput)
{
  // Segments that share endpoints and lines only up to rounding, as the
  // critical-surface traces do, plus crossings, duplicates and segments
  // through the corners: the mesh must stay valid and thin-free.
  std::mt19937 rng(4242);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const Domain d = { Vec3(0.2, 0.1, 1.0), Vec3(2.3, 0.4, 0.6), Vec3(0.9, 1.9, 1.3) };
  auto inside = [&]() {
    double a = U(rng), b = U(rng);
    if (a + b > 1.0)
    {
      a = 1.0 - a;
      b = 1.0 - b;
    }
    return d[0] + a * (d[1] - d[0]) + b * (d[2] - d[0]);
  };
  auto jitter = [&](const Vec3& p, double size) {
    return p + size * Vec3(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5);
  };
  double minHeight = std::numeric_limits<double>::infinity();
  for (int trial = 0; trial < 200; ++trial)
  {
    Segments s;
    std::vector<Vec3> anchors = { d[0], d[1], d[2] };
    for (int k = 0; k < 8; ++k)
    {
      anchors.push_back(inside());
    }
    for (int k = 0; k < 12; ++k)
    {
      const Vec3 a = anchors[rng() % anchors.size()];
      const Vec3 b = anchors[rng() % anchors.size()];
      const double size = (rng() % 2) ? 1e-14 : 1e-11;
      s.push_back({ jitter(a, size), jitter(b, size) });
      // A piece of the same line, slightly off, and an extension past b.
      s.push_back({ jitter(a + 0.3 * (b - a), size), jitter(a + 1.4 * (b - a), size) });
    }
    const PlanarTriangulation t = TriangulateWithConstraints(d, s);
    SCOPED_TRACE(testing::Message() << "trial " << trial);
    ExpectValidTriangulation(d, t);
    for (const auto& tri : t.Triangles)
    {
      const Vec3& a = t.Points[tri[0]];
      const Vec3& b = t.Points[tri[1]];
      const Vec3& c = t.Points[tri[2]];
      const double longest = std::max({ glm::length(b - a), glm::length(c - b), glm::length(a - c) });
      minHeight = std::min(minHeight, 2.0 * TriangleArea(a, b, c) / longest);
    }
    if (testing::Test::HasFailure())
    {
      break;
    }
  }
  // Without the snapping heights reach the rounding level (1e-16); with it
  // they stay near the snapping tolerance (1e-9 of the domain's size).
  // Crossings of nearly parallel segments could still go lower: this input
  // has none closer than its anchors.
  EXPECT_GT(minHeight, 1e-10);
}
