#include "Radiosity/Reference/AnalyticReference.h"

#include "Radiosity/Common/FormFactor.h"
#include "Radiosity/Common/SceneAnalysis.h"
#include "Radiosity/Reference/AnalyticLights.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace radiosity
{
namespace
{
/// Position-welded vertex ids (input files often repeat points per face).
std::vector<std::uint32_t> WeldVertices(const Scene& scene, double tolerance)
{
  std::map<std::tuple<long long, long long, long long>, std::uint32_t> index;
  std::vector<std::uint32_t> weld(scene.Points.size());
  for (std::size_t i = 0; i < scene.Points.size(); ++i)
  {
    const Vec3& p = scene.Points[i];
    const auto key = std::make_tuple(std::llround(p.x / tolerance), std::llround(p.y / tolerance),
      std::llround(p.z / tolerance));
    weld[i] = index.emplace(key, static_cast<std::uint32_t>(index.size())).first->second;
  }
  return weld;
}

/// Every directed edge has exactly one partner running the other way.
bool Watertight(const Scene& scene, const std::vector<std::uint32_t>& weld)
{
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (const Triangle& t : scene.Triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++edges[{ weld[t.V[k]], weld[t.V[(k + 1) % 3]] }];
    }
  }
  for (const auto& [edge, count] : edges)
  {
    const auto back = edges.find({ edge.second, edge.first });
    if (count != 1 || back == edges.end() || back->second != 1)
    {
      return false;
    }
  }
  return true;
}

bool SameColour(const RGB& a, const RGB& b)
{
  return glm::length(a - b) <= 1e-12 * (1.0 + glm::length(a));
}

/// Convex clip of polygon `in` by convex polygon `clip` (both in one plane
/// with normal `n`, counter-clockwise about n): Sutherland-Hodgman.
std::vector<Vec3> ClipConvex(std::vector<Vec3> in, const std::vector<Vec3>& clip, const Vec3& n)
{
  for (std::size_t i = 0; i < clip.size() && !in.empty(); ++i)
  {
    const Vec3 a = clip[i], b = clip[(i + 1) % clip.size()];
    const Vec3 inward = glm::cross(n, b - a);
    std::vector<Vec3> out;
    for (std::size_t j = 0; j < in.size(); ++j)
    {
      const Vec3 p = in[j], q = in[(j + 1) % in.size()];
      const double dp = glm::dot(p - a, inward), dq = glm::dot(q - a, inward);
      if (dp >= 0)
      {
        out.push_back(p);
      }
      if ((dp >= 0) != (dq >= 0))
      {
        out.push_back(p + dp / (dp - dq) * (q - p));
      }
    }
    in.swap(out);
  }
  return in;
}

/// Convex hull (counter-clockwise about n) of coplanar points.
std::vector<Vec3> PlanarHull(const std::vector<Vec3>& pts, const Vec3& n)
{
  const Vec3 u = glm::normalize(std::fabs(n.x) < 0.9 ? glm::cross(n, Vec3(1, 0, 0))
                                                     : glm::cross(n, Vec3(0, 1, 0)));
  const Vec3 v = glm::cross(n, u);
  std::vector<std::pair<std::pair<double, double>, Vec3>> p;
  for (const Vec3& x : pts)
  {
    p.push_back({ { glm::dot(x, u), glm::dot(x, v) }, x });
  }
  std::sort(p.begin(), p.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  const auto cross = [](const auto& o, const auto& a, const auto& b)
  {
    return (a.first.first - o.first.first) * (b.first.second - o.first.second) -
      (a.first.second - o.first.second) * (b.first.first - o.first.first);
  };
  std::vector<std::pair<std::pair<double, double>, Vec3>> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
  {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0)
    {
      --k;
    }
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;)
  {
    while (k >= t && cross(hull[k - 2], hull[k - 1], p[i]) <= 0)
    {
      --k;
    }
    hull[k++] = p[i];
  }
  std::vector<Vec3> out;
  for (std::size_t i = 0; i + 1 < k; ++i)
  {
    out.push_back(hull[i].second);
  }
  return out;
}

double PolygonArea(const std::vector<Vec3>& poly)
{
  Vec3 a(0.0);
  for (std::size_t i = 1; i + 1 < poly.size(); ++i)
  {
    a += glm::cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
  }
  return 0.5 * glm::length(a);
}

/// The triangles flagged in `occluders` that do not emit must form one convex
/// planar polygon of at most 5 vertices (both faces allowed), parallel to
/// every emitter: its vertices in `blocker` (empty when none is flagged).
bool FindConvexBlocker(const Scene& scene, const std::vector<unsigned char>& occluders,
  std::vector<Vec3>& blocker, std::string& why)
{
  const double diag = scene.Diagonal();
  std::vector<Vec3> blockerPoints;
  Vec3 blockerNormal(0.0);
  double blockerArea = 0.0;
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    if (!occluders[t] || MaxComponent(scene.Materials[t].Emission) > 0)
    {
      continue;
    }
    const Vec3 n = scene.Normal(t);
    if (blockerPoints.empty())
    {
      blockerNormal = n;
    }
    if (std::fabs(std::fabs(glm::dot(n, blockerNormal)) - 1.0) > 1e-9 ||
      std::fabs(glm::dot(scene.Vertex(t, 0) - (blockerPoints.empty() ? scene.Vertex(t, 0) : blockerPoints[0]), blockerNormal)) > 1e-9 * diag)
    {
      why = "no closed form: the occluders are not one planar blocker";
      return false;
    }
    if (glm::dot(n, blockerNormal) > 0)
    {
      blockerArea += scene.Area(t); // one side only (a two-sided blocker repeats it)
    }
    for (int k = 0; k < 3; ++k)
    {
      blockerPoints.push_back(scene.Vertex(t, k));
    }
  }
  blocker.clear();
  if (!blockerPoints.empty())
  {
    blocker = PlanarHull(blockerPoints, blockerNormal);
    if (std::fabs(PolygonArea(blocker) - blockerArea) > 1e-9 * blockerArea || blocker.size() > 5)
    {
      why = "no closed form: the blocker is not a convex polygon of at most 5 vertices";
      return false;
    }
    for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
    {
      if (MaxComponent(scene.Materials[t].Emission) > 0 &&
        std::fabs(std::fabs(glm::dot(scene.Normal(t), blockerNormal)) - 1.0) > 1e-9)
      {
        why = "no closed form: the blocker is not parallel to every emitter";
        return false;
      }
    }
  }
  return true;
}
}

