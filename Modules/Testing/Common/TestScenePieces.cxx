// A scene split over ranks and put together again (ScenePieces.h): the
// assembled scene is the scene before the split, whatever the pieces' point
// sets; a solution cut by input triangles covers every element once.
#include "Radiosity/Common/ScenePieces.h"
#include "Radiosity/Progressive/ProgressiveRadiosity.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

using namespace radiosity;

namespace
{
/// The triangles `which` of `scene`, over all its points (`compact` false)
/// or over only the points they use, in their order in `scene`
/// (SceneOfTriangles); `ids` receives the global ids (the scene's point and
/// triangle indices).
Scene PieceOf(const Scene& scene, const std::vector<std::size_t>& which, bool compact,
  PieceGlobalIds* ids = nullptr)
{
  std::vector<std::uint32_t> source;
  Scene piece = SceneOfTriangles(scene, which, &source);
  if (!compact)
  {
    // Every point of the scene, the triangles' indices unchanged.
    for (Triangle& tri : piece.Triangles)
    {
      for (auto& v : tri.V)
      {
        v = source[v];
      }
    }
    piece.Points = scene.Points;
    source.resize(scene.Points.size());
    for (std::uint32_t p = 0; p < scene.Points.size(); ++p)
    {
      source[p] = p;
    }
  }
  if (ids)
  {
    ids->Points.assign(source.begin(), source.end());
    ids->Triangles.assign(piece.SourceCells.begin(), piece.SourceCells.end());
  }
  return piece;
}

Scene PieceOf(const Scene& scene, std::size_t begin, std::size_t end, bool compact)
{
  std::vector<std::size_t> which;
  for (std::size_t t = begin; t < end; ++t)
  {
    which.push_back(t);
  }
  return PieceOf(scene, which, compact);
}

/// The scene cut into `ranks` pieces, packed: consecutive ranges, or
/// triangle t to rank t % ranks (`interleaved`, what a redistribution
/// may leave).
std::vector<std::vector<char>> Split(
  const Scene& scene, std::size_t ranks, bool compact, bool withIds, bool interleaved = false)
{
  std::vector<std::vector<char>> pieces;
  const std::size_t n = scene.Triangles.size();
  for (std::size_t r = 0; r < ranks; ++r)
  {
    std::vector<std::size_t> which;
    for (std::size_t t = 0; t < n; ++t)
    {
      if (interleaved ? t % ranks == r : (t >= n * r / ranks && t < n * (r + 1) / ranks))
      {
        which.push_back(t);
      }
    }
    PieceGlobalIds ids;
    const Scene piece = PieceOf(scene, which, compact, withIds ? &ids : nullptr);
    pieces.push_back(PackScenePiece(piece, ids));
  }
  return pieces;
}

/// A welded n x n grid of quads on the floor (every point shared).
Scene WeldedGrid(int n)
{
  Scene s;
  s.ObjectNames = { "grid" };
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      s.Points.emplace_back(i * 0.1, j * 0.1, 0.0);
    }
  }
  const auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      s.Triangles.push_back(Triangle{ { at(i, j), at(i + 1, j), at(i + 1, j + 1) } });
      s.Triangles.push_back(Triangle{ { at(i, j), at(i + 1, j + 1), at(i, j + 1) } });
    }
  }
  s.Materials.resize(s.Triangles.size());
  s.ObjectIds.assign(s.Triangles.size(), 0);
  return s;
}

void ExpectSameScene(const Scene& a, const Scene& b)
{
  ASSERT_EQ(a.Points.size(), b.Points.size());
  ASSERT_EQ(a.Triangles.size(), b.Triangles.size());
  for (std::size_t t = 0; t < a.Triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      ASSERT_EQ(a.Triangles[t].V[k], b.Triangles[t].V[k]) << "triangle " << t;
    }
    EXPECT_EQ(a.Materials[t].Reflectance.x, b.Materials[t].Reflectance.x);
    EXPECT_EQ(a.Materials[t].Emission.y, b.Materials[t].Emission.y);
    EXPECT_EQ(a.ObjectIds[t], b.ObjectIds[t]);
  }
  for (std::size_t p = 0; p < a.Points.size(); ++p)
  {
    EXPECT_EQ(a.Points[p].x, b.Points[p].x);
    EXPECT_EQ(a.Points[p].y, b.Points[p].y);
    EXPECT_EQ(a.Points[p].z, b.Points[p].z);
  }
}

