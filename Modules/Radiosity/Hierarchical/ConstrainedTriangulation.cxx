// Constrained Delaunay triangulation of a leaf triangle with discontinuity
// segments as constraints (Hardt & Teller, section 2.1 and 4: the k strongest
// EV/VE discontinuities of a quadtree leaf become the constraints of its
// explicit mesh).
//
// The domain is mapped isometrically to 2D,
//   x = (X - D0) . ex,  y = (X - D0) . ey,
//   ex = (D1 - D0)/|D1 - D0|,  ey = (n x ex)/|n x ex|,  n = (D1 - D0) x (D2 - D0),
// so that the image of the domain is counter-clockwise (D2 has y > 0) and
// CGAL's counter-clockwise faces map back to triangles whose right-hand
// normal is n. Points off the plane are projected orthogonally onto it.
//
// Robustness follows the usual split (Shewchuk 1997; CGAL's Epeck): segment
// clipping and snapping are done in double precision, with a tolerance tied
// to the domain's size, and every decision the triangulation makes afterwards
// (orientation, in-circle, intersection of crossing constraints) is exact.
// Snapping makes the exact input consistent with the intent of the double
// input: an endpoint that is meant to lie on a domain edge is constructed
// exactly on that edge (D_i + t (D_{i+1} - D_i) with exact arithmetic), so no
// needle triangle separates it from the boundary and no point ends up outside
// the convex domain, whose edges are constrained: hence every finite face of
// the triangulation lies inside the domain and together they cover it.
//
// CGAL stays in this translation unit only (DESIGN.md: compile time).
#include "Radiosity/Hierarchical/ConstrainedTriangulation.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>

namespace radiosity
{
namespace constrained_triangulation_detail
{
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Kernel>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_intersections_tag>;
// The "plus" layer remembers the input constraints, so that the intersection
// of two constraints is constructed from the input segments, not from pieces
// already produced by earlier intersections (no cascading constructions).
using CdtPlus = CGAL::Constrained_triangulation_plus_2<Cdt>;
using Point2 = Kernel::Point_2;
using Vec2 = glm::dvec2;

/// Relative size (to the domain's longest edge) below which a clipped segment
/// is dropped and within which an endpoint is snapped onto a domain edge or
/// corner, or welded to an endpoint already inserted.
constexpr double kRelativeTolerance = 1e-9;
/// ... but at least this many units in the last place of the domain's largest
/// coordinate (a domain of 1e-4 m at 1e4 m from the origin).
constexpr double kUlpTolerance = 64.0;

/// A constraint endpoint: its double image (for tolerance tests), its exact
/// position (what CGAL sees) and the domain edges it lies on exactly (bit i:
/// edge from corner i to corner i+1).
struct Endpoint
{
  Vec2 Approx;
  Point2 Exact;
  unsigned EdgeMask = 0;
};

struct Domain2
{
  std::array<Vec2, 3> Corner;
  std::array<Vec2, 3> InwardNormal; ///< unit, of edge i (corner i to corner i+1)
  std::array<double, 3> EdgeLength;
  std::array<Point2, 3> ExactCorner;

