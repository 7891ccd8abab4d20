#include "Radiosity/Backprojection.h"

#include "Radiosity/FormFactor.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace radiosity
{
namespace
{
struct Point2
{
  double X, Y;
};
using Polygon2 = std::vector<Point2>;

double Cross(const Point2& o, const Point2& a, const Point2& b)
{
  return (a.X - o.X) * (b.Y - o.Y) - (a.Y - o.Y) * (b.X - o.X);
}

double SignedArea(const Polygon2& p)
{
  double a = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
  {
    const Point2& u = p[i];
    const Point2& v = p[(i + 1) % p.size()];
    a += u.X * v.Y - v.X * u.Y;
  }
  return 0.5 * a;
}

// Sutherland-Hodgman against the half-plane on the `keepLeft` side of a->b.
Polygon2 ClipHalfPlane(const Polygon2& in, const Point2& a, const Point2& b, bool keepLeft)
{
  Polygon2 out;
  out.reserve(in.size() + 1);
  const double s = keepLeft ? 1.0 : -1.0;
  for (std::size_t i = 0; i < in.size(); ++i)
  {
    const Point2& p = in[i];
    const Point2& q = in[(i + 1) % in.size()];
    const double dp = s * Cross(a, b, p);
    const double dq = s * Cross(a, b, q);
    if (dp >= 0)
    {
      out.push_back(p);
    }
    if ((dp >= 0) != (dq >= 0))
    {
      const double t = dp / (dp - dq);
      out.push_back({ p.X + t * (q.X - p.X), p.Y + t * (q.Y - p.Y) });
    }
  }
  return out;
}

// Clip of a 3D polygon to the half-space d(p) = dot(p, m) - offset >= 0.
std::vector<Vec3> ClipPlane(const std::vector<Vec3>& in, const Vec3& m, double offset)
{
  std::vector<Vec3> out;
  out.reserve(in.size() + 1);
  for (std::size_t i = 0; i < in.size(); ++i)
  {
    const Vec3& p = in[i];
    const Vec3& q = in[(i + 1) % in.size()];
    const double dp = glm::dot(p, m) - offset;
    const double dq = glm::dot(q, m) - offset;
    if (dp >= 0)
    {
      out.push_back(p);
    }
    if ((dp >= 0) != (dq >= 0))
    {
      out.push_back(p + (dp / (dp - dq)) * (q - p));
    }
  }
  return out;
}

struct Box2
{
  double X0 = 1e300, Y0 = 1e300, X1 = -1e300, Y1 = -1e300;
  explicit Box2(const Polygon2& p)
  {
    for (const Point2& v : p)
    {
      X0 = std::min(X0, v.X);
      Y0 = std::min(Y0, v.Y);
      X1 = std::max(X1, v.X);
      Y1 = std::max(Y1, v.Y);
    }
  }
  bool Overlaps(const Box2& o) const
  {
    return X0 < o.X1 && o.X0 < X1 && Y0 < o.Y1 && o.Y0 < Y1;
  }
};

// Fragment minus a convex counter-clockwise polygon: the parts of `piece`
// outside each edge of `hole` in turn (disjoint by construction).
void Subtract(const Polygon2& piece, const Polygon2& hole, double minArea, std::vector<Polygon2>& out)
{
  Polygon2 rest = piece;
  for (std::size_t i = 0; i < hole.size() && rest.size() >= 3; ++i)
  {
    const Point2& a = hole[i];
    const Point2& b = hole[(i + 1) % hole.size()];
    Polygon2 outside = ClipHalfPlane(rest, a, b, false);
    if (outside.size() >= 3 && std::abs(SignedArea(outside)) > minArea)
    {
      out.push_back(std::move(outside));
    }
    rest = ClipHalfPlane(rest, a, b, true);
  }
}
} // namespace

double VisibleFormFactor(const Vec3& x, const Vec3& n, const TriangleCorners& source,
  const TriangleCorners* blockers, std::size_t blockerCount, bool* exact, std::size_t fragmentsLimit)
{
  if (exact)
  {
    *exact = true;
  }
  const Vec3 e1 = source[1] - source[0];
  const Vec3 e2 = source[2] - source[0];
  const Vec3 cross = glm::cross(e1, e2);
  const double twiceArea = glm::length(cross);
  if (!(twiceArea > 0))
  {
    return 0.0;
  }
  const Vec3 m = cross / twiceArea;
  const double planeOffset = glm::dot(source[0], m);
  const double height = glm::dot(x, m) - planeOffset;
  if (!(height > 0))
  {
    return 0.0; // behind the one-sided source
  }
  if (blockerCount == 0)
  {
    return PointToPolygonFormFactor(x, n, source.data(), 3);
  }

  // 2D frame in the source plane.
  const Vec3 u = e1 / glm::length(e1);
  const Vec3 v = glm::cross(m, u);
  auto to2 = [&](const Vec3& p) {
    const Vec3 d = p - source[0];
    return Point2{ glm::dot(d, u), glm::dot(d, v) };
  };
  auto to3 = [&](const Point2& p) { return source[0] + p.X * u + p.Y * v; };

  const double sourceArea = 0.5 * twiceArea;
  const double minArea = 1e-14 * sourceArea;
  std::vector<Polygon2> visible{ Polygon2{ to2(source[0]), to2(source[1]), to2(source[2]) } };
  // Blocker parts within this distance of either plane cast no shadow worth
  // a fragment (and would project to infinity at the receiver's plane).
  const double slack = 1e-9 * height;
  const double xLevel = glm::dot(x, m);

  std::vector<Polygon2> next;
  for (std::size_t b = 0; b < blockerCount && !visible.empty(); ++b)
  {
    std::vector<Vec3> poly(blockers[b].begin(), blockers[b].end());
    poly = ClipPlane(poly, m, planeOffset + slack);
    if (poly.size() < 3)
    {
      continue;
    }
    poly = ClipPlane(poly, -m, -(xLevel - slack));
    if (poly.size() < 3)
    {
      continue;
    }
    Polygon2 shadow;
    shadow.reserve(poly.size());
    for (const Vec3& p : poly)
    {
      const double t = height / (xLevel - glm::dot(p, m));
      shadow.push_back(to2(x + t * (p - x)));
    }
    const double area = SignedArea(shadow);
    if (std::abs(area) <= minArea)
    {
      continue; // seen edge-on from x
    }
    if (area < 0)
    {
      std::reverse(shadow.begin(), shadow.end());
    }
    const Box2 shadowBox(shadow);
    next.clear();
    for (const Polygon2& piece : visible)
    {
      if (!Box2(piece).Overlaps(shadowBox))
      {
        next.push_back(piece);
        continue;
      }
      Subtract(piece, shadow, minArea, next);
    }
    visible.swap(next);
    if (visible.size() > fragmentsLimit)
    {
      if (exact)
      {
        *exact = false;
      }
      break;
    }
  }

  double factor = 0.0;
  std::vector<Vec3> poly3;
  for (const Polygon2& piece : visible)
  {
    poly3.clear();
    for (const Point2& p : piece)
    {
      poly3.push_back(to3(p));
    }
    // The contour kernel takes up to 8 vertices; larger convex fragments as fans.
    if (poly3.size() <= 8)
    {
      factor += PointToPolygonFormFactor(x, n, poly3.data(), poly3.size());
    }
    else
    {
      for (std::size_t i = 1; i + 1 < poly3.size(); ++i)
      {
        factor += PointToTriangleFormFactor(x, n, poly3[0], poly3[i], poly3[i + 1]);
      }
    }
  }
  return std::max(0.0, factor);
}
} // namespace radiosity
