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

/// One edge of unoccluded sources, with the radiosity of the sources on
/// either side folded in (MergedLinkEdges).
struct ChainEdge
{
  Vec3 A, B;
  RGB Weight;
};

/**
 * Lambert's contour formula summed over several sources is a sum over their
 * edges, each weighted by its source's radiosity; an edge two sources share
 * is traversed once each way, so it takes one angle (atan2) with the
 * difference of their radiosities. A node's links partition what it sees
 * (the link hierarchy links every pair of points once), so neighbouring
 * sources of one node share most of their edges.
 *
 * This holds where the form factor is the plain contour sum: a source with
 * no blockers to backproject (unoccluded, or its visibility sampled), no
 * horizon clip and no facing test: its corners above the receiving node's
 * plane, and the node in front of its plane. Those links are marked, and
 * their edges kept per receiving node, shared ones merged; they serve every
 * leaf below the node, whose points pass the same tests (a leaf lies in its
 * ancestors' triangle). The office's chains: 1,353 edges per point become
 * 749 merged within each leaf.
 */
class MergedLinkEdges
{
public:
  explicit MergedLinkEdges(const HierarchicalRadiosity& s);
  /// Whether link i (an index into Links()) is brought by the edges.
  bool Merged(std::uint32_t i) const { return this->LinkMerged[i] != 0; }
  /// The merged edges of the links of `leaf` and its ancestors.
  std::vector<ChainEdge> ChainEdges(const HierarchicalRadiosity& s, std::uint32_t leaf) const;
  std::size_t NumberOfMergedLinks() const { return this->MergedCount; }
  /// The edges kept, over all nodes (at most three per merged link).
  std::size_t NumberOfEdges() const { return this->Edges.size(); }

private:
  std::vector<std::uint8_t> LinkMerged;
  std::vector<std::size_t> NodeStart; ///< per node, its edges' start in Edges (CSR)
  std::vector<ChainEdge> Edges;
  std::size_t MergedCount = 0;
};

/**
 * The sources of `leaf`, dark ones and hidden links left out, each partial
 * link with its blockers inside the link's shaft, coplanar pairs merged;
 * with `merged`, the links it brings by their edges left out too.
 * `constantPartial` (past the mesher's time limit): partial links take
 * their receiver-area mean instead of their blockers.
 */
std::vector<ChainSource> GatherChain(const HierarchicalRadiosity& s, std::uint32_t leaf, bool constantPartial = false,
  const MergedLinkEdges* merged = nullptr);

/// The irradiance at x (normal n) the chain brings: Lambert's contour
/// formula per source, through its blockers where it has them.
RGB ChainIrradiance(const std::vector<ChainSource>& chain, const Vec3& x, const Vec3& n);

/// The same with the chain's merged links' edges (GatherChain with the
/// MergedLinkEdges that made `edges`): equal to rounding, for x on the leaf.
RGB ChainIrradiance(
  const std::vector<ChainSource>& chain, const std::vector<ChainEdge>& edges, const Vec3& x, const Vec3& n);
} // namespace radiosity

#endif
