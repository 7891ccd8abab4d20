#include "Radiosity/Hierarchical/LinkChain.h"

#include "Radiosity/Common/ContourSum.h"
#include "Radiosity/Common/FormFactor.h"
#include "Radiosity/Hierarchical/Shaft.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace radiosity
{
namespace
{
/// Whether the contour sum of `source` is its form factor at every point of
/// `receiver` (normal n): above the plane, and facing it.
bool PlainContour(const TriangleCorners& source, const TriangleCorners& receiver, const Vec3& n)
{
  const Vec3 area = glm::cross(source[1] - source[0], source[2] - source[0]);
  for (const Vec3& r : receiver)
  {
    if (!(glm::dot(r - source[0], area) >= 0.0))
    {
      return false;
    }
    for (const Vec3& p : source)
    {
      if (!(glm::dot(p - r, n) >= 0.0))
      {
        return false;
      }
    }
  }
  return true;
}

/// Whether no point of `receiver` (normal n) sees any of `source`: the
/// source is on or below the receiver's plane, or the receiver on or behind
/// the source's (one-sided). A node's link may reach a leaf below it that
/// its source's plane cuts off.
bool SeesNothing(const TriangleCorners& source, const TriangleCorners& receiver, const Vec3& n)
{
  const Vec3 area = glm::cross(source[1] - source[0], source[2] - source[0]);
  bool below = true, behind = true;
  for (int k = 0; k < 3; ++k)
  {
    below = below && glm::dot(source[k] - receiver[0], n) <= 0.0;
    behind = behind && glm::dot(receiver[k] - source[0], area) <= 0.0;
  }
  return below || behind;
}

/// The merged edges of one node's plain links, marked in `merged`.
std::vector<ChainEdge> NodeEdges(const HierarchicalRadiosity& s, std::uint32_t node, std::vector<std::uint8_t>& merged)
{
  const TriangleCorners receiver = s.Corners(node);
  const Vec3& n = s.Mesh()[node].Normal;
  std::vector<ChainEdge> directed; // A before B lexicographically
  for (std::uint32_t i : s.LinksOf(node))
  {
    const HierarchicalLink& l = s.Links()[i];
    const bool sampled = l.Kind == HierarchicalLink::Partial && l.BlockersCut;
    if (!(l.Kind == HierarchicalLink::Visible || sampled) || !(MaxComponent(s.Radiosity(l.Source)) > 0))
    {
      continue;
    }
    const TriangleCorners p = s.Corners(l.Source);
    if (!PlainContour(p, receiver, n))
    {
      continue;
    }
    merged[i] = 1;
    const RGB weight = static_cast<double>(l.VisibleFraction) * s.Radiosity(l.Source);
    for (int k = 0; k < 3; ++k)
    {
      const Vec3& a = p[k];
      const Vec3& b = p[(k + 1) % 3];
      // An edge's term changes sign with its direction.
      directed.push_back(LexLess(a, b) ? ChainEdge{ a, b, weight } : ChainEdge{ b, a, -weight });
    }
  }
  std::sort(directed.begin(), directed.end(), [](const ChainEdge& d, const ChainEdge& e) {
    return LexLess(d.A, e.A) || (d.A == e.A && LexLess(d.B, e.B));
  });
  std::vector<ChainEdge> edges;
  for (const ChainEdge& d : directed)
  {
    if (!edges.empty() && edges.back().A == d.A && edges.back().B == d.B)
    {
      edges.back().Weight += d.Weight;
    }
    else
    {
      edges.push_back(d);
    }
  }
  // An edge between sources of one radiosity brings nothing.
  edges.erase(std::remove_if(edges.begin(), edges.end(), [](const ChainEdge& e) { return e.Weight == RGB(0.0); }),
    edges.end());
  return edges;
}
} // namespace

MergedLinkEdges::MergedLinkEdges(const HierarchicalRadiosity& s)
  : LinkMerged(s.Links().size(), 0)
  , NodeStart(s.Mesh().Elements().size() + 1, 0)
{
  const std::size_t nodes = s.Mesh().Elements().size();
  std::vector<std::vector<ChainEdge>> perNode(nodes);
  // Each node's links are its own consecutive range: the marks do not overlap.
  tbb::parallel_for(std::size_t(0), nodes, [&](std::size_t e) {
    const auto node = static_cast<std::uint32_t>(e);
    if (!s.LinksOf(node).empty())
    {
      perNode[e] = NodeEdges(s, node, this->LinkMerged);
    }
  });
  for (std::size_t e = 0; e < nodes; ++e)
  {
    this->NodeStart[e + 1] = this->NodeStart[e] + perNode[e].size();
  }
  this->Edges.resize(this->NodeStart.back());
  this->MergedCount = static_cast<std::size_t>(std::count(this->LinkMerged.begin(), this->LinkMerged.end(), 1));
  tbb::parallel_for(std::size_t(0), nodes, [&](std::size_t e) {
    std::copy(perNode[e].begin(), perNode[e].end(), this->Edges.begin() + static_cast<std::ptrdiff_t>(this->NodeStart[e]));
    perNode[e] = {};
  });
}

std::vector<ChainEdge> MergedLinkEdges::ChainEdges(const HierarchicalRadiosity& s, std::uint32_t leaf) const
{
  std::vector<ChainEdge> edges;
  for (std::int32_t a = static_cast<std::int32_t>(leaf); a >= 0; a = s.Mesh()[static_cast<std::uint32_t>(a)].Parent)
  {
    const auto e = static_cast<std::size_t>(a);
    edges.insert(edges.end(), this->Edges.begin() + static_cast<std::ptrdiff_t>(this->NodeStart[e]),
      this->Edges.begin() + static_cast<std::ptrdiff_t>(this->NodeStart[e + 1]));
  }
  return edges;
}

std::vector<ChainSource> GatherChain(const HierarchicalRadiosity& s, std::uint32_t leaf, bool constantPartial,
  const MergedLinkEdges* merged)
{
  const ElementMesh& mesh = s.Mesh();
  const Scene& scene = s.GetScene();
  const TriangleCorners receiver = s.Corners(leaf);
  std::vector<ChainSource> chain;
  for (std::int32_t a = static_cast<std::int32_t>(leaf); a >= 0;
       a = mesh[static_cast<std::uint32_t>(a)].Parent)
  {
    for (std::uint32_t i : s.LinksOf(static_cast<std::uint32_t>(a)))
    {
      // The merged links first: their marks are read in order, the
      // sources' radiosities at random.
      if (merged && merged->Merged(i))
      {
        continue;
      }
      const HierarchicalLink& l = s.Links()[i];
      if (l.Kind == HierarchicalLink::Hidden || !(MaxComponent(s.Radiosity(l.Source)) > 0))
      {
        continue;
      }
      ChainSource c{ s.Corners(l.Source), s.Radiosity(l.Source), nullptr, &l, l.VisibleFraction };
      if (l.Kind == HierarchicalLink::Partial && !l.BlockersCut && constantPartial)
      {
        c.Constant = true;
      }
      else if (SeesNothing(c.Polygon, receiver, mesh[leaf].Normal))
      {
        continue;
      }
      else if (l.Kind == HierarchicalLink::Partial && !l.BlockersCut)
      {
        // The solve kept the blockers inside the shaft of the link's own
        // receiver and source (HierarchicalLinkFactors.cxx): the leaf's own
        // links need no second test, an ancestor's are cut to the leaf's shaft.
        std::optional<Shaft> shaft;
        if (l.Receiver != leaf)
        {
          shaft.emplace(receiver, c.Polygon);
        }
        // Per thread, kept between links: a leaf gathers a few hundred.
        thread_local std::vector<TriangleCorners> corners;
        thread_local std::vector<std::array<std::uint32_t, 3>> ids;
        thread_local std::vector<std::pair<double, std::size_t>> size;
        thread_local std::vector<BlockerPolygon> polygons;
        corners.clear();
        ids.clear();
        for (std::uint32_t k = 0; k < l.BlockerCount; ++k)
        {
          const std::uint32_t b = s.Blockers(l)[k];
          const TriangleCorners triangle = { scene.Vertex(b, 0), scene.Vertex(b, 1), scene.Vertex(b, 2) };
          if (!shaft || !shaft->Excludes(triangle))
          {
            corners.push_back(triangle);
            ids.push_back(scene.Triangles[b].V);
          }
        }
        const std::vector<BlockerPolygon> merged = MergeCoplanarPairs(corners, ids);
        // The largest seen from the leaf first: a point in their umbra has
        // nothing left to subtract the others from.
        const Vec3 centre = (receiver[0] + receiver[1] + receiver[2]) / 3.0;
        auto apparent = [&](const BlockerPolygon& b) {
          Vec3 area(0.0), middle(0.0);
          for (int k = 0; k < b.Size; ++k)
          {
            middle += b.Corners[k] / static_cast<double>(b.Size);
          }
          for (int k = 1; k + 1 < b.Size; ++k)
          {
            area += glm::cross(b.Corners[k] - b.Corners[0], b.Corners[k + 1] - b.Corners[0]);
          }
          const Vec3 d = middle - centre;
          return glm::length(area) / std::max(glm::dot(d, d), 1e-300);
        };
        size.resize(merged.size());
        for (std::size_t k = 0; k < merged.size(); ++k)
        {
          size[k] = { -apparent(merged[k]), k };
        }
        std::sort(size.begin(), size.end());
        polygons.resize(merged.size());
        for (std::size_t k = 0; k < merged.size(); ++k)
        {
          polygons[k] = merged[size[k].second];
        }
        // A leaf in the umbra of one blocker takes nothing from the link.
        if (std::any_of(polygons.begin(), polygons.end(),
              [&](const BlockerPolygon& b) { return HidesWholly(receiver, c.Polygon, b); }))
        {
          continue;
        }
        if (!polygons.empty())
        {
          c.Blockers = std::make_unique<const PreparedVisibleFormFactor>(c.Polygon, polygons.data(), polygons.size());
        }
      }
      chain.push_back(std::move(c));
    }
  }
  return chain;
}

RGB ChainIrradiance(
  const std::vector<ChainSource>& chain, const std::vector<ChainEdge>& edges, const Vec3& x, const Vec3& n)
{
  // The contour sum of a source that faces x from above its horizon is
  // -2 pi times its form factor (PointToPolygonFormFactor takes the modulus).
  ContourSum<RGB> sum;
  for (const ChainEdge& e : edges)
  {
    sum.Add(e.A - x, e.B - x, n, e.Weight);
  }
  return ChainIrradiance(chain, x, n) - sum.Sum() / (2.0 * Pi);
}

RGB ChainIrradiance(const std::vector<ChainSource>& chain, const Vec3& x, const Vec3& n)
{
  RGB e(0.0);
  for (const ChainSource& c : chain)
  {
    if (c.Constant)
    {
      e += c.Link->Factor * c.Radiosity;
      continue;
    }
    const double f = c.Blockers ? (*c.Blockers)(x, n) : PointToPolygonFormFactor(x, n, c.Polygon.data(), 3);
    e += (c.Visible * f) * c.Radiosity;
  }
  return e;
}
} // namespace radiosity
