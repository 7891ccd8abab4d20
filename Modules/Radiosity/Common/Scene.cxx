#include "Radiosity/Common/Scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace radiosity
{
double Scene::Area(std::size_t tri) const
{
  return glm::length(AreaVector(Vertex(tri, 0), Vertex(tri, 1), Vertex(tri, 2)));
}

Vec3 Scene::Normal(std::size_t tri) const
{
  const Vec3 n = AreaVector(Vertex(tri, 0), Vertex(tri, 1), Vertex(tri, 2));
  const double len = glm::length(n);
  return len > 0 ? n / len : Vec3(0, 0, 1);
}

Vec3 Scene::Centroid(std::size_t tri) const
{
  return (Vertex(tri, 0) + Vertex(tri, 1) + Vertex(tri, 2)) / 3.0;
}

void Scene::BoundingBox(Vec3& lo, Vec3& hi) const
{
  const double inf = std::numeric_limits<double>::infinity();
  lo = Vec3(inf);
  hi = Vec3(-inf);
  for (const Triangle& t : Triangles)
  {
    for (auto v : t.V)
    {
      lo = glm::min(lo, Points[v]);
      hi = glm::max(hi, Points[v]);
    }
  }
}

double Scene::Diagonal() const
{
  if (Triangles.empty())
  {
    return 0.0;
  }
  Vec3 lo, hi;
  BoundingBox(lo, hi);
  return glm::length(hi - lo);
}

bool Scene::HasEmitters() const
{
  return std::any_of(Materials.begin(), Materials.end(),
    [](const Material& m) { return MaxComponent(m.Emission) > 0; });
}

std::size_t Scene::NumberOfEmitters() const
{
  return static_cast<std::size_t>(std::count_if(Materials.begin(), Materials.end(),
    [](const Material& m) { return MaxComponent(m.Emission) > 0; }));
}

double Scene::EmittedPower() const
{
  double p = 0;
  for (std::size_t t = 0; t < Triangles.size(); ++t)
  {
    p += SumComponents(Materials[t].Emission) / 3.0 * Area(t);
  }
  return p;
}

namespace
{
bool Finite(const Vec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string Describe(const RGB& c)
{
  std::ostringstream s;
  s.precision(9);
  s << "(" << c.r << ", " << c.g << ", " << c.b << ")";
  return s.str();
}
}

void ValidateScene(const Scene& scene)
{
  if (scene.Triangles.empty())
  {
    throw SceneError("the scene is empty: it has no polygons (lines, vertices and strips are "
                     "ignored)");
  }
  if (scene.Materials.size() != scene.Triangles.size() ||
    scene.ObjectIds.size() != scene.Triangles.size())
  {
    throw SceneError("internal: material or object arrays do not match the triangle count");
  }
  for (std::size_t p = 0; p < scene.Points.size(); ++p)
  {
    if (!Finite(scene.Points[p]))
    {
      throw SceneError("point " + std::to_string(p) + " has a non-finite coordinate " +
        Describe(scene.Points[p]));
    }
  }
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    const Material& m = scene.Materials[t];
    const long long cell = scene.SourceCells.empty() ? static_cast<long long>(t)
                                                     : scene.SourceCells[t];
    const std::string where = "cell " + std::to_string(cell);
    for (auto v : scene.Triangles[t].V)
    {
      if (v >= scene.Points.size())
      {
        throw SceneError(where + " references point " + std::to_string(v) +
          " which does not exist");
      }
    }
    if (!Finite(m.Reflectance))
    {
      throw SceneError("array Reflectance, " + where + ": non-finite value " +
        Describe(m.Reflectance));
    }
    for (int c = 0; c < 3; ++c)
    {
      if (m.Reflectance[c] < 0.0 || m.Reflectance[c] >= 1.0)
      {
        throw SceneError("array Reflectance, " + where + ": value " + Describe(m.Reflectance) +
          " is outside [0, 1)");
      }
    }
    if (!Finite(m.Emission))
    {
      throw SceneError("array Emission, " + where + ": non-finite value " + Describe(m.Emission));
    }
    for (int c = 0; c < 3; ++c)
    {
      if (m.Emission[c] < 0.0)
      {
        throw SceneError("array Emission, " + where + ": negative value " + Describe(m.Emission));
      }
    }
    if (!Finite(m.Specular) || !std::isfinite(m.Shininess))
    {
      throw SceneError("array Specular or Shininess, " + where + ": non-finite value");
    }
    if (m.Specular.r < 0 || m.Specular.g < 0 || m.Specular.b < 0 || m.Shininess < 0)
    {
      throw SceneError("array Specular or Shininess, " + where + ": negative value");
    }
  }
  LightSet lights = scene.Lighting;
  ValidateLights(lights);
}

SceneCleanupReport DropDegenerateTriangles(Scene& scene, std::vector<std::uint32_t>* kept)
{
  SceneCleanupReport report;
  if (kept)
  {
    kept->clear();
  }
  const double diag = scene.Diagonal();
  // Relative threshold: a triangle whose area is below double rounding of the
  // scene size carries no power and has no usable normal.
  const double minArea = diag * diag * 1e-24;
  std::size_t out = 0;
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    const auto& v = scene.Triangles[t].V;
    const bool repeated = v[0] == v[1] || v[1] == v[2] || v[0] == v[2];
    if (repeated || !(scene.Area(t) > minArea))
    {
      ++report.DegenerateTrianglesDropped;
      continue;
    }
    if (kept)
    {
      kept->push_back(static_cast<std::uint32_t>(t));
    }
    scene.Triangles[out] = scene.Triangles[t];
    scene.Materials[out] = scene.Materials[t];
    scene.ObjectIds[out] = scene.ObjectIds[t];
    if (!scene.SourceCells.empty())
    {
      scene.SourceCells[out] = scene.SourceCells[t];
    }
    ++out;
  }
  scene.Triangles.resize(out);
  scene.Materials.resize(out);
  scene.ObjectIds.resize(out);
  if (!scene.SourceCells.empty())
  {
    scene.SourceCells.resize(out);
  }
  return report;
}