RGB DirectIrradiance(
  const Scene& scene, const Vec3& p, const Vec3& n, const std::vector<Vec3>& blocker)
{
  RGB h(0.0);
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    const RGB& e = scene.Materials[t].Emission;
    if (MaxComponent(e) <= 0)
    {
      continue;
    }
    const std::vector<Vec3> tri = { scene.Vertex(t, 0), scene.Vertex(t, 1), scene.Vertex(t, 2) };
    double f = PointToPolygonFormFactor(p, n, tri.data(), 3);
    if (f > 0 && !blocker.empty())
    {
      // Project the blocker from p onto the emitter's plane, when it lies
      // between them, and remove the covered part of the emitter.
      const Vec3 m = scene.Normal(t);
      const double dp = glm::dot(p - tri[0], m);
      std::vector<Vec3> shadow;
      bool between = true;
      for (const Vec3& b : blocker)
      {
        const double db = glm::dot(b - tri[0], m);
        if (!(db < dp && db > 0))
        {
          between = false;
          break;
        }
        shadow.push_back(p + (b - p) * (dp / (dp - db)));
      }
      if (between)
      {
        // Orient both counter-clockwise about the emitter normal.
        if (glm::dot(glm::cross(shadow[1] - shadow[0], shadow[2] - shadow[0]), m) < 0)
        {
          std::reverse(shadow.begin(), shadow.end());
        }
        const std::vector<Vec3> covered = ClipConvex(tri, shadow, m);
        if (covered.size() >= 3)
        {
          f -= PointToPolygonFormFactor(p, n, covered.data(), covered.size());
        }
      }
    }
    h += std::max(f, 0.0) * e;
  }
  return h;
}

