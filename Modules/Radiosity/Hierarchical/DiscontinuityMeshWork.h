// The discontinuity mesher's per-leaf work and its phases that span leaves
// (internal to BuildDiscontinuityMesh, DiscontinuityMesher.cxx): the
// conforming of neighbouring leaves' boundaries and the numbering of the
// samples they share. Hardt & Teller 1996, sections 4.2 and 5; the phases are
// in Hierarchical/README.md.
#ifndef Radiosity_DiscontinuityMeshWork_h
#define Radiosity_DiscontinuityMeshWork_h

#include "Radiosity/Common/DirectLighting.h"
#include "Radiosity/Hierarchical/ConstrainedTriangulation.h"
#include "Radiosity/Hierarchical/HierarchicalRadiosity.h"

#include <boost/container/small_vector.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace radiosity
{
namespace discontinuity_mesh_detail
{
/// A sample of one leaf's triangulation: shared (a leaf corner or the
/// midpoint of a whole leaf edge, index into the shared samples) or local.
struct SampleRef
{
  bool Shared;
  std::uint32_t Index;
};

/// A shared sample as its leaf lists it before numbering: vertex A of the
/// leaf's triangulation (A == B) or the midpoint of its edge A-B.
using SampleCandidate = std::array<std::uint32_t, 2>;

/// One leaf's discontinuities, triangulation and samples. The small vectors
/// hold an undivided leaf (3 vertices, 1 triangle, 6 shared samples) without
/// a heap allocation: a million-leaf scene is mostly such leaves.
struct LeafWork
{
  std::vector<std::array<Vec3, 2>> Segments;
  std::vector<std::array<Vec3, 2>> HardSegments; ///< D0: the lights' shadow boundaries
  std::vector<RGB> PunctualNodes;    ///< the punctual lights at each triangle's six nodes, from inside it
  std::vector<RGB> PunctualVertices; ///< and at each vertex (the point output)
  PlanarTriangulation Mesh;
  std::vector<Vec3> LocalPoints;
  std::vector<RGB> LocalValues;
  boost::container::small_vector<std::array<SampleRef, 6>, 1> TriangleSamples; ///< r0..r5 per triangle
  boost::container::small_vector<SampleRef, 3> VertexSamples;
  boost::container::small_vector<SampleCandidate, 6> SharedCandidates; ///< until numbered
};

/// The LeafWork records of every leaf, default-constructed in parallel in
/// chunks: a million leaves' records are half a gigabyte, whose first touch
/// (page faults, not the constructors) took 1.6 s on one thread.
class LeafWorks
{
public:
  explicit LeafWorks(std::size_t n);
  ~LeafWorks();
  LeafWork& operator[](std::size_t i) { return this->Chunks[i >> ChunkBits][i & (ChunkSize - 1)]; }
  const LeafWork& operator[](std::size_t i) const { return this->Chunks[i >> ChunkBits][i & (ChunkSize - 1)]; }
  std::size_t size() const { return this->Size; }

private:
  static constexpr std::size_t ChunkBits = 12, ChunkSize = std::size_t(1) << ChunkBits;
  std::vector<std::unique_ptr<LeafWork[]>> Chunks;
  std::size_t Size;
};

/// Distance from p to the segment ab, and whether p projects strictly inside it
/// (more than `margin` from either end).
double EdgeDistance(const Vec3& p, const Vec3& a, const Vec3& b, bool& inside, double margin);

/// The edge (a, b) of a triangulation as one key, whichever way it runs.
inline std::uint64_t EdgeKey(std::uint32_t a, std::uint32_t b)
{
  return (static_cast<std::uint64_t>(a < b ? a : b) << 32) | (a < b ? b : a);
}

/// The edge of the leaf triangle `corners` that x lies on (within
/// 1e-7 of the leaf's longest edge, `tolerance`), or -1.
int LeafEdgeOf(const TriangleCorners& corners, double tolerance, const Vec3& x);

/// Inserts into each leaf's triangulation the neighbours' boundary vertices
/// that lie on its edges (no T-junctions); returns the leaves changed.
std::size_t ConformBoundaries(
  const HierarchicalRadiosity& s, const std::vector<std::uint32_t>& leaves, LeafWorks& work);

/// The samples that leaves share by position: one value per point and
/// surface, evaluated once by its owner.
struct SharedSamples
{
  std::vector<Vec3> Points;
  std::vector<std::uint32_t> Owner; ///< index into the leaves: the first leaf that lists the point
};

/// Each leaf's vertex and triangle sample references (VertexSamples,
/// TriangleSamples, LocalPoints). A sample on the leaf's boundary is shared by
/// position and surface normal with the leaves that meet there, so that
/// neighbouring interpolants agree along their common edges; the shared
/// samples are numbered in the order of their first appearance in leaf order.
SharedSamples ReferenceSamples(
  const HierarchicalRadiosity& s, const std::vector<std::uint32_t>& leaves, LeafWorks& work);
class EdgeTopology;
/// Per scene triangle and side, the coplanar occluder across that side whose
/// union with the triangle is a convex quad, EdgeTopology::None where there
/// is none or the triangle is no occluder: SkyHiddenOverLeaves' `quads`.
std::vector<std::array<std::uint32_t, 3>> ConvexCoplanarNeighbours(
  const Scene& scene, const EdgeTopology& topology, const Visibility& occluders);
/**
 * The sky quadrature's directions that no point of a leaf sees, for the
 * leaves `leaves[order[k]]`, k in [begin, end): those whose rays from the
 * leaf's three corners all cross one occluder, the one that the ray from its
 * corner of lowest point index meets first. Parallel rays from the points of
 * the triangle cross that occluder's plane at the same convex combination of
 * the corners' crossings, inside it and no farther than the farthest, so
 * each point's ray crosses it too (each ray starts at its point moved by one
 * offset along n, the same for all). The traced corner's rays are cast once
 * for the leaves that share it; the three crossings are tested against the
 * one occluder in double precision with a margin, and where one misses it,
 * against the union of it and a neighbour of `quads` (the same argument:
 * that union is convex) (DiscontinuityMeshSky.cxx).
 * SkyMaskWords() words per leaf, in k order.
 */
std::vector<std::uint64_t> SkyHiddenOverLeaves(const HierarchicalRadiosity& s, const DirectLighting& lights,
  const std::vector<std::array<std::uint32_t, 3>>& quads, const std::vector<std::uint32_t>& leaves, const std::vector<std::uint32_t>& order, std::size_t begin,
  std::size_t end);
} // namespace discontinuity_mesh_detail
} // namespace radiosity

#endif
