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

#include <algorithm>
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

/// The vector form factor of the same visible part (Lambert's contour
/// integral over its fragments, each clipped to x's horizon): its dot
/// product with n is VisibleFormFactor's value. Face cluster radiosity's
/// output shows an emitter's direct light with it, shadows exact.
Vec3 VisibleVectorFormFactor(const Vec3& x, const Vec3& n, const TriangleCorners& source,
  const TriangleCorners* blockers, std::size_t blockerCount, bool* exact = nullptr,
  std::size_t fragmentsLimit = 4096);

/// The same for a convex planar source polygon of up to MaxSourceCorners
/// corners (a lamp of several triangles at once), facing as its corners
/// turn (right-handed).
constexpr int MaxSourceCorners = 6;
Vec3 VisibleVectorFormFactor(const Vec3& x, const Vec3& n, const Vec3* source, int corners,
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
 * Whether the convex `blocker` alone hides all of `source` from every point
 * of `receiver` (both triangles): each segment from a receiver corner to a
 * source corner meets it. The umbra of a convex blocker from a convex
 * source (the points whose every segment to the source meets the blocker)
 * is convex, an intersection of convex cones, so its corners decide for
 * the whole receiver, whose form factor to the source through the blocker
 * is then 0 everywhere, boundary included (the closed umbra).
 */
bool HidesWholly(const TriangleCorners& receiver, const TriangleCorners& source, const BlockerPolygon& blocker);

namespace backprojection_detail
{
struct Point2
{
  double X, Y;
};

/// A convex polygon in the source plane with a fixed capacity: fragments are
/// clipped millions of times, and heap allocation dominated the cost. A copy
/// takes its N corners only: most fragments have 3 to 6 of the 16, and the
/// whole array's copy was 28% of VisibleFromPoint's own time (Cornell box).
struct Polygon2
{
  static constexpr int Capacity = 16;
  Point2 V[Capacity];
  int N = 0;
  Polygon2() = default;
  Polygon2(const Polygon2& o)
    : N(o.N)
  {
    std::copy(o.V, o.V + o.N, this->V);
  }
  Polygon2& operator=(const Polygon2& o)
  {
    this->N = o.N;
    std::copy(o.V, o.V + o.N, this->V);
    return *this;
  }
  void Push(const Point2& p) { V[N++] = p; }
};

/// What the backprojection needs of a source whatever the point: its plane
/// (unit normal M, offset), a 2D frame in it (U along its first edge) and
/// its outline there.
struct SourceFrame
{
  explicit SourceFrame(const TriangleCorners& source);
  /// A convex planar polygon of at most MaxSourceCorners corners.
  SourceFrame(const Vec3* corners, int count);
  TriangleCorners Source; ///< its first three corners
  std::array<Vec3, MaxSourceCorners> Outline{};
  int Corners = 3;
  Vec3 M{ 0.0 }, U{ 0.0 }, V{ 0.0 };
  double PlaneOffset = 0.0;
  double MinArea = 0.0; ///< fragments below it are dropped
  double Size = 0.0;    ///< the longest edge
  bool Valid = false;   ///< a source of positive area
  Polygon2 Whole;
  Point2 To2(const Vec3& p) const
  {
    const Vec3 d = p - this->Source[0];
    return Point2{ glm::dot(d, this->U), glm::dot(d, this->V) };
  }
  Vec3 To3(const Point2& p) const { return this->Source[0] + p.X * this->U + p.Y * this->V; }
};

/// A blocker's corners with their levels along a source's normal (the
/// lowest and highest: which blockers lie between a point and the source)
/// and their coordinates in the source's frame (a shadow corner is then an
/// affine combination in 2D of the point's and the corner's).
struct BlockerLevels
{
  Vec3 Corner[4];
  int Size = 0;
  double Level[4];
  Point2 Flat[4];
  double Lowest = 0.0, Highest = 0.0;
  void FindLevels(const SourceFrame& frame);
};
} // namespace backprojection_detail

/**
 * VisibleFormFactor for many points against one source and its blockers
 * (the discontinuity mesher's samples on one leaf): the source's plane,
 * frame and outline and the blockers' levels are found once, not per point.
 * The value is VisibleFormFactor's to the last bit.
 */
class PreparedVisibleFormFactor
{
public:
  PreparedVisibleFormFactor(const TriangleCorners& source, const BlockerPolygon* blockers, std::size_t count);
  double operator()(const Vec3& x, const Vec3& n) const;
  std::size_t BlockerCount() const { return this->Blockers.size(); }

private:
  backprojection_detail::SourceFrame Frame;
  std::vector<backprojection_detail::BlockerLevels> Blockers;
};

/// Whether every turn of the closed quad quad[0] -> ... -> quad[3] is along
/// `normal` (any length): a convex quad wound about it. MergeCoplanarPairs'
/// test of a pair, and the mesher's sky test of an occluder and its
/// neighbour (DiscontinuityMeshSky.cxx).
bool ConvexQuad(const Vec3 (&quad)[4], const Vec3& normal);

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
