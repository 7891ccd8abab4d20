#include "Radiosity/Hierarchical/EdgeTopology.h"

#include "Radiosity/Hierarchical/DiscontinuityMeshWork.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>

namespace radiosity
{
namespace discontinuity_mesh_detail
{
EdgeTopology::EdgeTopology(const Scene& scene)
  : SourceScene(scene)
  , Edges(3 * scene.Triangles.size())
  , CoplanarAcross(3 * scene.Triangles.size(), NoTriangle)
{
  tbb::parallel_for(std::size_t(0), scene.Triangles.size(), [&](std::size_t t) {
    for (int k = 0; k < 3; ++k)
    {
      this->Edges[3 * t + k] = { EdgeKey(scene.Triangles[t].V[k], scene.Triangles[t].V[(k + 1) % 3]),
        static_cast<std::uint32_t>(3 * t + k) };
    }
  });
  tbb::parallel_sort(this->Edges.begin(), this->Edges.end());
  // One pass over the runs of equal keys: a manifold edge has two entries.
  tbb::parallel_for(std::size_t(0), this->Edges.size(), [&](std::size_t i) {
    if (i > 0 && this->Edges[i - 1].first == this->Edges[i].first)
    {
      return; // not the start of its run
    }
    std::size_t end = i + 1;
    while (end < this->Edges.size() && this->Edges[end].first == this->Edges[i].first)
    {
      ++end;
    }
    if (end - i > 2)
    {
      for (std::size_t j = i; j < end; ++j)
      {
        this->CoplanarAcross[this->Edges[j].second] = SeveralTriangles;
      }
      return;
    }
    if (end - i == 2)
    {
      const std::uint32_t a = this->Edges[i].second, b = this->Edges[i + 1].second;
      if (a / 3 != b / 3 && this->Coplanar(a / 3, b / 3))
      {
        this->CoplanarAcross[a] = b / 3;
        this->CoplanarAcross[b] = a / 3;
      }
    }
  });
}

bool EdgeTopology::Coplanar(std::uint32_t a, std::uint32_t b) const
{
  const Vec3 na = this->SourceScene.Normal(a), nb = this->SourceScene.Normal(b);
  return glm::dot(na, nb) > 1.0 - 1e-9;
}

std::pair<const EdgeTopology::EdgeEntry*, const EdgeTopology::EdgeEntry*> EdgeTopology::Sharing(
  std::uint64_t edge) const
{
  const EdgeEntry* first = std::lower_bound(this->Edges.data(), this->Edges.data() + this->Edges.size(),
    EdgeEntry(edge, std::uint32_t(0)));
  const EdgeEntry* last = first;
  while (last != this->Edges.data() + this->Edges.size() && last->first == edge)
  {
    ++last;
  }
  return { first, last };
}

template <typename Visit>
bool EdgeTopology::AnyCoplanarAcross(std::uint32_t t, int k, const Visit& visit) const
{
  const std::uint32_t across = this->CoplanarAcross[3 * t + static_cast<std::uint32_t>(k)];
  if (across == NoTriangle)
  {
    return false;
  }
  if (across != SeveralTriangles)
  {
    return visit(across);
  }
  const Triangle& tri = this->SourceScene.Triangles[t];
  const auto range = this->Sharing(EdgeKey(tri.V[k], tri.V[(k + 1) % 3]));
  for (const EdgeEntry* e = range.first; e != range.second; ++e)
  {
    const std::uint32_t o = e->second / 3;
    if (o != t && this->Coplanar(o, t) && visit(o))
    {
      return true;
    }
  }
  return false;
}

bool EdgeTopology::InteriorEmitterEdge(std::uint32_t t, int k) const
{
  return this->AnyCoplanarAcross(t, k, [&](std::uint32_t o) {
    return this->SourceScene.Materials[o].Emission == this->SourceScene.Materials[t].Emission;
  });
}

std::vector<BlockerEdge> EdgeTopology::Silhouette(const std::vector<std::uint32_t>& blockers) const
{
  std::vector<BlockerEdge> out;
  for (std::uint32_t b : blockers)
  {
    const Triangle& tri = this->SourceScene.Triangles[b];
    for (int k = 0; k < 3; ++k)
    {
      const bool interior = this->AnyCoplanarAcross(
        b, k, [&](std::uint32_t o) { return std::binary_search(blockers.begin(), blockers.end(), o); });
      if (!interior)
      {
        out.push_back({ this->SourceScene.Points[tri.V[k]], this->SourceScene.Points[tri.V[(k + 1) % 3]] });
      }
    }
  }
  return out;
}
} // namespace discontinuity_mesh_detail
} // namespace radiosity
