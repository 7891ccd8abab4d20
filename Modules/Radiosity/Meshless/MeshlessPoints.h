// The point hierarchy of meshless finite elements (Lehtinen et al. 2007,
// section 6.1, "Point Placement"): a hierarchical Poisson-disk distribution
// on the triangles by rejection sampling (every surface point equally likely
// to be proposed), the disk radius scaled by the dot product of the normals
// (points may be arbitrarily close across a corner of 90 degrees or more),
// 1000 rejections in a row closing a level, the radius halved per level, the
// acceptance test against the points of all coarser levels too; one
// reconstruction group per object; a proposed point whose normal ray hits a
// back face is inside geometry and rejected. Each point's support radius is
// its distance to its k-th nearest neighbour on its level (section 4.2,
// k = 10). Each level has its own spatial index (nanoflann k-d tree) to find
// the basis functions that are non-zero at a point.
#ifndef Radiosity_MeshlessPoints_h
#define Radiosity_MeshlessPoints_h

#include "Radiosity/Common/Scene.h"

#include <cstdint>
#include <memory>
#include <functional>
#include <vector>

namespace radiosity
{
class Visibility;

struct MeshlessPoint
{
  Vec3 Position{ 0.0 };
  Vec3 Normal{ 0.0, 0.0, 1.0 };
  double Radius = 0.0;        ///< support radius r_j (eq. 13)
  std::uint16_t Level = 0;
  std::uint32_t Group = 0;    ///< reconstruction group: the scene object
  std::uint32_t Triangle = 0; ///< the input triangle it lies on
};

struct PointPlacementOptions
{
  double InitialRadius = 0.1; ///< coarsest Poisson-disk radius R, fraction of the scene diagonal
  int Levels = 5;             ///< levels; R halves from one to the next
  int MaxRejections = 1000;   ///< rejections in a row that close a level
  int Neighbours = 10;        ///< k of the support radius
  std::uint64_t Seed = 1;     ///< the same seed gives the same points
  bool RejectInsideGeometry = true;
};

/// An upper bound of the points PointHierarchy places: Poisson-disk points
/// of radius r are at most as dense as the hexagonal packing, 2 / (sqrt(3)
/// r^2) per unit area, and the radius halves per level. Its memory
/// estimate, before any point is placed.
double MaxPoissonDiskPoints(const Scene& scene, const PointPlacementOptions& options);

/// Thrown by PointHierarchy when its `keepGoing` said stop (an abort).
struct PlacementAborted
{
};

class PointHierarchy
{
public:
  /**
   * Places the points. `rays`, when given, must be built over every triangle
   * (Visibility::AllTriangles): it serves the inside-geometry test.
   * `keepGoing`, when given, is asked every 1,024 candidate points (on this
   * thread); false ends the placement with PlacementAborted.
   */
  PointHierarchy(const Scene& scene, const PointPlacementOptions& options, const Visibility* rays,
    const std::function<bool()>& keepGoing = {});
  ~PointHierarchy();
  PointHierarchy(const PointHierarchy&) = delete;
  PointHierarchy& operator=(const PointHierarchy&) = delete;

  /// All points, sorted by level (coarsest first).
  const std::vector<MeshlessPoint>& Points() const { return this->All; }
  int NumberOfLevels() const { return static_cast<int>(this->LevelStart.size()) - 1; }
  std::size_t LevelBegin(int level) const { return this->LevelStart[level]; }
  std::size_t LevelEnd(int level) const { return this->LevelStart[level + 1]; }

  /// Indices of the points of `level` and `group` whose support contains x
  /// (|x - x_j| < r_j), appended to `out`. Thread-safe.
  void Supporting(int level, std::uint32_t group, const Vec3& x, std::vector<std::uint32_t>& out) const;
  /// Indices of the points of `level` and `group` whose support reaches
  /// within `reach` of c (|c - x_j| < r_j + reach): every point that
  /// Supporting finds for some x within `reach` of c, from one search (the
  /// samples of an output element). Unordered. Thread-safe.
  void Reaching(int level, std::uint32_t group, const Vec3& c, double reach, std::vector<std::uint32_t>& out) const;

  /// Proposals rejected by the inside-geometry ray (statistics).
  std::size_t RejectedInside() const { return this->Inside; }

private:
  struct Index;
  /// Supporting (reach 0, sorted by distance, as the solve has always
  /// summed) and Reaching (unsorted).
  void Search(int level, std::uint32_t group, const Vec3& c, double reach, bool sorted,
    std::vector<std::uint32_t>& out) const;
  std::vector<MeshlessPoint> All;
  std::vector<std::size_t> LevelStart; ///< NumberOfLevels() + 1 entries
  std::vector<std::unique_ptr<Index>> Indices; ///< one per level
  std::size_t Inside = 0;
};
} // namespace radiosity

#endif