/// The vertex positions of every triangle, and which triangles share a point.
void ExpectSameConnectivity(const Scene& a, const Scene& b, bool samePointCount = true)
{
  ASSERT_EQ(a.Triangles.size(), b.Triangles.size());
  if (samePointCount)
  {
    EXPECT_EQ(a.Points.size(), b.Points.size());
  }
  std::map<std::uint32_t, std::uint32_t> aToB;
  for (std::size_t t = 0; t < a.Triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Vec3 pa = a.Vertex(t, k), pb = b.Vertex(t, k);
      EXPECT_TRUE(pa.x == pb.x && pa.y == pb.y && pa.z == pb.z) << "triangle " << t;
      const auto found = aToB.emplace(a.Triangles[t].V[k], b.Triangles[t].V[k]);
      EXPECT_EQ(found.first->second, b.Triangles[t].V[k]) << "triangle " << t << " corner " << k;
    }
  }
}
}

TEST(ScenePieces, ConsecutiveRangesOverAllPointsGiveTheSceneBack)
{
  const Scene box = MakeCornellBox();
  for (std::size_t ranks : { 1, 2, 4, 7 })
  {
    const AssembledScene a = AssembleScenePieces(Split(box, ranks, false, false));
    ExpectSameScene(a.Whole, box);
    ASSERT_EQ(a.RankTriangles.size(), ranks);
    for (std::size_t t = 0; t < box.Triangles.size(); ++t)
    {
      // Triangle t was rank r's (t - n r / ranks)-th.
      const std::size_t n = box.Triangles.size();
      std::size_t r = 0;
      while (t >= n * (r + 1) / ranks)
      {
        ++r;
      }
      ASSERT_EQ(a.Owner[t], r);
      ASSERT_EQ(a.LocalIndex[t], t - n * r / ranks);
    }
    EXPECT_EQ(a.SharedPoints, (ranks - 1) * box.Points.size());
    EXPECT_FALSE(a.ByGlobalIds);
    EXPECT_FALSE(a.OrderedByGlobalCellIds);
  }
}

TEST(ScenePieces, GlobalIdsGiveTheSceneBackFromAnyPartition)
{
  // Interleaved compact pieces (no rank holds a whole wall) with VTK's
  // global ids: the scene comes back exactly, point for point in its own
  // numbering (which the face cluster hierarchy's tie-breaks follow: a
  // renumbered bunny room gave other clusters and a 4% different peak), the
  // Cornell box's unwelded corners (walls meeting at coincident, distinct
  // points) included.
  const Scene box = MakeCornellBox();
  for (std::size_t ranks : { 2, 3, 4 })
  {
    const AssembledScene a = AssembleScenePieces(Split(box, ranks, true, true, true));
    EXPECT_TRUE(a.ByGlobalIds);
    EXPECT_TRUE(a.OrderedByGlobalCellIds);
    ExpectSameScene(box, a.Whole);
    for (std::size_t t = 0; t < box.Triangles.size(); ++t)
    {
      ASSERT_EQ(a.Owner[t], t % ranks);
      ASSERT_EQ(a.LocalIndex[t], t / ranks);
    }
  }
}

TEST(ScenePieces, CompactPiecesOfAWeldedMeshAreWeldedByPosition)
{
  // Without global ids each rank's points on the cut are welded to the lower
  // ranks' points at the same position.
  const Scene grid = WeldedGrid(6);
  for (std::size_t ranks : { 2, 3, 4 })
  {
    const AssembledScene a = AssembleScenePieces(Split(grid, ranks, true, false));
    EXPECT_FALSE(a.ByGlobalIds);
    ExpectSameConnectivity(grid, a.Whole);
    EXPECT_GT(a.SharedPoints, 0u);
  }
}