  double SignedDistance(int edge, const Vec2& p) const
  {
    return glm::dot(this->InwardNormal[edge], p - this->Corner[edge]);
  }
};

/// Liang-Barsky clipping of p + t (q - p), t in [0,1], to the closed domain.
bool ClipToDomain(const Domain2& d, Vec2& p, Vec2& q)
{
  double t0 = 0.0, t1 = 1.0;
  for (int e = 0; e < 3; ++e)
  {
    const double dp = d.SignedDistance(e, p);
    const double dq = d.SignedDistance(e, q);
    if (dp < 0.0 && dq < 0.0)
    {
      return false;
    }
    if (dp < 0.0)
    {
      t0 = std::max(t0, dp / (dp - dq));
    }
    else if (dq < 0.0)
    {
      t1 = std::min(t1, dp / (dp - dq));
    }
  }
  if (!(t0 <= t1))
  {
    return false;
  }
  const Vec2 dir = q - p;
  const Vec2 a = p + t0 * dir;
  const Vec2 b = p + t1 * dir;
  p = a;
  q = b;
  return true;
}

/// Snaps a point of the (closed) domain: within `tol` of two edges it becomes
/// their common corner, within `tol` of one edge it is projected exactly onto
/// that edge, otherwise it stays (it is then inside by more than `tol`).
Endpoint Snap(const Domain2& d, const Vec2& p, double tol)
{
  std::array<double, 3> dist{};
  unsigned near = 0;
  int count = 0;
  for (int e = 0; e < 3; ++e)
  {
    dist[e] = d.SignedDistance(e, p);
    if (dist[e] < tol)
    {
      near |= 1u << e;
      ++count;
    }
  }
  // Corner i lies on edges i and i-1.
  auto corner = [&](int i) {
    return Endpoint{ d.Corner[i], d.ExactCorner[i], (1u << i) | (1u << ((i + 2) % 3)) };
  };
  if (count >= 2)
  {
    // The two nearest edges meet at the corner nearest to p.
    int far = 0;
    for (int e = 1; e < 3; ++e)
    {
      if (dist[e] > dist[far])
      {
        far = e;
      }
    }
    // The corner opposite to edge `far` is corner far+2.
    return corner((far + 2) % 3);
  }
  if (count == 1)
  {
    const int e = near == 1u ? 0 : (near == 2u ? 1 : 2);
    const Vec2 a = d.Corner[e];
    const Vec2 b = d.Corner[(e + 1) % 3];
    const double len = d.EdgeLength[e];
    const double s = glm::dot(p - a, b - a) / len; // arc length along the edge
    if (s < tol)
    {
      return corner(e);
    }
    if (s > len - tol)
    {
      return corner((e + 1) % 3);
    }
    const double t = s / len;
    const Point2& ea = d.ExactCorner[e];
    const Point2& eb = d.ExactCorner[(e + 1) % 3];
    return Endpoint{ a + t * (b - a), ea + Kernel::FT(t) * (eb - ea), 1u << e };
  }
  return Endpoint{ p, Point2(p.x, p.y), 0u };
}

bool IsFinite(const Vec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

PlanarTriangulation DomainOnly(const std::array<Vec3, 3>& domain)
{
  PlanarTriangulation result;
  result.Points.assign(domain.begin(), domain.end());
  result.Triangles.push_back({ 0u, 1u, 2u });
  return result;
}
} // namespace constrained_triangulation_detail

PlanarTriangulation TriangulateWithConstraints(const std::array<Vec3, 3>& domain,
  const std::vector<std::array<Vec3, 2>>& constraints, const std::vector<Vec3>& boundaryPoints)
{
  namespace detail = constrained_triangulation_detail;
  using detail::Vec2;

  const Vec3 origin = domain[0];
  const Vec3 e01 = domain[1] - origin;
  const Vec3 e02 = domain[2] - origin;
  const double longest = std::max(
    { glm::length(e01), glm::length(e02), glm::length(domain[2] - domain[1]) });
  const Vec3 normal = glm::cross(e01, e02);
  const double normalLength = glm::length(normal);
  // A degenerate or non-finite domain has no plane to triangulate in.
  if (!detail::IsFinite(domain[0]) || !detail::IsFinite(domain[1]) ||
    !detail::IsFinite(domain[2]) || !(longest > 0.0) || !std::isfinite(normalLength) ||
    !(normalLength > 1e-14 * longest * longest))
  {
    return detail::DomainOnly(domain);
  }

  const Vec3 ex = glm::normalize(e01);
  const Vec3 ey = glm::normalize(glm::cross(normal / normalLength, ex));
  auto to2 = [&](const Vec3& p) {
    const Vec3 r = p - origin;
    return Vec2(glm::dot(r, ex), glm::dot(r, ey));
  };

  detail::Domain2 d;
  d.Corner = { Vec2(0.0, 0.0), Vec2(glm::length(e01), 0.0), to2(domain[2]) };
  for (int e = 0; e < 3; ++e)
  {
    const Vec2 a = d.Corner[e];
    const Vec2 b = d.Corner[(e + 1) % 3];
    d.EdgeLength[e] = glm::length(b - a);
    d.InwardNormal[e] = Vec2(-(b.y - a.y), b.x - a.x) / d.EdgeLength[e];
    d.ExactCorner[e] = detail::Point2(a.x, a.y);
  }
  // The output is rounded to doubles at the domain's absolute position, so
  // features finer than a few ulps of its coordinates would come out folded:
  // far from the origin the tolerance grows to keep clear of that.
  double magnitude = 0.0;
  for (const Vec3& p : domain)
  {
    magnitude = std::max({ magnitude, std::abs(p.x), std::abs(p.y), std::abs(p.z) });
  }
  const double tol = std::max(detail::kRelativeTolerance * longest,
    detail::kUlpTolerance * std::numeric_limits<double>::epsilon() * magnitude);

  // Clip, snap and weld in double precision; keep the exact endpoints.
  std::vector<detail::Endpoint> points;
  for (int i = 0; i < 3; ++i)
  {
    points.push_back(
      detail::Endpoint{ d.Corner[i], d.ExactCorner[i], (1u << i) | (1u << ((i + 2) % 3)) });
  }
  std::vector<std::array<std::size_t, 2>> segments;

  // Distance from x to the segment ab, and the parameter of x's projection.
  auto project = [](const Vec2& x, const Vec2& a, const Vec2& b, double& t) {
    const Vec2 ab = b - a;
    t = glm::dot(x - a, ab) / glm::dot(ab, ab);
    return glm::length(x - (a + std::clamp(t, 0.0, 1.0) * ab));
  };
  // Near-coincidences in the input are resolved before the exact
  // triangulation sees them, for otherwise it would faithfully build
  // triangles as thin as the rounding errors of the critical-surface
  // computation (collinear EV and VE traces that share a line only up to
  // rounding, endpoints computed twice by different formulas). An endpoint
  //  - within `tol` of a point already kept becomes that point, provided the
  //    kept one lies on every domain edge the new one lies on;
  //  - else, within `tol` of a kept segment, is moved exactly onto it (the
  //    triangulation then splits that segment there).
  auto resolve = [&](detail::Endpoint p) -> std::size_t {
    for (std::size_t k = 0; k < points.size(); ++k)
    {
      if ((p.EdgeMask & ~points[k].EdgeMask) == 0u &&
        glm::length(points[k].Approx - p.Approx) < tol)
      {
        return k;
      }
    }
    if (p.EdgeMask == 0u)
    {
      for (const auto& s : segments)
      {
        const detail::Endpoint& a = points[s[0]];
        const detail::Endpoint& b = points[s[1]];
        double t = 0.0;
        if (project(p.Approx, a.Approx, b.Approx, t) < tol && t > 0.0 && t < 1.0)
        {
          p.Approx = a.Approx + t * (b.Approx - a.Approx);
          p.Exact = a.Exact + detail::Kernel::FT(t) * (b.Exact - a.Exact);
          break;
        }
      }
    }
    points.push_back(p);
    return points.size() - 1;
  };
  // A new segment passing within `tol` of a kept point goes through it.
  auto addSegment = [&](std::size_t ip, std::size_t iq) {
    std::vector<std::pair<double, std::size_t>> through;
    for (std::size_t k = 0; k < points.size(); ++k)
    {
      double t = 0.0;
      if (k != ip && k != iq &&
        project(points[k].Approx, points[ip].Approx, points[iq].Approx, t) < tol && t > 0.0 &&
        t < 1.0)
      {
        through.emplace_back(t, k);
      }
    }
    std::sort(through.begin(), through.end());
    std::size_t from = ip;
    through.emplace_back(1.0, iq);
    for (const auto& [t, k] : through)
    {
      if (k != from && (points[k].EdgeMask & points[from].EdgeMask) == 0u)
      {
        segments.push_back({ from, k });
      }
      from = k;
    }
  };

  for (const auto& c : constraints)
  {
    if (!detail::IsFinite(c[0]) || !detail::IsFinite(c[1]))
    {
      continue;
    }
    Vec2 p = to2(c[0]);
    Vec2 q = to2(c[1]);
    if (!detail::ClipToDomain(d, p, q) || !(glm::length(q - p) >= tol))
    {
      continue;
    }
    const detail::Endpoint sp = detail::Snap(d, p, tol);
    const detail::Endpoint sq = detail::Snap(d, q, tol);
    // Both ends on one domain edge: the segment is (part of) that edge, which
    // is a constraint already.
    if ((sp.EdgeMask & sq.EdgeMask) != 0u || !(glm::length(sq.Approx - sp.Approx) >= tol))
    {
      continue;
    }
    const std::size_t ip = resolve(sp);
    const std::size_t iq = resolve(sq);
    if (ip != iq && (points[ip].EdgeMask & points[iq].EdgeMask) == 0u)
    {
      addSegment(ip, iq);
    }
  }
  // Vertices of neighbours on the edges: snapped exactly onto their edge.
  std::vector<std::size_t> onEdges;
  for (const Vec3& b : boundaryPoints)
  {
    if (!detail::IsFinite(b))
    {
      continue;
    }
    const detail::Endpoint e = detail::Snap(d, to2(b), tol);
    const unsigned m = e.EdgeMask;
    if (m == 1u || m == 2u || m == 4u) // on exactly one edge: not a corner, not inside
    {
      onEdges.push_back(resolve(e));
    }
  }
  if (segments.empty() && onEdges.empty())
  {
    return detail::DomainOnly(domain);
  }

  PlanarTriangulation result;
  try
  {
    detail::CdtPlus cdt;
    std::array<detail::CdtPlus::Vertex_handle, 3> corners;
    for (int i = 0; i < 3; ++i)
    {
      corners[i] = cdt.insert(d.ExactCorner[i]);
    }
    for (int i = 0; i < 3; ++i)
    {
      cdt.insert_constraint(corners[i], corners[(i + 1) % 3]);
    }
    for (std::size_t k : onEdges)
    {
      cdt.insert(points[k].Exact); // splits the constrained domain edge there
    }
    for (const auto& s : segments)
    {
      cdt.insert_constraint(points[s[0]].Exact, points[s[1]].Exact);
    }

    constexpr std::uint32_t unset = std::numeric_limits<std::uint32_t>::max();
    for (auto v : cdt.finite_vertex_handles())
    {
      v->info() = unset;
    }
    result.Points.assign(domain.begin(), domain.end());
    for (int i = 0; i < 3; ++i)
    {
      corners[i]->info() = static_cast<std::uint32_t>(i);
    }
    for (auto v : cdt.finite_vertex_handles())
    {
      if (v->info() == unset)
      {
        v->info() = static_cast<std::uint32_t>(result.Points.size());
        const double x = CGAL::to_double(v->point().x());
        const double y = CGAL::to_double(v->point().y());
        result.Points.push_back(origin + x * ex + y * ey);
      }
    }
    result.Triangles.reserve(cdt.number_of_faces());
    for (auto f : cdt.finite_face_handles())
    {
      result.Triangles.push_back({ f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info() });
    }
  }
  catch (const std::exception&)
  {
    // CGAL reports violated preconditions by throwing; exact predicates make
    // that unexpected here, and the unconstrained domain is still a valid
    // (coarser) mesh of the leaf, flagged so that the loss is reported.
    PlanarTriangulation fallback = detail::DomainOnly(domain);
    fallback.ConstraintsDropped = true;
    return fallback;
  }
  return result;
}
} // namespace radiosity
