#include "Radiosity/Scenes/SceneGenerators.h"

#include <algorithm>

#include <array>
#include <cmath>
#include <map>

namespace radiosity
{
void AppendQuad(Scene& scene, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
  const Material& material, int n, const std::string& object)
{
  Scene quad;
  quad.ObjectNames.push_back(object);
  // Bilinear grid: exact for the planar parallelograms and quads used here.
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      const double s = static_cast<double>(i) / n, t = static_cast<double>(j) / n;
      quad.Points.push_back((1 - s) * (1 - t) * a + s * (1 - t) * b + s * t * c + (1 - s) * t * d);
    }
  }
  const auto id = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      quad.Triangles.push_back({ { id(i, j), id(i + 1, j), id(i + 1, j + 1) } });
      quad.Triangles.push_back({ { id(i, j), id(i + 1, j + 1), id(i, j + 1) } });
    }
  }
  quad.Materials.assign(quad.Triangles.size(), material);
  quad.ObjectIds.assign(quad.Triangles.size(), 0);
  AppendScene(scene, quad);
}

namespace
{
Vec3 Mm(double x, double y, double z)
{
  return Vec3(x, y, z) * 1e-3;
}

/// Appends the quad so that its front faces `towards` (flips the order if needed).
void AppendFacing(Scene& scene, Vec3 a, Vec3 b, Vec3 c, Vec3 d, const Vec3& towards,
  const Material& m, const std::string& name, bool inward, int n = 1)
{
  const Vec3 normal = glm::cross(b - a, c - a);
  const Vec3 centre = 0.25 * (a + b + c + d);
  const double side = glm::dot(towards - centre, normal);
  if ((inward && side < 0) || (!inward && side > 0))
  {
    std::swap(b, d);
  }
  AppendQuad(scene, a, b, c, d, m, n, name);
}
}

Scene MakeCornellBox()
{
  Material white, red, green, light;
  white.Reflectance = RGB(0.725, 0.71, 0.68);
  red.Reflectance = RGB(0.63, 0.065, 0.05);
  green.Reflectance = RGB(0.14, 0.45, 0.091);
  light.Reflectance = RGB(0.78, 0.78, 0.78);
  constexpr double Pi = 3.14159265358979323846;
  light.Emission = Pi * RGB(17.0, 12.0, 4.0);

  Scene s;
  const Vec3 inside = Mm(278, 274, 280);
  AppendFacing(s, Mm(552.8, 0, 0), Mm(0, 0, 0), Mm(0, 0, 559.2), Mm(549.6, 0, 559.2), inside,
    white, "floor", true);
  AppendFacing(s, Mm(556.0, 548.8, 0), Mm(556.0, 548.8, 559.2), Mm(0, 548.8, 559.2),
    Mm(0, 548.8, 0), inside, white, "ceiling", true);
  AppendFacing(s, Mm(549.6, 0, 559.2), Mm(0, 0, 559.2), Mm(0, 548.8, 559.2),
    Mm(556.0, 548.8, 559.2), inside, white, "back wall", true);
  AppendFacing(s, Mm(552.8, 0, 0), Mm(549.6, 0, 559.2), Mm(556.0, 548.8, 559.2),
    Mm(556.0, 548.8, 0), inside, red, "red wall", true);
  AppendFacing(s, Mm(0, 0, 559.2), Mm(0, 0, 0), Mm(0, 548.8, 0), Mm(0, 548.8, 559.2), inside,
    green, "green wall", true);
  AppendFacing(s, Mm(343.0, 548.7, 227.0), Mm(343.0, 548.7, 332.0), Mm(213.0, 548.7, 332.0),
    Mm(213.0, 548.7, 227.0), Mm(278, 0, 280), light, "light", true);

  const double shortBlock[5][4][3] = {
    { { 130.0, 165.0, 65.0 }, { 82.0, 165.0, 225.0 }, { 240.0, 165.0, 272.0 }, { 290.0, 165.0, 114.0 } },
    { { 290.0, 0.0, 114.0 }, { 290.0, 165.0, 114.0 }, { 240.0, 165.0, 272.0 }, { 240.0, 0.0, 272.0 } },
    { { 130.0, 0.0, 65.0 }, { 130.0, 165.0, 65.0 }, { 290.0, 165.0, 114.0 }, { 290.0, 0.0, 114.0 } },
    { { 82.0, 0.0, 225.0 }, { 82.0, 165.0, 225.0 }, { 130.0, 165.0, 65.0 }, { 130.0, 0.0, 65.0 } },
    { { 240.0, 0.0, 272.0 }, { 240.0, 165.0, 272.0 }, { 82.0, 165.0, 225.0 }, { 82.0, 0.0, 225.0 } } };
  const double tallBlock[5][4][3] = {
    { { 423.0, 330.0, 247.0 }, { 265.0, 330.0, 296.0 }, { 314.0, 330.0, 456.0 }, { 472.0, 330.0, 406.0 } },
    { { 423.0, 0.0, 247.0 }, { 423.0, 330.0, 247.0 }, { 472.0, 330.0, 406.0 }, { 472.0, 0.0, 406.0 } },
    { { 472.0, 0.0, 406.0 }, { 472.0, 330.0, 406.0 }, { 314.0, 330.0, 456.0 }, { 314.0, 0.0, 456.0 } },
    { { 314.0, 0.0, 456.0 }, { 314.0, 330.0, 456.0 }, { 265.0, 330.0, 296.0 }, { 265.0, 0.0, 296.0 } },
    { { 265.0, 0.0, 296.0 }, { 265.0, 330.0, 296.0 }, { 423.0, 330.0, 247.0 }, { 423.0, 0.0, 247.0 } } };
  const auto block = [&](const double (*q)[4][3], const Vec3& centre, const std::string& name)
  {
    Scene b;
    for (int f = 0; f < 5; ++f)
    {
      AppendFacing(b, Mm(q[f][0][0], q[f][0][1], q[f][0][2]), Mm(q[f][1][0], q[f][1][1], q[f][1][2]),
        Mm(q[f][2][0], q[f][2][1], q[f][2][2]), Mm(q[f][3][0], q[f][3][1], q[f][3][2]), centre,
        white, name, false);
    }
    // One object per block, not per face.
    b.ObjectIds.assign(b.Triangles.size(), 0);
    b.ObjectNames = { name };
    AppendScene(s, b);
  };
  block(shortBlock, Mm(186, 82.5, 168.5), "short block");
  block(tallBlock, Mm(368.5, 165, 351.5), "tall block");
  return s;
}

