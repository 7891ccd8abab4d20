#include "Radiosity/FaceCluster/FaceClusterVisibility.h"

#include "Radiosity/Common/Visibility.h"
#include "Radiosity/FaceCluster/FaceClusterDescent.h"
#include "Radiosity/Hierarchical/Shaft.h"

#include <algorithm>
#include <functional>
#include <cmath>

namespace radiosity
{
namespace
{
thread_local std::size_t Visited = 0;

struct Range
{
  std::uint32_t First = 0, End = 0;
  bool Contains(std::uint32_t first, std::uint32_t count) const
  {
    return first >= this->First && first + count <= this->End;
  }
  bool Overlaps(std::uint32_t first, std::uint32_t count) const
  {
    return first < this->End && first + count > this->First;
  }
};

// The triangle ranges of the receiver's and the emitter's own clusters,
// which do not occlude between them; how many.
int OwnRanges(const FaceClusterHierarchy& h, std::uint32_t receiver, std::uint32_t emitter, Range* skip)
{
  int skips = 0;
  for (std::uint32_t id : { receiver, emitter })
  {
    if (id != FaceCluster::None)
    {
      const FaceCluster* c = h.InternalCluster(id);
      const std::uint32_t first = c ? c->First : h.TrianglePosition(id);
      skip[skips++] = { first, first + (c ? c->Count : 1u) };
    }
  }
  return skips;
}

/// Whether the triangles [first, first + count) lie inside one of the own ranges.
bool InsideOwn(const Range* skip, int skips, std::uint32_t first, std::uint32_t count)
{
  for (int k = 0; k < skips; ++k)
  {
    if (skip[k].Contains(first, count))
    {
      return true;
    }
  }
  return false;
}

/// The own triangles' test for Visibility::TestSegmentsPassing, held by
/// reference (std::cref) so that the std::function allocates nothing on
/// this hot path (one call per receiver point and transfer).
struct OwnTriangles
{
  const FaceClusterHierarchy& Hierarchy;
  Range Skip[2];
  int Skips = 0;
  bool operator()(std::uint32_t t) const
  {
    return InsideOwn(this->Skip, this->Skips, this->Hierarchy.TrianglePosition(t), 1);
  }
};
}

bool LineHitsTriangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p, const Vec3& d, double& t)
{
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 pv = glm::cross(d, e2);
  const double det = glm::dot(e1, pv);
  if (std::abs(det) < 1e-300)
  {
    return false;
  }
  const double inv = 1.0 / det;
  const Vec3 tv = p - a;
  const double u = glm::dot(tv, pv) * inv;
  if (u < 0.0 || u > 1.0)
  {
    return false;
  }
  const Vec3 qv = glm::cross(tv, e1);
  const double v = glm::dot(d, qv) * inv;
  if (v < 0.0 || u + v > 1.0)
  {
    return false;
  }
  t = glm::dot(e2, qv) * inv;
  return true;
}

bool SegmentCrossesBox(const FaceCluster& c, const Vec3& p, const Vec3& d, double t0, double t1)
{
  // Slabs in the box's frame.
  const Vec3 o = p - Vec3(c.Centre);
  for (int j = 0; j < 3; ++j)
  {
    const Vec3 axis(c.Axis[j]);
    const double origin = glm::dot(o, axis), direction = glm::dot(d, axis);
    // A little slack: flat boxes have zero thickness.
    const double h = double(c.HalfSize[j]) * (1.0 + 1e-6) + 1e-9 * (1.0 + std::abs(origin));
    if (std::abs(direction) < 1e-300)
    {
      if (std::abs(origin) > h)
      {
        return false;
      }
      continue;
    }
    double a = (-h - origin) / direction, b = (h - origin) / direction;
    if (a > b)
    {
      std::swap(a, b);
    }
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t0 > t1)
    {
      return false;
    }
  }
  return true;
}

FaceClusterVisibility::FaceClusterVisibility(const FaceClusterHierarchy& hierarchy)
  : Source(hierarchy)
{
}

FaceClusterVisibility::~FaceClusterVisibility() = default;

void FaceClusterVisibility::Visible(const Vec3& x, const Vec3* ys, std::size_t n,
  std::uint32_t receiver, std::uint32_t emitter, unsigned char* visible) const
{
  const FaceClusterHierarchy& h = this->Source;
  const Visibility& rays = this->AllTriangles();
  OwnTriangles own{ h, {}, 0 };
  own.Skips = OwnRanges(h, receiver, emitter, own.Skip);
  const std::function<bool(std::uint32_t)> passes = std::cref(own);
  thread_local std::vector<Vec3> from;
  from.assign(n, x);
  rays.TestSegmentsPassing(from.data(), ys, n, passes, visible);
}

const Visibility& FaceClusterVisibility::AllTriangles() const
{
  std::call_once(this->Built, [&]() {
    const Scene& scene = this->Source.GetScene();
    this->Rays = std::make_unique<Visibility>(scene, Visibility::AllTriangles(scene));
  });
  return *this->Rays;
}

std::size_t FaceClusterVisibility::NodesVisited()
{
  return Visited;
}

