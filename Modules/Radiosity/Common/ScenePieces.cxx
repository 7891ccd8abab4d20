#include "Radiosity/Common/ScenePieces.h"

#include <array>
#include <algorithm>
#include <cstring>
#include <numeric>
#include <string>
#include <unordered_map>

namespace radiosity
{
namespace
{
constexpr std::uint32_t PieceMagic = 0x52505331; // "RPS1"

class Writer
{
public:
  template <typename T>
  void Put(const T& value)
  {
    const auto* p = reinterpret_cast<const char*>(&value);
    this->Bytes.insert(this->Bytes.end(), p, p + sizeof(T));
  }
  template <typename T>
  void PutVector(const std::vector<T>& values)
  {
    this->Put(static_cast<std::uint64_t>(values.size()));
    const auto* p = reinterpret_cast<const char*>(values.data());
    this->Bytes.insert(this->Bytes.end(), p, p + values.size() * sizeof(T));
  }
  void PutString(const std::string& s)
  {
    this->Put(static_cast<std::uint64_t>(s.size()));
    this->Bytes.insert(this->Bytes.end(), s.begin(), s.end());
  }
  std::vector<char> Bytes;
};

class Reader
{
public:
  Reader(const std::vector<char>& bytes, std::size_t rank)
    : Bytes(bytes)
    , Rank(rank)
  {
  }
  template <typename T>
  T Get()
  {
    this->Need(sizeof(T));
    T value;
    std::memcpy(&value, this->Bytes.data() + this->At, sizeof(T));
    this->At += sizeof(T);
    return value;
  }
  template <typename T>
  std::vector<T> GetVector()
  {
    const auto n = this->Get<std::uint64_t>();
    if (n > (this->Bytes.size() - this->At) / sizeof(T))
    {
      this->Fail();
    }
    std::vector<T> values(static_cast<std::size_t>(n));
    std::memcpy(values.data(), this->Bytes.data() + this->At, values.size() * sizeof(T));
    this->At += values.size() * sizeof(T);
    return values;
  }
  std::string GetString()
  {
    const auto n = this->Get<std::uint64_t>();
    this->Need(static_cast<std::size_t>(n));
    std::string s(this->Bytes.data() + this->At, static_cast<std::size_t>(n));
    this->At += s.size();
    return s;
  }
  [[noreturn]] void Fail() const
  {
    throw SceneError("rank " + std::to_string(this->Rank) + ": its scene piece (" +
      std::to_string(this->Bytes.size()) + " bytes) is truncated or malformed");
  }

private:
  void Need(std::size_t n) const
  {
    if (n > this->Bytes.size() - this->At)
    {
      this->Fail();
    }
  }
  const std::vector<char>& Bytes;
  std::size_t Rank;
  std::size_t At = 0;
};

/// A point's position, its coordinates' bits.
using Key = std::array<std::uint64_t, 3>;
struct KeyHash
{
  std::size_t operator()(const Key& k) const
  {
    std::uint64_t h = 1469598103934665603ull;
    for (std::uint64_t v : k)
    {
      h = (h ^ v) * 1099511628211ull;
    }
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

Key PositionKey(const Vec3& p)
{
  Key k{};
  std::memcpy(&k[0], &p.x, 8);
  std::memcpy(&k[1], &p.y, 8);
  std::memcpy(&k[2], &p.z, 8);
  return k;
}

/// The distinct planes (unit normals, up to three) of the triangles that
/// use a point: what tells apart the copies of a vertex split along a crease.
struct PointNormals
{
  std::array<Vec3, 3> N{};
  int Count = 0;
  void Add(const Vec3& n)
  {
    for (int i = 0; i < this->Count; ++i)
    {
      if (glm::dot(this->N[static_cast<std::size_t>(i)], n) > ParallelCosine)
      {
        return;
      }
    }
    if (this->Count < 3)
    {
      this->N[static_cast<std::size_t>(this->Count++)] = n;
    }
  }
  /// The largest cosine between a plane of this point and one of `other`'s
  /// (1 when either is used by no triangle: such a point welds to any).
  double Closeness(const PointNormals& other) const
  {
    if (this->Count == 0 || other.Count == 0)
    {
      return 1.0;
    }
    double best = -1.0;
    for (int i = 0; i < this->Count; ++i)
    {
      for (int j = 0; j < other.Count; ++j)
      {
        best = std::max(best,
          glm::dot(this->N[static_cast<std::size_t>(i)], other.N[static_cast<std::size_t>(j)]));
      }
    }
    return best;
  }
  static constexpr double ParallelCosine = 0.99985; ///< cos 1 degree: one plane
  /// Copies whose planes differ by more than 60 degrees are not one point:
  /// the copies of a vertex split along a crease (a box's top and side).
  /// Across a cut through a tessellated smooth surface, the neighbours' planes
  /// differ by less (an icosahedron's faces by 42 degrees).
  static constexpr double WeldCosine = 0.5;
};
} // namespace

std::vector<char> PackScenePiece(const Scene& piece, const PieceGlobalIds& ids)
{
  Writer w;
  w.Put(PieceMagic);
  w.PutVector(piece.Points);
  w.PutVector(piece.Triangles);
  w.PutVector(piece.Materials);
  w.PutVector(piece.ObjectIds);
  w.PutVector(piece.SourceCells);
  w.Put(static_cast<std::uint64_t>(piece.ObjectNames.size()));
  for (const std::string& name : piece.ObjectNames)
  {
    w.PutString(name);
  }
  const std::vector<long long> none;
  w.PutVector(ids.Points.size() == piece.Points.size() ? ids.Points : none);
  w.PutVector(ids.Triangles.size() == piece.Triangles.size() ? ids.Triangles : none);
  return std::move(w.Bytes);
}

AssembledScene AssembleScenePieces(const std::vector<std::vector<char>>& pieces)
{
  struct Piece
  {
    Scene Part;
    std::vector<long long> GlobalIds, CellIds;
  };
  std::vector<Piece> parts(pieces.size());
  bool allGlobalIds = true, anyPoints = false, allCellIds = true;
  for (std::size_t r = 0; r < pieces.size(); ++r)
  {
    Reader in(pieces[r], r);
    if (in.Get<std::uint32_t>() != PieceMagic)
    {
      in.Fail();
    }
    Scene& s = parts[r].Part;
    s.Points = in.GetVector<Vec3>();
    s.Triangles = in.GetVector<Triangle>();
    s.Materials = in.GetVector<Material>();
    s.ObjectIds = in.GetVector<int>();
    s.SourceCells = in.GetVector<long long>();
    const auto names = in.Get<std::uint64_t>();
    for (std::uint64_t i = 0; i < names; ++i)
    {
      s.ObjectNames.push_back(in.GetString());
    }
    parts[r].GlobalIds = in.GetVector<long long>();
    parts[r].CellIds = in.GetVector<long long>();
    const std::size_t n = s.Triangles.size();
    if (s.Materials.size() != n || s.ObjectIds.size() != n ||
      (!s.SourceCells.empty() && s.SourceCells.size() != n))
    {
      in.Fail();
    }
    for (std::size_t t = 0; t < n; ++t)
    {
      for (std::uint32_t v : s.Triangles[t].V)
      {
        if (v >= s.Points.size())
        {
          throw SceneError("rank " + std::to_string(r) + ": triangle " + std::to_string(t) +
            " refers to point " + std::to_string(v) + " of " + std::to_string(s.Points.size()));
        }
      }
      if (s.ObjectIds[t] < 0 || static_cast<std::size_t>(s.ObjectIds[t]) >= s.ObjectNames.size())
      {
        throw SceneError("rank " + std::to_string(r) + ": triangle " + std::to_string(t) +
          " has object " + std::to_string(s.ObjectIds[t]) + " of " +
          std::to_string(s.ObjectNames.size()));
      }
    }
    if (!s.Points.empty())
    {
      anyPoints = true;
      allGlobalIds = allGlobalIds && parts[r].GlobalIds.size() == s.Points.size();
    }
    if (n > 0)
    {
      allCellIds = allCellIds && parts[r].CellIds.size() == n;
    }
  }

  AssembledScene out;
  out.ByGlobalIds = anyPoints && allGlobalIds;
  Scene& whole = out.Whole;
  std::unordered_map<std::string, int> objectOfName;
  std::unordered_map<long long, std::uint32_t> pointOfGlobalId;
  std::vector<long long> globalIdOfPoint; // of whole's points, when welded by global ids
  // Position -> the lower ranks' points there, in order of appearance.
  struct AtPosition
  {
    std::uint32_t Id;
    int Object; ///< the object of the first triangle using it; -1: unused there
    std::size_t TakenBy; ///< the last rank welded to it (+1; 0: none)
    PointNormals Normals; ///< of the triangles using it there
  };
  std::unordered_map<Key, std::vector<AtPosition>, KeyHash> pointsAt;
  for (std::size_t r = 0; r < parts.size(); ++r)
  {
    const Scene& s = parts[r].Part;
    std::vector<int> objectMap(s.ObjectNames.size());
    for (std::size_t o = 0; o < s.ObjectNames.size(); ++o)
    {
      const auto found =
        objectOfName.emplace(s.ObjectNames[o], static_cast<int>(whole.ObjectNames.size()));
      if (found.second)
      {
        whole.ObjectNames.push_back(s.ObjectNames[o]);
      }
      objectMap[o] = found.first->second;
    }
    // Welding by position joins points of one object (or a point no
    // triangle of its rank uses): a scene's blocks have points of their
    // own, and a crease between two objects (a wall on a floor) is no seam.
    std::vector<int> objectOfPoint(s.Points.size(), -1);
    std::vector<PointNormals> normalsOfPoint(out.ByGlobalIds ? 0 : s.Points.size());
    for (std::size_t t = 0; t < s.Triangles.size(); ++t)
    {
      for (std::uint32_t v : s.Triangles[t].V)
      {
        if (objectOfPoint[v] < 0)
        {
          objectOfPoint[v] = objectMap[static_cast<std::size_t>(s.ObjectIds[t])];
        }
        if (!out.ByGlobalIds)
        {
          normalsOfPoint[v].Add(s.Normal(t));
        }
      }
    }
    std::vector<std::uint32_t> pointMap(s.Points.size());
    std::vector<std::pair<Key, AtPosition>> added;
    for (std::size_t p = 0; p < s.Points.size(); ++p)
    {
      std::uint32_t id = static_cast<std::uint32_t>(whole.Points.size());
      bool shared = false;
      if (out.ByGlobalIds)
      {
        const auto found = pointOfGlobalId.emplace(parts[r].GlobalIds[p], id);
        shared = !found.second;
        id = found.first->second;
      }
      else
      {
        // A lower-rank point here of the same object that no point of this
        // rank took yet (two distinct points at one position stay two): of
        // several, the one whose triangles' planes are closest to this
        // point's, and none whose planes all differ by more than 60 degrees
        // (PointNormals::WeldCosine). The copies of a vertex split along a
        // crease (a box's top and its sides, each with points of its own)
        // keep to their own faces whatever order each rank holds them in.
        const Key key = PositionKey(s.Points[p]);
        const int object = objectOfPoint[p];
        const auto at = pointsAt.find(key);
        if (at != pointsAt.end())
        {
          AtPosition* chosen = nullptr;
          double closest = 0.0;
          for (AtPosition& candidate : at->second)
          {
            if (candidate.TakenBy != r + 1 &&
              (candidate.Object == object || candidate.Object < 0 || object < 0))
            {
              double closeness = candidate.Normals.Closeness(normalsOfPoint[p]);
              // One plane: the first such candidate (the k-th copy is the k-th).
              closeness = closeness >= PointNormals::ParallelCosine ? 1.0 : closeness;
              if (closeness >= PointNormals::WeldCosine && (!chosen || closeness > closest))
              {
                chosen = &candidate;
                closest = closeness;
              }
            }
          }
          if (chosen)
          {
            chosen->TakenBy = r + 1;
            chosen->Object = std::max(chosen->Object, object);
            shared = true;
            id = chosen->Id;
          }
        }
        if (!shared)
        {
          added.push_back({ key, AtPosition{ id, object, 0, normalsOfPoint[p] } }); // for the higher ranks
        }
      }
      if (shared)
      {
        ++out.SharedPoints;
      }
      else
      {
        whole.Points.push_back(s.Points[p]);
        if (out.ByGlobalIds)
        {
          globalIdOfPoint.push_back(parts[r].GlobalIds[p]);
        }
      }
      pointMap[p] = id;
    }
    for (const auto& a : added)
    {
      pointsAt[a.first].push_back(a.second);
    }
    for (std::size_t t = 0; t < s.Triangles.size(); ++t)
    {
      Triangle tri;
      for (int k = 0; k < 3; ++k)
      {
        tri.V[k] = pointMap[s.Triangles[t].V[k]];
      }
      whole.Triangles.push_back(tri);
      whole.Materials.push_back(s.Materials[t]);
      whole.ObjectIds.push_back(objectMap[static_cast<std::size_t>(s.ObjectIds[t])]);
      whole.SourceCells.push_back(s.SourceCells.empty() ? static_cast<long long>(t) : s.SourceCells[t]);
      out.Owner.push_back(static_cast<std::uint32_t>(r));
      out.LocalIndex.push_back(static_cast<std::uint32_t>(t));
    }
    out.RankTriangles.push_back(s.Triangles.size());
  }
  out.OrderedByGlobalCellIds = allCellIds && !whole.Triangles.empty();
  if (out.OrderedByGlobalCellIds)
  {
    std::vector<std::uint32_t> order(whole.Triangles.size());
    std::iota(order.begin(), order.end(), 0u);
    const auto cellId = [&](std::uint32_t t) { return parts[out.Owner[t]].CellIds[out.LocalIndex[t]]; };
    std::stable_sort(order.begin(), order.end(),
      [&](std::uint32_t a, std::uint32_t b) { return cellId(a) < cellId(b); });
    Scene sorted;
    sorted.Points = std::move(whole.Points);
    sorted.ObjectNames = std::move(whole.ObjectNames);
    std::vector<std::uint32_t> owner, local;
    for (std::uint32_t t : order)
    {
      sorted.Triangles.push_back(whole.Triangles[t]);
      sorted.Materials.push_back(whole.Materials[t]);
      sorted.ObjectIds.push_back(whole.ObjectIds[t]);
      sorted.SourceCells.push_back(whole.SourceCells[t]);
      owner.push_back(out.Owner[t]);
      local.push_back(out.LocalIndex[t]);
    }
    whole = std::move(sorted);
    out.Owner = std::move(owner);
    out.LocalIndex = std::move(local);
    // Objects numbered in order of their first triangle, as one process
    // numbers them (which rank holds an object first does not matter).
    std::vector<int> renumbered(whole.ObjectNames.size(), -1);
    std::vector<std::string> names;
    for (int& o : whole.ObjectIds)
    {
      if (renumbered[static_cast<std::size_t>(o)] < 0)
      {
        renumbered[static_cast<std::size_t>(o)] = static_cast<int>(names.size());
        names.push_back(whole.ObjectNames[static_cast<std::size_t>(o)]);
      }
      o = renumbered[static_cast<std::size_t>(o)];
    }
    for (std::size_t o = 0; o < renumbered.size(); ++o)
    {
      if (renumbered[o] < 0)
      {
        names.push_back(whole.ObjectNames[o]);
      }
    }
    whole.ObjectNames = std::move(names);
  }
  if (out.ByGlobalIds)
  {
    // Points in the order of their global ids: where the ids are the
    // original data set's point numbers (a partitioned reader's, or
    // RedistributeDataSet's), the scene is the one process's point for point,
    // and so is every answer that depends on the numbering (the face
    // cluster hierarchy's tie-breaks).
    std::vector<std::uint32_t> order(whole.Points.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
      [&](std::uint32_t a, std::uint32_t b) { return globalIdOfPoint[a] < globalIdOfPoint[b]; });
    std::vector<std::uint32_t> newIndex(order.size());
    std::vector<Vec3> points(order.size());
    for (std::size_t k = 0; k < order.size(); ++k)
    {
      newIndex[order[k]] = static_cast<std::uint32_t>(k);
      points[k] = whole.Points[order[k]];
    }
    whole.Points = std::move(points);
    for (Triangle& t : whole.Triangles)
    {
      for (std::uint32_t& v : t.V)
      {
        v = newIndex[v];
      }
    }
  }
  return out;
}

SolutionMesh SolutionOfTriangles(const SolutionMesh& whole, const std::vector<char>& keep,
  std::vector<std::uint32_t>* pointSource)
{
  SolutionMesh out;
  const std::uint32_t unused = ~std::uint32_t(0);
  std::vector<std::uint32_t> remap(whole.Points.size(), unused);
  if (pointSource)
  {
    pointSource->clear();
  }
  for (std::size_t e = 0; e < whole.Triangles.size(); ++e)
  {
    const std::size_t source = whole.SourceTriangle[e];
    if (source >= keep.size() || !keep[source])
    {
      continue;
    }
    Triangle tri;
    for (int k = 0; k < 3; ++k)
    {
      std::uint32_t& id = remap[whole.Triangles[e].V[k]];
      if (id == unused)
      {
        id = static_cast<std::uint32_t>(out.Points.size());
        const std::uint32_t p = whole.Triangles[e].V[k];
        out.Points.push_back(whole.Points[p]);
        out.PointIrradiance.push_back(whole.PointIrradiance[p]);
        out.PointRadiosity.push_back(whole.PointRadiosity[p]);
        if (pointSource)
        {
          pointSource->push_back(p);
        }
      }
      tri.V[k] = id;
    }
    out.Triangles.push_back(tri);
    out.CellIrradiance.push_back(whole.CellIrradiance[e]);
    out.CellRadiosity.push_back(whole.CellRadiosity[e]);
    out.ElementId.push_back(whole.ElementId[e]);
    out.Level.push_back(whole.Level[e]);
    out.SourceTriangle.push_back(whole.SourceTriangle[e]);
    if (e < whole.Samples.size())
    {
      out.Samples.push_back(whole.Samples[e]);
    }
    if (e < whole.Normals.size())
    {
      out.Normals.push_back(whole.Normals[e]);
    }
  }
  return out;
}
Scene SceneOfTriangles(
  const Scene& scene, const std::vector<std::size_t>& which, std::vector<std::uint32_t>* pointSource)
{
  Scene piece;
  piece.ObjectNames = scene.ObjectNames;
  // The points used, in their order in `scene`.
  const std::uint32_t unused = ~std::uint32_t(0);
  std::vector<std::uint32_t> index(scene.Points.size(), unused);
  for (std::size_t t : which)
  {
    for (std::uint32_t v : scene.Triangles[t].V)
    {
      index[v] = 0;
    }
  }
  for (std::size_t p = 0; p < scene.Points.size(); ++p)
  {
    if (index[p] != unused)
    {
      index[p] = static_cast<std::uint32_t>(piece.Points.size());
      piece.Points.push_back(scene.Points[p]);
      if (pointSource)
      {
        pointSource->push_back(static_cast<std::uint32_t>(p));
      }
    }
  }
  for (std::size_t t : which)
  {
    Triangle tri = scene.Triangles[t];
    for (auto& v : tri.V)
    {
      v = index[v];
    }
    piece.Triangles.push_back(tri);
    piece.Materials.push_back(scene.Materials[t]);
    piece.ObjectIds.push_back(scene.ObjectIds[t]);
    piece.SourceCells.push_back(static_cast<long long>(t));
  }
  return piece;
}
} // namespace radiosity
