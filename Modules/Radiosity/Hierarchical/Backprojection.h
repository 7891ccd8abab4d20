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
} // namespace radiosity

#endif
