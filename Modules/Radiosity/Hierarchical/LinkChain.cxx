#include "Radiosity/Hierarchical/LinkChain.h"

#include "Radiosity/Common/FormFactor.h"
#include "Radiosity/Hierarchical/Shaft.h"

namespace radiosity
{
std::vector<ChainSource> GatherChain(const HierarchicalRadiosity& s, std::uint32_t leaf, bool constantPartial)
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
      else if (l.Kind == HierarchicalLink::Partial && !l.BlockersCut)
      {
        const Shaft shaft(receiver, c.Polygon);
        std::vector<TriangleCorners> corners;
        std::vector<std::array<std::uint32_t, 3>> ids;
        for (std::uint32_t k = 0; k < l.BlockerCount; ++k)
        {
          const std::uint32_t b = s.Blockers(l)[k];
          const TriangleCorners triangle = { scene.Vertex(b, 0), scene.Vertex(b, 1), scene.Vertex(b, 2) };
          if (!shaft.Excludes(triangle))
          {
            corners.push_back(triangle);
            ids.push_back(scene.Triangles[b].V);
          }
        }
        const std::vector<BlockerPolygon> merged = MergeCoplanarPairs(corners, ids);
        if (!merged.empty())
        {
          c.Blockers = std::make_unique<const PreparedVisibleFormFactor>(c.Polygon, merged.data(), merged.size());
        }
      }
      chain.push_back(std::move(c));
    }
  }
  return chain;
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
