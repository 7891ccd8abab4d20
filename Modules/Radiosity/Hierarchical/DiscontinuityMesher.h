// Hardt & Teller's hybrid quadtree-mesh (sections 2 to 5) over a solved
// hierarchical radiosity solution:
// - per quadtree leaf, the EV and VE discontinuities between the sources
//   that reach it through partially visible links and those links' blockers
//   (CriticalSurfaces.h), ranked by w = max(d_sb / d_br) B_src; the k
//   strongest of weight at least w_min are kept (section 4.2), and a leaf
//   with none is not meshed at all;
// - the kept segments constrain a CGAL Delaunay triangulation of the leaf
//   (ConstrainedTriangulation.h, section 2.1);
// - every triangle gets a quadratic interpolant (QuadraticInterpolant.h,
//   section 2.2) through accurate point irradiance at its vertices and edge
//   midpoints (section 5): the exact form factor of every source linked to
//   the leaf or its ancestors, through that link's blockers by backprojection
//   (Backprojection.h), times the source's radiosity.
// The paper spent 80 times the solve on construction; here the samples at
// leaf corners and whole-edge midpoints are shared between the leaves that
// meet there (computed once, and neighbouring interpolants agree along the
// shared edge), and leaves are processed in parallel.
#ifndef Radiosity_DiscontinuityMesher_h
#define Radiosity_DiscontinuityMesher_h

#include "Radiosity/Hierarchical/HierarchicalRadiosity.h"
#include "Radiosity/Hierarchical/QuadraticInterpolant.h"

#include <vector>

namespace radiosity
{
class DirectLighting;
struct DiscontinuityMeshOptions
{
  /// Mesh the discontinuities; off: one interpolant per leaf (no CGAL work).
  bool Discontinuities = true;
  int MaxPerLeaf = 10;     ///< k: the strongest discontinuities kept per leaf
  /// w_min as a fraction of the largest emitted exitance (one channel), so
  /// that the default does not depend on the emission's units; in a scene
  /// with no emitting triangle (lights and the sky), of the largest radiosity.
  double MinWeight = 0.05;
  int Threads = 0;         ///< 0: all cores
  /// Insert every vertex lying on a leaf's edge into that leaf (neighbours of
  /// other levels, discontinuities ending on the edge), so that the mesh has
  /// no T-junction and its rasterisation no crack. Off: the paper's hybrid
  /// mesh as it is, a leaf without discontinuities being one triangle.
  bool Conforming = true;
  /// Seconds the meshing may take (0: no limit), so that a scene whose
  /// leaves see hundreds of blockers is still meshed in bounded time. Past
  /// half of it the leaves left are meshed without their discontinuities,
  /// one interpolant each (DiscontinuityMesh::LeavesPastTimeLimit); past
  /// all of it the leaves left take their partially visible links' mean
  /// (the solve's value) instead of the exact backprojection at each sample
  /// (LeavesSampledPastTimeLimit). Either is reported as a warning.
  double MaxSeconds = 0.0;
};

struct DiscontinuityMesh
{
  std::vector<Vec3> Points;
  std::vector<Triangle> Triangles;
  std::vector<QuadraticInterpolant> Interpolants; ///< irradiance, per triangle
  /// The punctual lights' part of each interpolant (through their values at
  /// the six nodes); empty without punctual lights.
  std::vector<QuadraticInterpolant> PunctualInterpolants;
  std::vector<RGB> PointIrradiance;               ///< the sample at each point
  std::vector<std::uint32_t> Leaf;                ///< quadtree leaf of each triangle
  std::vector<std::uint32_t> SourceTriangle;      ///< input triangle of each triangle
  std::vector<std::uint16_t> Level;
  std::vector<Vec3> Normals; ///< per triangle

  std::size_t LeavesMeshed = 0;      ///< leaves split by at least one discontinuity
  std::size_t LeavesConformed = 0;   ///< leaves that took in neighbours' boundary vertices
  std::size_t SegmentsFound = 0;     ///< EV/VE traces on leaves before ranking
  std::size_t SegmentsKept = 0;
  /// Leaves whose constraints the triangulation refused: meshed as the leaf
  /// alone (PlanarTriangulation::ConstraintsDropped), reported as a warning.
  std::size_t LeavesTriangulationFailed = 0;
  /// Leaves not searched for discontinuities: half of MaxSeconds had passed.
  std::size_t LeavesPastTimeLimit = 0;
  /// Leaves sampled with their partial links' means: MaxSeconds had passed.
  std::size_t LeavesSampledPastTimeLimit = 0;
  std::size_t PointSamples = 0;      ///< accurate point irradiance evaluations
  double Seconds = 0.0;
  /// Of Seconds: finding the discontinuities and triangulating the leaves
  /// (with the conforming step), and the accurate point irradiance.
  double DiscontinuitySeconds = 0.0, SampleSeconds = 0.0;
};

/// Builds the hybrid quadtree-mesh with its interpolants.
DiscontinuityMesh BuildDiscontinuityMesh(const HierarchicalRadiosity& solution,
  const DiscontinuityMeshOptions& options, const ProgressCallback& progress = {});

/// Accurate point irradiance (section 5) at x with normal n on leaf `leaf`.
RGB AccuratePointIrradiance(
  const HierarchicalRadiosity& solution, std::uint32_t leaf, const Vec3& x, const Vec3& n);

/// Irradiance at probes from the interpolants: each probe is located on the
/// mesh (within `tolerance`, normals within 25 degrees); NaN where none is found.
/// With `exactPunctual`, the punctual lights' direct light is taken exactly
/// at each probe and the interpolant carries the rest (the interpolant less
/// its punctual part), as ProbeEvaluator does for the sensors.
std::vector<RGB> EvaluateInterpolants(const DiscontinuityMesh& mesh, const std::vector<Probe>& probes,
  double tolerance, const DirectLighting* exactPunctual = nullptr);
} // namespace radiosity

#endif
