// The EV/VE critical surfaces traced on a receiver and their weights
// (Hardt & Teller, section 4).
#include "DiscontinuityTestSupport.h"

namespace
{
/// Unit square light at height h, as the two triangles a caller would pass,
/// both facing down (-z).
std::array<Domain, 2> SquareLight(double h)
{
  return { Domain{ Vec3(0, 0, h), Vec3(0, 1, h), Vec3(1, 1, h) },
    Domain{ Vec3(0, 0, h), Vec3(1, 1, h), Vec3(1, 0, h) } };
}

/// The boundary of the square [x0,x1] x [y0,y1] at height z.
std::vector<BlockerEdge> SquareBlocker(double x0, double x1, double y0, double y1, double z)
{
  const Vec3 p00(x0, y0, z), p10(x1, y0, z), p11(x1, y1, z), p01(x0, y1, z);
  return { { p00, p10 }, { p10, p11 }, { p11, p01 }, { p01, p00 } };
}

/// A floor triangle at z = 0 containing [-5,5]^2, facing up.
const Domain kFloor = { Vec3(-20, -10, 0), Vec3(20, -10, 0), Vec3(0, 30, 0) };

std::vector<DiscontinuitySegment> AllSegments(const Domain& receiver, const std::array<Domain, 2>& light,
  double radiosity, const std::vector<BlockerEdge>& blocker, double minLength = 1e-9)
{
  std::vector<DiscontinuitySegment> out;
  for (const Domain& s : light)
  {
    FindCriticalSegments(receiver, Vec3(0, 0, 1), s, radiosity, blocker, minLength, out);
  }
  return out;
}

void ExpectFinite(const std::vector<DiscontinuitySegment>& segments)
{
  for (const auto& s : segments)
  {
    EXPECT_TRUE(std::isfinite(s.A.x) && std::isfinite(s.A.y) && std::isfinite(s.A.z));
    EXPECT_TRUE(std::isfinite(s.B.x) && std::isfinite(s.B.y) && std::isfinite(s.B.z));
    EXPECT_TRUE(std::isfinite(s.Weight));
  }
}

bool Near(double a, double b)
{
  return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b));
}
} // namespace

TEST(CriticalSurfaces, PenumbraBoundariesBySimilarTriangles)
{
  // Light [0,1]^2 at z = 1, blocker [0.2,0.8] x [0.25,0.75] at z = 0.5, floor
  // at z = 0. From the light point (xl, yl) the blocker point (xb, yb) lands
  // at (2 xb - xl, 2 yb - yl): its edge y = 0.25 (along x) casts the lines
  // y = 0.5 (through the light edge y = 0) and y = -0.5 (through y = 1).
  const double B = 3.5;
  const auto light = SquareLight(1.0);
  const auto blocker = SquareBlocker(0.2, 0.8, 0.25, 0.75, 0.5);
  const auto segments = AllSegments(kFloor, light, B, blocker);
  ASSERT_FALSE(segments.empty());
  ExpectFinite(segments);

  // Every segment parallel to x lies at y = 2 yb - yl, yb in {0.25, 0.75},
  // yl in {0, 1}; both lines of the edge y = 0.25 are there, with the extent
  // of their VE segments: x in [2 * 0.2 - xl, 2 * 0.8 - xl] for xl in {0, 1}.
  std::set<double> ys;
  bool veFromOrigin = false, veFromX1 = false;
  for (const auto& s : segments)
  {
    EXPECT_NEAR(s.A.z, 0.0, 1e-14);
    EXPECT_NEAR(s.B.z, 0.0, 1e-14);
    if (std::abs(s.A.y - s.B.y) > 1e-12)
    {
      continue;
    }
    const double y = s.A.y;
    EXPECT_TRUE(Near(y, 0.5) || Near(y, -0.5) || Near(y, 1.5)) << "y = " << y;
    ys.insert(std::round(y * 1e6) / 1e6);
    const double lo = std::min(s.A.x, s.B.x), hi = std::max(s.A.x, s.B.x);
    veFromOrigin = veFromOrigin || (Near(y, 0.5) && Near(lo, 0.4) && Near(hi, 1.6));
    veFromX1 = veFromX1 || (Near(y, -0.5) && Near(lo, -0.6) && Near(hi, 0.6));
  }
  EXPECT_TRUE(ys.count(0.5) == 1 && ys.count(-0.5) == 1 && ys.count(1.5) == 1);
  EXPECT_TRUE(veFromOrigin) << "VE of light vertex (0,0) and the edge y = 0.25 missing";
  EXPECT_TRUE(veFromX1) << "VE of light vertex (1,1) and the edge y = 0.25 missing";

  // Half way between light and floor: d_sb / d_br = 1 for every pair.
  for (const auto& s : segments)
  {
    EXPECT_NEAR(s.Weight, B, 1e-12 * B);
  }
}

