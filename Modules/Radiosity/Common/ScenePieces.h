// A scene distributed over processes (ParaView's MPI ranks): each rank holds
// a piece, light does not stop at a piece's boundary, so the pieces are put
// together into the one scene every rank solves, and the solution is cut
// back into the pieces. The glue to MPI (vtkMultiProcessController) lives in
// Filters/; this is the part that decides what the assembled scene is.
#ifndef Radiosity_ScenePieces_h
#define Radiosity_ScenePieces_h

#include "Radiosity/Common/Scene.h"
#include "Radiosity/Common/SolutionMesh.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace radiosity
{
/// Global ids of a piece (VTK's vtkPointData/vtkCellData GetGlobalIds):
/// empty when the piece has none.
struct PieceGlobalIds
{
  std::vector<long long> Points;    ///< one per point of the piece
  std::vector<long long> Triangles; ///< one per triangle: its input cell's id
};

/**
 * One rank's piece as bytes: points, triangles, materials, the objects'
 * names, the source cells, and the global ids when the piece has them
 * (ids of the wrong count are dropped). Lights are not packed: every rank
 * is given the same lights (ParaView sets a filter's properties on every
 * rank alike).
 */
std::vector<char> PackScenePiece(const Scene& piece, const PieceGlobalIds& ids = {});

/// The scene put together from the ranks' pieces (AssembleScenePieces).
struct AssembledScene
{
  Scene Whole;
  /// The rank each triangle of Whole came from, and its index there.
  std::vector<std::uint32_t> Owner, LocalIndex;
  /// How many triangles each rank gave.
  std::vector<std::size_t> RankTriangles;
  /// Points that two or more ranks hold (one point each in Whole).
  std::size_t SharedPoints = 0;
  /// True when the points were matched by their global ids (and are in
  /// their order), false when by their coordinates.
  bool ByGlobalIds = false;
  /// True when the triangles were ordered by their cells' global ids (and
  /// the objects numbered in order of their first triangle).
  bool OrderedByGlobalCellIds = false;
};

/**
 * The pieces put together. Triangles in order of their cells' global ids
 * when every piece with triangles has them (the scene's order before it was
 * redistributed, whatever the partition; the triangles of one cell keep
 * their order), otherwise in rank order, each rank's in its own order
 * (pieces that are consecutive ranges of a scene give it back in order).
 *
 * A point several ranks hold (a vertex on a piece's boundary) becomes one
 * point, as it was before the scene was split (the solution's vertex values
 * average over every triangle around a point):
 *  - by global id, when every piece with points carries them (partitioned
 *    readers; ParaView 5.11's RedistributeDataSet leaves none);
 *  - otherwise by its exact coordinates (copies of one point are bit-equal),
 *    within one object: a rank's point is welded to the lower ranks' point
 *    there whose triangles' planes are closest to its own (the copies of a
 *    vertex split along a crease, a box's top and sides with points of their
 *    own, keep to their own faces in whatever order the ranks hold them),
 *    never to one whose planes all differ from its own by more than 60
 *    degrees (such a vertex, welded across a crease and cut there, stays
 *    two), and among copies in one plane the k-th to the k-th (two distinct
 *    points at one position, an unwelded seam, stay two).
 * Objects are matched by name (a composite's blocks have the same names on
 * every rank), numbered in order of first appearance. Throws SceneError on a
 * malformed piece (naming the rank).
 */
AssembledScene AssembleScenePieces(const std::vector<std::vector<char>>& pieces);

/**
 * The elements of `whole` whose input triangle t has keep[t] != 0, in their
 * order, over the points they use (point values kept: they are the whole
 * scene's averages). `pointSource`, when given, receives for each point of
 * the result its index in `whole`.
 */
SolutionMesh SolutionOfTriangles(const SolutionMesh& whole, const std::vector<char>& keep,
  std::vector<std::uint32_t>* pointSource = nullptr);

/**
 * The triangles `which` of `scene`, in that order, over only the points they
 * use (in their order in `scene`): a piece as a partitioned reader gives it.
 * Materials, object ids and names kept; SourceCells the triangles' indices
 * in `scene`. `pointSource`, when given, receives each point's index in
 * `scene` (VTK's global point ids of the piece).
 */
Scene SceneOfTriangles(const Scene& scene, const std::vector<std::size_t>& which,
  std::vector<std::uint32_t>* pointSource = nullptr);
} // namespace radiosity

#endif