Scene MakeClosedCube(double size, int n, double reflectance, double emission)
{
  Material m;
  m.Reflectance = RGB(reflectance);
  m.Emission = RGB(emission);
  Scene s;
  const double h = size;
  const Vec3 p[8] = { { 0, 0, 0 }, { h, 0, 0 }, { h, h, 0 }, { 0, h, 0 }, { 0, 0, h }, { h, 0, h },
    { h, h, h }, { 0, h, h } };
  const Vec3 centre(0.5 * h);
  AppendFacing(s, p[0], p[3], p[2], p[1], centre, m, "z0", true, n);
  AppendFacing(s, p[4], p[5], p[6], p[7], centre, m, "z1", true, n);
  AppendFacing(s, p[0], p[1], p[5], p[4], centre, m, "y0", true, n);
  AppendFacing(s, p[3], p[7], p[6], p[2], centre, m, "y1", true, n);
  AppendFacing(s, p[0], p[4], p[7], p[3], centre, m, "x0", true, n);
  AppendFacing(s, p[1], p[2], p[6], p[5], centre, m, "x1", true, n);
  return s;
}

Scene MakeParallelSquares(double a, double c, int n, double reflectance, double emission)
{
  Material emitter, receiver;
  emitter.Reflectance = RGB(0.0);
  emitter.Emission = RGB(emission);
  receiver.Reflectance = RGB(reflectance);
  Scene s;
  AppendQuad(s, Vec3(0, 0, 0), Vec3(a, 0, 0), Vec3(a, a, 0), Vec3(0, a, 0), emitter, n, "emitter");
  AppendQuad(s, Vec3(0, 0, c), Vec3(0, a, c), Vec3(a, a, c), Vec3(a, 0, c), receiver, n, "receiver");
  return s;
}

void SubdivideAtMidpoints(std::vector<Vec3>& points, std::vector<Triangle>& triangles,
  const std::function<Vec3(const Vec3&)>& place)
{
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
  const auto midpoint = [&](std::uint32_t a, std::uint32_t b)
  {
    const auto key = std::make_pair(std::min(a, b), std::max(a, b));
    const auto it = mid.find(key);
    if (it != mid.end())
    {
      return it->second;
    }
    const Vec3 m = 0.5 * (points[a] + points[b]);
    points.push_back(place ? place(m) : m);
    return mid[key] = static_cast<std::uint32_t>(points.size() - 1);
  };
  std::vector<Triangle> next;
  next.reserve(4 * triangles.size());
  for (const Triangle& t : triangles)
  {
    const std::uint32_t ab = midpoint(t.V[0], t.V[1]), bc = midpoint(t.V[1], t.V[2]),
                        ca = midpoint(t.V[2], t.V[0]);
    next.push_back({ { t.V[0], ab, ca } });
    next.push_back({ { ab, t.V[1], bc } });
    next.push_back({ { ca, bc, t.V[2] } });
    next.push_back({ { ab, bc, ca } });
  }
  triangles.swap(next);
}

