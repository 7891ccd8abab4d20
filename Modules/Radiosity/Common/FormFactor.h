// Point-to-polygon form factor kernels.
//
// - Lambert's contour formula (exact, any planar polygon, clipped to the
//   receiver's hemisphere): Cohen & Wallace 1993, eq. 4.x; used where the
//   receiver is near or touches the emitter, where the disc approximation's
//   kernel is singular (Coombe et al. 2004, section 3.3).
// - The disc approximation of Coombe et al. 2004, eq. 2 (Wallace et al. 1989),
//   with m = 1: cheap, accurate when the shooter is small seen from the receiver.
#ifndef Radiosity_FormFactor_h
#define Radiosity_FormFactor_h

#include "Radiosity/Common/Types.h"

#include <cstddef>

namespace radiosity
{
/**
 * Exact form factor from a differential receiver at `p` with unit normal `n`
 * to the planar polygon `poly` (vertices in order, any count). The polygon
 * is one-sided: its front is the side its right-hand normal points to; a
 * receiver behind it gets 0. The part of the polygon below the receiver's
 * tangent plane is clipped away (horizon clipping).
 */
double PointToPolygonFormFactor(const Vec3& p, const Vec3& n, const Vec3* poly, std::size_t count);

/// The vector form factor of a one-sided convex polygon at p (Lambert's
/// contour integral without a receiver: (1 / 2 pi) sum of theta_i times the
/// unit normal of the plane through p and edge i), pointing toward the
/// polygon; radiosity times it is the irradiance vector of vector radiosity.
/// With a receiver normal `horizon`, the polygon is first clipped to the
/// receiver's hemisphere, so that n . it is the receiver's form factor even
/// when the polygon straddles its tangent plane. Zero when p is behind the
/// polygon.
Vec3 PointToPolygonVectorFormFactor(
  const Vec3& p, const Vec3* poly, std::size_t count, const Vec3* horizon = nullptr);

/// Convenience overload for a triangle.
inline double PointToTriangleFormFactor(
  const Vec3& p, const Vec3& n, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 tri[3] = { a, b, c };
  return PointToPolygonFormFactor(p, n, tri, 3);
}

/**
 * Coombe et al. 2004 eq. 2 with one disc: form factor from a differential
 * receiver (p, n) to a shooter of area `area`, centre `q` and unit normal `m`:
 * A cos(theta_r) cos(theta_s) / (pi r^2 + A). Returns 0 when either side faces away.
 */
double DiscFormFactor(const Vec3& p, const Vec3& n, const Vec3& q, const Vec3& m, double area);

/**
 * Relative size of the shooter seen from the receiver, A / (pi r^2): the
 * disc approximation's error grows with it (it is exact for a coaxial disc,
 * and its error for other shapes and orientations is of this order).
 */
inline double ApparentSize(const Vec3& p, const Vec3& q, double area)
{
  const Vec3 d = q - p;
  const double r2 = glm::dot(d, d);
  return r2 > 0 ? area / (3.14159265358979323846 * r2) : 1e300;
}
} // namespace radiosity

#endif
