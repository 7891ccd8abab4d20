// Irradiance discontinuities on a receiver from one source polygon and its
// blockers: the EV and VE critical surfaces of Heckbert 1992 and Lischinski,
// Tampieri & Greenberg 1992 (EEE surfaces are ignored, as Hardt & Teller
// section 4.1 does), intersected with a receiving triangle, each weighted by
// the heuristic of Hardt & Teller section 4.2:
//   w = max(d_sb / d_br) * B_src
// over the source-blocker vertex pairs that span the surface, where d_sb is the
// distance from the source vertex to the blocker vertex and d_br the distance
// from the blocker vertex on to the receiver along the same line.
#ifndef Radiosity_CriticalSurfaces_h
#define Radiosity_CriticalSurfaces_h

#include "Radiosity/Common/Types.h"

#include <array>
#include <vector>

namespace radiosity
{
/// A piece of a discontinuity curve on a receiver, with its Hardt-Teller weight.
struct DiscontinuitySegment
{
  Vec3 A{ 0.0 }, B{ 0.0 };
  double Weight = 0.0; ///< W/m^2: the geometric factor times the source radiosity
};

/// An edge of a blocker that can be part of its silhouette (edges shared by two
/// coplanar blocker triangles are left out by the caller).
struct BlockerEdge
{
  Vec3 A{ 0.0 }, B{ 0.0 };
};

/**
 * Appends to `out` the intersections with the receiver triangle `receiver`
 * (plane normal `receiverNormal`) of
 *  - the EV surfaces: wedges spanned by a source edge and a blocker vertex
 *    (the endpoints of `blockerEdges`), and
 *  - the VE surfaces: wedges spanned by a source vertex and a blocker edge,
 * restricted to the part of each wedge beyond the blocker (seen from the
 * source) and clipped to the receiver triangle. `sourceRadiosity` is B_src
 * (a scalar, e.g. the largest channel). Segments shorter than `minLength`
 * are dropped. Surfaces that do not reach the receiver add nothing.
 *
 * The wedges, for source vertex v, blocker edge ab, source edge pq and
 * blocker vertex b:
 *   VE: { v + s (a + u (b - a) - v) : u in [0,1], s >= 1 },
 *   EV: { b + s (b - (p + u (q - p))) : u in [0,1], s >= 0 }.
 * `receiverNormal` is the normal of the receiver's plane (either sign; if it
 * is zero the triangle's own normal is used). Blocker vertices are the
 * distinct endpoints of `blockerEdges` (exact equality).
 *
 * Weight: for each source-blocker vertex pair spanning the surface (EV: p
 * and q with b; VE: v with a and with b), d_sb / d_br = 1 / (lambda - 1)
 * where v + lambda (b - v) is where the line from the source vertex through
 * the blocker vertex meets the receiver plane; a pair whose line meets the
 * plane before the blocker vertex, or never, does not count. Contact
 * (d_br -> 0) is capped at d_sb / d_br = 1e6, and a surface that reaches the
 * receiver although no pair counts (a blocker edge touching or piercing the
 * receiver plane) gets that cap too: weights are always finite.
 *
 * Left out: degenerate wedges (v on the line ab, b on the line pq), wedges
 * whose plane is parallel to the receiver's (no curve, or the whole plane),
 * and blocker edges and vertices lying in the receiver plane (they trace at
 * most their own outline). Every EV/VE wedge is reported; whether it is a
 * real discontinuity (silhouette test, occlusion of the wedge by other
 * blockers) is not decided here: the weight ranking is meant to sort that.
 * The result is appended to `out`, which is never cleared.
 */
/// `sourceEdges[i]` false leaves out the EV surfaces of source edge i -> i+1
/// (an edge inside a larger emitting polygon, the diagonal of a quad light).
/// Surfaces of weight below `minWeight` (H&T 4.2's w_min) are not traced:
/// their weight depends on the wedge and the receiver's plane only.
void FindCriticalSegments(const std::array<Vec3, 3>& receiver, const Vec3& receiverNormal,
  const std::array<Vec3, 3>& source, double sourceRadiosity,
  const std::vector<BlockerEdge>& blockerEdges, double minLength,
  std::vector<DiscontinuitySegment>& out,
  const std::array<bool, 3>& sourceEdges = { true, true, true }, double minWeight = 0.0);
} // namespace radiosity

#endif