Scene SubdividedScene(const Scene& scene, int levels)
{
  Scene out = scene;
  // SubdivideAtMidpoints puts a triangle's four parts together in its place.
  auto repeat = [](auto& values) {
    std::remove_reference_t<decltype(values)> four;
    four.reserve(4 * values.size());
    for (const auto& v : values)
    {
      four.insert(four.end(), 4, v);
    }
    values.swap(four);
  };
  for (int l = 0; l < levels; ++l)
  {
    SubdivideAtMidpoints(out.Points, out.Triangles);
    repeat(out.Materials);
    repeat(out.ObjectIds);
    repeat(out.SourceCells);
  }
  return out;
}

Scene MakeSphereInterior(double radius, int levels, double reflectance, const RGB& emission)
{
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> v = { { -1, g, 0 }, { 1, g, 0 }, { -1, -g, 0 }, { 1, -g, 0 }, { 0, -1, g },
    { 0, 1, g }, { 0, -1, -g }, { 0, 1, -g }, { g, 0, -1 }, { g, 0, 1 }, { -g, 0, -1 },
    { -g, 0, 1 } };
  const std::vector<std::array<std::uint32_t, 3>> faces = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 },
    { 0, 7, 10 }, { 0, 10, 11 }, { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 },
    { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 },
    { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 } };
  for (Vec3& p : v)
  {
    p = glm::normalize(p);
  }
  std::vector<Triangle> f;
  for (const auto& t : faces)
  {
    f.push_back({ t });
  }
  for (int l = 0; l < levels; ++l)
  {
    SubdivideAtMidpoints(v, f, [](const Vec3& p) { return glm::normalize(p); });
  }
  Scene s;
  for (const Vec3& p : v)
  {
    s.Points.push_back(radius * p);
  }
  for (const Triangle& t : f)
  {
    // The icosahedron's faces point outward: reverse them to face inward.
    s.Triangles.push_back({ { t.V[0], t.V[2], t.V[1] } });
    Material m;
    m.Reflectance = RGB(reflectance);
    const Vec3 c = (v[t.V[0]] + v[t.V[1]] + v[t.V[2]]) / 3.0;
    m.Emission = c.z > 0.5 ? emission : RGB(0.0);
    s.Materials.push_back(m);
    s.ObjectIds.push_back(0);
  }
  s.ObjectNames = { "sphere" };
  return s;
}

std::vector<Probe> CentroidProbes(const Scene& scene, std::size_t count)
{
  std::vector<Probe> probes;
  const std::size_t step = std::max<std::size_t>(1, scene.Triangles.size() / std::max<std::size_t>(count, 1));
  for (std::size_t t = 0; t < scene.Triangles.size(); t += step)
  {
    probes.push_back({ scene.Centroid(t), scene.Normal(t) });
  }
  return probes;
}

std::vector<Probe> PenumbraLineProbes()
{
  std::vector<Probe> probes;
  for (int i = 0; i <= 36; ++i)
  {
    probes.push_back({ Vec3(-0.9 + 0.05 * i, 0.05, 0.0), Vec3(0, 0, 1) });
  }
  return probes;
}

Scene MakeShadowScene(int n, double emission)
{
  Material black, light;
  black.Reflectance = RGB(0.0);
  light.Reflectance = RGB(0.0);
  light.Emission = RGB(emission);
  Scene s;
  AppendQuad(s, Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0), black, n, "floor");
  AppendQuad(s, Vec3(-0.25, -0.25, 1), Vec3(-0.25, 0.25, 1), Vec3(0.25, 0.25, 1),
    Vec3(0.25, -0.25, 1), light, 1, "emitter");
  // The blocker faces down (towards the floor) and up (towards the emitter).
  const Vec3 b0(-0.05, -0.2, 0.5), b1(0.35, -0.2, 0.5), b2(0.35, 0.2, 0.5), b3(-0.05, 0.2, 0.5);
  AppendQuad(s, b0, b1, b2, b3, black, 1, "blocker top");
  AppendQuad(s, b0, b3, b2, b1, black, 1, "blocker bottom");
  return s;
}

Scene MakeContactScene(int n, double reflectance, double emission)
{
  Material floor, wall;
  floor.Reflectance = RGB(reflectance);
  wall.Reflectance = RGB(0.0);
  wall.Emission = RGB(emission);
  Scene s;
  AppendQuad(s, Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(0, 1, 0), floor, n, "floor");
  AppendQuad(s, Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(0, 1, 1), Vec3(0, 0, 1), wall, n, "wall");
  return s;
}
} // namespace radiosity
