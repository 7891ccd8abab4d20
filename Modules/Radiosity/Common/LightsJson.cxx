// LIGHTS.json (SPEC.md "Lights and sky"): KHR_lights_punctual's field names and
// defaults (color (1, 1, 1), intensity 1, spot cones 0 and pi/4, direction -z),
// with the placement a glTF node would give written out: position for point
// and spot lights, direction for spot and directional ones. Parsed with
// nlohmann::json; every refusal names the file, the light's index and the field.
#include "Radiosity/Common/Lights.h"

#include "Radiosity/Common/Scene.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

namespace radiosity
{
void ValidateLight(Light& light, const std::string& who);
void ValidateSky(Sky& sky, const std::string& who);

namespace
{
using Json = nlohmann::json;

[[noreturn]] void RefuseField(const std::string& who, const std::string& field, const std::string& why)
{
  throw SceneError(who + ": field '" + field + "' " + why);
}

double NumberField(const Json& entry, const char* field, double fallback, const std::string& who)
{
  if (!entry.contains(field))
  {
    return fallback;
  }
  const Json& v = entry.at(field);
  if (!v.is_number())
  {
    RefuseField(who, field, "must be a number, got " + v.dump());
  }
  return v.get<double>();
}

Vec3 VectorField(const Json& entry, const char* field, const Vec3* fallback, const std::string& who)
{
  if (!entry.contains(field))
  {
    if (!fallback)
    {
      RefuseField(who, field, "is missing (SPEC: explicit placement)");
    }
    return *fallback;
  }
  const Json& v = entry.at(field);
  if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
  {
    RefuseField(who, field, "must be an array of 3 numbers, got " + v.dump());
  }
  return Vec3(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
}

std::string TextField(const Json& entry, const char* field, const std::string& fallback, const std::string& who)
{
  if (!entry.contains(field))
  {
    return fallback;
  }
  const Json& v = entry.at(field);
  if (!v.is_string())
  {
    RefuseField(who, field, "must be a string, got " + v.dump());
  }
  return v.get<std::string>();
}
}

LightSet ParseLightsJson(const std::string& text, const std::string& fileName)
{
  Json doc;
  try
  {
    doc = Json::parse(text);
  }
  catch (const Json::exception& e)
  {
    // parse_error, and out_of_range for a number beyond double (1e999).
    throw SceneError(fileName + ": not valid JSON: " + e.what());
  }
  const Json* list = &doc;
  if (doc.is_object())
  {
    if (!doc.contains("lights"))
    {
      throw SceneError(fileName + ": no \"lights\" array");
    }
    list = &doc.at("lights");
  }
  if (!list->is_array())
  {
    throw SceneError(fileName + ": \"lights\" must be an array");
  }
  LightSet result;
  bool haveSky = false;
  for (std::size_t i = 0; i < list->size(); ++i)
  {
    const Json& entry = (*list)[i];
    std::string who = fileName + ": light " + std::to_string(i);
    if (!entry.is_object())
    {
      throw SceneError(who + ": must be an object, got " + entry.dump());
    }
    if (!entry.contains("type"))
    {
      RefuseField(who, "type", "is missing (point, spot, directional or sky)");
    }
    const std::string type = TextField(entry, "type", "", who);
    const std::string name = TextField(entry, "name", "", who);
    who += " (" + type + (name.empty() ? std::string() : ", '" + name + "'") + ")";
    const Vec3 white(1.0);
    const Vec3 minusZ(0.0, 0.0, -1.0);
    const RGB color = VectorField(entry, "color", &white, who);
    const double intensity = NumberField(entry, "intensity", 1.0, who);
    if (type == "sky")
    {
      if (haveSky)
      {
        throw SceneError(who + ": a second sky (a scene has at most one)");
      }
      haveSky = true;
      Sky sky;
      const std::string model = TextField(entry, "model", "uniform", who);
      if (model == "uniform")
      {
        sky.Model = SkyModel::Uniform;
      }
      else if (model == "cie-overcast")
      {
        sky.Model = SkyModel::CieOvercast;
      }
      else
      {
        RefuseField(who, "model", "is unknown: \"" + model + "\" (uniform or cie-overcast)");
      }
      const Vec3 zUp(0.0, 0.0, 1.0);
      sky.Up = VectorField(entry, "up", &zUp, who);
      sky.Radiance = color * intensity;
      if (!std::isfinite(intensity) || intensity < 0.0)
      {
        RefuseField(who, "intensity", "must be finite and >= 0, got " + Json(intensity).dump());
      }
      ValidateSky(sky, who);
      result.SkyLight = sky;
      continue;
    }
    Light light;
    light.Name = name;
    if (type == "point")
    {
      light.Type = LightType::Point;
    }
    else if (type == "spot")
    {
      light.Type = LightType::Spot;
    }
    else if (type == "directional")
    {
      light.Type = LightType::Directional;
    }
    else
    {
      RefuseField(who, "type", "is unknown: \"" + type + "\" (point, spot, directional or sky)");
    }
    if (intensity < 0.0)
    {
      RefuseField(who, "intensity", "is negative: " + Json(intensity).dump());
    }
    light.Intensity = color * intensity;
    if (light.Type != LightType::Directional)
    {
      light.Position = VectorField(entry, "position", nullptr, who);
    }
    if (light.Type != LightType::Point)
    {
      light.Direction = VectorField(entry, "direction", &minusZ, who);
    }
    if (light.Type == LightType::Spot)
    {
      // KHR_lights_punctual nests the cones in "spot"; SPEC's example has them at the top.
      const Json& cones = entry.contains("spot") && entry.at("spot").is_object() ? entry.at("spot") : entry;
      light.InnerConeAngle = NumberField(cones, "innerConeAngle", 0.0, who);
      light.OuterConeAngle = NumberField(cones, "outerConeAngle", Pi / 4.0, who);
    }
    ValidateLight(light, who);
    result.Lights.push_back(light);
  }
  return result;
}

LightSet ReadLightsFile(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  if (!in)
  {
    throw SceneError(fileName + ": cannot open the lights file");
  }
  std::ostringstream text;
  text << in.rdbuf();
  return ParseLightsJson(text.str(), fileName);
}
} // namespace radiosity
