// The analytic light cases (Scenes/LightScenes.h): ComputeAnalyticReference
// recognises each, and its values equal the explicit formulas of
// AnalyticLights.h and hand-derived closed forms written here (I h / d^3,
// the wall's form factor integrated by hand, the power balance of the sphere).
#include "Radiosity/Reference/AnalyticLights.h"
#include "Radiosity/Reference/AnalyticReference.h"
#include "Radiosity/Scenes/LightScenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

using namespace radiosity;

namespace
{
constexpr double TestPi = 3.14159265358979323846;

AnalyticReference Recognise(const LightCase& c)
{
  AnalyticReference ref;
  std::string why;
  EXPECT_TRUE(ComputeAnalyticReference(c.Geometry, c.Probes, ref, why)) << c.Name << ": " << why;
  EXPECT_EQ(ref.Irradiance.size(), c.Probes.size()) << c.Name;
  return ref;
}

const LightCase& Case(const std::vector<LightCase>& cases, const std::string& name)
{
  for (const LightCase& c : cases)
  {
    if (c.Name == name)
    {
      return c;
    }
  }
  throw std::runtime_error("no light case " + name);
}

/// The form factor from a horizontal element at the origin to the vertical
/// rectangle y = c, x in [x0, x1], z in [0, h] (its front facing the origin):
/// F = (c / pi) int int z / (x^2 + c^2 + z^2)^2 dz dx, the z integral done by
/// hand: (c / 2 pi) [atan(x / c) / c - atan(x / s) / s] from x0 to x1, s^2 = c^2 + h^2.
double HorizontalToVerticalRectangle(double c, double x0, double x1, double h)
{
  const double s = std::sqrt(c * c + h * h);
  const auto g = [&](double x) { return std::atan(x / c) / c - std::atan(x / s) / s; };
  return c / (2.0 * TestPi) * (g(x1) - g(x0));
}
}

TEST(AnalyticLights, EveryCaseIsRecognised)
{
  for (double scale : { 1.0, 1e-3, 1e3 })
  {
    for (const LightCase& c : AnalyticLightCases(scale))
    {
      const AnalyticReference ref = Recognise(c);
      std::cout << c.Name << " (scale " << scale << "): " << ref.Kind << "\n";
      for (const RGB& h : ref.Irradiance)
      {
        EXPECT_TRUE(std::isfinite(h.r) && h.r >= 0.0) << c.Name;
      }
    }
  }
}

TEST(AnalyticLights, PointAndSpotOverThePlane)
{
  for (double scale : { 1.0, 1e-3, 1e3 })
  {
    const std::vector<LightCase> cases = AnalyticLightCases(scale);
    for (const char* name : { "point light over a black plane", "point light over a grey plane" })
    {
      const LightCase& c = Case(cases, name);
      const AnalyticReference ref = Recognise(c);
      EXPECT_EQ(ref.Kind, "direct light of lights");
      for (std::size_t i = 0; i < c.Probes.size(); ++i)
      {
        const Vec3 p = c.Probes[i].Position / scale;
        const double d = std::sqrt(p.x * p.x + p.y * p.y + 1.0); // the light at height 1
        const double exact = lightscenes::PointIntensity * 1.0 / (d * d * d) / (scale * scale);
        EXPECT_NEAR(ref.Irradiance[i].r, exact, 1e-13 * exact) << name << " probe " << i;
        EXPECT_NEAR(analyticlights::PointLightOnPlane(
                      lightscenes::PointIntensity, scale, scale * d),
          exact, 1e-13 * exact);
      }
    }
    // The spot: glTF's falloff written out here, (clamp((cos - cos outer) /
    // (cos inner - cos outer)))^2, times I h / d^3.
    const LightCase& spot = Case(cases, "spot over a black plane");
    const AnalyticReference ref = Recognise(spot);
    const Vec3 axis = glm::normalize(Vec3(0.3, 0.0, -1.0));
    int full = 0, ramp = 0, dark = 0;
    for (std::size_t i = 0; i < spot.Probes.size(); ++i)
    {
      const Vec3 p = spot.Probes[i].Position / scale;
      const Vec3 d = p - Vec3(0, 0, 1);
      const double r = glm::length(d);
      const double cosAxis = glm::dot(d / r, axis);
      double t = (cosAxis - std::cos(lightscenes::SpotOuter)) /
        (std::cos(lightscenes::SpotInner) - std::cos(lightscenes::SpotOuter));
      t = t < 0 ? 0 : (t > 1 ? 1 : t);
      full += t == 1;
      dark += t == 0;
      ramp += t > 0 && t < 1;
      const double exact = lightscenes::PointIntensity * t * t / (r * r * r) / (scale * scale);
      EXPECT_NEAR(ref.Irradiance[i].r, exact, 1e-13 * lightscenes::PointIntensity / (scale * scale))
        << "spot probe " << i;
    }
    EXPECT_GE(full, 2);
    EXPECT_GE(ramp, 3);
    EXPECT_GE(dark, 2);
  }
}

