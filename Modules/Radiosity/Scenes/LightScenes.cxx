#include "Radiosity/Scenes/LightScenes.h"

#include "Radiosity/Scenes/SceneGenerators.h"

#include <cmath>

namespace radiosity
{
namespace
{
Material Grey(double reflectance)
{
  Material m;
  m.Reflectance = RGB(reflectance);
  m.Emission = RGB(0.0);
  return m;
}

/// The floor [-h, h]^2 x scale at z = 0, facing up.
void AppendFloor(Scene& s, double half, double scale, double reflectance, int n)
{
  const double h = half * scale;
  AppendQuad(s, Vec3(-h, -h, 0), Vec3(h, -h, 0), Vec3(h, h, 0), Vec3(-h, h, 0), Grey(reflectance),
    n, "floor");
}

Probe Up(double x, double y, double z = 0.0)
{
  return Probe{ Vec3(x, y, z), Vec3(0.0, 0.0, 1.0) };
}

std::vector<Probe> Scaled(std::vector<Probe> probes, double scale)
{
  for (Probe& p : probes)
  {
    p.Position *= scale;
  }
  return probes;
}

Sky MakeSky(SkyModel model)
{
  Sky sky;
  sky.Model = model;
  sky.Up = Vec3(0.0, 0.0, 1.0);
  sky.Radiance = RGB(lightscenes::SkyRadiance);
  return sky;
}
}

Scene MakePointLightOverPlane(double scale, double reflectance, int n)
{
  Scene s;
  AppendFloor(s, 2.0, scale, reflectance, n);
  Light light;
  light.Type = LightType::Point;
  light.Position = Vec3(0.0, 0.0, lightscenes::LightHeight * scale);
  light.Intensity = RGB(lightscenes::PointIntensity);
  light.Name = "point";
  s.Lighting.Lights.push_back(light);
  return s;
}

Scene MakeSpotOverPlane(double scale, double reflectance, int n)
{
  Scene s;
  AppendFloor(s, 2.0, scale, reflectance, n);
  Light light;
  light.Type = LightType::Spot;
  light.Position = Vec3(0.0, 0.0, lightscenes::LightHeight * scale);
  light.Direction = glm::normalize(Vec3(0.3, 0.0, -1.0));
  light.Intensity = RGB(lightscenes::PointIntensity);
  light.InnerConeAngle = lightscenes::SpotInner;
  light.OuterConeAngle = lightscenes::SpotOuter;
  light.Name = "spot";
  s.Lighting.Lights.push_back(light);
  return s;
}

std::vector<Vec3> SunPlateCorners(double scale)
{
  const double h = lightscenes::PlateHalfSide * scale, z = lightscenes::PlateHeight * scale;
  return { Vec3(-h, -h, z), Vec3(h, -h, z), Vec3(h, h, z), Vec3(-h, h, z) };
}

Scene MakeSunOverPlate(double scale, int n)
{
  Scene s;
  AppendFloor(s, 2.0, scale, 0.0, n);
  const std::vector<Vec3> c = SunPlateCorners(scale);
  AppendQuad(s, c[0], c[1], c[2], c[3], Grey(0.0), 2, "plate top");
  AppendQuad(s, c[0], c[3], c[2], c[1], Grey(0.0), 2, "plate bottom");
  Light sun;
  sun.Type = LightType::Directional;
  sun.Direction = glm::normalize(Vec3(0.5, 0.25, -1.0));
  sun.Intensity = RGB(lightscenes::SunIrradiance);
  sun.Name = "sun";
  s.Lighting.Lights.push_back(sun);
  return s;
}

Scene MakePointLightInSphere(double radius, int levels, double reflectance)
{
  Scene s = MakeSphereInterior(radius, levels, reflectance, RGB(0.0));
  Light light;
  light.Type = LightType::Point;
  light.Position = Vec3(0.3, 0.1, -0.2) * radius;
  light.Intensity = RGB(lightscenes::PointIntensity);
  light.Name = "point";
  s.Lighting.Lights.push_back(light);
  return s;
}

Scene MakeUniformSkyOverPlane(double scale, double reflectance, int n)
{
  Scene s;
  AppendFloor(s, 2.0, scale, reflectance, n);
  s.Lighting.SkyLight = MakeSky(SkyModel::Uniform);
  return s;
}

std::vector<Vec3> SkyWallCorners(double scale)
{
  const double w = lightscenes::WallHalfWidth * scale, h = lightscenes::WallHeight * scale;
  // Counter-clockwise seen from -y: the front faces -y.
  return { Vec3(-w, 0, 0), Vec3(w, 0, 0), Vec3(w, 0, h), Vec3(-w, 0, h) };
}

Scene MakeUniformSkyBesideWall(double scale, int n)
{
  Scene s;
  const double f = 4.0 * scale;
  AppendQuad(s, Vec3(-f, -f, 0), Vec3(f, -f, 0), Vec3(f, 0, 0), Vec3(-f, 0, 0), Grey(0.0), n,
    "floor");
  const std::vector<Vec3> c = SkyWallCorners(scale);
  AppendQuad(s, c[0], c[1], c[2], c[3], Grey(0.0), n, "wall");
  s.Lighting.SkyLight = MakeSky(SkyModel::Uniform);
  return s;
}

Scene MakeCieSkyOverPlane(double scale, double reflectance, int n)
{
  Scene s;
  AppendFloor(s, 2.0, scale, reflectance, n);
  s.Lighting.SkyLight = MakeSky(SkyModel::CieOvercast);
  return s;
}

std::vector<LightCase> AnalyticLightCases(double scale)
{
  std::vector<LightCase> cases;
  // Floor probes: under the light, at mid distances and near a corner.
  const std::vector<Probe> floorProbes = { Up(0, 0), Up(0.5, 0), Up(0.3, -0.8), Up(1.0, 0.7),
    Up(-1.5, 1.2), Up(1.8, -1.7) };
  cases.push_back({ "point light over a black plane", MakePointLightOverPlane(scale, 0.0),
    Scaled(floorProbes, scale), true, false });
  cases.push_back({ "point light over a grey plane", MakePointLightOverPlane(scale, 0.5),
    Scaled(floorProbes, scale), true, false });
  // The spot's axis meets the floor at x = 0.3; the inner cone reaches about
  // x in [0, 0.64], the outer about [-0.35, 1.3] (at y = 0).
  cases.push_back({ "spot over a black plane", MakeSpotOverPlane(scale, 0.0),
    Scaled({ Up(0.3, 0), Up(0.1, 0.15), Up(0.8, 0), Up(1.0, 0.2), Up(-0.2, 0), Up(0.3, 0.6),
             Up(1.6, 0), Up(-1.0, -1.0) },
      scale),
    true, false });
  // The plate's shadow: x in [-0.15, 0.65], y in [-0.275, 0.525] on the floor.
  cases.push_back({ "sun over a plate", MakeSunOverPlate(scale),
    Scaled({ Up(0.25, 0.125), Up(0.5, 0.4), Up(-0.05, -0.15), Up(-0.5, 0), Up(1.0, 0),
             Up(0.25, -0.6), Up(0.8, 0.7), Up(0.1, 0.2, lightscenes::PlateHeight) },
      scale),
    true, false });
  {
    LightCase sphere{ "point light in a sphere", MakePointLightInSphere(scale, 3, 0.5), {}, false,
      false };
    for (std::size_t t = 0; t < sphere.Geometry.Triangles.size(); t += 211)
    {
      sphere.Probes.push_back(Probe{ sphere.Geometry.Centroid(t), sphere.Geometry.Normal(t) });
    }
    cases.push_back(sphere);
  }
  cases.push_back({ "uniform sky over a plane", MakeUniformSkyOverPlane(scale),
    Scaled({ Up(0, 0), Up(1.0, 0.7), Up(-1.8, 1.5) }, scale), false, true });
  cases.push_back({ "uniform sky beside a wall", MakeUniformSkyBesideWall(scale),
    Scaled({ Up(0, -0.3), Up(0, -1.0), Up(0, -2.5), Up(2.0, -1.0), Up(2.8, -0.3), Up(-3.5, -1.0),
             Up(-3.8, -3.8) },
      scale),
    false, true });
  cases.push_back({ "CIE overcast sky over a plane", MakeCieSkyOverPlane(scale),
    Scaled({ Up(0, 0), Up(1.0, 0.7), Up(-1.8, 1.5) }, scale), false, true });
  return cases;
}

Scene WithOtherLighting(const Scene& scene)
{
  Scene other = scene;
  const double shift = 0.1 * scene.Diagonal();
  for (Light& l : other.Lighting.Lights)
  {
    l.Intensity *= RGB(0.3, 0.6, 1.0);
    l.Position += Vec3(shift, 0.5 * shift, 0.0);
  }
  other.Lighting.SkyLight.Radiance *= RGB(0.3, 0.6, 1.0);
  return other;
}
} // namespace radiosity
