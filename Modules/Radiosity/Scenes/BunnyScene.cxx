#include "Radiosity/Scenes/BunnyScene.h"

#include "Radiosity/Scenes/SceneGenerators.h"

#include <algorithm>
#include <array>
#include <unordered_map>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace radiosity
{
namespace
{
/// The numbers between `from` and the end (or `until`), brackets and commas skipped.
std::vector<double> Numbers(const std::string& text, std::size_t from, std::size_t until)
{
  std::vector<double> out;
  const char* p = text.c_str() + from;
  const char* end = text.c_str() + until;
  while (p < end)
  {
    if ((*p >= '0' && *p <= '9') || *p == '-' || *p == '.')
    {
      char* next = nullptr;
      const double value = std::strtod(p, &next);
      if (next == p) // a lone '-' or '.' (as in "exports.cells")
      {
        ++p;
        continue;
      }
      out.push_back(value);
      p = next;
    }
    else
    {
      ++p;
    }
  }
  return out;
}
}

Scene ReadNpmBunny(const std::string& indexJs)
{
  std::ifstream in(indexJs);
  if (!in)
  {
    throw SceneError("cannot read the bunny data " + indexJs);
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  const std::size_t positions = text.find("exports.positions=");
  const std::size_t cells = text.find("exports.cells=");
  if (positions == std::string::npos || cells == std::string::npos || cells < positions)
  {
    throw SceneError(indexJs + ": not the npm package bunny's index.js");
  }
  const std::vector<double> xyz = Numbers(text, positions, cells);
  const std::vector<double> ids = Numbers(text, cells, text.size());
  if (xyz.size() % 3 != 0 || ids.size() % 3 != 0 || xyz.empty() || ids.empty())
  {
    throw SceneError(indexJs + ": positions or cells are not triples");
  }
  Scene bunny;
  for (std::size_t i = 0; i < xyz.size(); i += 3)
  {
    bunny.Points.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
  }
  for (std::size_t i = 0; i < ids.size(); i += 3)
  {
    Triangle t;
    for (int k = 0; k < 3; ++k)
    {
      const double id = ids[i + k];
      if (id < 0 || id >= static_cast<double>(bunny.Points.size()))
      {
        throw SceneError(indexJs + ": cell " + std::to_string(i / 3) + " has point index " +
          std::to_string(id) + " out of range");
      }
      t.V[k] = static_cast<std::uint32_t>(id);
    }
    bunny.Triangles.push_back(t);
  }
  bunny.Materials.assign(bunny.Triangles.size(), Material());
  bunny.ObjectIds.assign(bunny.Triangles.size(), 0);
  bunny.ObjectNames = { "bunny" };
  return bunny;
}

namespace
{
// Adds `count` triangles by splitting interior edges, spread evenly over the
// mesh, at their midpoints: each split turns the edge's two triangles into
// four, so the mesh stays conforming (an odd last one splits a single
// triangle, leaving one T-junction). No triangle is split twice in a pass.
void BisectEvenly(Scene& scene, std::size_t count)
{
  const std::size_t n = scene.Triangles.size();
  std::unordered_map<std::uint64_t, std::array<std::uint32_t, 2>> edges;
  auto key = [](std::uint32_t a, std::uint32_t b) {
    return static_cast<std::uint64_t>(std::min(a, b)) << 32 | std::max(a, b);
  };
  for (std::uint32_t t = 0; t < n; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      auto [it, inserted] = edges.try_emplace(
        key(scene.Triangles[t].V[k], scene.Triangles[t].V[(k + 1) % 3]), std::array<std::uint32_t, 2>{ t, t });
      if (!inserted)
      {
        it->second[1] = t;
      }
    }
  }
  std::vector<char> touched(n, 0);
  // Splits triangle t at the midpoint m of its edge (a, b).
  auto split = [&scene](std::uint32_t t, std::uint32_t a, std::uint32_t b, std::uint32_t m) {
    Triangle& tri = scene.Triangles[t];
    int k = 0;
    while (!(tri.V[k] == a && tri.V[(k + 1) % 3] == b) && !(tri.V[k] == b && tri.V[(k + 1) % 3] == a))
    {
      ++k;
    }
    const std::uint32_t p = tri.V[k], q = tri.V[(k + 1) % 3], r = tri.V[(k + 2) % 3];
    Triangle second = tri;
    tri.V = { p, m, r };
    second.V = { m, q, r };
    scene.Triangles.push_back(second);
  };
  const std::size_t stride = std::max<std::size_t>(1, n / std::max<std::size_t>(1, count / 2));
  for (std::size_t start = 0; start < stride && count > 0; ++start)
  {
    for (std::size_t t = start; t < n && count > 0; t += stride)
    {
      if (touched[t])
      {
        continue;
      }
      const Triangle tri = scene.Triangles[t];
      int longest = 0;
      double length = -1.0;
      for (int k = 0; k < 3; ++k)
      {
        const double l = glm::length(scene.Points[tri.V[(k + 1) % 3]] - scene.Points[tri.V[k]]);
        if (l > length)
        {
          length = l;
          longest = k;
        }
      }
      const std::uint32_t a = tri.V[longest], b = tri.V[(longest + 1) % 3];
      const auto& pair = edges.at(key(a, b));
      const std::uint32_t u = pair[0] == t ? pair[1] : pair[0];
      const bool both = u != t && !touched[u] && count >= 2;
      if (u != t && !both && count >= 2)
      {
        continue; // its neighbour was split already: try another
      }
      const auto m = static_cast<std::uint32_t>(scene.Points.size());
      scene.Points.push_back(0.5 * (scene.Points[a] + scene.Points[b]));
      split(static_cast<std::uint32_t>(t), a, b, m);
      touched[t] = 1;
      --count;
      if (both)
      {
        split(u, a, b, m);
        touched[u] = 1;
        --count;
      }
    }
  }
}

Scene PlaceInRoom(Scene bunny);
}

Scene MakeBunnyRoom(const Scene& source, int levels)
{
  Scene bunny = source;
  for (int l = 0; l < levels; ++l)
  {
    SubdivideAtMidpoints(bunny.Points, bunny.Triangles);
  }
  return PlaceInRoom(std::move(bunny));
}

Scene MakeBunnyRoomWithTriangles(const Scene& source, std::size_t triangles)
{
  Scene bunny = source;
  while (4 * bunny.Triangles.size() <= triangles)
  {
    SubdivideAtMidpoints(bunny.Points, bunny.Triangles);
  }
  while (bunny.Triangles.size() < triangles)
  {
    BisectEvenly(bunny, triangles - bunny.Triangles.size());
  }
  return PlaceInRoom(std::move(bunny));
}

void StandUpright(Scene& bunny, double height, const Vec3& base)
{
  double volume = 0.0;
  for (std::size_t t = 0; t < bunny.Triangles.size(); ++t)
  {
    volume += glm::dot(bunny.Vertex(t, 0), glm::cross(bunny.Vertex(t, 1), bunny.Vertex(t, 2)));
  }
  if (volume < 0)
  {
    for (Triangle& t : bunny.Triangles)
    {
      std::swap(t.V[1], t.V[2]);
    }
  }
  Vec3 lo, hi;
  bunny.BoundingBox(lo, hi);
  const double scale = height / (hi.y - lo.y);
  const Vec3 foot(0.5 * (lo.x + hi.x), lo.y, 0.5 * (lo.z + hi.z));
  for (Vec3& p : bunny.Points)
  {
    p = (p - foot) * scale + base;
  }
}

namespace
{
Scene PlaceInRoom(Scene bunny)
{
  StandUpright(bunny, 0.5, Vec3(1.0, 0.0, 1.0));
  Material statue;
  statue.Reflectance = RGB(0.7);
  bunny.Materials.assign(bunny.Triangles.size(), statue);
  bunny.ObjectIds.assign(bunny.Triangles.size(), 0);
  bunny.ObjectNames = { "bunny" };

  // The room, y up, faces inward, with the light just below the ceiling.
  Material wall, floor, light;
  wall.Reflectance = RGB(0.7);
  floor.Reflectance = RGB(0.5);
  light.Reflectance = RGB(0.0);
  light.Emission = RGB(50.0);
  Scene room;
  const double h = 2.0;
  AppendQuad(room, Vec3(0, 0, 0), Vec3(0, 0, h), Vec3(h, 0, h), Vec3(h, 0, 0), floor, 4, "floor");
  AppendQuad(room, Vec3(0, h, 0), Vec3(h, h, 0), Vec3(h, h, h), Vec3(0, h, h), wall, 4, "ceiling");
  AppendQuad(room, Vec3(0, 0, 0), Vec3(h, 0, 0), Vec3(h, h, 0), Vec3(0, h, 0), wall, 4, "wall z0");
  AppendQuad(room, Vec3(0, 0, h), Vec3(0, h, h), Vec3(h, h, h), Vec3(h, 0, h), wall, 4, "wall z1");
  AppendQuad(room, Vec3(0, 0, 0), Vec3(0, h, 0), Vec3(0, h, h), Vec3(0, 0, h), wall, 4, "wall x0");
  AppendQuad(room, Vec3(h, 0, 0), Vec3(h, 0, h), Vec3(h, h, h), Vec3(h, h, 0), wall, 4, "wall x1");
  AppendQuad(room, Vec3(0.75, h - 1e-3, 0.75), Vec3(1.25, h - 1e-3, 0.75),
    Vec3(1.25, h - 1e-3, 1.25), Vec3(0.75, h - 1e-3, 1.25), light, 1, "light");
  AppendScene(room, bunny);
  return room;
}
}
Scene MakeGlossyStatueCornell(Scene bunny, int levels, std::size_t* firstBunnyPoint)
{
  // The box without its blocks, every triangle split in 16.
  const Scene box = MakeCornellBox();
  Scene room;
  room.Points = box.Points;
  room.ObjectNames = box.ObjectNames;
  for (std::size_t t = 0; t < box.Triangles.size(); ++t)
  {
    if (box.ObjectIds[t] < 6)
    {
      room.Triangles.push_back(box.Triangles[t]);
      room.Materials.push_back(box.Materials[t]);
      room.ObjectIds.push_back(box.ObjectIds[t]);
    }
  }
  room.ObjectNames.resize(6);
  room = SubdividedScene(room, 2);
  // The bunny, 0.25 m high, standing in the middle of the floor, glossy.
  for (int l = 0; l < levels; ++l)
  {
    SubdivideAtMidpoints(bunny.Points, bunny.Triangles);
  }
  StandUpright(bunny, 0.25, Vec3(0.278, 0.0, 0.3));
  Material statue;
  statue.Reflectance = RGB(0.6, 0.55, 0.5);
  statue.Specular = RGB(0.35);
  statue.Shininess = 10.0;
  bunny.Materials.assign(bunny.Triangles.size(), statue);
  bunny.ObjectIds.assign(bunny.Triangles.size(), 0);
  bunny.ObjectNames = { "bunny" };
  if (firstBunnyPoint)
  {
    *firstBunnyPoint = room.Points.size();
  }
  AppendScene(room, bunny);
  room.SourceCells.clear();
  return room;
}
} // namespace radiosity