void AppendScene(Scene& scene, const Scene& other)
{
  const auto offset = static_cast<std::uint32_t>(scene.Points.size());
  const int objectOffset = static_cast<int>(scene.ObjectNames.size());
  scene.Points.insert(scene.Points.end(), other.Points.begin(), other.Points.end());
  for (std::size_t t = 0; t < other.Triangles.size(); ++t)
  {
    Triangle tri = other.Triangles[t];
    for (auto& v : tri.V)
    {
      v += offset;
    }
    scene.Triangles.push_back(tri);
    scene.Materials.push_back(other.Materials[t]);
    scene.ObjectIds.push_back(other.ObjectIds[t] + objectOffset);
    scene.SourceCells.push_back(other.SourceCells.empty()
        ? static_cast<long long>(scene.Triangles.size() - 1)
        : other.SourceCells[t]);
  }
  if (other.ObjectNames.empty())
  {
    scene.ObjectNames.push_back("object" + std::to_string(objectOffset));
  }
  else
  {
    scene.ObjectNames.insert(
      scene.ObjectNames.end(), other.ObjectNames.begin(), other.ObjectNames.end());
  }
  scene.Lighting.Lights.insert(
    scene.Lighting.Lights.end(), other.Lighting.Lights.begin(), other.Lighting.Lights.end());
  if (other.Lighting.SkyLight.Enabled() && !scene.Lighting.SkyLight.Enabled())
  {
    scene.Lighting.SkyLight = other.Lighting.SkyLight;
  }
}
bool SameSurfaces(const Scene& a, const Scene& b, std::string* why)
{
  const auto differ = [why](const std::string& what) {
    if (why)
    {
      *why = what;
    }
    return false;
  };
  const auto text = [](const Vec3& v) {
    std::ostringstream s;
    s.precision(9);
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
  };
  if (a.Points.size() != b.Points.size() || a.Triangles.size() != b.Triangles.size())
  {
    return differ("the geometry changed: " + std::to_string(a.Triangles.size()) + " triangles on " +
      std::to_string(a.Points.size()) + " points, now " + std::to_string(b.Triangles.size()) + " on " +
      std::to_string(b.Points.size()));
  }
  for (std::size_t p = 0; p < a.Points.size(); ++p)
  {
    if (a.Points[p] != b.Points[p])
    {
      return differ("the geometry changed: point " + std::to_string(p) + " moved from " + text(a.Points[p]) +
        " to " + text(b.Points[p]));
    }
  }
  for (std::size_t t = 0; t < a.Triangles.size(); ++t)
  {
    const Triangle& x = a.Triangles[t];
    const Triangle& y = b.Triangles[t];
    if (x.V[0] != y.V[0] || x.V[1] != y.V[1] || x.V[2] != y.V[2] || a.ObjectIds[t] != b.ObjectIds[t])
    {
      return differ("the geometry changed: triangle " + std::to_string(t) + " has other points or another object");
    }
    if (a.Materials[t].Reflectance != b.Materials[t].Reflectance)
    {
      return differ("the reflectance of triangle " + std::to_string(t) + " changed from " +
        text(a.Materials[t].Reflectance) + " to " + text(b.Materials[t].Reflectance));
    }
    if (a.Materials[t].Specular != b.Materials[t].Specular || a.Materials[t].Shininess != b.Materials[t].Shininess)
    {
      return differ("the specular colour of triangle " + std::to_string(t) + " changed");
    }
  }
  return true;
}
} // namespace radiosity
