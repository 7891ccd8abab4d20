// EV and VE critical surfaces traced on a receiver triangle, with the
// Hardt & Teller (section 4.2) weight. See CriticalSurfaces.h for the
// definitions; this file holds the geometry.
//
// Both kinds of surface are the same convex planar region, a cone with apex O
// spanned by the directions D(u) = D0 + u (D1 - D0), u in [0,1]:
//   VE (source vertex v, blocker edge ab):  O = v, D(u) = a + u (b - a) - v,
//        points O + s D(u) with s >= 1 (beyond the blocker edge);
//   EV (source edge pq, blocker vertex b):  O = b, D(u) = b - (p + u (q - p)),
//        points O + s D(u) with s >= 0 (beyond the blocker vertex).
// Its plane has normal m = D0 x D1. In that plane the region is the
// intersection of the half-planes
//   (m x D0) . (X - O) >= 0,  (D1 x m) . (X - O) >= 0          (the two rays)
// and, for VE, (m x (b - a)) . (X - a) <= 0                    (beyond ab),
// each of them valid because the cone's opening is below pi (m != 0).
// The receiver plane cuts the region's plane in a line X(t) = P + t dir,
// dir = m x n_r; every half-plane, and each of the three edge half-planes of
// the receiver triangle, is affine in t, so the trace on the receiver is the
// interval of t left after clipping against all of them (Liang-Barsky).
// That is exact geometry; the only tolerances are for deciding that two
// planes are parallel or that a wedge is degenerate.
//
// The computation runs in coordinates centred on the receiver (the local
// origin is its centroid), so that a scene 1e4 m from the world origin loses
// no more digits than one at the origin.
#include "Radiosity/Hierarchical/CriticalSurfaces.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace radiosity
{
namespace critical_surfaces_detail
{
/// d_sb / d_br for a blocker vertex touching the receiver (d_br -> 0): the
/// heuristic's limit is infinite, a contact shadow being the strongest
/// discontinuity there is; a large finite value keeps the ranking meaningful
/// and the arithmetic free of Inf/NaN.
constexpr double kContactRatioCap = 1e6;

/// |sin| of the angle between the wedge plane and the receiver plane below
/// which they are taken as parallel (the trace is then at infinity, or the
/// wedge lies in the receiver plane, where it is no curve).
constexpr double kParallelSine = 1e-9;

/// |sin| of the wedge's opening angle below which the wedge is degenerate
/// (the source vertex on the blocker edge's line, or the blocker vertex on the
/// source edge's line): it spans no plane.
constexpr double kDegenerateSine = 1e-12;

struct HalfPlane
{
  Vec3 Point;
  Vec3 Normal; ///< unit; keeps X with Normal . (X - Point) >= 0
};

struct Receiver
{
  std::array<Vec3, 3> Corner; ///< local coordinates
  Vec3 Normal;                ///< unit normal of the receiver plane
  std::array<HalfPlane, 3> Edge;
  double Tolerance; ///< a length small against the scene
  /// A plane farther than this from every corner misses the receiver, however
  /// the trace rounds (far above Tolerance, far below any element).
  double PlaneMargin;
};

bool IsFinite(const Vec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// Keeps the t with c + g t >= 0 in [t0, t1]; false when nothing is left.
bool ClipInterval(double c, double g, double tol, double& t0, double& t1)
{
  if (std::abs(g) < 1e-15)
  {
    return c >= -tol;
  }
  const double t = -c / g;
  if (g > 0.0)
  {
    t0 = std::max(t0, t);
  }
  else
  {
    t1 = std::min(t1, t);
  }
  return t0 <= t1;
}

/// The trace on the receiver triangle of the planar convex region through
/// `planePoint` with unit normal `planeNormal`, bounded by `halfPlanes`.
bool TraceOnReceiver(const Receiver& r, const Vec3& planePoint, const Vec3& planeNormal,
  const HalfPlane* halfPlanes, int count, Vec3& a, Vec3& b)
{
  const Vec3 u = glm::cross(planeNormal, r.Normal);
  const double sine = glm::length(u);
  if (!(sine > kParallelSine))
  {
    return false;
  }
  // The point of the line nearest to the local origin (which lies in the
  // receiver plane, so d2 is a rounding error away from 0):
  //   P = (d1 (n2 x u) + d2 (u x n1)) / |u|^2,  d_i = n_i . X_i.
  const double d1 = glm::dot(planeNormal, planePoint);
  const double d2 = glm::dot(r.Normal, r.Corner[0]);
  const Vec3 p = (d1 * glm::cross(r.Normal, u) + d2 * glm::cross(u, planeNormal)) / (sine * sine);
  const Vec3 dir = u / sine;

  double t0 = -std::numeric_limits<double>::infinity();
  double t1 = std::numeric_limits<double>::infinity();
  for (int i = 0; i < count; ++i)
  {
    const HalfPlane& h = halfPlanes[i];
    if (!ClipInterval(glm::dot(h.Normal, p - h.Point), glm::dot(h.Normal, dir), r.Tolerance, t0, t1))
    {
      return false;
    }
  }
  for (const HalfPlane& h : r.Edge)
  {
    if (!ClipInterval(glm::dot(h.Normal, p - h.Point), glm::dot(h.Normal, dir), r.Tolerance, t0, t1))
    {
      return false;
    }
  }
  if (!std::isfinite(t0) || !std::isfinite(t1))
  {
    return false;
  }
  a = p + t0 * dir;
  b = p + t1 * dir;
  return true;
}

/// d_sb / d_br for the line from source vertex `s` through blocker vertex
/// `bv`, or a negative value when that line does not meet the receiver plane
/// beyond the blocker. With X = s + lambda (bv - s) on the plane,
/// d_br / d_sb = lambda - 1, whatever the scale.
double PairRatio(const Receiver& r, const Vec3& s, const Vec3& bv)
{
  const Vec3 d = bv - s;
  const double dl = glm::length(d);
  const double denom = glm::dot(r.Normal, d);
  if (!(dl > 0.0) || !(std::abs(denom) > 1e-12 * dl))
  {
    return -1.0;
  }
  const double beyond = glm::dot(r.Normal, r.Corner[0] - s) / denom - 1.0;
  if (!(beyond > -1e-9))
  {
    return -1.0;
  }
  return 1.0 / std::max(beyond, 1.0 / kContactRatioCap);
}

/// The Hardt-Teller geometric factor max(d_sb/d_br) over the given pairs.
/// When the wedge reaches the receiver but no pair's line does beyond its
/// blocker vertex, the blocker itself touches or pierces the receiver plane:
/// a contact, weighted by the cap.
double GeometricFactor(const Receiver& r, const Vec3& s0, const Vec3& b0, const Vec3& s1, const Vec3& b1)
{
  const double w = std::max(PairRatio(r, s0, b0), PairRatio(r, s1, b1));
  return w > 0.0 ? w : kContactRatioCap;
}

/// The cone with apex `apex` spanned by d0 and d1, as a plane and two
/// half-planes; false when it is degenerate or its plane misses the receiver.
bool ConeHalfPlanes(
  const Receiver& r, const Vec3& apex, const Vec3& d0, const Vec3& d1, Vec3& normal, HalfPlane* hp)
{
  const Vec3 m = glm::cross(d0, d1);
  // Most wedges pass beside the receiver: its three corners on one side of
  // the wedge's plane, farther than any rounding of the trace, leave nothing
  // to trace (the half-planes below are not needed then). Tested first, on
  // squares (no square root for the wedges that miss): a degenerate wedge
  // (m near 0) passes this test and fails the next.
  const double margin2 = r.PlaneMargin * r.PlaneMargin * glm::dot(m, m);
  const double s0 = glm::dot(m, r.Corner[0] - apex);
  const double s1 = glm::dot(m, r.Corner[1] - apex);
  const double s2 = glm::dot(m, r.Corner[2] - apex);
  const bool beyond = s0 * s0 > margin2 && s1 * s1 > margin2 && s2 * s2 > margin2;
  if (beyond && ((s0 > 0.0 && s1 > 0.0 && s2 > 0.0) || (s0 < 0.0 && s1 < 0.0 && s2 < 0.0)))
  {
    return false;
  }
  const double ml = glm::length(m);
  if (!(ml > kDegenerateSine * glm::length(d0) * glm::length(d1)))
  {
    return false;
  }
  normal = m / ml;
  hp[0] = HalfPlane{ apex, glm::normalize(glm::cross(normal, d0)) };
  hp[1] = HalfPlane{ apex, glm::normalize(glm::cross(d1, normal)) };
  return true;
}

void Emit(const Vec3& a, const Vec3& b, double weight, const Vec3& origin, double minLength,
  double tolerance, std::vector<DiscontinuitySegment>& out)
{
  const double len = glm::length(b - a);
  if (!(len >= minLength) || !(len > tolerance) || !std::isfinite(weight))
  {
    return;
  }
  DiscontinuitySegment seg;
  seg.A = a + origin;
  seg.B = b + origin;
  seg.Weight = weight;
  out.push_back(seg);
}
} // namespace critical_surfaces_detail

void FindCriticalSegments(const std::array<Vec3, 3>& receiver, const Vec3& receiverNormal,
  const std::array<Vec3, 3>& source, double sourceRadiosity,
  const std::vector<BlockerEdge>& blockerEdges, double minLength,
  std::vector<DiscontinuitySegment>& out, const std::array<bool, 3>& sourceEdges, double minWeight)
{
  namespace detail = critical_surfaces_detail;
  for (const Vec3& p : receiver)
  {
    if (!detail::IsFinite(p))
    {
      return;
    }
  }
  for (const Vec3& p : source)
  {
    if (!detail::IsFinite(p))
    {
      return;
    }
  }
  if (blockerEdges.empty())
  {
    return;
  }

  const Vec3 origin = (receiver[0] + receiver[1] + receiver[2]) / 3.0;
  detail::Receiver r;
  for (int i = 0; i < 3; ++i)
  {
    r.Corner[i] = receiver[i] - origin;
  }
  const Vec3 triangleNormal = glm::cross(r.Corner[1] - r.Corner[0], r.Corner[2] - r.Corner[0]);
  const double triangleNormalLength = glm::length(triangleNormal);
  double scale = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    scale = std::max({ scale, glm::length(r.Corner[i]), glm::length(source[i] - origin) });
  }
  if (!(triangleNormalLength > 1e-14 * scale * scale))
  {
    return; // a degenerate receiver has no interior to carry a curve
  }
  const Vec3 nT = triangleNormal / triangleNormalLength;
  const double givenLength = glm::length(receiverNormal);
  r.Normal = (givenLength > 0.0 && std::isfinite(givenLength)) ? receiverNormal / givenLength : nT;
  r.Tolerance = 1e-12 * scale;
  r.PlaneMargin = 1e-9 * scale;
  for (int i = 0; i < 3; ++i)
  {
    const Vec3 edge = r.Corner[(i + 1) % 3] - r.Corner[i];
    r.Edge[i] = detail::HalfPlane{ r.Corner[i], glm::normalize(glm::cross(nT, edge)) };
  }

  std::array<Vec3, 3> src;
  for (int i = 0; i < 3; ++i)
  {
    src[i] = source[i] - origin;
  }
  // Per thread, kept between calls (one per leaf and source).
  thread_local std::vector<std::array<Vec3, 2>> edges;
  thread_local std::vector<Vec3> vertices;
  edges.clear();
  vertices.clear();
  for (const BlockerEdge& e : blockerEdges)
  {
    if (detail::IsFinite(e.A) && detail::IsFinite(e.B))
    {
      edges.push_back({ e.A - origin, e.B - origin });
      vertices.push_back(e.A);
      vertices.push_back(e.B);
    }
  }
  // Distinct blocker vertices: an endpoint shared by several edges spans one
  // EV surface per source edge, not one per edge it belongs to.
  // (A lambda, so that the comparison is inlined: a function pointer is not.)
  std::sort(vertices.begin(), vertices.end(), [](const Vec3& a, const Vec3& b) { return LexLess(a, b); });
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  for (Vec3& v : vertices)
  {
    v -= origin;
  }

  // A blocker element lying in the receiver plane traces its own outline at
  // best, and only through rounding: it is left out (contact with the
  // receiver is seen through elements that leave the plane).
  const auto height = [&](const Vec3& p) { return glm::dot(r.Normal, p - r.Corner[0]); };
  const double planeTolerance = 1e-9 * scale;
  auto inReceiverPlane = [&](const Vec3& p) { return std::abs(height(p)) <= planeTolerance; };

  // H&T's weight of a surface is the larger of its two pairs' d_sb/d_br
  // (PairRatio) times the source's radiosity. With the heights h above the
  // receiver's plane, a pair whose line reaches the receiver has
  // d_sb/d_br = (h_s - h_b)/h_b; when every pair's blocker vertex lies below
  // every source vertex (so one pair of each surface reaches it, and no
  // weight is the contact's cap), the surfaces of blocker vertices no lower
  // than hb weigh at most B (max h_s - hb)/hb: below w_min, they are not
  // searched. The margin (0.1%) is far above PairRatio's rounding.
  double sourceLow = std::numeric_limits<double>::infinity(), sourceHigh = -sourceLow;
  for (const Vec3& p : src)
  {
    sourceLow = std::min(sourceLow, height(p));
    sourceHigh = std::max(sourceHigh, height(p));
  }
  const auto belowMinWeight = [&](double blockerLow) {
    if (!(minWeight > 0.0) || !(sourceLow > 0.0) || !(blockerLow > 0.0) || !(blockerLow < sourceLow * (1.0 - 1e-9)))
    {
      return false;
    }
    const double ratio = (sourceHigh - blockerLow) / blockerLow;
    return ratio < 1e-3 * detail::kContactRatioCap && sourceRadiosity * ratio * 1.001 < minWeight;
  };

  Vec3 a, b, planeNormal;
  detail::HalfPlane hp[3];

  // VE: source vertex v, blocker edge (ea, eb).
  for (const auto& e : edges)
  {
    if (inReceiverPlane(e[0]) && inReceiverPlane(e[1]))
    {
      continue;
    }
    if (belowMinWeight(std::min(height(e[0]), height(e[1]))))
    {
      continue;
    }
    const Vec3 edgeDir = e[1] - e[0];
    for (const Vec3& v : src)
    {
      if (!detail::ConeHalfPlanes(r, v, e[0] - v, e[1] - v, planeNormal, hp))
      {
        continue;
      }
      const double w = detail::GeometricFactor(r, v, e[0], v, e[1]) * sourceRadiosity;
      if (!(w >= minWeight))
      {
        continue;
      }
      // Beyond the blocker edge as seen from v: (m x (b - a)) . (X - a) <= 0.
      hp[2] = detail::HalfPlane{ e[0], -glm::normalize(glm::cross(planeNormal, edgeDir)) };
      if (!detail::TraceOnReceiver(r, v, planeNormal, hp, 3, a, b))
      {
        continue;
      }
      detail::Emit(a, b, w, origin, minLength, r.Tolerance, out);
    }
  }

  // EV: source edge (p, q), blocker vertex bv.
  for (const Vec3& bv : vertices)
  {
    if (inReceiverPlane(bv) || belowMinWeight(height(bv)))
    {
      continue;
    }
    for (int i = 0; i < 3; ++i)
    {
      if (!sourceEdges[i])
      {
        continue;
      }
      const Vec3& p = src[i];
      const Vec3& q = src[(i + 1) % 3];
      if (!detail::ConeHalfPlanes(r, bv, bv - p, bv - q, planeNormal, hp))
      {
        continue;
      }
      const double w = detail::GeometricFactor(r, p, bv, q, bv) * sourceRadiosity;
      if (!(w >= minWeight))
      {
        continue;
      }
      if (!detail::TraceOnReceiver(r, bv, planeNormal, hp, 2, a, b))
      {
        continue;
      }
      detail::Emit(a, b, w, origin, minLength, r.Tolerance, out);
    }
  }
}
} // namespace radiosity
