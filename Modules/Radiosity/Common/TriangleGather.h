// Exact vector irradiance at a point from triangles of constant radiosity:
// the gather of vector radiosity (Arvo 1994; Gobbetti, Spano & Agus 2003,
// section 3.5, the irradiance vector a glossy display reads).
//
// For a point p with unit normal n:
//
//   E_c(p) = sum over triangles t of B_t,c * V_t(p) * F_t(p)
//
// F_t(p) is t's exact vector form factor at p (Lambert's contour integral,
// PointToPolygonVectorFormFactor) with t clipped to p's hemisphere, zero
// when p lies behind t or in its plane (one-sided sources; a neighbour on
// the same flat face seen edge on).
//
// Visibility V_t(p) by stratified shadow rays: four first, from the ray
// origin to t's centroid and to three points just inside its corners. When
// all four agree, t is wholly visible or hidden; otherwise t is split into
// m x m congruent strata, each weighted by one ray to its centroid. The
// contour integral is additive, so an unoccluded triangle is exact at any
// m, and only a shadow boundary is sampled.
//
// Used by the dense gather reference (VectorIrradianceReference.h) over a
// converged solution's triangles, and by face cluster radiosity's output
// for the emitting triangles of a lamp hidden behind more blockers than
// its shaft lists (FaceClusterExactEmitters::MaxBlockers).
#ifndef Radiosity_TriangleGather_h
#define Radiosity_TriangleGather_h

#include "Radiosity/Common/Types.h"

#include <array>
#include <vector>

namespace radiosity
{
class Visibility;

/// A triangle with constant radiosity (W/m^2, RGB), front side right-handed.
struct RadiantTriangle
{
  std::array<Vec3, 3> Corners;
  RGB Radiosity{ 0.0 };
};

class TriangleGather
{
public:
  /// `rays`: the occluders (null or empty: nothing hides anything), kept
  /// alive by the caller. `strataPerEdge`: m of a partly hidden triangle.
  TriangleGather(std::vector<RadiantTriangle> sources, const Visibility* rays, int strataPerEdge = 6);

  /// Per call scratch space, one per thread.
  struct Scratch
  {
    std::vector<std::uint32_t> Facing;
    std::vector<Vec3> Vectors, From, To;
    std::vector<unsigned char> Visible, PartVisible;
    std::vector<std::array<Vec3, 3>> Parts;
  };

  /// The three channels' irradiance vectors at p (unit normal n), the
  /// shadow rays cast from `rayOrigin` (p moved off its surface).
  std::array<Vec3, 3> At(const Vec3& p, const Vec3& n, const Vec3& rayOrigin, Scratch& scratch) const;

  std::size_t Size() const { return this->Sources.size(); }
  const std::vector<RadiantTriangle>& Triangles() const { return this->Sources; }

private:
  std::vector<RadiantTriangle> Sources;
  std::vector<Vec3> AreaVectors; ///< twice the area along the front normal
  const Visibility* Rays;
  int Strata;
};

/// The m x m congruent parts of triangle t, all oriented as it is.
void SplitTriangle(const std::array<Vec3, 3>& t, int m, std::vector<std::array<Vec3, 3>>& parts);
} // namespace radiosity

#endif
