#ifndef Radiosity_Hierarchical_EdgeTopology_h
#define Radiosity_Hierarchical_EdgeTopology_h

// Internal to the discontinuity mesher: which edges of the input bound
// something (Hardt & Teller section 4.2 traces critical surfaces from the
// silhouette edges of blockers and the outline of sources only).

#include "Radiosity/Common/Scene.h"
#include "Radiosity/Hierarchical/CriticalSurfaces.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace radiosity
{
namespace discontinuity_mesh_detail
{
/// Which edges of the input are silhouettes: an edge shared with a coplanar
/// triangle of the same emission (the diagonal of a quad) bounds nothing.
class EdgeTopology
{
public:
  explicit EdgeTopology(const Scene& scene);

  bool Coplanar(std::uint32_t a, std::uint32_t b) const;
  /// The one triangle across side k of triangle t (the side from corner k to
  /// k + 1) when it is coplanar with t, else None (no such triangle, or more
  /// than two triangles share that edge).
  std::uint32_t CoplanarNeighbour(std::uint32_t t, int k) const
  {
    const std::uint32_t across = this->CoplanarAcross[3 * t + static_cast<std::uint32_t>(k)];
    return across == SeveralTriangles ? None : across;
  }
  static constexpr std::uint32_t None = 0xffffffffu;

  /// Edge k of source triangle t lies inside a larger emitting polygon.
  bool InteriorEmitterEdge(std::uint32_t t, int k) const;

  /// The edges of a blocker set (sorted triangle ids) that are not shared by
  /// two coplanar members.
  std::vector<BlockerEdge> Silhouette(const std::vector<std::uint32_t>& blockers) const;

private:
  using EdgeEntry = std::pair<std::uint64_t, std::uint32_t>; ///< (edge key, 3 triangle + side)

  /// The entries of Edges with this key: the triangles that have the edge.
  std::pair<const EdgeEntry*, const EdgeEntry*> Sharing(std::uint64_t edge) const;

  /// The other triangles across side k of triangle t that are coplanar with
  /// it, through `visit` (true from visit stops the walk and is returned).
  template <typename Visit>
  bool AnyCoplanarAcross(std::uint32_t t, int k, const Visit& visit) const;

  static constexpr std::uint32_t NoTriangle = None;
  static constexpr std::uint32_t SeveralTriangles = 0xfffffffeu;

  const Scene& SourceScene;
  std::vector<EdgeEntry> Edges; ///< sorted
  /// Per side 3 t + k: the one other triangle on that edge when it is
  /// coplanar with t, NoTriangle when there is none such, SeveralTriangles
  /// when more than two triangles share the edge (then Edges is searched).
  /// Read for every blocker edge of every leaf under a partial link: a
  /// search of Edges per edge was most of the mesher's first phase at a
  /// million triangles.
  std::vector<std::uint32_t> CoplanarAcross;
};
} // namespace discontinuity_mesh_detail
} // namespace radiosity

#endif
