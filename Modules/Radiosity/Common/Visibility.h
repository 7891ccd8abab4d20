// Segment visibility on Embree 3: one BVH over the triangles that can occlude
// (SceneAnalysis), occlusion rays in batches (rtcOccluded1M).
#ifndef Radiosity_Visibility_h
#define Radiosity_Visibility_h

#include "Radiosity/Common/Scene.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace radiosity
{
class Visibility
{
public:
  /// Builds the BVH over the triangles with `canOcclude[t]` set.
  Visibility(const Scene& scene, const std::vector<unsigned char>& canOcclude);
  ~Visibility();
  Visibility(const Visibility&) = delete;
  Visibility& operator=(const Visibility&) = delete;

  /// True when nothing can occlude: every segment is visible, no rays needed.
  bool Empty() const { return this->NumberOfOccluders == 0; }

  /**
   * The self-intersection offset: a distance that scales with the scene size
   * (Embree works in single precision, so the offset is relative to the
   * scene's extent, and the same test passes at 1e-4 m and at 1e4 m).
   */
  double Offset() const { return this->Epsilon; }

  /**
   * For each i < n: visible[i] = 1 when the open segment from[i] -> to[i],
   * shortened by the offset at both ends, hits no occluder, else 0.
   * Thread-safe; call it from parallel loops with batches of segments.
   */
  void TestSegments(const Vec3* from, const Vec3* to, std::size_t n, unsigned char* visible) const;

  /// No occluder on a segment (FirstHits).
  static constexpr std::uint32_t NoHit = 0xFFFFFFFFu;
  /**
   * For each i < n: the occluder (scene triangle index) the segment
   * from[i] -> to[i], shortened by the offset at both ends, meets first, or
   * NoHit. The segments of TestSegments, with Embree's nearest hit instead
   * of any hit. Thread-safe.
   */
  void FirstHits(const Vec3* from, const Vec3* to, std::size_t n, std::uint32_t* triangle) const;

  /**
   * As TestSegments, where the occluders `passes` accepts (scene triangle
   * indices) let the segments through: a receiver's and an emitter's own
   * triangles (face cluster radiosity's exact visibility). `passes` is
   * called only for the triangles a segment meets. Thread-safe.
   */
  void TestSegmentsPassing(const Vec3* from, const Vec3* to, std::size_t n,
    const std::function<bool(std::uint32_t)>& passes, unsigned char* visible) const;

  /**
   * Every occluder that any of the segments from[i] -> to[i] passes through
   * (not only the nearest), appended to `triangles` as scene triangle indices
   * (sorted, without repeats). These are the blockers of a link (Hanrahan,
   * Salzman, Aupperle 1991; Hardt & Teller section 3). Thread-safe.
   */
  void CollectOccluders(
    const Vec3* from, const Vec3* to, std::size_t n, std::vector<std::uint32_t>& triangles) const;

  /**
   * Every occluder whose bounding box meets the sphere (centre, radius),
   * appended to `triangles` (Embree point query over the BVH): a superset of
   * the blockers of any shaft inside the sphere. Thread-safe.
   */
  void OccludersInSphere(
    const Vec3& centre, double radius, std::vector<std::uint32_t>& triangles) const;
  /**
   * The same, keeping only the occluders `keep` accepts, as the query meets
   * them, and stopping once more than `most` are kept: then returns false
   * (the list holds most + 1 of them), true when it holds them all. A shaft
   * that crosses a dense mesh is told it has too many blockers without every
   * triangle in its sphere being listed first.
   */
  bool OccludersInSphere(const Vec3& centre, double radius, const std::function<bool(std::uint32_t)>& keep,
    std::size_t most, std::vector<std::uint32_t>& triangles) const;

  /**
   * The triangle t (scene index) that minimises `distance(t)` among those
   * within `radius` of p, -1 when none: an Embree point query over the BVH,
   * whose sphere shrinks to the best distance so far when `shrink` is set
   * (then `distance` must be at least the Euclidean distance from p to t;
   * infinity excludes t). Ties go to the lowest index, as a loop over the
   * triangles would. Thread-safe.
   */
  std::int64_t NearestTriangle(const Vec3& p, double radius,
    const std::function<double(std::uint32_t)>& distance, bool shrink) const;
  /// Nearest hit of a ray, for primary rays of images; returns false on a miss.
  /// Only meaningful when built over every triangle (see `AllTriangles`).
  bool Intersect(const Vec3& origin, const Vec3& direction, double& t, unsigned& triangle,
    double& u, double& v) const;

  static std::vector<unsigned char> AllTriangles(const Scene& scene)
  {
    return std::vector<unsigned char>(scene.Triangles.size(), 1);
  }

  std::size_t RaysCast() const;
  /// Whether scene triangle t is one of the occluders (built into the BVH).
  bool Occludes(std::uint32_t t) const;

private:
  struct Internals;
  std::unique_ptr<Internals> Impl;
  std::size_t NumberOfOccluders = 0;
  double Epsilon = 0.0;
};
} // namespace radiosity

#endif
