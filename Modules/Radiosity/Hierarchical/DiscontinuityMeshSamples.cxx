// The discontinuity mesh's sample references (DiscontinuityMeshWork.h,
// ReferenceSamples): every sample on a leaf's boundary (corners, edge
// midpoints, vertices of neighbours inserted by the conforming step) is
// shared by position between the leaves that meet there, computed once, so
// that neighbouring interpolants agree along their common edges.
//
// The leaves list their samples in parallel; the shared ones are then
// numbered by their first appearance in leaf order with a parallel sort of
// their keys' hashes (a million-leaf scene lists some 9 million), so that the
// numbering and each sample's owner are those of a sequential pass.
#include "Radiosity/Hierarchical/DiscontinuityMeshWork.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace radiosity
{
namespace discontinuity_mesh_detail
{
namespace
{
/// The key is the position and the surface's normal: a point on a contact
/// line belongs to both surfaces, with a different irradiance on each.
using SampleKey = std::array<std::int64_t, 6>;

SampleKey KeyOf(const Vec3& x, const Vec3& normal, double quantum)
{
  return { std::llround(x.x / quantum), std::llround(x.y / quantum), std::llround(x.z / quantum),
    std::llround(normal.x * 1e6), std::llround(normal.y * 1e6), std::llround(normal.z * 1e6) };
}

/// A 64-bit hash of a key (the splitmix64 finaliser over its words): equal
/// keys have equal hashes; unequal ones are told apart after the sort.
std::uint64_t HashOf(const SampleKey& key)
{
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (std::int64_t v : key)
  {
    h ^= static_cast<std::uint64_t>(v) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
    h ^= h >> 31;
  }
  return h;
}

/// Leaf i's vertex and triangle references, its shared samples listed as
/// candidates (vertices first, then the boundary pieces' midpoints).
void ListSamples(const HierarchicalRadiosity& s, std::uint32_t leaf, LeafWork& w)
{
  const TriangleCorners corners = s.Corners(leaf);
  const double tolerance = 1e-7 * s.Mesh().LongestEdge(leaf);
  auto edgeOf = [&](const Vec3& x) { return LeafEdgeOf(corners, tolerance, x); };
  auto shared = [&](std::uint32_t a, std::uint32_t b) {
    w.SharedCandidates.push_back({ a, b });
    return SampleRef{ true, static_cast<std::uint32_t>(w.SharedCandidates.size() - 1) };
  };
  boost::container::small_vector<int, 8> edge(w.Mesh.Points.size(), -1);
  std::map<std::uint64_t, std::uint32_t> localMid;
  w.VertexSamples.resize(w.Mesh.Points.size());
  for (std::uint32_t v = 0; v < w.Mesh.Points.size(); ++v)
  {
    const Vec3& x = w.Mesh.Points[v];
    edge[v] = v < 3 ? 3 : edgeOf(x); // corners are on two edges: 3 marks them
    if (edge[v] >= 0)
    {
      w.VertexSamples[v] = shared(v, v);
    }
    else
    {
      w.VertexSamples[v] = { false, static_cast<std::uint32_t>(w.LocalPoints.size()) };
      w.LocalPoints.push_back(x);
    }
  }
  for (const auto& t : w.Mesh.Triangles)
  {
    std::array<SampleRef, 6> r{};
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      r[2 * k] = w.VertexSamples[a];
      const Vec3 mid = 0.5 * (w.Mesh.Points[a] + w.Mesh.Points[b]);
      if (edge[a] >= 0 && edge[b] >= 0 && edgeOf(mid) >= 0)
      {
        r[2 * k + 1] = shared(a, b); // a piece of the leaf's boundary
      }
      else
      {
        auto it = localMid.find(EdgeKey(a, b));
        if (it == localMid.end())
        {
          it = localMid.emplace(EdgeKey(a, b), static_cast<std::uint32_t>(w.LocalPoints.size())).first;
          w.LocalPoints.push_back(mid);
        }
        r[2 * k + 1] = { false, it->second };
      }
    }
    w.TriangleSamples.push_back(r);
  }
}

Vec3 CandidatePoint(const LeafWork& w, const SampleCandidate& c)
{
  return c[0] == c[1] ? w.Mesh.Points[c[0]] : 0.5 * (w.Mesh.Points[c[0]] + w.Mesh.Points[c[1]]);
}
} // namespace

SharedSamples ReferenceSamples(
  const HierarchicalRadiosity& s, const std::vector<std::uint32_t>& leaves, LeafWorks& work)
{
  const ElementMesh& mesh = s.Mesh();
  const double quantum = 1e-9 * std::max(s.Analysis().Diagonal, 1e-300);
  tbb::parallel_for(std::size_t(0), leaves.size(), [&](std::size_t i) { ListSamples(s, leaves[i], work[i]); });

  // Candidate g (in leaf order) is candidate g - start[i] of leaf i.
  std::vector<std::size_t> start(leaves.size() + 1, 0);
  for (std::size_t i = 0; i < leaves.size(); ++i)
  {
    start[i + 1] = start[i] + work[i].SharedCandidates.size();
  }
  const std::size_t total = start.back();
  if (total >= std::numeric_limits<std::uint32_t>::max())
  {
    throw std::length_error("discontinuity meshing: " + std::to_string(total) + " shared samples, more than 2^32");
  }
  // (hash, candidate, its leaf): sorted by hash, then in leaf order.
  struct Entry
  {
    std::uint64_t Hash;
    std::uint32_t G;
    std::uint32_t Leaf;
    bool operator<(const Entry& o) const { return this->Hash < o.Hash || (this->Hash == o.Hash && this->G < o.G); }
  };
  auto keyOf = [&](const Entry& e) {
    const LeafWork& w = work[e.Leaf];
    return KeyOf(CandidatePoint(w, w.SharedCandidates[e.G - start[e.Leaf]]), mesh[leaves[e.Leaf]].Normal, quantum);
  };
  std::vector<Entry> byHash(total);
  tbb::parallel_for(std::size_t(0), leaves.size(), [&](std::size_t i) {
    const LeafWork& w = work[i];
    for (std::size_t j = 0; j < w.SharedCandidates.size(); ++j)
    {
      const auto g = static_cast<std::uint32_t>(start[i] + j);
      byHash[g] = { 0, g, static_cast<std::uint32_t>(i) };
      byHash[g].Hash = HashOf(keyOf(byHash[g]));
    }
  });
  tbb::parallel_sort(byHash.begin(), byHash.end());

  // first[g]: the first candidate (in leaf order) with g's key. A run of
  // equal hashes is in leaf order; its keys are compared to tell a collision.
  std::vector<std::uint32_t> first(total);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, total), [&](const tbb::blocked_range<std::size_t>& range) {
    std::size_t r = range.begin();
    while (r > 0 && r < total && byHash[r - 1].Hash == byHash[r].Hash)
    {
      ++r; // the run began in the range before: its range takes it whole
    }
    while (r < range.end())
    {
      std::size_t end = r + 1;
      while (end < total && byHash[end].Hash == byHash[r].Hash)
      {
        ++end;
      }
      if (end == r + 1)
      {
        first[byHash[r].G] = byHash[r].G;
      }
      else
      {
        boost::container::small_vector<SampleKey, 8> keys;
        for (std::size_t m = r; m < end; ++m)
        {
          keys.push_back(keyOf(byHash[m]));
          std::size_t p = r;
          while (keys[p - r] != keys[m - r])
          {
            ++p;
          }
          first[byHash[m].G] = byHash[p].G;
        }
      }
      r = end;
    }
  });

  // Numbered by first appearance; first[] becomes each candidate's number.
  // Each first appearance's number is the count of first appearances before
  // it: per leaf, then a prefix over the leaves, then written in parallel.
  std::vector<std::uint32_t> firstsBefore(leaves.size() + 1, 0);
  tbb::parallel_for(std::size_t(0), leaves.size(), [&](std::size_t i) {
    std::uint32_t count = 0;
    for (std::size_t g = start[i]; g < start[i + 1]; ++g)
    {
      count += first[g] == g;
    }
    firstsBefore[i + 1] = count;
  });
  for (std::size_t i = 0; i < leaves.size(); ++i)
  {
    firstsBefore[i + 1] += firstsBefore[i];
  }
  SharedSamples out;
  out.Points.resize(firstsBefore.back());
  out.Owner.resize(firstsBefore.back());
  std::vector<std::uint32_t> number(total);
  tbb::parallel_for(std::size_t(0), leaves.size(), [&](std::size_t i) {
    const LeafWork& w = work[i];
    std::uint32_t next = firstsBefore[i];
    for (std::size_t j = 0; j < w.SharedCandidates.size(); ++j)
    {
      const std::size_t g = start[i] + j;
      if (first[g] == g)
      {
        number[g] = next;
        out.Points[next] = CandidatePoint(w, w.SharedCandidates[j]);
        out.Owner[next] = static_cast<std::uint32_t>(i);
        ++next;
      }
    }
  });
  // A later appearance takes its first's number (first[g] < g, numbered above).
  tbb::parallel_for(std::size_t(0), total, [&](std::size_t g) {
    if (first[g] != g)
    {
      number[g] = number[first[g]];
    }
  });
  first.swap(number);
  tbb::parallel_for(std::size_t(0), leaves.size(), [&](std::size_t i) {
    LeafWork& w = work[i];
    for (SampleRef& r : w.VertexSamples)
    {
      r.Index = r.Shared ? first[start[i] + r.Index] : r.Index;
    }
    for (auto& t : w.TriangleSamples)
    {
      for (SampleRef& r : t)
      {
        r.Index = r.Shared ? first[start[i] + r.Index] : r.Index;
      }
    }
    w.SharedCandidates.clear();
  });
  return out;
}
} // namespace discontinuity_mesh_detail
} // namespace radiosity
