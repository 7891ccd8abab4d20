// What the receiver oracle and the fit of Lehtinen et al. 2007 (section
// 6.3, RECEIVER-ORACLE; eq. 10) look up around each basis function, listed
// once for every point: its neighbours on the coarsest level, its children
// on the next level, the coarser functions to compute before it, and the
// coarser levels' normalised basis values at its point. The solve finds
// them through the point index (a k-d tree search each); a relight, which
// refines the direct light again for every new lighting, reads them here
// instead (MeshlessRadiosity::Refine), in the same order, so that the two
// give the same field to the last bit. Section 6.5's runtime is the
// application of precomputed structure; this is the direct light's part.
#ifndef Radiosity_MeshlessNeighbourhoods_h
#define Radiosity_MeshlessNeighbourhoods_h

#include "Radiosity/Meshless/MeshlessPoints.h"

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace radiosity
{
class MeshlessNeighbourhoods
{
public:
  /// Lists every point's neighbourhoods (parallel). `keepGoing` is asked
  /// between blocks of points (false: PlacementAborted).
  explicit MeshlessNeighbourhoods(const PointHierarchy& points, const std::function<bool()>& keepGoing = {});

  /// A list's items: [begin, end).
  template <typename T>
  struct Span
  {
    const T* Begin;
    const T* End;
    const T* begin() const { return this->Begin; }
    const T* end() const { return this->End; }
  };
  /// Level 0 only: the coarsest functions non-zero at j's point facing its side.
  Span<std::uint32_t> Neighbours(std::uint32_t j) const { return this->Get(this->NeighbourStart, this->NeighbourItems, j); }
  /// The next level's functions centred in j's support, facing its side.
  Span<std::uint32_t> Children(std::uint32_t j) const { return this->Get(this->ChildStart, this->ChildItems, j); }
  /// Levels 1 to level(j) - 1: the functions non-zero at j's point facing its side.
  Span<std::uint32_t> Ancestors(std::uint32_t j) const { return this->Get(this->AncestorStart, this->AncestorItems, j); }
  /// Levels 0 to level(j) - 1: each level's normalised basis at j's point
  /// (ShepardField::Basis), level by level: the coarser approximation there.
  Span<std::pair<std::uint32_t, double>> Fit(std::uint32_t j) const { return this->Get(this->FitStart, this->FitItems, j); }

  std::size_t MemoryBytes() const;

private:
  template <typename T>
  static Span<T> Get(const std::vector<std::size_t>& start, const std::vector<T>& items, std::uint32_t j)
  {
    return { items.data() + start[j], items.data() + start[j + 1] };
  }
  std::vector<std::size_t> NeighbourStart, ChildStart, AncestorStart, FitStart;
  std::vector<std::uint32_t> NeighbourItems, ChildItems, AncestorItems;
  std::vector<std::pair<std::uint32_t, double>> FitItems;
};
} // namespace radiosity

#endif