double FaceClusterVisibility::Transmittance(const Vec3& x, const Vec3& y, std::uint32_t receiver,
  std::uint32_t emitter, double shadowThreshold) const
{
  const FaceClusterHierarchy& h = this->Source;
  const Scene& scene = h.GetScene();
  const Vec3 d = y - x;
  const double length = glm::length(d);
  if (!(length > 0.0))
  {
    return 1.0;
  }
  // The segment's ends lie on the receiver and the emitter: keep clear of
  // the surfaces they touch.
  const double t0 = 1e-7, t1 = 1.0 - 1e-7;
  const Vec3 direction = d / length;
  Range skip[2];
  const int skips = OwnRanges(h, receiver, emitter, skip);
  double transmittance = 1.0;
  thread_local std::vector<std::uint32_t> stack;
  stack.assign(h.Roots().begin(), h.Roots().end());
  while (!stack.empty())
  {
    const std::uint32_t id = stack.back();
    stack.pop_back();
    ++Visited;
    const FaceCluster* c = h.InternalCluster(id);
    const std::uint32_t first = c ? c->First : h.TrianglePosition(id);
    const std::uint32_t count = c ? c->Count : 1u;
    bool around = false;
    for (int k = 0; k < skips; ++k)
    {
      around = around || skip[k].Overlaps(first, count);
    }
    if (InsideOwn(skip, skips, first, count))
    {
      continue;
    }
    if (!c)
    {
      double t = 0.0;
      if (LineHitsTriangle(scene.Vertex(id, 0), scene.Vertex(id, 1), scene.Vertex(id, 2), x, d, t) &&
        t > t0 && t < t1)
      {
        return 0.0;
      }
      continue;
    }
    if (!SegmentCrossesBox(*c, x, d, t0, t1))
    {
      continue;
    }
    if (shadowThreshold > 0.0 && !around)
    {
      const double size = 2.0 * std::max({ c->HalfSize.x, c->HalfSize.y, c->HalfSize.z });
      const double toEmitter = glm::length(y - Vec3(c->Centre));
      if (toEmitter > 0.0 && size * length / toEmitter < shadowThreshold)
      {
        const double box = c->BoxProjectedArea(direction);
        // Faces block from either side: the larger of the areas the cluster
        // shows the two ends (exact for a flat patch and a closed convex one),
        // each the mean of Willmott's bounds.
        const double front = 0.5 * (c->MinProjectedArea(direction) + c->MaxProjectedArea(direction));
        const double back = 0.5 * (c->MinProjectedArea(-direction) + c->MaxProjectedArea(-direction));
        const double opacity = box > 0.0 ? std::clamp(std::max(front, back) / box, 0.0, 1.0) : 1.0;
        transmittance *= 1.0 - opacity;
        if (transmittance < 1e-9)
        {
          return 0.0;
        }
        continue;
      }
    }
    stack.push_back(c->Child[0]);
    stack.push_back(c->Child[1]);
  }
  return transmittance;
}

bool FaceClusterVisibility::ShaftBlockers(const TriangleCorners& receiver, const TriangleCorners& source,
  std::uint32_t receiverId, std::uint32_t emitterId, std::size_t limit,
  std::vector<TriangleCorners>& out) const
{
  const FaceClusterHierarchy& h = this->Source;
  const Scene& scene = h.GetScene();
  const Shaft shaft(receiver, source);
  Range skip[2];
  const int skips = OwnRanges(h, receiverId, emitterId, skip);
  const Vec3 nr = glm::cross(receiver[1] - receiver[0], receiver[2] - receiver[0]);
  const Vec3 ns = glm::cross(source[1] - source[0], source[2] - source[0]);
  double scale = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    scale = std::max({ scale, glm::length(receiver[k] - receiver[0]), glm::length(source[k] - receiver[0]) });
  }
  // A vertex in front of a plane by more than this (relative to the shaft's
  // size: a blocker touching the receiver's plane along an edge hides
  // nothing in front of it).
  const double tolerance = 1e-9 * scale;
  const double lr = glm::length(nr), ls = glm::length(ns);
  if (!(lr > 0.0) || !(ls > 0.0))
  {
    return true;
  }
  const auto open = [&](const FaceCluster& c) {
    if (InsideOwn(skip, skips, c.First, c.Count))
    {
      return false;
    }
    Vec3 corners[8];
    GrownBoxCorners(c, 1e-6, tolerance, corners);
    // A triangle is kept only with a vertex in front of both ends' planes
    // (take): a box wholly behind either holds none (the ceiling around a
    // lamp, the receiver's own surface around it, which the descent
    // otherwise opened down to every triangle: most of the shafts' time).
    bool frontR = false, frontS = false;
    for (const Vec3& v : corners)
    {
      frontR = frontR || glm::dot(v - receiver[0], nr) > tolerance * lr;
      frontS = frontS || glm::dot(v - source[0], ns) > tolerance * ls;
    }
    return frontR && frontS && !shaft.Excludes(corners, 8);
  };
  const auto take = [&](std::uint32_t id) {
    if (InsideOwn(skip, skips, h.TrianglePosition(id), 1u))
    {
      return true;
    }
    const TriangleCorners t{ scene.Vertex(id, 0), scene.Vertex(id, 1), scene.Vertex(id, 2) };
    bool frontR = false, frontS = false;
    for (const Vec3& v : t)
    {
      frontR = frontR || glm::dot(v - receiver[0], nr) > tolerance * lr;
      frontS = frontS || glm::dot(v - source[0], ns) > tolerance * ls;
    }
    if (frontR && frontS && !shaft.Excludes(t))
    {
      if (out.size() >= limit)
      {
        return false;
      }
      out.push_back(t);
    }
    return true;
  };
  return DescendClusters(h, open, take);
}
} // namespace radiosity