TEST(CriticalSurfaces, WeightIsTheDistanceRatio)
{
  // Blocker at z = 0.75 under the light at z = 1: d_sb / d_br = 0.25 / 0.75
  // along every line from a light vertex through a blocker vertex.
  const double B = 2.0;
  const auto segments = AllSegments(kFloor, SquareLight(1.0), B, SquareBlocker(0.3, 0.6, 0.3, 0.7, 0.75));
  ASSERT_FALSE(segments.empty());
  for (const auto& s : segments)
  {
    EXPECT_NEAR(s.Weight, B / 3.0, 1e-12);
  }
  // A tilted blocker edge from (0.5, 0.5, 0.9) to (0.6, 0.4, 0.3): the VE
  // wedges take the maximum over both ends, 0.7 / 0.3 (the end nearer to the
  // floor); the EV wedges of the upper vertex have 0.1 / 0.9 only.
  std::vector<DiscontinuitySegment> out;
  const std::vector<BlockerEdge> tilted = { { Vec3(0.5, 0.5, 0.9), Vec3(0.6, 0.4, 0.3) } };
  FindCriticalSegments(kFloor, Vec3(0, 0, 1), SquareLight(1.0)[0], 1.0, tilted, 0.0, out);
  ASSERT_FALSE(out.empty());
  int strong = 0, weak = 0;
  for (const auto& s : out)
  {
    const bool isStrong = std::abs(s.Weight - 0.7 / 0.3) < 1e-12;
    const bool isWeak = std::abs(s.Weight - 0.1 / 0.9) < 1e-12;
    EXPECT_TRUE(isStrong || isWeak) << s.Weight;
    strong += isStrong;
    weak += isWeak;
  }
  EXPECT_GE(strong, 3); // three VE wedges and the EV wedges of the lower vertex
  EXPECT_GE(weak, 1);
}

TEST(CriticalSurfaces, AppendsAndDropsShortSegments)
{
  std::vector<DiscontinuitySegment> out(2);
  const auto light = SquareLight(1.0);
  FindCriticalSegments(
    kFloor, Vec3(0, 0, 1), light[0], 1.0, SquareBlocker(0.2, 0.8, 0.25, 0.75, 0.5), 0.0, out);
  ASSERT_GT(out.size(), 2u);
  EXPECT_EQ(out[0].Weight, 0.0); // the two already there are kept
  std::vector<DiscontinuitySegment> longOnes;
  FindCriticalSegments(
    kFloor, Vec3(0, 0, 1), light[0], 1.0, SquareBlocker(0.2, 0.8, 0.25, 0.75, 0.5), 1.1, longOnes);
  EXPECT_LT(longOnes.size(), out.size() - 2);
  for (const auto& s : longOnes)
  {
    EXPECT_GE(glm::length(s.B - s.A), 1.1);
  }
}

