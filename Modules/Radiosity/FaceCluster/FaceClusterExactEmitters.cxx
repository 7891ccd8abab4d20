#include "Radiosity/FaceCluster/FaceClusterExactEmitters.h"

#include "Radiosity/FaceCluster/FaceClusterVisibility.h"

#include <atomic>

namespace radiosity
{
FaceClusterExactEmitters::FaceClusterExactEmitters(
  const FaceClusterVisibility& visibility, const std::vector<std::uint32_t>& triangles, const std::vector<RGB>& emission)
  : Shafts(visibility)
  , Ids(triangles)
  , Emission(emission)
{
  static std::atomic<std::uint64_t> made{ 0 };
  this->Generation = ++made;
  const Scene& scene = visibility.Hierarchy().GetScene();
  for (std::uint32_t s : this->Ids)
  {
    this->Corners.push_back({ scene.Vertex(s, 0), scene.Vertex(s, 1), scene.Vertex(s, 2) });
  }
  for (std::size_t k = 0; k < this->Ids.size(); ++k)
  {
    this->Sampled.emplace_back(
      std::vector<RadiantTriangle>{ RadiantTriangle{ this->Corners[k], this->Emission[k] } }, &visibility.AllTriangles());
  }
}

std::array<Vec3, 3> FaceClusterExactEmitters::At(
  std::uint32_t t, const Vec3& x, const Vec3& n, const Vec3& rayOrigin) const
{
  // The blockers of every emitter as seen from triangle t, kept per thread
  // for the next point of the same triangle (the output asks for its
  // corners and centre one after the other).
  struct ShaftCache
  {
    std::uint32_t Triangle = 0xffffffffu;
    std::uint64_t Owner = 0;
    std::vector<std::vector<TriangleCorners>> Blockers;
    std::vector<char> Complete;
  };
  thread_local ShaftCache cache;
  const std::size_t count = this->Ids.size();
  if (cache.Triangle != t || cache.Owner != this->Generation)
  {
    const Scene& scene = this->Shafts.Hierarchy().GetScene();
    const TriangleCorners receiver{ scene.Vertex(t, 0), scene.Vertex(t, 1), scene.Vertex(t, 2) };
    cache.Blockers.resize(count);
    cache.Complete.assign(count, 0);
    for (std::size_t k = 0; k < count; ++k)
    {
      cache.Blockers[k].clear();
      cache.Complete[k] = t != this->Ids[k] &&
        this->Shafts.ShaftBlockers(receiver, this->Corners[k], t, this->Ids[k], MaxBlockers, cache.Blockers[k]);
    }
    cache.Triangle = t;
    cache.Owner = this->Generation;
  }
  std::array<Vec3, 3> e{ Vec3(0.0), Vec3(0.0), Vec3(0.0) };
  thread_local TriangleGather::Scratch scratch;
  for (std::size_t k = 0; k < count; ++k)
  {
    if (t == this->Ids[k])
    {
      continue; // an emitter does not light itself
    }
    if (cache.Complete[k])
    {
      const std::vector<TriangleCorners>& b = cache.Blockers[k];
      const Vec3 f = VisibleVectorFormFactor(x, n, this->Corners[k], b.data(), b.size());
      for (int c = 0; c < 3; ++c)
      {
        e[c] += this->Emission[k][c] * f;
      }
      continue;
    }
    const std::array<Vec3, 3> sampled = this->Sampled[k].At(x, n, rayOrigin, scratch);
    for (int c = 0; c < 3; ++c)
    {
      e[c] += sampled[c];
    }
  }
  return e;
}
} // namespace radiosity
