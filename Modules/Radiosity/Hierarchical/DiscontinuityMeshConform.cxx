// Conforming the discontinuity mesh's leaves (DiscontinuityMeshWork.h):
// neighbouring leaves of different levels, or with discontinuity segments
// ending on their common edge, do not share their boundary vertices, and the
// T-junctions leave pixel cracks when the meshes are rasterised. Every vertex
// that lies on a leaf's edge is inserted into that leaf's triangulation: the
// boundary vertices of all leaves go into a uniform grid (cells of the mean
// leaf edge), and each leaf walks its three edges through it.
#include "Radiosity/Hierarchical/DiscontinuityMeshWork.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>

namespace radiosity
{
namespace discontinuity_mesh_detail
{
double EdgeDistance(const Vec3& p, const Vec3& a, const Vec3& b, bool& inside, double margin)
{
  const Vec3 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0 ? glm::dot(p - a, ab) / len2 : 0.0;
  const double m = len2 > 0 ? margin / std::sqrt(len2) : 1.0;
  inside = t > m && t < 1.0 - m;
  return glm::length(p - (a + std::clamp(t, 0.0, 1.0) * ab));
}

int LeafEdgeOf(const TriangleCorners& corners, double tolerance, const Vec3& x)
{
  for (int k = 0; k < 3; ++k)
  {
    bool inside = false;
    if (EdgeDistance(x, corners[k], corners[(k + 1) % 3], inside, 0.0) < tolerance)
    {
      return k;
    }
  }
  return -1;
}

namespace
{
/// The vertices of leaf i's triangulation on its boundary (its corners first).
template <typename Visit>
void BoundaryVertices(const HierarchicalRadiosity& s, std::uint32_t leaf, const LeafWork& w, Visit&& visit)
{
  const TriangleCorners c = s.Corners(leaf);
  const double tol = 1e-7 * s.Mesh().LongestEdge(leaf);
  for (std::size_t v = 0; v < w.Mesh.Points.size(); ++v)
  {
    const Vec3& p = w.Mesh.Points[v];
    if (v < 3 || LeafEdgeOf(c, tol, p) >= 0)
    {
      visit(p);
    }
  }
}
} // namespace

std::size_t ConformBoundaries(
  const HierarchicalRadiosity& s, const std::vector<std::uint32_t>& leaves, LeafWorks& work)
{
  const ElementMesh& mesh = s.Mesh();
  if (leaves.empty())
  {
    return 0;
  }
  double meanEdge = 0.0;
  for (std::uint32_t leaf : leaves)
  {
    meanEdge += mesh.LongestEdge(leaf);
  }
  const double h = meanEdge / static_cast<double>(leaves.size());
  if (!(h > 0))
  {
    return 0;
  }
  auto cellOf = [h](const Vec3& p) {
    return std::array<std::int64_t, 3>{ static_cast<std::int64_t>(std::floor(p.x / h)),
      static_cast<std::int64_t>(std::floor(p.y / h)), static_cast<std::int64_t>(std::floor(p.z / h)) };
  };
  auto keyOf = [](const std::array<std::int64_t, 3>& c) {
    return static_cast<std::uint64_t>(c[0]) * 73856093u ^ static_cast<std::uint64_t>(c[1]) * 19349663u ^
      static_cast<std::uint64_t>(c[2]) * 83492791u;
  };
  // Boundary vertices of every leaf's current triangulation, in leaf order:
  // counted, then written, in parallel.
  std::vector<std::size_t> start(leaves.size() + 1, 0);
  tbb::parallel_for(std::size_t(0), leaves.size(), [&](std::size_t i) {
    BoundaryVertices(s, leaves[i], work[i], [&](const Vec3&) { ++start[i + 1]; });
  });
  for (std::size_t i = 0; i < leaves.size(); ++i)
  {
    start[i + 1] += start[i];
  }
  std::vector<Vec3> points(start.back());
  std::vector<std::uint32_t> owner(start.back());
  // The grid: (cell key, point) sorted, each key's run found by a hash of
  // the keys; a run lists its points in leaf order.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> byCell(start.back());
  tbb::parallel_for(std::size_t(0), leaves.size(), [&](std::size_t i) {
    std::size_t k = start[i];
    BoundaryVertices(s, leaves[i], work[i], [&](const Vec3& p) {
      points[k] = p;
      owner[k] = static_cast<std::uint32_t>(i);
      byCell[k] = { keyOf(cellOf(p)), static_cast<std::uint32_t>(k) };
      ++k;
    });
  });
  tbb::parallel_sort(byCell.begin(), byCell.end());
  // Each key's run in an open-addressing table (linear probing, at most half
  // full): the leaves look up some 40 cells each, and a node-based map's
  // lookups were most of this step at a million leaves.
  struct Run
  {
    std::uint64_t Key = 0;
    std::uint32_t Begin = 0, End = 0; ///< End 0: an empty slot
  };
  std::size_t runs = 0;
  for (std::size_t k = 0; k < byCell.size(); ++k)
  {
    runs += k == 0 || byCell[k].first != byCell[k - 1].first;
  }
  std::size_t capacity = 16;
  while (capacity < 2 * runs)
  {
    capacity *= 2;
  }
  const std::uint64_t mask = capacity - 1;
  auto slotOf = [mask](std::uint64_t key) {
    key ^= key >> 33; // the cell keys' low bits alone cluster
    key *= 0xff51afd7ed558ccdull;
    key ^= key >> 33;
    return key & mask;
  };
  std::vector<Run> grid(capacity);
  for (std::size_t k = 0; k < byCell.size();)
  {
    std::size_t end = k + 1;
    while (end < byCell.size() && byCell[end].first == byCell[k].first)
    {
      ++end;
    }
    std::uint64_t slot = slotOf(byCell[k].first);
    while (grid[slot].End != 0)
    {
      slot = (slot + 1) & mask;
    }
    grid[slot] = { byCell[k].first, static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(end) };
    k = end;
  }
  auto find = [&](std::uint64_t key) -> const Run* {
    for (std::uint64_t slot = slotOf(key);; slot = (slot + 1) & mask)
    {
      if (grid[slot].End == 0)
      {
        return nullptr;
      }
      if (grid[slot].Key == key)
      {
        return &grid[slot];
      }
    }
  };
  std::vector<unsigned char> conformed(leaves.size(), 0);
  tbb::parallel_for(std::size_t(0), leaves.size(), [&](std::size_t i) {
    const TriangleCorners c = s.Corners(leaves[i]);
    const double longest = mesh.LongestEdge(leaves[i]);
    const double tol = 1e-7 * longest;
    boost::container::small_vector<Vec3, 8> extra;
    boost::container::small_vector<std::uint64_t, 32> cells;
    for (int e = 0; e < 3; ++e)
    {
      const Vec3& a = c[e];
      const Vec3& b = c[(e + 1) % 3];
      const double length = glm::length(b - a);
      // The cells that a point within tol of the edge can lie in: those
      // meeting the boxes of the edge's pieces no longer than a cell, each
      // at most two cells wide per axis.
      const int pieces = 1 + static_cast<int>(length / h);
      cells.clear();
      for (int t = 0; t < pieces; ++t)
      {
        const Vec3 p = a + (static_cast<double>(t) / pieces) * (b - a);
        const Vec3 q = a + (static_cast<double>(t + 1) / pieces) * (b - a);
        const auto lo = cellOf(glm::min(p, q) - Vec3(tol));
        const auto hi = cellOf(glm::max(p, q) + Vec3(tol));
        for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
        {
          for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
          {
            for (std::int64_t z = lo[2]; z <= hi[2]; ++z)
            {
              cells.push_back(keyOf({ x, y, z }));
            }
          }
        }
      }
      std::sort(cells.begin(), cells.end());
      cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
      // A point outside the edge's box grown by 2 tol is farther than tol
      // from it whatever the rounding: EdgeDistance is not needed there.
      const Vec3 boxLo = glm::min(a, b) - Vec3(2.0 * tol), boxHi = glm::max(a, b) + Vec3(2.0 * tol);
      for (const std::uint64_t key : cells)
      {
        const Run* run = find(key);
        if (!run)
        {
          continue;
        }
        for (std::uint32_t r = run->Begin; r < run->End; ++r)
        {
          const std::uint32_t k = byCell[r].second;
          bool inside = false;
          const Vec3& p = points[k];
          if (owner[k] != i && glm::all(glm::greaterThanEqual(p, boxLo)) && glm::all(glm::lessThanEqual(p, boxHi)) &&
            EdgeDistance(p, a, b, inside, 10.0 * tol) < tol && inside)
          {
            extra.push_back(p);
          }
        }
      }
    }
    // Only points the leaf does not have yet.
    std::vector<Vec3> missing;
    for (const Vec3& p : extra)
    {
      bool known = false;
      for (const Vec3& q : work[i].Mesh.Points)
      {
        known = known || glm::length(p - q) < tol;
      }
      for (const Vec3& q : missing)
      {
        known = known || glm::length(p - q) < tol;
      }
      if (!known)
      {
        missing.push_back(p);
      }
    }
    if (!missing.empty())
    {
      work[i].Mesh = TriangulateWithConstraints(c, work[i].Segments, missing);
      conformed[i] = 1;
    }
  });
  return static_cast<std::size_t>(std::count(conformed.begin(), conformed.end(), 1));
}
} // namespace discontinuity_mesh_detail
} // namespace radiosity