TEST(CriticalSurfaces, NothingWithoutAShadowOnTheReceiver)
{
  const auto light = SquareLight(1.0);
  // Blocker behind the light (above it, the light facing down).
  EXPECT_TRUE(AllSegments(kFloor, light, 1.0, SquareBlocker(0.2, 0.8, 0.2, 0.8, 1.5)).empty());
  // Blocker below the receiver.
  EXPECT_TRUE(AllSegments(kFloor, light, 1.0, SquareBlocker(0.2, 0.8, 0.2, 0.8, -0.5)).empty());
  // Blocker lying in the receiver plane.
  EXPECT_TRUE(AllSegments(kFloor, light, 1.0, SquareBlocker(0.2, 0.8, 0.2, 0.8, 0.0)).empty());
  // Receiver far from the shadow, which covers [-0.6, 1.6]^2 at most.
  const Domain away = { Vec3(3, 3, 0), Vec3(6, 3, 0), Vec3(3, 6, 0) };
  EXPECT_TRUE(AllSegments(away, light, 1.0, SquareBlocker(0.2, 0.8, 0.2, 0.8, 0.5)).empty());
  // Receiver between the blocker and the light: the wedges start beyond the blocker.
  const Domain between = { Vec3(-20, -10, 0.75), Vec3(20, -10, 0.75), Vec3(0, 30, 0.75) };
  EXPECT_TRUE(AllSegments(between, light, 1.0, SquareBlocker(0.2, 0.8, 0.2, 0.8, 0.5)).empty());
  // No blockers, and degenerate blocker edges (a point, and one collinear with a light vertex).
  EXPECT_TRUE(AllSegments(kFloor, light, 1.0, {}).empty());
  // A blocker edge collapsed to a point has no VE wedge but is a blocker
  // vertex: the shadows of the six light-triangle edges through it, each as
  // long as the edge (half way down).
  const std::vector<BlockerEdge> point = { { Vec3(0.5, 0.5, 0.5), Vec3(0.5, 0.5, 0.5) } };
  const auto fromPoint = AllSegments(kFloor, light, 1.0, point);
  EXPECT_EQ(fromPoint.size(), 6u);
  for (const auto& s : fromPoint)
  {
    const double len = glm::length(s.B - s.A);
    EXPECT_TRUE(Near(len, 1.0) || Near(len, std::sqrt(2.0))) << len;
  }
  // A blocker edge on a line through a light vertex: no NaN from the
  // degenerate wedge.
  ExpectFinite(AllSegments(kFloor, light, 1.0, { { Vec3(0.25, 0.25, 0.75), Vec3(0.5, 0.5, 0.5) } }));
  // A degenerate receiver.
  const Domain flat = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0) };
  std::vector<DiscontinuitySegment> out;
  FindCriticalSegments(flat, Vec3(0, 0, 1), light[0], 1.0, SquareBlocker(0.2, 0.8, 0.2, 0.8, 0.5), 0.0, out);
  EXPECT_TRUE(out.empty());
}

TEST(CriticalSurfaces, ReceiverClipping)
{
  // A receiver covering only x < 1 (with y in [-2, 2]): the VE segment on
  // y = 0.5 from (0.4, 0.5) to (1.6, 0.5) is cut at x = 1.
  const Domain part = { Vec3(-3, -2, 0), Vec3(1, -2, 0), Vec3(1, 2, 0) };
  std::vector<DiscontinuitySegment> out;
  FindCriticalSegments(part, Vec3(0, 0, 1), SquareLight(1.0)[0], 1.0,
    { { Vec3(0.2, 0.25, 0.5), Vec3(0.8, 0.25, 0.5) } }, 0.0, out);
  bool found = false;
  for (const auto& s : out)
  {
    EXPECT_LE(std::max(s.A.x, s.B.x), 1.0 + 1e-12);
    const double lo = std::min(s.A.x, s.B.x), hi = std::max(s.A.x, s.B.x);
    found = found || (Near(s.A.y, 0.5) && Near(s.B.y, 0.5) && Near(lo, 0.4) && Near(hi, 1.0));
  }
  EXPECT_TRUE(found);
}

