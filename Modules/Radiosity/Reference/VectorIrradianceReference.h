// A dense gather of the vector irradiance (the irradiance vector of vector
// radiosity: one 3-vector per colour channel, whose dot product with a unit
// normal is the irradiance through that normal) at points with normals,
// from a converged radiosity given on triangles: the reference the face
// cluster solver's vertex output (section 3.5 of Gobbetti, Spano & Agus
// 2003: what vtkVectorIrradianceMapper displays) is checked against.
//
// The algorithm, for a point p with unit normal n:
//
//   E_c(p) = sum over source triangles t of B_t,c * V_t(p) * F_t(p)
//
// where F_t(p) is the exact vector form factor of t at p (Lambert's contour
// integral, (1 / 2 pi) sum over the edges of the angle the edge subtends at
// p times the unit normal of the plane through p and the edge:
// PointToPolygonVectorFormFactor), with t first clipped to p's hemisphere
// (the horizon: light from behind the surface never arrives), and zero when
// p is behind t (one-sided emitters). Every triangle counts, emitters and
// reflectors alike, whatever its distance: no clustering, no fit.
//
// Visibility V_t(p), by stratified shadow rays (Embree, Visibility.h): four
// rays first, from p (offset by the scene-relative epsilon along n) to t's
// centroid and to three points just inside its corners. When all four
// agree, t is taken as wholly visible or wholly hidden. Otherwise t is split
// into m x m congruent strata (m = MaxStrataPerEdge), each stratum's own
// exact vector form factor weighted by one ray to its centroid; since the
// contour integral is additive, an unoccluded triangle gets its exact vector
// form factor at any m, and only the shadow boundary is sampled.
//
// The radiosity B_t is constant on each source triangle; a smooth solution
// (a SolutionMesh with corner and centre samples per element) is handed in
// finely split by RadiantTrianglesOf, each part with the solution's
// radiosity at its centroid.
//
// Cost: points x sources x (4 rays + a contour integral), plus m^2 of both
// for each partly hidden source; in parallel over the points (TBB).
#ifndef Radiosity_VectorIrradianceReference_h
#define Radiosity_VectorIrradianceReference_h

#include "Radiosity/Common/Scene.h"
#include "Radiosity/Common/SolutionMesh.h"
#include "Radiosity/Common/TriangleGather.h"

#include <array>
#include <vector>

namespace radiosity
{
struct VectorGatherOptions
{
  /// Strata per edge of a partly hidden source triangle (m x m strata).
  int MaxStrataPerEdge = 6;
};

/// Per point, the three channels' irradiance vectors (R, G, B) gathered
/// from `sources`, with visibility against every triangle of `occluders`.
std::vector<std::array<Vec3, 3>> GatherVectorIrradiance(const Scene& occluders,
  const std::vector<RadiantTriangle>& sources, const std::vector<Vec3>& points,
  const std::vector<Vec3>& normals, const VectorGatherOptions& options = {});

/// The solution's elements, each split into m x m congruent parts
/// (`strataPerEdge`), each with emission + reflectance times the solution's
/// irradiance at its centroid (InterpolateSamples); the materials are those
/// of the elements' source triangles in `scene`. Black non-emitting parts
/// are left out.
std::vector<RadiantTriangle> RadiantTrianglesOf(
  const Scene& scene, const SolutionMesh& solution, int strataPerEdge);
} // namespace radiosity

#endif