TEST(ScenePieces, ObjectsMeetingAtACreaseAreNotWelded)
{
  // A floor and a wall on two ranks touch along an edge, with points of
  // their own (two blocks): welding by position keeps them apart.
  Scene s;
  s.ObjectNames = { "floor", "wall" };
  s.Points = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(0, 0, 1) };
  s.Triangles = { Triangle{ { 0, 1, 2 } }, Triangle{ { 3, 4, 5 } } };
  s.Materials.resize(2);
  s.ObjectIds = { 0, 1 };
  const AssembledScene a =
    AssembleScenePieces({ PackScenePiece(PieceOf(s, 0, 1, true)), PackScenePiece(PieceOf(s, 1, 2, true)) });
  ExpectSameConnectivity(s, a.Whole);
  EXPECT_EQ(a.SharedPoints, 0u);
}

TEST(ScenePieces, AnUnweldedSeamStaysUnwelded)
{
  // Two distinct points at one position (two quads meeting without sharing
  // their edge's points), both on both ranks: two points after assembly.
  Scene s;
  s.ObjectNames = { "object 0" };
  s.Points = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0) };
  s.Triangles = { Triangle{ { 0, 1, 2 } }, Triangle{ { 3, 5, 4 } } };
  s.Materials.resize(2);
  s.ObjectIds = { 0, 0 };
  std::vector<std::vector<char>> pieces;
  pieces.push_back(PackScenePiece(PieceOf(s, 0, 1, false)));
  pieces.push_back(PackScenePiece(PieceOf(s, 1, 2, false)));
  const AssembledScene a = AssembleScenePieces(pieces);
  ExpectSameScene(a.Whole, s);
}

TEST(ScenePieces, ObjectsAreMatchedByName)
{
  Scene s;
  s.Points = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0) };
  s.Triangles = { Triangle{ { 0, 1, 2 } } };
  s.Materials.resize(1);
  s.ObjectIds = { 0 };
  s.ObjectNames = { "floor" };
  Scene t = s;
  t.ObjectNames = { "lamp", "floor" };
  t.ObjectIds = { 1 };
  Scene u = s;
  u.ObjectNames = { "lamp" };
  u.ObjectIds = { 0 };
  const AssembledScene a = AssembleScenePieces(
    { PackScenePiece(s), PackScenePiece(t), PackScenePiece(u) });
  ASSERT_EQ(a.Whole.ObjectNames.size(), 2u);
  EXPECT_EQ(a.Whole.ObjectNames[0], "floor");
  EXPECT_EQ(a.Whole.ObjectNames[1], "lamp");
  EXPECT_EQ(a.Whole.ObjectIds, (std::vector<int>{ 0, 0, 1 }));
}

TEST(ScenePieces, EmptyPiecesAndMalformedBytes)
{
  const Scene box = MakeCornellBox();
  std::vector<std::vector<char>> pieces = Split(box, 1, false, false);
  pieces.insert(pieces.begin(), PackScenePiece(Scene()));
  pieces.push_back(PackScenePiece(Scene()));
  const AssembledScene a = AssembleScenePieces(pieces);
  ExpectSameScene(a.Whole, box);
  EXPECT_EQ(a.RankTriangles, (std::vector<std::size_t>{ 0, box.Triangles.size(), 0 }));
  EXPECT_EQ(a.Owner, std::vector<std::uint32_t>(box.Triangles.size(), 1u));

  pieces[1].resize(pieces[1].size() / 2);
  try
  {
    AssembleScenePieces(pieces);
    FAIL() << "a truncated piece was accepted";
  }
  catch (const SceneError& e)
  {
    EXPECT_NE(std::string(e.what()).find("rank 1"), std::string::npos) << e.what();
  }
}