TEST(CriticalSurfaces, ContactStaysFinite)
{
  // A post standing on the floor under the light, and a blocker edge touching
  // the floor at one end, and a blocker edge piercing the floor.
  const std::vector<BlockerEdge> contact = {
    { Vec3(0.5, 0.5, 0.0), Vec3(0.5, 0.5, 0.4) },
    { Vec3(0.5, 0.5, 0.4), Vec3(0.7, 0.5, 0.4) },
    { Vec3(0.7, 0.5, 0.4), Vec3(0.7, 0.5, 0.0) },
    { Vec3(0.2, 0.2, 0.0), Vec3(0.3, 0.6, 0.0) }, // in the floor: nothing
    { Vec3(0.1, 0.8, -0.2), Vec3(0.2, 0.8, 0.3) }, // pierces the floor
  };
  const auto segments = AllSegments(kFloor, SquareLight(1.0), 5.0, contact, 0.0);
  ASSERT_FALSE(segments.empty());
  ExpectFinite(segments);
  double largest = 0.0;
  for (const auto& s : segments)
  {
    EXPECT_GT(s.Weight, 0.0);
    EXPECT_LE(s.Weight, 5.0 * 1e6 * (1 + 1e-12));
    largest = std::max(largest, s.Weight);
  }
  // The contact shadow is the strongest discontinuity.
  EXPECT_NEAR(largest, 5.0 * 1e6, 1e-6);
  // The shadow line of the post starts at its foot.
  bool fromFoot = false;
  for (const auto& s : segments)
  {
    fromFoot = fromFoot || glm::length(s.A - Vec3(0.5, 0.5, 0)) < 1e-12 ||
      glm::length(s.B - Vec3(0.5, 0.5, 0)) < 1e-12;
  }
  EXPECT_TRUE(fromFoot);
  // A receiver triangle touching the light: finite too.
  const Domain wall = { Vec3(0, -1, 1.0), Vec3(0, 2, 1.0), Vec3(0, 0.5, -2.0) };
  std::vector<DiscontinuitySegment> out;
  for (const auto& s : SquareLight(1.0))
  {
    FindCriticalSegments(wall, Vec3(1, 0, 0), s, 1.0, SquareBlocker(0.2, 0.8, 0.2, 0.8, 0.5), 0.0, out);
  }
  ExpectFinite(out);
}

TEST(CriticalSurfaces, ScaleInvariance)
{
  // The whole configuration scaled and moved: positions scale, weights do not.
  const auto reference = AllSegments(kFloor, SquareLight(1.0), 1.0, SquareBlocker(0.2, 0.8, 0.25, 0.75, 0.5), 0.0);
  for (const double scale : { 1e4, 1e-4 })
  {
    for (const double offset : { 0.0, 1e4 })
    {
      const Vec3 o(offset, 2 * offset, -offset);
      auto map = [&](const Vec3& p) { return o + scale * p; };
      Domain floor;
      for (int i = 0; i < 3; ++i)
      {
        floor[i] = map(kFloor[i]);
      }
      std::array<Domain, 2> light = SquareLight(1.0);
      for (auto& t : light)
      {
        for (auto& p : t)
        {
          p = map(p);
        }
      }
      auto blocker = SquareBlocker(0.2, 0.8, 0.25, 0.75, 0.5);
      for (auto& e : blocker)
      {
        e.A = map(e.A);
        e.B = map(e.B);
      }
      const auto segments = AllSegments(floor, light, 1.0, blocker, 0.0);
      SCOPED_TRACE(testing::Message() << "scale " << scale << " offset " << offset);
      ASSERT_EQ(segments.size(), reference.size());
      const double tol = 1e-11 * scale + 1e-14 * glm::length(o);
      for (std::size_t i = 0; i < segments.size(); ++i)
      {
        // The input coordinates themselves are rounded at ulp(|o|): relative to
        // the configuration's size that is an error of ulp(|o|) / scale.
        EXPECT_NEAR(segments[i].Weight, reference[i].Weight, 1e-12 + 1e-14 * glm::length(o) / scale);
        EXPECT_LE(glm::length(segments[i].A - map(reference[i].A)), tol);
        EXPECT_LE(glm::length(segments[i].B - map(reference[i].B)), tol);
      }
    }
  }
}

