// Exact point-to-polygon form factors through polygonal blockers.
//
// Hardt & Teller section 5 ("Accurate point irradiance"): "we backproject
// potential blockers to the source [Drettakis & Fiume 1994], and add only
// irradiance from unobscured fragments". For a point x, each blocker triangle
// is clipped to the slab between x and the source's plane and projected
// centrally from x onto that plane; the visible part of the source is the
// source minus the union of these convex shadows, kept as disjoint convex
// fragments (a convex polygon minus a convex polygon is at most one convex
// piece per edge of the subtrahend). The form factor is the sum of Lambert's
// contour formula over the fragments, so it is exact for polygonal blockers:
// no sampling, no noise.
#ifndef Radiosity_Backprojection_h
#define Radiosity_Backprojection_h

#include "Radiosity/Common/Types.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace radiosity
{
using TriangleCorners = std::array<Vec3, 3>;

/**
 * Form factor from the differential receiver (x, n) to the part of the
 * one-sided source triangle `source` that no triangle of `blockers` hides
 * from x. Blockers behind x, behind the source or outside the pyramid from x
 * to the source change nothing. `fragmentsLimit` bounds the number of convex
 * visible fragments kept (beyond it the remaining blockers are ignored and
 * `exact`, when given, is set to false).
 */
double VisibleFormFactor(const Vec3& x, const Vec3& n, const TriangleCorners& source,
  const TriangleCorners* blockers, std::size_t blockerCount, bool* exact = nullptr,
  std::size_t fragmentsLimit = 4096);

/// A planar convex blocker of three or four corners (in order around it).
struct BlockerPolygon
{
  std::array<Vec3, 4> Corners;
  int Size = 3;
};

/// The same through convex polygons: two coplanar triangles of a quad cast
/// one shadow, so the visible part is clipped once, not twice along their
/// shared diagonal (MergeCoplanarPairs).
double VisibleFormFactor(const Vec3& x, const Vec3& n, const TriangleCorners& source,
  const BlockerPolygon* blockers, std::size_t blockerCount, bool* exact = nullptr,
  std::size_t fragmentsLimit = 4096);

/**
 * Blocker triangles (`corners`, with `vertexIds` their shared point indices)
 * as convex polygons: each pair that shares an edge, lies in one plane
 * (normals within 1e-9) and forms a convex quad becomes one quad; the rest
 * stay triangles. The union, and so the shadow, is the same.
 */
std::vector<BlockerPolygon> MergeCoplanarPairs(
  const std::vector<TriangleCorners>& corners, const std::vector<std::array<std::uint32_t, 3>>& vertexIds);
} // namespace radiosity

#endif