TEST(ScenePieces, SolutionCutByTrianglesCoversEveryElementOnce)
{
  const Scene box = MakeCornellBox();
  ProgressiveOptions options;
  options.MaxIterations = 20;
  ProgressiveRadiosity solver(box, options);
  solver.Solve();
  const SolutionMesh whole = ExtractSolution(solver.Mesh());
  const std::size_t n = box.Triangles.size();
  std::vector<int> seen(whole.Triangles.size(), 0);
  for (std::size_t r = 0; r < 3; ++r)
  {
    std::vector<char> keep(n);
    for (std::size_t t = 0; t < n; ++t)
    {
      keep[t] = t % 3 == r;
    }
    std::vector<std::uint32_t> source;
    const SolutionMesh piece = SolutionOfTriangles(whole, keep, &source);
    ASSERT_EQ(source.size(), piece.Points.size());
    std::size_t at = 0; // the piece keeps the whole's order
    for (std::size_t e = 0; e < piece.Triangles.size(); ++e)
    {
      while (at < whole.Triangles.size() && whole.ElementId[at] != piece.ElementId[e])
      {
        ++at;
      }
      ASSERT_LT(at, whole.Triangles.size()) << "element " << piece.ElementId[e] << " out of order";
      ++seen[at];
      EXPECT_EQ(piece.SourceTriangle[e] % 3, r);
      EXPECT_EQ(piece.CellIrradiance[e].x, whole.CellIrradiance[at].x);
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_EQ(source[piece.Triangles[e].V[k]], whole.Triangles[at].V[k]);
      }
    }
    for (std::size_t p = 0; p < source.size(); ++p)
    {
      EXPECT_EQ(piece.PointRadiosity[p].y, whole.PointRadiosity[source[p]].y);
    }
  }
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(seen.size()));
}

TEST(ScenePieces, CreaseCopiesAreWeldedToTheirOwnFacesInAnyOrder)
{
  // The Cornell box's blocks: each quad has points of its own, so a block's
  // corner is three coincident points of one object (top, and two sides).
  // Cut at random over 4 ranks, each rank's triangles shuffled, no global ids
  // (what ParaView's RedistributeDataSet leaves): each copy is welded to the
  // copy of its own face, whatever order the ranks hold them in.
  const Scene box = MakeCornellBox();
  const std::size_t n = box.Triangles.size();
  for (unsigned seed : { 1u, 2u, 3u, 4u, 5u })
  {
    std::vector<std::vector<std::size_t>> which(4);
    std::uint64_t state = seed * 0x9E3779B97F4A7C15ull;
    const auto next = [&state]() {
      state ^= state << 13;
      state ^= state >> 7;
      state ^= state << 17;
      return state;
    };
    for (std::size_t t = 0; t < n; ++t)
    {
      which[next() % 4].push_back(t);
    }
    std::vector<std::vector<char>> pieces;
    for (auto& w : which)
    {
      for (std::size_t i = w.size(); i > 1; --i)
      {
        std::swap(w[i - 1], w[next() % i]);
      }
      pieces.push_back(PackScenePiece(PieceOf(box, w, true)));
    }
    const AssembledScene a = AssembleScenePieces(pieces);
    ASSERT_EQ(a.Whole.Triangles.size(), n);
    EXPECT_EQ(a.Whole.Points.size(), box.Points.size()) << "seed " << seed;
    // Two corners share a point after assembly iff they did before.
    std::map<std::uint32_t, std::uint32_t> toWhole, toBox;
    for (std::size_t t = 0; t < n; ++t)
    {
      const std::size_t source = static_cast<std::size_t>(a.Whole.SourceCells[t]);
      for (int k = 0; k < 3; ++k)
      {
        const std::uint32_t p = box.Triangles[source].V[k], q = a.Whole.Triangles[t].V[k];
        EXPECT_EQ(toWhole.emplace(p, q).first->second, q) << "seed " << seed << ", triangle " << source;
        EXPECT_EQ(toBox.emplace(q, p).first->second, p) << "seed " << seed << ", triangle " << source;
      }
    }
  }
}