namespace
{
/// The scenes with lights that have a closed form (AnalyticLights.h).
bool AnalyticLightsReference(const Scene& scene, const std::vector<Probe>& probes,
  const std::vector<std::uint32_t>& weld, AnalyticReference& reference, std::string& why)
{
  namespace al = analyticlights;
  const LightSet& lights = scene.Lighting;
  const double diag = scene.Diagonal();
  const double tol = 1e-9 * diag;
  bool uniformReflectance = true, black = true;
  for (const Material& m : scene.Materials)
  {
    uniformReflectance = uniformReflectance && SameColour(m.Reflectance, scene.Materials[0].Reflectance);
    black = black && MaxComponent(m.Reflectance) == 0.0;
  }
  const RGB rho = scene.Materials[0].Reflectance;

  // Lights inside a closed sphere of uniform reflectance: the reflected
  // light is uniform, rho P / ((1 - rho) A) (+ mean(E) / (1 - rho)).
  if (uniformReflectance && Watertight(scene, weld))
  {
    Vec3 centre(0.0);
    for (const Vec3& p : scene.Points)
    {
      centre += p;
    }
    centre /= static_cast<double>(scene.Points.size());
    double rMin = 1e300, rMax = 0.0;
    for (const Vec3& p : scene.Points)
    {
      rMin = std::min(rMin, glm::length(p - centre));
      rMax = std::max(rMax, glm::length(p - centre));
    }
    if (rMax - rMin <= 1e-6 * rMax)
    {
      std::vector<Light> inside;
      for (std::size_t l = 0; l < lights.Lights.size(); ++l)
      {
        const Light& light = lights.Lights[l];
        if (light.Type == LightType::Directional)
        {
          continue; // no sunlight gets into a closed sphere (nor any sky)
        }
        for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
        {
          if (!(glm::dot(light.Position - scene.Vertex(t, 0), scene.Normal(t)) > tol))
          {
            why = "no closed form: light " + std::to_string(l) + " is not inside the closed sphere";
            return false;
          }
        }
        inside.push_back(light);
      }
      RGB meanEmission(0.0);
      double area = 0.0;
      for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
      {
        meanEmission += scene.Materials[t].Emission * scene.Area(t);
        area += scene.Area(t);
      }
      meanEmission /= area;
      reference.Kind = "sphere interior with lights";
      for (const Probe& probe : probes)
      {
        reference.Irradiance.push_back(
          al::LightsInSphere(inside, rho, area, probe.Position, glm::normalize(probe.Normal)) +
          meanEmission / (RGB(1.0) - rho));
      }
      return true;
    }
  }

  // Otherwise nothing may reflect light onto anything: every surface black,
  // or one plane (which never sees itself).
  bool onePlane = true;
  const Vec3 n0 = scene.Normal(0), p0 = scene.Vertex(0, 0);
  for (std::size_t t = 0; t < scene.Triangles.size() && onePlane; ++t)
  {
    onePlane = glm::dot(scene.Normal(t), n0) > 1.0 - 1e-9;
    for (int k = 0; k < 3 && onePlane; ++k)
    {
      onePlane = std::fabs(glm::dot(scene.Vertex(t, k) - p0, n0)) <= tol;
    }
  }
  if (!black && !onePlane)
  {
    why = "no closed form: surfaces reflect the lights onto each other (the scene is not black, "
          "not one plane and not a closed sphere)";
    return false;
  }
  // What can hide a light from a probe: a triangle with a scene point, a
  // probe or a point light behind its plane, a sun shining from behind it, or
  // a sky it can stand in front of (a plane not facing up).
  const SceneAnalysis analysis = AnalyzeScene(scene);
  std::vector<unsigned char> occluders = analysis.CanOcclude;
  const Vec3 up = lights.SkyLight.Enabled() ? glm::normalize(lights.SkyLight.Up) : Vec3(0.0);
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    const Vec3 n = scene.Normal(t), o = scene.Vertex(t, 0);
    bool can = occluders[t] != 0;
    for (std::size_t i = 0; i < probes.size() && !can; ++i)
    {
      can = glm::dot(probes[i].Position - o, n) < -tol;
    }
    for (const Light& light : lights.Lights)
    {
      can = can ||
        (light.Type == LightType::Directional ? glm::dot(light.Direction, n) > 1e-12
                                              : glm::dot(light.Position - o, n) < -tol);
    }
    can = can || (lights.SkyLight.Enabled() && glm::dot(n, up) < 1.0 - 1e-12);
    occluders[t] = can ? 1 : 0;
  }
  std::vector<Vec3> blocker;
  if (!FindConvexBlocker(scene, occluders, blocker, why))
  {
    return false;
  }
  Vec3 lo, hi;
  scene.BoundingBox(lo, hi);
  const Vec3 centre = 0.5 * (lo + hi);
  for (const Probe& probe : probes)
  {
    const Vec3 p = probe.Position, n = glm::normalize(probe.Normal);
    RGB h = DirectIrradiance(scene, p, n, blocker);
    for (const Light& light : lights.Lights)
    {
      const Vec3 target = light.Type == LightType::Directional
        ? p - 2.0 * (diag + glm::length(p - centre)) * glm::normalize(light.Direction)
        : light.Position;
      if (!al::SegmentCrossesConvexPolygon(p, target, blocker, tol))
      {
        h += al::PunctualIrradiance(light, p, n);
      }
    }
    if (lights.SkyLight.Enabled())
    {
      if (lights.SkyLight.Model == SkyModel::Uniform)
      {
        h += al::UniformSkyIrradiance(lights.SkyLight, p, n, blocker);
      }
      else if (blocker.empty() && glm::dot(n, up) > 1.0 - 1e-12)
      {
        h += al::CieOvercastHorizontal(lights.SkyLight);
      }
      else
      {
        why = "no closed form: a CIE overcast sky partly hidden, or a probe not facing up";
        reference.Irradiance.clear();
        return false;
      }
    }
    reference.Irradiance.push_back(h);
  }
  reference.Kind = std::string("direct light of lights") +
    (lights.SkyLight.Enabled() ? " and sky" : "") + (blocker.empty() ? "" : " with convex blocker");
  return true;
}
}

