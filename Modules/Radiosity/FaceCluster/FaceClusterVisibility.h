// Multiresolution visibility through the face cluster hierarchy (Gobbetti et
// al. 2003, section 3.3.1, after Sillion & Drettakis 1995 and Gibson &
// Hubbold 1996): a segment from a receiver point x to an emitter point y
// descends from the roots into every cluster whose oriented box it crosses,
// until the cluster is a triangle (an exact segment-triangle test) or the
// shadow it would cast on the receiver, its size times |x - y| / |y - c|, is
// smaller than a threshold (the spacing of the receiver's cubature nodes).
// Such a cluster is not descended: it absorbs the fraction of the segment
// given by its opacity, the ratio of its visible projected area in the
// segment's direction (the mean of Willmott's bounds) to the projected area
// of its box. The transmittance is the product over the clusters crossed.
// Clusters inside the receiver's or the emitter's own cluster are skipped.
#ifndef Radiosity_FaceClusterVisibility_h
#define Radiosity_FaceClusterVisibility_h

#include "Radiosity/FaceCluster/FaceClusterHierarchy.h"
#include "Radiosity/Hierarchical/Backprojection.h"

#include <memory>
#include <mutex>
#include <vector>

namespace radiosity
{
class Visibility;

class FaceClusterVisibility
{
public:
  explicit FaceClusterVisibility(const FaceClusterHierarchy& hierarchy);
  ~FaceClusterVisibility();

  /**
   * Fraction of the light from y that reaches x, in [0, 1]. `receiver` and
   * `emitter` are cluster ids whose triangles do not occlude (None for
   * none); `shadowThreshold` is the shadow size below which a cluster is
   * treated as a semi-transparent volume (0: exact, down to the triangles).
   */
  double Transmittance(const Vec3& x, const Vec3& y, std::uint32_t receiver, std::uint32_t emitter,
    double shadowThreshold) const;

  /**
   * Transmittance at threshold 0 for the segments from x to ys[0..n), as 1
   * (visible) or 0, in one batch of Embree occlusion rays
   * (Visibility::TestSegmentsPassing) where the triangles of `receiver` and
   * `emitter` let the segments through. The BVH over every triangle is
   * built on the first call. The same answers as the descent of
   * Transmittance but for the float BVH's offset at the ends (1e-5 of the
   * scene's extent); the descent tested every oriented box on the way,
   * most of the bunny room's solve (64% of its profile).
   */
  void Visible(const Vec3& x, const Vec3* ys, std::size_t n, std::uint32_t receiver,
    std::uint32_t emitter, unsigned char* visible) const;

  /**
   * The triangles that may hide part of triangle `source` from a point of
   * triangle `receiver`: shaft culling (Haines & Wallace 1991) down the
   * hierarchy, each cluster's box tested against the shaft's planes, and a
   * triangle kept when it meets the shaft with a vertex in front of both
   * ends. The triangles of clusters `receiver` and `emitter` are skipped, as
   * Transmittance skips them. False, with `out` incomplete, past `limit`.
   */
  bool ShaftBlockers(const TriangleCorners& receiver, const TriangleCorners& source,
    std::uint32_t receiverId, std::uint32_t emitterId, std::size_t limit,
    std::vector<TriangleCorners>& out) const;

  const FaceClusterHierarchy& Hierarchy() const { return this->Source; }
  /// The Embree BVH over every triangle (Visible's), built on the first
  /// call: the output's shadow rays use it too.
  const Visibility& AllTriangles() const;

  /// Clusters visited by the last calls (for the statistics), per thread.
  static std::size_t NodesVisited();

private:
  const FaceClusterHierarchy& Source;
  mutable std::once_flag Built;
  mutable std::unique_ptr<Visibility> Rays;
};

/// Moller-Trumbore: whether the line p + t d meets triangle abc, with its t.
bool LineHitsTriangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p, const Vec3& d, double& t);

/// Whether the segment p + t d, t in [t0, t1], crosses the oriented box of c.
bool SegmentCrossesBox(const FaceCluster& c, const Vec3& p, const Vec3& d, double t0, double t1);
} // namespace radiosity

#endif
