#include "Radiosity/Meshless/MeshlessNeighbourhoods.h"

#include "Radiosity/Meshless/ShepardField.h"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace radiosity
{
namespace
{
/// Points listed between two asks of keepGoing.
constexpr std::size_t NeighbourhoodBlock = 4096;

template <typename T>
void AppendLists(std::vector<std::vector<T>>& lists, std::vector<std::size_t>& start, std::vector<T>& items)
{
  for (std::vector<T>& l : lists)
  {
    items.insert(items.end(), l.begin(), l.end());
    start.push_back(items.size());
    l.clear();
  }
}
}

MeshlessNeighbourhoods::MeshlessNeighbourhoods(const PointHierarchy& points, const std::function<bool()>& keepGoing)
{
  const auto& all = points.Points();
  const int levels = points.NumberOfLevels();
  const ShepardField basis(points);
  for (std::vector<std::size_t>* start : { &this->NeighbourStart, &this->ChildStart, &this->AncestorStart, &this->FitStart })
  {
    start->assign(1, 0);
  }
  std::vector<std::vector<std::uint32_t>> neighbours, children, ancestors;
  std::vector<std::vector<std::pair<std::uint32_t, double>>> fit;
  for (std::size_t begin = 0; begin < all.size(); begin += NeighbourhoodBlock)
  {
    if (keepGoing && !keepGoing())
    {
      throw PlacementAborted();
    }
    const std::size_t end = std::min(all.size(), begin + NeighbourhoodBlock);
    neighbours.resize(end - begin);
    children.resize(end - begin);
    ancestors.resize(end - begin);
    fit.resize(end - begin);
    tbb::parallel_for(begin, end, [&](std::size_t j) {
      const MeshlessPoint& p = all[j];
      const std::size_t i = j - begin;
      thread_local std::vector<std::uint32_t> near;
      // As MeshlessRadiosity::Refine's searches: facing the point's side.
      const auto facing = [&](int level, const Vec3& at, std::vector<std::uint32_t>& into, double within) {
        near.clear();
        points.Supporting(level, p.Group, at, near);
        for (std::uint32_t k : near)
        {
          if (glm::dot(all[k].Normal, p.Normal) > 0 && (within <= 0 || glm::length(all[k].Position - at) < within))
          {
            into.push_back(k);
          }
        }
      };
      if (p.Level == 0)
      {
        facing(0, p.Position, neighbours[i], 0.0);
      }
      if (p.Level + 1 < levels)
      {
        facing(p.Level + 1, p.Position, children[i], p.Radius);
      }
      for (int coarser = 1; coarser < p.Level; ++coarser)
      {
        facing(coarser, p.Position, ancestors[i], 0.0);
      }
      for (int level = 0; level < p.Level; ++level)
      {
        basis.Basis(level, p.Group, p.Position, p.Normal, fit[i]);
      }
    });
    AppendLists(neighbours, this->NeighbourStart, this->NeighbourItems);
    AppendLists(children, this->ChildStart, this->ChildItems);
    AppendLists(ancestors, this->AncestorStart, this->AncestorItems);
    AppendLists(fit, this->FitStart, this->FitItems);
  }
}

std::size_t MeshlessNeighbourhoods::MemoryBytes() const
{
  return (this->NeighbourStart.size() + this->ChildStart.size() + this->AncestorStart.size() + this->FitStart.size()) *
    sizeof(std::size_t) +
    (this->NeighbourItems.size() + this->ChildItems.size() + this->AncestorItems.size()) * sizeof(std::uint32_t) +
    this->FitItems.size() * sizeof(std::pair<std::uint32_t, double>);
}
} // namespace radiosity