bool ComputeAnalyticReference(const Scene& scene, const std::vector<Probe>& probes,
  AnalyticReference& reference, std::string& why)
{
  reference = AnalyticReference();
  if (scene.Triangles.empty())
  {
    why = "the scene is empty";
    return false;
  }
  const double diag = scene.Diagonal();
  const std::vector<std::uint32_t> weld = WeldVertices(scene, 1e-9 * diag);
  if (!scene.Lighting.Empty())
  {
    return AnalyticLightsReference(scene, probes, weld, reference, why);
  }
  bool uniformReflectance = true, uniformEmission = true, black = true;
  for (const Material& m : scene.Materials)
  {
    uniformReflectance = uniformReflectance && SameColour(m.Reflectance, scene.Materials[0].Reflectance);
    uniformEmission = uniformEmission && SameColour(m.Emission, scene.Materials[0].Emission);
    black = black && MaxComponent(m.Reflectance) == 0.0;
  }
  const RGB rho = scene.Materials[0].Reflectance;
  if (uniformReflectance && Watertight(scene, weld))
  {
    if (uniformEmission)
    {
      reference.Kind = "closed uniform enclosure";
      reference.Irradiance.assign(probes.size(), scene.Materials[0].Emission / (RGB(1.0) - rho));
      return true;
    }
    // A sphere: every vertex at the same distance from the centre.
    Vec3 centre(0.0);
    for (const Vec3& p : scene.Points)
    {
      centre += p;
    }
    centre /= static_cast<double>(scene.Points.size());
    double rMin = 1e300, rMax = 0.0;
    for (const Vec3& p : scene.Points)
    {
      const double r = glm::length(p - centre);
      rMin = std::min(rMin, r);
      rMax = std::max(rMax, r);
    }
    if (rMax - rMin <= 1e-6 * rMax)
    {
      RGB meanEmission(0.0);
      double area = 0.0;
      for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
      {
        meanEmission += scene.Materials[t].Emission * scene.Area(t);
        area += scene.Area(t);
      }
      reference.Kind = "sphere interior";
      reference.Irradiance.assign(probes.size(), meanEmission / area / (RGB(1.0) - rho));
      return true;
    }
  }
  if (!black)
  {
    why = "no closed form: surfaces reflect and the scene is not a uniform closed enclosure or sphere";
    return false;
  }
  // Direct light only: the occluders that are not emitters must form one
  // convex planar blocker parallel to every emitter.
  const SceneAnalysis analysis = AnalyzeScene(scene);
  std::vector<Vec3> blocker;
  if (!FindConvexBlocker(scene, analysis.CanOcclude, blocker, why))
  {
    return false;
  }
  reference.Kind = blocker.empty() ? "direct" : "direct with convex blocker";
  for (const Probe& probe : probes)
  {
    reference.Irradiance.push_back(
      DirectIrradiance(scene, probe.Position, glm::normalize(probe.Normal), blocker));
  }
  return true;
}
} // namespace radiosity