TEST(CriticalSurfaces, SegmentsFeedTheTriangulation)
{
  // The two kernels together, as the mesher uses them: the segments on a
  // floor triangle constrain its triangulation.
  const Domain receiver = { Vec3(-1, -1, 0), Vec3(2, -1, 0), Vec3(-1, 2, 0) };
  std::vector<DiscontinuitySegment> segments;
  for (const auto& s : SquareLight(1.0))
  {
    FindCriticalSegments(receiver, Vec3(0, 0, 1), s, 1.0, SquareBlocker(0.2, 0.8, 0.25, 0.75, 0.5), 1e-6, segments);
  }
  ASSERT_FALSE(segments.empty());
  Segments constraints;
  for (const auto& s : segments)
  {
    constraints.push_back({ s.A, s.B });
  }
  const PlanarTriangulation t = TriangulateWithConstraints(receiver, constraints);
  ExpectValidTriangulation(receiver, t);
  // Many traces overlap (the EV and VE surfaces through one blocker edge
  // share a line): each is still a union of mesh edges between mesh vertices,
  // up to the welding tolerance.
  const double tol = 1e-9 * DomainScale(receiver);
  for (const auto& s : segments)
  {
    EXPECT_GE(FindVertex(t, s.A, tol), 0);
    EXPECT_GE(FindVertex(t, s.B, tol), 0);
    EXPECT_NEAR(LengthOfEdgesOn(t, s.A, s.B, tol), glm::length(s.B - s.A), 4 * tol);
  }
}

// ---------------------------------------------------------------------------
// Randomised checks against brute force

