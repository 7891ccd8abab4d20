#include "Radiosity/Reference/AnalyticLights.h"

#include "Radiosity/Common/FormFactor.h"

#include <algorithm>
#include <cmath>

namespace radiosity
{
namespace analyticlights
{
double SpotFalloff(double innerConeAngle, double outerConeAngle, double cosAngleToAxis)
{
  // KHR_lights_punctual's reference: lightAngleScale = 1 / max(0.001, cos inner
  // - cos outer), offset = -cos outer * scale, attenuation = clamp(cd * scale
  // + offset, 0, 1)^2; without the 0.001 floor (inner < outer is validated).
  const double cosOuter = std::cos(outerConeAngle);
  const double ramp = (cosAngleToAxis - cosOuter) / (std::cos(innerConeAngle) - cosOuter);
  const double t = std::min(1.0, std::max(0.0, ramp));
  return t * t;
}

double PointLightOnPlane(double intensity, double height, double distance)
{
  return intensity * height / (distance * distance * distance);
}

RGB PunctualIrradiance(const Light& light, const Vec3& p, const Vec3& n)
{
  if (light.Type == LightType::Directional)
  {
    const Vec3 towards = -glm::normalize(light.Direction);
    return std::max(0.0, glm::dot(n, towards)) * light.Intensity;
  }
  const Vec3 d = light.Position - p;
  const double r = glm::length(d);
  if (!(r > 0.0))
  {
    return RGB(0.0);
  }
  const double cosine = glm::dot(n, d) / r;
  if (!(cosine > 0.0))
  {
    return RGB(0.0);
  }
  double scale = cosine / (r * r);
  if (light.Type == LightType::Spot)
  {
    scale *= SpotFalloff(light.InnerConeAngle, light.OuterConeAngle,
      glm::dot(-d / r, glm::normalize(light.Direction)));
  }
  return scale * light.Intensity;
}

RGB PunctualPower(const Light& light)
{
  switch (light.Type)
  {
    case LightType::Point:
      return 4.0 * Pi * light.Intensity;
    case LightType::Spot:
    {
      // 2 pi (int_{cos inner}^1 dmu + int_{cos outer}^{cos inner} ramp(mu)^2 dmu).
      const double ci = std::cos(light.InnerConeAngle), co = std::cos(light.OuterConeAngle);
      return 2.0 * Pi * ((1.0 - ci) + (ci - co) / 3.0) * light.Intensity;
    }
    case LightType::Directional:
      break;
  }
  return RGB(0.0);
}

std::vector<Vec3> ShadowOnPlane(const std::vector<Vec3>& blocker, const Vec3& travel,
  const Vec3& planePoint, const Vec3& planeNormal)
{
  std::vector<Vec3> shadow;
  const double along = glm::dot(travel, planeNormal);
  for (const Vec3& b : blocker)
  {
    // b + t travel on the plane: (b + t travel - q) . m = 0.
    shadow.push_back(b + travel * (glm::dot(planePoint - b, planeNormal) / along));
  }
  return shadow;
}

bool InsideConvexPolygon(const Vec3& p, const std::vector<Vec3>& poly)
{
  if (poly.size() < 3)
  {
    return false;
  }
  Vec3 normal(0.0);
  for (std::size_t i = 1; i + 1 < poly.size(); ++i)
  {
    normal += glm::cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
  }
  for (std::size_t i = 0; i < poly.size(); ++i)
  {
    const Vec3& a = poly[i];
    const Vec3& b = poly[(i + 1) % poly.size()];
    if (glm::dot(glm::cross(b - a, p - a), normal) < 0.0)
    {
      return false;
    }
  }
  return true;
}

bool SegmentCrossesConvexPolygon(
  const Vec3& a, const Vec3& b, const std::vector<Vec3>& poly, double tolerance)
{
  if (poly.size() < 3)
  {
    return false;
  }
  Vec3 normal(0.0);
  for (std::size_t i = 1; i + 1 < poly.size(); ++i)
  {
    normal += glm::cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
  }
  normal = glm::normalize(normal);
  const double da = glm::dot(a - poly[0], normal), db = glm::dot(b - poly[0], normal);
  if (std::fabs(da) <= tolerance || std::fabs(db) <= tolerance || (da > 0.0) == (db > 0.0))
  {
    return false;
  }
  const Vec3 x = a + (b - a) * (da / (da - db));
  return InsideConvexPolygon(x, poly);
}

RGB SunOnFloorWithBlocker(const Light& sun, const std::vector<Vec3>& blocker,
  const Vec3& floorPoint, const Vec3& floorNormal, const Vec3& p)
{
  const std::vector<Vec3> shadow = ShadowOnPlane(blocker, sun.Direction, floorPoint, floorNormal);
  return InsideConvexPolygon(p, shadow) ? RGB(0.0) : PunctualIrradiance(sun, p, floorNormal);
}

RGB LightsInSphere(const std::vector<Light>& lights, const RGB& rho, double area,
  const Vec3& p, const Vec3& n)
{
  RGB direct(0.0), power(0.0);
  for (const Light& light : lights)
  {
    direct += PunctualIrradiance(light, p, n);
    power += PunctualPower(light);
  }
  return direct + rho * power / ((RGB(1.0) - rho) * area);
}

double SkyHiddenBy(const Vec3& p, const Vec3& n, const Vec3& up, const std::vector<Vec3>& blocker)
{
  if (blocker.size() < 3)
  {
    return 0.0;
  }
  // Clip to the half-space (y - p) . up >= 0: below the horizon there is no sky to hide.
  std::vector<Vec3> above;
  for (std::size_t i = 0; i < blocker.size(); ++i)
  {
    const Vec3& a = blocker[i];
    const Vec3& b = blocker[(i + 1) % blocker.size()];
    const double ha = glm::dot(a - p, up), hb = glm::dot(b - p, up);
    if (ha >= 0.0)
    {
      above.push_back(a);
    }
    if ((ha >= 0.0) != (hb >= 0.0))
    {
      above.push_back(a + (b - a) * (ha / (ha - hb)));
    }
  }
  if (above.size() < 3)
  {
    return 0.0;
  }
  // Face p: the contour formula counts a polygon seen from its front only.
  const Vec3 normal = glm::cross(above[1] - above[0], above[2] - above[0]);
  if (glm::dot(normal, p - above[0]) < 0.0)
  {
    std::reverse(above.begin(), above.end());
  }
  return PointToPolygonFormFactor(p, n, above.data(), above.size());
}

RGB UniformSkyIrradiance(const Sky& sky, const Vec3& p, const Vec3& n, const std::vector<Vec3>& blocker)
{
  const Vec3 up = glm::normalize(sky.Up);
  const double open = 0.5 * (1.0 + glm::dot(n, up));
  return Pi * std::max(0.0, open - SkyHiddenBy(p, n, up, blocker)) * sky.Radiance;
}

RGB CieOvercastHorizontal(const Sky& sky)
{
  // int L_z (1 + 2 cos) / 3 cos dw = L_z / 3 (pi + 2 * 2 pi / 3).
  return (Pi + 4.0 * Pi / 3.0) / 3.0 * sky.Radiance;
}
} // namespace analyticlights
} // namespace radiosity
