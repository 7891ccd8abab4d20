#include "Radiosity/FaceCluster/FaceClusterExactEmitters.h"

#include "Radiosity/Common/DirectLighting.h"
#include "Radiosity/Common/Visibility.h"
#include "Radiosity/FaceCluster/FaceClusterVisibility.h"

#include <algorithm>
#include <atomic>

namespace radiosity
{
namespace
{
/// How an input triangle sees an emitting triangle.
enum EmitterSeen : char
{
  Whole,
  Hidden,
  Exact,  ///< partly hidden: its shaft's blockers listed, backprojected
  Sampled ///< partly hidden behind more than MaxBlockers: strata
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
  const std::vector<RadiantTriangle> sources = RadiantTrianglesAt(visibility.Hierarchy().GetScene(), triangles, emission);
  for (const RadiantTriangle& source : sources)
  {
    this->Sources.push_back(source);
    this->Strata.emplace_back(std::vector<RadiantTriangle>{ source }, &visibility.AllTriangles());
  }
}

std::array<Vec3, 3> FaceClusterExactEmitters::At(
  std::uint32_t t, const Vec3& x, const Vec3& n, const Vec3& rayOrigin) const
{
  // Per emitter, how triangle t sees it, decided when a point of t first
  // asks and kept per thread for its next points (the output asks for its
  // corners and centre one after the other).
  struct ShaftCache
  {
    std::uint32_t Triangle = 0xffffffffu;
    std::uint64_t Owner = 0;
    std::vector<std::vector<TriangleCorners>> Blockers;
    std::vector<char> States;
  };
  thread_local ShaftCache cache;
  const std::size_t count = this->Ids.size();
  if (cache.Triangle != t || cache.Owner != this->Generation)
  {
    this->Classify(t, cache.States);
    cache.Blockers.resize(count);
    const Scene& scene = this->Shafts.Hierarchy().GetScene();
    const TriangleCorners receiver{ scene.Vertex(t, 0), scene.Vertex(t, 1), scene.Vertex(t, 2) };
    for (std::size_t k = 0; k < count; ++k)
    {
      // Not hidden: the shaft's blockers, none for a whole emitter.
      cache.Blockers[k].clear();
      if (cache.States[k] != Hidden)
      {
        cache.States[k] =
          this->Shafts.ShaftBlockers(receiver, this->Sources[k].Corners, t, this->Ids[k], MaxBlockers, cache.Blockers[k])
          ? Exact
          : Sampled;
      }
    }
    cache.Triangle = t;
    cache.Owner = this->Generation;
  }
  std::array<Vec3, 3> e{ Vec3(0.0), Vec3(0.0), Vec3(0.0) };
  thread_local TriangleGather::Scratch scratch;
  for (std::size_t k = 0; k < count; ++k)
  {
    if (cache.States[k] == Hidden || t == this->Ids[k]) // an emitter does not light itself
    {
      continue;
    }
    if (cache.States[k] == Sampled)
    {
      const std::array<Vec3, 3> sampled = this->Strata[k].At(x, n, rayOrigin, scratch);
      for (int c = 0; c < 3; ++c)
      {
        e[c] += sampled[c];
      }
      continue;
    }
    // Whole: no blockers; the backprojection is then the contour integral
    // over the emitter, zero behind it.
    const std::vector<TriangleCorners>& b = cache.Blockers[k];
    const Vec3 f = VisibleVectorFormFactor(x, n, this->Sources[k].Corners, b.data(), b.size());
    for (int c = 0; c < 3; ++c)
    {
      e[c] += this->Sources[k].Radiosity[c] * f;
    }
  }
  return e;
}

void FaceClusterExactEmitters::Classify(std::uint32_t t, std::vector<char>& states) const
{
  // Rays from four points of t (its centroid and points just inside its
  // corners, off its plane) to seven of each emitter (its centroid, its
  // edges' midpoints, points just inside its corners): all blocked, the
  // emitter is hidden from t; all through, whole as far as the rays can
  // tell; else partly hidden. At uses only "hidden" (the shaft decides the
  // rest).
  const Scene& scene = this->Shafts.Hierarchy().GetScene();
  const radiosity::Visibility& rays = this->Shafts.AllTriangles();
  const Vec3 n = scene.Normal(t);
  Vec3 from[4];
  from[0] = scene.Centroid(t);
  for (int k = 0; k < 3; ++k)
  {
    from[k + 1] = 0.998 * scene.Vertex(t, k) + 0.001 * scene.Vertex(t, (k + 1) % 3) + 0.001 * scene.Vertex(t, (k + 2) % 3);
  }
  for (Vec3& f : from)
  {
    f = RayOriginOff(rays.Offset(), f, n);
  }
  constexpr int Targets = 7;
  states.assign(this->Ids.size(), Whole);
  thread_local std::vector<Vec3> origins, targets;
  thread_local std::vector<unsigned char> visible;
  const TriangleCorners receiver{ scene.Vertex(t, 0), scene.Vertex(t, 1), scene.Vertex(t, 2) };
  for (std::size_t k = 0; k < this->Ids.size(); ++k)
  {
    const auto& c = this->Sources[k].Corners;
    // Itself, wholly below t's horizon, or t behind it: no light, no ray.
    const Vec3 m = glm::cross(c[1] - c[0], c[2] - c[0]);
    bool above = false, before = false;
    for (int j = 0; j < 3; ++j)
    {
      above = above || glm::dot(c[j] - receiver[0], n) > 0.0;
      before = before || glm::dot(receiver[j] - c[0], m) > 0.0;
    }
    if (t == this->Ids[k] || !above || !before)
    {
      states[k] = Hidden;
      continue;
    }
    Vec3 to[Targets] = { (c[0] + c[1] + c[2]) / 3.0, 0.5 * (c[0] + c[1]), 0.5 * (c[1] + c[2]), 0.5 * (c[2] + c[0]) };
    for (int j = 0; j < 3; ++j)
    {
      to[4 + j] = 0.998 * c[j] + 0.001 * c[(j + 1) % 3] + 0.001 * c[(j + 2) % 3];
    }
    origins.clear();
    targets.clear();
    for (const Vec3& f : from)
    {
      for (const Vec3& y : to)
      {
        origins.push_back(f);
        targets.push_back(y);
      }
    }
    visible.resize(origins.size());
    rays.TestSegments(origins.data(), targets.data(), origins.size(), visible.data());
    const std::size_t seen = static_cast<std::size_t>(std::count(visible.begin(), visible.end(), 1));
    states[k] = seen == visible.size() ? Whole : seen == 0 ? Hidden : Exact;
  }
}
} // namespace radiosity
