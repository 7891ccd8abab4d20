// The links that irradiate one quadtree leaf of Hanrahan-Salzman-Aupperle
// hierarchical radiosity (its own and its ancestors'), gathered with the
// blockers of each partially visible one for Hardt & Teller's accurate point
// irradiance (section 5: backprojection through the blockers at a point).
// Internal to the discontinuity mesher (DiscontinuityMesher.cxx).
#ifndef Radiosity_LinkChain_h
#define Radiosity_LinkChain_h

#include "Radiosity/Hierarchical/Backprojection.h"
#include "Radiosity/Hierarchical/HierarchicalRadiosity.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace radiosity
{
/// One source that irradiates a leaf: a link of the leaf or of an ancestor.
struct ChainSource
{
  TriangleCorners Polygon;
  RGB Radiosity;
  /// The backprojection through the link's blockers inside its shaft,
  /// coplanar pairs merged, prepared for the leaf's points; null for an
  /// unoccluded link (and when no blocker is left in the shaft).
  std::unique_ptr<const PreparedVisibleFormFactor> Blockers;
  const HierarchicalLink* Link;
  /// A link whose blockers were cut: its sampled visible fraction scales the
  /// unoccluded form factor (HierarchicalLink::BlockersCut).
  double Visible = 1.0;
  /// Past the mesher's time limit a partial link brings its receiver-area
  /// mean (HierarchicalLink::Factor: the solve's own value) to every point,
  /// instead of the exact backprojection through its blockers.
  bool Constant = false;
};

/**
 * The sources of `leaf`, dark ones and hidden links left out, each partial
 * link with its blockers inside the link's shaft, coplanar pairs merged.
 * `constantPartial` (past the mesher's time limit): partial links take
 * their receiver-area mean instead of their blockers.
 */
std::vector<ChainSource> GatherChain(const HierarchicalRadiosity& s, std::uint32_t leaf, bool constantPartial = false);

/// The irradiance at x (normal n) the chain brings: Lambert's contour
/// formula per source, through its blockers where it has them.
RGB ChainIrradiance(const std::vector<ChainSource>& chain, const Vec3& x, const Vec3& n);
} // namespace radiosity

#endif
