#include "Radiosity/FaceCluster/FaceClusterExactEmitters.h"

#include "Radiosity/Common/DirectLighting.h"
#include "Radiosity/Common/FormFactor.h"
#include "Radiosity/Common/Visibility.h"
#include "Radiosity/FaceCluster/FaceClusterVisibility.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <map>
#include <cstdio>

namespace radiosity
{
namespace
{
/// How an input triangle sees a lamp.
enum LampSeen : char
{
  Hidden,
  Exact,  ///< its shaft's blockers listed (none: whole), backprojected
  Sampled ///< behind more than MaxBlockers: strata
};

std::vector<RadiantTriangle> RadiantTrianglesAt(
  const Scene& scene, const std::vector<std::uint32_t>& triangles, const std::vector<RGB>& emission)
{
  std::vector<RadiantTriangle> out;
  for (std::size_t k = 0; k < triangles.size(); ++k)
  {
    const std::uint32_t s = triangles[k];
    out.push_back(RadiantTriangle{ { scene.Vertex(s, 0), scene.Vertex(s, 1), scene.Vertex(s, 2) }, emission[k] });
  }
  return out;
}
}

FaceClusterExactEmitters::FaceClusterExactEmitters(
  const FaceClusterVisibility& visibility, const std::vector<std::uint32_t>& triangles, const std::vector<RGB>& emission)
  : Shafts(visibility)
  , Ids(triangles)
{
  static std::atomic<std::uint64_t> made{ 0 };
  this->Generation = ++made;
  const Scene& scene = visibility.Hierarchy().GetScene();
  const std::vector<RadiantTriangle> sources = RadiantTrianglesAt(scene, triangles, emission);
  for (const RadiantTriangle& source : sources)
  {
    this->Sources.push_back(source);
    this->Strata.emplace_back(std::vector<RadiantTriangle>{ source }, &visibility.AllTriangles());
  }
  this->MakePatches(scene);
}

double FaceClusterExactEmitters::Lamps() const
{
  double lamps = 0.0;
  for (const Patch& patch : this->Patches)
  {
    lamps += patch.Convex.empty() ? static_cast<double>(patch.Members.size()) : 1.0;
  }
  return lamps;
}

void FaceClusterExactEmitters::MakePatches(const Scene& scene)
{
  // Union-find over the emitters: joined where they share a vertex and a
  // plane (normals within 1e-9, each one's corners in the other's plane).
  const std::size_t count = this->Ids.size();
  std::vector<std::size_t> root(count);
  for (std::size_t k = 0; k < count; ++k)
  {
    root[k] = k;
  }
  const auto find = [&](std::size_t k) {
    while (root[k] != k)
    {
      k = root[k] = root[root[k]];
    }
    return k;
  };
  for (std::size_t a = 0; a < count; ++a)
  {
    const Vec3 na = scene.Normal(this->Ids[a]);
    for (std::size_t b = a + 1; b < count; ++b)
    {
      bool shared = false, coplanar = glm::dot(na, scene.Normal(this->Ids[b])) > 1.0 - 1e-9;
      for (int i = 0; i < 3 && coplanar; ++i)
      {
        const Vec3& corner = this->Sources[b].Corners[i];
        const double size = glm::length(this->Sources[a].Corners[1] - this->Sources[a].Corners[0]);
        coplanar = std::abs(glm::dot(corner - this->Sources[a].Corners[0], na)) <= 1e-9 * size;
        for (int j = 0; j < 3; ++j)
        {
          shared = shared || scene.Triangles[this->Ids[a]].V[j] == scene.Triangles[this->Ids[b]].V[i];
        }
      }
      if (shared && coplanar)
      {
        root[find(a)] = find(b);
      }
    }
  }
  std::vector<std::size_t> patchOf(count, count);
  for (std::size_t k = 0; k < count; ++k)
  {
    std::size_t& p = patchOf[find(k)];
    if (p == count)
    {
      p = this->Patches.size();
      this->Patches.emplace_back();
    }
    this->Patches[p].Members.push_back(static_cast<std::uint32_t>(k));
  }
  for (Patch& patch : this->Patches)
  {
    // In the lamp's plane (u along its first triangle's first edge): the
    // triangle (u0, v0), (u0 + 2w, v0), (u0, v0 + 2h) around the bounding
    // rectangle [u0, u0 + w] x [v0, v0 + h], grown by 1e-6 of its size, and
    // the samples: the area centroid and the corners extreme along u, v
    // and the diagonals, just inside towards the centroid.
    const TriangleCorners& first = this->Sources[patch.Members[0]].Corners;
    const Vec3 m = glm::normalize(glm::cross(first[1] - first[0], first[2] - first[0]));
    const Vec3 u = glm::normalize(first[1] - first[0]), v = glm::cross(m, u);
    double u0 = std::numeric_limits<double>::infinity(), v0 = u0, u1 = -u0, v1 = -u0, area = 0.0;
    Vec3 centroid(0.0);
    const Vec3 directions[6] = { u, -u, v, -v, u + v, -u - v };
    Vec3 extreme[6] = { first[0], first[0], first[0], first[0], first[0], first[0] };
    double reach[6];
    std::fill(reach, reach + 6, -std::numeric_limits<double>::infinity());
    for (std::uint32_t k : patch.Members)
    {
      const TriangleCorners& c = this->Sources[k].Corners;
      const double a = 0.5 * glm::length(glm::cross(c[1] - c[0], c[2] - c[0]));
      area += a;
      centroid += a * (c[0] + c[1] + c[2]) / 3.0;
      for (const Vec3& corner : c)
      {
        const Vec3 d = corner - first[0];
        u0 = std::min(u0, glm::dot(d, u));
        u1 = std::max(u1, glm::dot(d, u));
        v0 = std::min(v0, glm::dot(d, v));
        v1 = std::max(v1, glm::dot(d, v));
        for (int i = 0; i < 6; ++i)
        {
          if (glm::dot(corner, directions[i]) > reach[i])
          {
            reach[i] = glm::dot(corner, directions[i]);
            extreme[i] = corner;
          }
        }
      }
    }
    centroid = area > 0.0 ? centroid / area : first[0];
    const double grow = 1e-6 * std::max(u1 - u0, v1 - v0);
    u0 -= grow;
    v0 -= grow;
    const double w = u1 - u0 + grow, h = v1 - v0 + grow;
    const auto at = [&](double a, double b) { return first[0] + a * u + b * v; };
    patch.Around = { at(u0, v0), at(u0 + 2.0 * w, v0), at(u0, v0 + 2.0 * h) };
    patch.Normal = m;
    patch.Offset = glm::dot(first[0], m);
    patch.Size = std::max(w, h);
    patch.Samples[0] = centroid;
    for (int i = 0; i < 6; ++i)
    {
      patch.Samples[i + 1] = 0.998 * extreme[i] + 0.002 * centroid;
    }
    this->FindOutline(scene, patch);
  }
}

void FaceClusterExactEmitters::FindOutline(const Scene& scene, Patch& patch) const
{
  patch.Outline.clear();
  const RGB radiosity = this->Sources[patch.Members[0]].Radiosity;
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges; // directed, by point index
  for (std::uint32_t k : patch.Members)
  {
    if (this->Sources[k].Radiosity != radiosity)
    {
      return;
    }
    const auto& v = scene.Triangles[this->Ids[k]].V;
    for (int i = 0; i < 3; ++i)
    {
      ++edges[{ v[i], v[(i + 1) % 3] }];
    }
  }
  // The boundary: edges whose reverse no member has; one loop through them.
  std::map<std::uint32_t, std::uint32_t> next;
  for (const auto& [edge, uses] : edges)
  {
    if (uses != 1 || edges.count({ edge.second, edge.first }))
    {
      if (uses != 1)
      {
        return; // a repeated edge: not one sheet
      }
      continue;
    }
    if (!next.emplace(edge.first, edge.second).second)
    {
      return; // two boundary edges leave one point: not one simple loop
    }
  }
  if (next.size() < 3)
  {
    return;
  }
  std::vector<Vec3> loop;
  std::uint32_t at = next.begin()->first;
  for (std::size_t step = 0; step < next.size(); ++step)
  {
    loop.push_back(scene.Points[at]);
    const auto found = next.find(at);
    if (found == next.end())
    {
      return;
    }
    at = found->second;
  }
  if (at != next.begin()->first)
  {
    return; // more than one loop
  }
  patch.Outline = std::move(loop);
  patch.Radiosity = radiosity;
  // Its corners that turn (relative to its size), all the same way.
  const std::vector<Vec3>& o = patch.Outline;
  const std::size_t count = o.size();
  Vec3 normal(0.0);
  double size = 0.0;
  for (std::size_t i = 0; i < count; ++i)
  {
    normal += glm::cross(o[i], o[(i + 1) % count]);
    size = std::max(size, glm::length(o[i] - o[0]));
  }
  normal = glm::normalize(normal);
  std::vector<Vec3> corners;
  for (std::size_t i = 0; i < count; ++i)
  {
    const Vec3 turn = glm::cross(o[i] - o[(i + count - 1) % count], o[(i + 1) % count] - o[i]);
    const double along = glm::dot(turn, normal);
    if (along < -1e-12 * size * size)
    {
      return; // a reflex corner: not convex
    }
    if (along > 1e-12 * size * size)
    {
      corners.push_back(o[i]);
    }
  }
  if (corners.size() >= 3 && corners.size() <= static_cast<std::size_t>(MaxSourceCorners))
  {
    patch.Convex = std::move(corners);
  }
}

std::array<Vec3, 3> FaceClusterExactEmitters::At(
  std::uint32_t t, const Vec3& x, const Vec3& n, const Vec3& rayOrigin) const
{
  // Per lamp, its shaft's blockers from triangle t, listed when a point of t
  // first asks and kept per thread for its next points (the output asks
  // for its corners and centre one after the other).
  struct ShaftCache
  {
    std::uint32_t Triangle = 0xffffffffu;
    std::uint64_t Owner = 0;
    std::vector<std::vector<TriangleCorners>> Blockers;
    std::vector<char> States;
    std::vector<char> Member; ///< t is one of the lamp's triangles
  };
  thread_local ShaftCache cache;
  const std::size_t patches = this->Patches.size();
  if (cache.Triangle != t || cache.Owner != this->Generation)
  {
    std::vector<char> hidden;
    this->FindHidden(t, hidden);
    cache.Blockers.resize(patches);
    cache.States.assign(patches, Hidden);
    cache.Member.assign(patches, 0);
    for (std::size_t p = 0; p < patches; ++p)
    {
      for (std::uint32_t k : this->Patches[p].Members)
      {
        cache.Member[p] = cache.Member[p] || this->Ids[k] == t;
      }
    }
    const Scene& scene = this->Shafts.Hierarchy().GetScene();
    const TriangleCorners receiver{ scene.Vertex(t, 0), scene.Vertex(t, 1), scene.Vertex(t, 2) };
    for (std::size_t p = 0; p < patches; ++p)
    {
      cache.Blockers[p].clear();
      if (!hidden[p])
      {
        // The lamp's own triangles are skipped as the shaft's source
        // (ShaftBlockers' emitter): they cast no shadow on one another.
        const std::uint32_t own = this->Patches[p].Members.size() == 1 ? this->Ids[this->Patches[p].Members[0]]
                                                                       : FaceCluster::None;
        cache.States[p] =
          this->Shafts.ShaftBlockers(receiver, this->Patches[p].Around, t, own, MaxBlockers, cache.Blockers[p])
          ? Exact
          : Sampled;
      }
    }
    cache.Triangle = t;
    cache.Owner = this->Generation;
  }
  std::array<Vec3, 3> e{ Vec3(0.0), Vec3(0.0), Vec3(0.0) };
  thread_local TriangleGather::Scratch scratch;
  const Vec3 inside = this->Shafts.Hierarchy().GetScene().Centroid(t);
  for (std::size_t p = 0; p < patches; ++p)
  {
    if (cache.States[p] == Hidden)
    {
      continue;
    }
    const Patch& patch = this->Patches[p];
    if (cache.Member[p])
    {
      continue; // on the lamp: its triangles, coplanar, light nothing here
    }
    // A point in the lamp's plane (a vertex on the edge where a wall meets
    // an emitting ceiling, the cube's faces all emitting) takes the limit
    // from inside its triangle, 1e-8 of the way to its centroid: in the
    // plane itself the lamp is seen edge on (0), and the vertex drew a dark
    // seam (a closed emitting cube's edges 7.5% low).
    const bool inPlane = std::abs(glm::dot(x, patch.Normal) - patch.Offset) <= 1e-9 * patch.Size;
    const Vec3 y = inPlane ? x + 1e-8 * (inside - x) : x;
    if (cache.States[p] == Exact && (!patch.Convex.empty() || (cache.Blockers[p].empty() && !patch.Outline.empty())))
    {
      // The lamp at once: the backprojection over its convex outline, or
      // seen whole, the contour integral over its outline.
      const std::vector<TriangleCorners>& b = cache.Blockers[p];
      const Vec3 f = !patch.Convex.empty()
        ? VisibleVectorFormFactor(y, n, patch.Convex.data(), static_cast<int>(patch.Convex.size()), b.data(), b.size())
        : PointToPolygonVectorFormFactor(y, patch.Outline.data(), patch.Outline.size(), &n);
      for (int c = 0; c < 3; ++c)
      {
        e[c] += patch.Radiosity[c] * f;
      }
      continue;
    }
    for (std::uint32_t k : patch.Members)
    {
      if (t == this->Ids[k])
      {
        continue; // an emitter does not light itself
      }
      if (cache.States[p] == Sampled)
      {
        const std::array<Vec3, 3> sampled = this->Strata[k].At(y, n, rayOrigin, scratch);
        for (int c = 0; c < 3; ++c)
        {
          e[c] += sampled[c];
        }
        continue;
      }
      // No blockers: the contour integral over the emitter, zero behind it.
      const std::vector<TriangleCorners>& b = cache.Blockers[p];
      const Vec3 f = VisibleVectorFormFactor(y, n, this->Sources[k].Corners, b.data(), b.size());
      for (int c = 0; c < 3; ++c)
      {
        e[c] += this->Sources[k].Radiosity[c] * f;
      }
    }
  }
  return e;
}

void FaceClusterExactEmitters::FindHidden(std::uint32_t t, std::vector<char>& hidden) const
{
  // Rays from four points of t (its centroid and points just inside its
  // corners, off its plane) to the seven samples of each lamp: all
  // blocked, the lamp is hidden from t. Else its shaft decides.
  const Scene& scene = this->Shafts.Hierarchy().GetScene();
  const radiosity::Visibility& rays = this->Shafts.AllTriangles();
  const Vec3 n = scene.Normal(t);
  const TriangleCorners receiver{ scene.Vertex(t, 0), scene.Vertex(t, 1), scene.Vertex(t, 2) };
  Vec3 from[4];
  from[0] = scene.Centroid(t);
  for (int k = 0; k < 3; ++k)
  {
    from[k + 1] = 0.998 * receiver[k] + 0.001 * receiver[(k + 1) % 3] + 0.001 * receiver[(k + 2) % 3];
  }
  for (Vec3& f : from)
  {
    f = RayOriginOff(rays.Offset(), f, n);
  }
  hidden.assign(this->Patches.size(), 0);
  thread_local std::vector<Vec3> origins, targets;
  thread_local std::vector<unsigned char> visible;
  for (std::size_t p = 0; p < this->Patches.size(); ++p)
  {
    const Patch& patch = this->Patches[p];
    // Wholly below t's horizon, or t behind the lamp: no light, no ray.
    const auto& c = patch.Around;
    const Vec3 m = glm::cross(c[1] - c[0], c[2] - c[0]);
    bool above = false, before = false;
    for (std::uint32_t k : patch.Members)
    {
      for (const Vec3& corner : this->Sources[k].Corners)
      {
        above = above || glm::dot(corner - receiver[0], n) > 0.0;
      }
    }
    for (const Vec3& corner : receiver)
    {
      before = before || glm::dot(corner - c[0], m) > 0.0;
    }
    if (!above || !before)
    {
      hidden[p] = 1;
      continue;
    }
    origins.clear();
    targets.clear();
    for (const Vec3& f : from)
    {
      for (const Vec3& y : patch.Samples)
      {
        origins.push_back(f);
        targets.push_back(y);
      }
    }
    visible.resize(origins.size());
    rays.TestSegments(origins.data(), targets.data(), origins.size(), visible.data());
    hidden[p] = std::count(visible.begin(), visible.end(), 1) == 0 ? 1 : 0;
  }
}
} // namespace radiosity