namespace
{
/// Closest distance between the segments [p0,p1] and [q0,q1] (Ericson,
/// Real-Time Collision Detection, 5.1.9), and the parameters there.
double SegmentSegmentDistance(
  const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1, double& s, double& t)
{
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
  const double c = glm::dot(d1, r), b = glm::dot(d1, d2);
  const double denom = a * e - b * b;
  s = denom > 1e-300 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
  t = (b * s + f) / e;
  if (t < 0.0)
  {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
  }
  else if (t > 1.0)
  {
    t = 1.0;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  return glm::length((p0 + s * d1) - (q0 + t * d2));
}

/// Whether m lies on one of the EV or VE wedges (brute force, by definition):
/// VE: the segment [v, m] meets the blocker edge; EV: the ray from m through
/// the blocker vertex meets the source edge beyond it.
bool OnSomeWedge(const Vec3& m, const Domain& source, const std::vector<BlockerEdge>& blocker, double tol)
{
  double s = 0.0, t = 0.0;
  for (const Vec3& v : source)
  {
    for (const auto& e : blocker)
    {
      if (SegmentSegmentDistance(v, m, e.A, e.B, s, t) < tol)
      {
        return true;
      }
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    for (const auto& e : blocker)
    {
      for (const Vec3& b : { e.A, e.B })
      {
        // The ray m -> b, long enough to pass the source.
        const Vec3 far = m + 100.0 * (b - m);
        if (SegmentSegmentDistance(m, far, source[i], source[(i + 1) % 3], s, t) < tol &&
          s >= 0.01 - 1e-12)
        {
          return true;
        }
      }
    }
  }
  return false;
}

/// Whether p lies in the triangle t, grown by `margin` (shrunk if negative),
/// and within 1e-9 of its plane.
bool InTriangle(const Vec3& p, const Domain& t, double margin)
{
  const Vec3 n = glm::normalize(glm::cross(t[1] - t[0], t[2] - t[0]));
  for (int e = 0; e < 3; ++e)
  {
    const Vec3 edge = t[(e + 1) % 3] - t[e];
    if (glm::dot(glm::cross(edge, p - t[e]), n) / glm::length(edge) < -margin)
    {
      return false;
    }
  }
  return std::abs(glm::dot(p - t[0], n)) <= 1e-9;
}

/// Random configurations: uniform numbers in [lo, hi), a source triangle
/// above (z in [1.5, 2.5]) and a receiver triangle around z = 0 (tilted).
struct RandomGeometry
{
  explicit RandomGeometry(unsigned seed)
    : Engine(seed)
  {
  }
  double operator()(double lo, double hi) { return lo + (hi - lo) * this->Unit(this->Engine); }
  Domain Source()
  {
    auto& rnd = *this;
    return { Vec3(rnd(-1, 1), rnd(-1, 1), rnd(1.5, 2.5)), Vec3(rnd(-1, 1), rnd(-1, 1), rnd(1.5, 2.5)),
      Vec3(rnd(-1, 1), rnd(-1, 1), rnd(1.5, 2.5)) };
  }
  Domain Receiver()
  {
    auto& rnd = *this;
    return { Vec3(rnd(-4, 0), rnd(-4, 0), rnd(-0.3, 0.3)), Vec3(rnd(0, 4), rnd(-4, 4), rnd(-0.3, 0.3)),
      Vec3(rnd(-4, 4), rnd(0, 4), rnd(-0.3, 0.3)) };
  }
  std::mt19937 Engine;
  std::uniform_real_distribution<double> Unit{ 0.0, 1.0 };
};

Vec3 UnitNormal(const Domain& t)
{
  return glm::normalize(glm::cross(t[1] - t[0], t[2] - t[0]));
}

double DistanceToSegments(const Vec3& p, const std::vector<DiscontinuitySegment>& segments)
{
  double best = std::numeric_limits<double>::infinity();
  for (const auto& s : segments)
  {
    best = std::min(best, PointSegmentDistance(p, s.A, s.B));
  }
  return best;
}
} // namespace

TEST(CriticalSurfaces, RandomConfigurationsMatchBruteForce)
{
  RandomGeometry rnd(12345);
  int checkedPoints = 0;
  for (int trial = 0; trial < 200; ++trial)
  {
    // Source above, receiver around z = 0 (tilted), blocker edges in between.
    const Domain source = rnd.Source();
    const Domain receiver = rnd.Receiver();
    const Vec3 normal = UnitNormal(receiver);
    std::vector<BlockerEdge> blocker;
    for (int k = 0; k < 3; ++k)
    {
      blocker.push_back({ Vec3(rnd(-1, 1), rnd(-1, 1), rnd(0.4, 1.2)), Vec3(rnd(-1, 1), rnd(-1, 1), rnd(0.4, 1.2)) });
    }
    std::vector<DiscontinuitySegment> out;
    FindCriticalSegments(receiver, trial % 2 ? normal : -normal, source, 1.0, blocker, 0.0, out);
    SCOPED_TRACE(testing::Message() << "trial " << trial);
    for (const auto& s : out)
    {
      ASSERT_TRUE(std::isfinite(s.Weight) && s.Weight > 0.0);
      EXPECT_TRUE(InTriangle(s.A, receiver, 1e-9));
      EXPECT_TRUE(InTriangle(s.B, receiver, 1e-9));
      EXPECT_TRUE(OnSomeWedge(0.5 * (s.A + s.B), source, blocker, 1e-9)) << "a segment on no wedge";
    }
    // Every trace point of every wedge on the receiver is covered: sample the
    // VE wedges by rays from a source vertex through the blocker edge, the EV
    // wedges by rays from a source edge through the blocker vertex.
    auto check = [&](const Vec3& from, const Vec3& through) {
      const Vec3 d = through - from;
      const double denom = glm::dot(normal, d);
      if (std::abs(denom) < 1e-12)
      {
        return;
      }
      const double lambda = glm::dot(normal, receiver[0] - from) / denom;
      const Vec3 hit = from + lambda * d;
      if (lambda >= 1.0 && InTriangle(hit, receiver, -1e-9))
      {
        ++checkedPoints;
        EXPECT_LT(DistanceToSegments(hit, out), 1e-9) << "a trace point not covered";
      }
    };
    for (int k = 0; k <= 20; ++k)
    {
      const double u = k / 20.0;
      for (const auto& e : blocker)
      {
        for (const Vec3& v : source)
        {
          check(v, e.A + u * (e.B - e.A));
        }
        for (int i = 0; i < 3; ++i)
        {
          for (const Vec3& b : { e.A, e.B })
          {
            check(source[i] + u * (source[(i + 1) % 3] - source[i]), b);
          }
        }
      }
    }
  }
  EXPECT_GT(checkedPoints, 1000);
}

// The surfaces a bound on H&T's weight skips (blocker vertices below every
// source vertex: w <= B (max h_s - h_b)/h_b) are exactly those below w_min:
// with w_min the search finds what the full search keeps at w_min, in the
// same order, to the bit.
TEST(CriticalSurfaces, MinimumWeightSkipsOnlyWhatItWouldDrop)
{
  RandomGeometry rnd(2101);
  std::size_t dropped = 0, kept = 0;
  for (int trial = 0; trial < 400; ++trial)
  {
    const Domain source = rnd.Source();
    const Domain receiver = rnd.Receiver();
    const Vec3 normal = UnitNormal(receiver);
    std::vector<BlockerEdge> blocker;
    for (int k = 0; k < 4; ++k)
    {
      // Mostly between the two, some through the receiver's plane (contact).
      const double low = trial % 5 == 0 ? -0.2 : 0.4;
      blocker.push_back({ Vec3(rnd(-1, 1), rnd(-1, 1), rnd(low, 1.4)), Vec3(rnd(-1, 1), rnd(-1, 1), rnd(low, 1.4)) });
    }
    const double radiosity = rnd(0.1, 10.0);
    std::vector<DiscontinuitySegment> all;
    FindCriticalSegments(receiver, normal, source, radiosity, blocker, 0.0, all);
    if (all.empty())
    {
      continue;
    }
    std::vector<double> weights;
    for (const auto& s : all)
    {
      weights.push_back(s.Weight);
    }
    std::sort(weights.begin(), weights.end());
    for (double quantile : { 0.25, 0.5, 0.9 })
    {
      const double minWeight = weights[static_cast<std::size_t>(quantile * static_cast<double>(weights.size() - 1))];
      std::vector<DiscontinuitySegment> expected;
      for (const auto& s : all)
      {
        if (s.Weight >= minWeight)
        {
          expected.push_back(s);
        }
      }
      std::vector<DiscontinuitySegment> found;
      FindCriticalSegments(receiver, normal, source, radiosity, blocker, 0.0, found, { true, true, true }, minWeight);
      SCOPED_TRACE(testing::Message() << "trial " << trial << ", w_min " << minWeight);
      ASSERT_EQ(found.size(), expected.size());
      for (std::size_t k = 0; k < found.size(); ++k)
      {
        EXPECT_EQ(found[k].A, expected[k].A);
        EXPECT_EQ(found[k].B, expected[k].B);
        EXPECT_EQ(found[k].Weight, expected[k].Weight);
      }
      dropped += all.size() - expected.size();
      kept += expected.size();
    }
  }
  // The configurations exercise both sides of w_min.
  EXPECT_GT(dropped, 1000u);
  EXPECT_GT(kept, 1000u);
}
