#include "Radiosity/Common/Lights.h"

#include "Radiosity/Common/Scene.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace radiosity
{
const char* LightTypeName(LightType type)
{
  switch (type)
  {
    case LightType::Point:
      return "point";
    case LightType::Spot:
      return "spot";
    case LightType::Directional:
      return "directional";
  }
  return "unknown";
}

const char* SkyModelName(SkyModel model)
{
  switch (model)
  {
    case SkyModel::None:
      return "none";
    case SkyModel::Uniform:
      return "uniform";
    case SkyModel::CieOvercast:
      return "cie-overcast";
  }
  return "unknown";
}

double SpotFalloff(const Light& spot, double cosAngleToAxis)
{
  const double cosInner = std::cos(spot.InnerConeAngle);
  const double cosOuter = std::cos(spot.OuterConeAngle);
  if (cosAngleToAxis >= cosInner)
  {
    return 1.0;
  }
  if (cosAngleToAxis <= cosOuter)
  {
    return 0.0;
  }
  const double t = (cosAngleToAxis - cosOuter) / (cosInner - cosOuter);
  return t * t;
}

RGB UnshadowedIrradiance(const Light& light, const Vec3& x, const Vec3& n)
{
  if (light.Type == LightType::Directional)
  {
    const double c = -glm::dot(n, light.Direction);
    return c > 0.0 ? c * light.Intensity : RGB(0.0);
  }
  const Vec3 d = light.Position - x;
  const double d2 = glm::dot(d, d);
  if (!(d2 > 0.0))
  {
    return RGB(0.0);
  }
  const double dist = std::sqrt(d2);
  const double c = glm::dot(n, d) / dist;
  if (!(c > 0.0))
  {
    return RGB(0.0);
  }
  double falloff = 1.0;
  if (light.Type == LightType::Spot)
  {
    falloff = SpotFalloff(light, -glm::dot(d, light.Direction) / dist);
  }
  return (falloff * c / d2) * light.Intensity;
}

Vec3 ShadowRayTarget(const Light& light, const Vec3& x, double farDistance)
{
  return light.Type == LightType::Directional ? x - farDistance * light.Direction
                                              : light.Position;
}

RGB SkyRadiance(const Sky& sky, const Vec3& towards)
{
  const double c = glm::dot(towards, sky.Up);
  if (!(c > 0.0))
  {
    return RGB(0.0);
  }
  switch (sky.Model)
  {
    case SkyModel::Uniform:
      return sky.Radiance;
    case SkyModel::CieOvercast:
      return sky.Radiance * ((1.0 + 2.0 * c) / 3.0);
    case SkyModel::None:
      break;
  }
  return RGB(0.0);
}

RGB UnobstructedHorizontalIrradiance(const Sky& sky)
{
  switch (sky.Model)
  {
    case SkyModel::Uniform:
      return Pi * sky.Radiance;
    case SkyModel::CieOvercast:
      return (7.0 / 9.0) * Pi * sky.Radiance;
    case SkyModel::None:
      break;
  }
  return RGB(0.0);
}

RGB EmittedPower(const Light& light)
{
  switch (light.Type)
  {
    case LightType::Point:
      return 4.0 * Pi * light.Intensity;
    case LightType::Spot:
    {
      const double ci = std::cos(light.InnerConeAngle), co = std::cos(light.OuterConeAngle);
      return 2.0 * Pi * ((1.0 - ci) + (ci - co) / 3.0) * light.Intensity;
    }
    case LightType::Directional:
      break;
  }
  return RGB(0.0);
}

namespace
{
std::string Number(double v)
{
  std::ostringstream s;
  s.precision(9);
  s << v;
  return s.str();
}

std::string Triple(const Vec3& v)
{
  return "(" + Number(v.x) + ", " + Number(v.y) + ", " + Number(v.z) + ")";
}

bool FiniteVec(const Vec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

[[noreturn]] void Refuse(const std::string& who, const std::string& field, const std::string& why)
{
  throw SceneError(who + ": field '" + field + "' " + why);
}

void CheckIntensity(const RGB& value, const std::string& who)
{
  if (!FiniteVec(value))
  {
    Refuse(who, "intensity", "(color x intensity) is not finite: " + Triple(value));
  }
  if (std::min({ value.x, value.y, value.z }) < 0.0)
  {
    Refuse(who, "intensity", "(color x intensity) is negative: " + Triple(value));
  }
}

Vec3 UnitDirection(const Vec3& d, const std::string& who, const std::string& field)
{
  if (!FiniteVec(d))
  {
    Refuse(who, field, "is not finite: " + Triple(d));
  }
  const double len = glm::length(d);
  if (!(len > 0.0) || !std::isfinite(len))
  {
    Refuse(who, field, "is a zero vector " + Triple(d));
  }
  return d / len;
}
}

void ValidateLight(Light& light, const std::string& who)
{
  CheckIntensity(light.Intensity, who);
  if (light.Type != LightType::Directional && !FiniteVec(light.Position))
  {
    Refuse(who, "position", "is not finite: " + Triple(light.Position));
  }
  if (light.Type != LightType::Point)
  {
    light.Direction = UnitDirection(light.Direction, who, "direction");
  }
  if (light.Type == LightType::Spot)
  {
    const double inner = light.InnerConeAngle, outer = light.OuterConeAngle;
    if (!std::isfinite(inner) || inner < 0.0)
    {
      Refuse(who, "innerConeAngle", "must be finite and >= 0, got " + Number(inner));
    }
    if (!std::isfinite(outer) || outer > Pi / 2.0 + 1e-12)
    {
      Refuse(who, "outerConeAngle", "must be finite and <= pi/2, got " + Number(outer));
    }
    if (!(inner < outer))
    {
      Refuse(who, "innerConeAngle", "must be below outerConeAngle: inner " + Number(inner) +
          " >= outer " + Number(outer));
    }
  }
}

void ValidateSky(Sky& sky, const std::string& who)
{
  if (sky.Model == SkyModel::None)
  {
    return;
  }
  CheckIntensity(sky.Radiance, who);
  sky.Up = UnitDirection(sky.Up, who, "up");
}

void ValidateLights(LightSet& lights)
{
  for (std::size_t i = 0; i < lights.Lights.size(); ++i)
  {
    Light& l = lights.Lights[i];
    ValidateLight(l, "light " + std::to_string(i) + " (" + LightTypeName(l.Type) +
        (l.Name.empty() ? std::string() : ", '" + l.Name + "'") + ")");
  }
  ValidateSky(lights.SkyLight, "the sky");
}
} // namespace radiosity