TEST(AnalyticLights, SunShadowIsTheProjectedPlate)
{
  for (double scale : { 1.0, 1e-3, 1e3 })
  {
    const std::vector<LightCase> cases = AnalyticLightCases(scale);
    const LightCase& c = Case(cases, "sun over a plate");
    const AnalyticReference ref = Recognise(c);
    EXPECT_EQ(ref.Kind, "direct light of lights with convex blocker");
    const Light& sun = c.Geometry.Lighting.Lights[0];
    const double cosine = -sun.Direction.z; // on a floor facing up
    // The shadow by hand: the plate shifted by 0.5 (0.5, 0.25) / 1 (its height
    // over the direction's slope): x in [-0.15, 0.65], y in [-0.275, 0.525].
    int shadowed = 0, lit = 0;
    for (std::size_t i = 0; i < c.Probes.size(); ++i)
    {
      const Vec3 p = c.Probes[i].Position / scale;
      const bool onPlate = p.z > 0.25;
      const bool shadow = !onPlate && p.x > -0.15 && p.x < 0.65 && p.y > -0.275 && p.y < 0.525;
      const double exact = shadow ? 0.0 : lightscenes::SunIrradiance * cosine;
      shadowed += shadow;
      lit += !shadow;
      EXPECT_NEAR(ref.Irradiance[i].r, exact, 1e-12 * lightscenes::SunIrradiance) << "probe " << i;
      if (!onPlate)
      {
        const RGB explicitForm = analyticlights::SunOnFloorWithBlocker(sun, SunPlateCorners(scale),
          Vec3(0.0), Vec3(0, 0, 1), c.Probes[i].Position);
        EXPECT_NEAR(explicitForm.r, exact, 1e-12 * lightscenes::SunIrradiance) << "probe " << i;
      }
    }
    EXPECT_GE(shadowed, 3);
    EXPECT_GE(lit, 4);
  }
}

TEST(AnalyticLights, PointLightInTheSphere)
{
  // H = I cos / d^2 + rho 4 pi I / ((1 - rho) A), A the facets' area (4 pi R^2
  // for the smooth sphere, 0.6% less for the 1280 facets).
  for (double radius : { 1.0, 1e-3, 1e3 })
  {
    const std::vector<LightCase> cases = AnalyticLightCases(radius);
    const LightCase& c = Case(cases, "point light in a sphere");
    const AnalyticReference ref = Recognise(c);
    EXPECT_EQ(ref.Kind, "sphere interior with lights");
    double area = 0.0;
    for (std::size_t t = 0; t < c.Geometry.Triangles.size(); ++t)
    {
      area += c.Geometry.Area(t);
    }
    const double smooth = 4.0 * TestPi * radius * radius;
    EXPECT_NEAR(area / smooth, 1.0, 0.01);
    const double intensity = lightscenes::PointIntensity, rho = 0.5;
    const Vec3 light = Vec3(0.3, 0.1, -0.2) * radius;
    for (std::size_t i = 0; i < c.Probes.size(); ++i)
    {
      const Vec3 d = light - c.Probes[i].Position;
      const double r = glm::length(d);
      const double direct = intensity * glm::dot(d / r, c.Probes[i].Normal) / (r * r);
      const double exact = direct + rho * 4.0 * TestPi * intensity / ((1.0 - rho) * area);
      EXPECT_NEAR(ref.Irradiance[i].r, exact, 1e-12 * exact) << "probe " << i;
      // The smooth sphere's rho I / ((1 - rho) R^2) differs by the area alone.
      EXPECT_NEAR(ref.Irradiance[i].r,
        direct + rho * intensity / ((1.0 - rho) * radius * radius), 0.01 * exact);
    }
  }
}

TEST(AnalyticLights, SkyOverThePlaneAndBesideTheWall)
{
  for (double scale : { 1.0, 1e-3, 1e3 })
  {
    const std::vector<LightCase> cases = AnalyticLightCases(scale);
    const double l = lightscenes::SkyRadiance;
    for (const RGB& h : Recognise(Case(cases, "uniform sky over a plane")).Irradiance)
    {
      EXPECT_NEAR(h.r, TestPi * l, 1e-13 * l);
    }
    for (const RGB& h : Recognise(Case(cases, "CIE overcast sky over a plane")).Irradiance)
    {
      EXPECT_NEAR(h.r, 7.0 / 9.0 * TestPi * l, 1e-13 * l);
    }
    const LightCase& wall = Case(cases, "uniform sky beside a wall");
    const AnalyticReference ref = Recognise(wall);
    EXPECT_EQ(ref.Kind, "direct light of lights and sky with convex blocker");
    for (std::size_t i = 0; i < wall.Probes.size(); ++i)
    {
      const Vec3 p = wall.Probes[i].Position / scale;
      const double f = HorizontalToVerticalRectangle(-p.y, -lightscenes::WallHalfWidth - p.x,
        lightscenes::WallHalfWidth - p.x, lightscenes::WallHeight);
      const double exact = TestPi * l * (1.0 - f);
      std::cout << "wall probe " << i << ": F " << f << ", H / (pi L) " << exact / (TestPi * l)
                << "\n";
      EXPECT_NEAR(ref.Irradiance[i].r, exact, 1e-12 * l) << "probe " << i;
    }
  }
}

TEST(AnalyticLights, NoClosedFormWhereLightReflects)
{
  // A grey sun scene: the plate's top reflects the sun, nothing closed-form.
  Scene s = MakeSunOverPlate(1.0);
  for (Material& m : s.Materials)
  {
    m.Reflectance = RGB(0.5);
  }
  AnalyticReference ref;
  std::string why;
  EXPECT_FALSE(ComputeAnalyticReference(s, { Probe{} }, ref, why));
  EXPECT_NE(why.find("no closed form"), std::string::npos) << why;
  // A CIE sky partly hidden by the wall.
  Scene wall = MakeUniformSkyBesideWall(1.0);
  wall.Lighting.SkyLight.Model = SkyModel::CieOvercast;
  EXPECT_FALSE(ComputeAnalyticReference(wall, { Probe{ Vec3(0, -1, 0), Vec3(0, 0, 1) } }, ref, why));
  EXPECT_NE(why.find("CIE"), std::string::npos) << why;
}
