// Constrained Delaunay triangulation of one planar triangle with segments
// inside it as constraints: the explicit mesh of a leaf in Hardt & Teller's
// hybrid quadtree-mesh (section 2.1: "These discontinuity segments form the
// input to a constrained Delaunay triangulation algorithm"). CGAL's
// Constrained_Delaunay_triangulation_2 with exact predicates and constructions
// (Epeck, Exact_intersections_tag), so crossing constraints are split exactly.
#ifndef Radiosity_ConstrainedTriangulation_h
#define Radiosity_ConstrainedTriangulation_h

#include "Radiosity/Common/Types.h"

#include <array>
#include <cstdint>
#include <vector>

namespace radiosity
{
struct PlanarTriangulation
{
  std::vector<Vec3> Points;                            ///< in the plane of the domain
  std::vector<std::array<std::uint32_t, 3>> Triangles; ///< same orientation as the domain
  /// CGAL refused the constraints (it throws on a violated precondition):
  /// the result is the domain alone, and the caller counts and reports it.
  bool ConstraintsDropped = false;
};

/**
 * `boundaryPoints` are extra vertices on the domain's edges (the vertices of
 * neighbouring meshes there, so that neighbours share their boundary vertices
 * and no T-junction leaves a crack when the meshes are rasterised); points
 * not within the tolerance of an edge, or at a corner, are ignored.
 *
 * Triangulates `domain` with every segment of `constraints` as a constraint.
 * Segments are clipped to the domain first (parts outside are ignored, points
 * are projected into the domain's plane). The result covers the domain
 * exactly; its first three points are the domain's corners. With no usable
 * constraint the result is the domain itself (one triangle).
 *
 * Near-coincidences are resolved in double precision before the exact
 * triangulation, with a tolerance tol = max(1e-9 * longest domain edge,
 * 64 ulp of the domain's largest coordinate): clipped pieces shorter than tol
 * are dropped, endpoints within tol of a domain edge or corner are put
 * exactly onto it, endpoints within tol of an earlier endpoint are merged
 * with it, endpoints within tol of an earlier segment are put exactly onto
 * it, a segment passing within tol of an earlier endpoint is routed through
 * it, and segments along a domain edge are ignored (the edge is a constraint
 * already). Constraints may cross and overlap; their intersections are exact.
 * Points are moved by less than tol. A degenerate or non-finite domain is
 * returned as is.
 */
PlanarTriangulation TriangulateWithConstraints(const std::array<Vec3, 3>& domain,
  const std::vector<std::array<Vec3, 2>>& constraints,
  const std::vector<Vec3>& boundaryPoints = {});
} // namespace radiosity

#endif
