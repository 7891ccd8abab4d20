// The emitters' direct light at an output point, exact: what face cluster
// radiosity's output shows in place of its first iteration's fit of it
// where the emitting triangles are few (FaceClusterSettings::
// ExactEmitterTriangles), as it shows the punctual lights' closed form.
//
// For a point x (unit normal n) on input triangle t and each emitting
// triangle s of emission B_s:
//
//   E(x) += B_s * F_vis(x, s)
//
// F_vis is the vector form factor of the part of s that no triangle hides
// from x (Lambert's contour integral clipped to x's horizon): the
// backprojection of Hardt & Teller section 5 (Backprojection.h,
// VisibleVectorFormFactor), the integral over the visible fragments, so a
// penumbra is exact, not sampled. Its blockers are the triangles in the
// shaft between t and s (Haines & Wallace 1991, FaceClusterVisibility::
// ShaftBlockers), listed once per triangle and lamp and reused for t's
// corners and centre; none: the integral over the whole of s.
//
// The emitting triangles of one lamp (coplanar, sharing vertices) share one
// shaft per input triangle, to a triangle around them (the glossy statue's
// lamp of 32 triangles: one shaft instead of 32), and where its outline is
// convex and its emission uniform, one backprojection per point with the
// lamp as the source polygon. A point in a lamp's plane (where a wall meets
// an emitting one) takes the limit from inside t. Before the shaft, 28 rays (from
// four points of t to seven of the lamp) find the lamps t cannot see at
// all; those take 0 and no shaft (the floor under a statue, whose shafts
// hold the statue). Rays alone cannot tell a whole emitter from a partly
// hidden one: 28 of them all passed where a blocker's corner hid 3% of a
// lamp triangle from a floor vertex (0.7% of the exact penumbra's peak).
// Beyond MaxBlockers in a shaft, each emitter's visibility is sampled
// (TriangleGather: four rays, then 6 x 6 strata).
#ifndef Radiosity_FaceClusterExactEmitters_h
#define Radiosity_FaceClusterExactEmitters_h

#include "Radiosity/Common/TriangleGather.h"
#include "Radiosity/Hierarchical/Backprojection.h"

#include <array>
#include <cstdint>
#include <vector>

namespace radiosity
{
class FaceClusterVisibility;

class FaceClusterExactEmitters
{
public:
  /// Emitting triangles `triangles` (scene ids) with their emission.
  FaceClusterExactEmitters(
    const FaceClusterVisibility& visibility, const std::vector<std::uint32_t>& triangles, const std::vector<RGB>& emission);

  /// The emitters' vector irradiance (per channel) at x on triangle t
  /// (normal n); `rayOrigin`: where a sampled shadow ray starts.
  std::array<Vec3, 3> At(std::uint32_t t, const Vec3& x, const Vec3& n, const Vec3& rayOrigin) const;

  std::size_t Size() const { return this->Ids.size(); }
  /// The lamps, each counted once where one backprojection takes it whole
  /// (convex outline, one emission), else once per triangle: the output's
  /// cost per point.
  double Lamps() const;

  /// Blockers in a shaft beyond which visibility is sampled.
  static constexpr std::size_t MaxBlockers = 256;

private:
  const FaceClusterVisibility& Shafts;
  std::vector<std::uint32_t> Ids;
  std::vector<RadiantTriangle> Sources;
  /// Per emitter, its sampled gather (behind more than MaxBlockers).
  std::vector<TriangleGather> Strata;
  /// A lamp: emitting triangles in one plane, joined by shared vertices.
  /// One shaft (to a triangle around them all) lists the blockers of all
  /// of them, a superset for each: a blocker outside the pyramid from a
  /// point to an emitter casts its shadow beside it.
  struct Patch
  {
    std::vector<std::uint32_t> Members; ///< indices into Sources
    TriangleCorners Around;             ///< holds them all, facing as they do
    std::array<Vec3, 7> Samples;        ///< the rays' targets (hidden or not)
    Vec3 Normal{ 0.0 };                 ///< its plane: unit normal, offset,
    double Offset = 0.0, Size = 0.0;    ///< and the size of its bounds
    /// Where its triangles share one emission and their union one outline
    /// (a loop of boundary edges): that outline and the emission. Seen
    /// whole, the lamp's vector form factor is the contour integral over
    /// the outline alone (its inner edges cancel): one for the glossy
    /// statue's lamp instead of 32.
    std::vector<Vec3> Outline;
    RGB Radiosity{ 0.0 };
    /// That outline without its straight-through corners, where it is
    /// convex with at most MaxSourceCorners of them: the backprojection
    /// takes the lamp as one source (the glossy statue's lamp: a square).
    std::vector<Vec3> Convex;
  };
  std::vector<Patch> Patches;
  void MakePatches(const Scene& scene);
  void FindOutline(const Scene& scene, Patch& patch) const;
  /// Per patch, whether all 28 rays from four points of triangle t to its
  /// seven samples are blocked (or it lies behind t, or t behind it).
  void FindHidden(std::uint32_t t, std::vector<char>& hidden) const;
  /// Which object a thread's cached shafts belong to (never reused, unlike an address).
  std::uint64_t Generation = 0;
};
} // namespace radiosity

#endif
