// LIGHTS.json and the light checks (SPEC.md "Lights and sky"): every bad
// light of SPEC's list is refused with a SceneError naming the file, the
// light's index and the field (unknown type, a non-finite value, a negative
// intensity, a zero direction, cone angles out of order, above pi/2 or
// negative, an unknown sky model, a second sky, a missing position, a field
// that is not a number); JSON cannot hold NaN, so a number too large for a
// double (1e999) stands for it in a file (refused by the JSON parser itself,
// naming the file and the number), and NaN itself goes through the C++ path,
// ValidateLights, naming the light and field. A good file reads with glTF's
// defaults (color 1, intensity 1, cones 0 and pi/4, direction -z).
#include "Radiosity/Common/Lights.h"
#include "Radiosity/Common/Scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>

namespace
{
using namespace radiosity;

const std::string File = "lights-test.json";

/// The message of the SceneError that parsing `text` throws ("" when none).
std::string Refusal(const std::string& text)
{
  try
  {
    ParseLightsJson(text, File);
  }
  catch (const SceneError& e)
  {
    return e.what();
  }
  return "";
}

std::string Refusal(LightSet lights)
{
  try
  {
    ValidateLights(lights);
  }
  catch (const SceneError& e)
  {
    return e.what();
  }
  return "";
}

/// A file whose light 1 is `bad` (light 0 a good point light, so the index counts).
std::string SecondLight(const std::string& bad)
{
  return R"({ "lights": [ { "type": "point", "position": [0, 0, 2] }, )" + bad + " ] }";
}

void ExpectNames(const std::string& message, const std::string& field, const std::string& light = "light 1")
{
  EXPECT_NE(message.find(File), std::string::npos) << "no file name in: " << message;
  EXPECT_NE(message.find(light), std::string::npos) << "no '" << light << "' in: " << message;
  EXPECT_NE(message.find("'" + field + "'"), std::string::npos) << "no field '" << field << "' in: " << message;
}

struct BadCase
{
  const char* What;
  const char* Light;
  const char* Field;
};

const BadCase BadLights[] = {
  { "unknown type", R"({ "type": "area", "position": [0, 0, 1] })", "type" },
  { "missing type", R"({ "position": [0, 0, 1] })", "type" },
  { "type not a string", R"({ "type": 3, "position": [0, 0, 1] })", "type" },
  { "negative intensity", R"({ "type": "point", "position": [0, 0, 1], "intensity": -2 })", "intensity" },
  { "negative colour", R"({ "type": "spot", "position": [0, 0, 1], "color": [1, -0.5, 1] })", "intensity" },
  { "zero direction (directional)", R"({ "type": "directional", "direction": [0, 0, 0] })", "direction" },
  { "zero direction (spot)", R"({ "type": "spot", "position": [0, 0, 1], "direction": [0, 0, 0] })",
    "direction" },
  { "cones out of order",
    R"({ "type": "spot", "position": [0, 0, 1], "innerConeAngle": 0.6, "outerConeAngle": 0.3 })",
    "innerConeAngle" },
  { "equal cones",
    R"({ "type": "spot", "position": [0, 0, 1], "innerConeAngle": 0.5, "outerConeAngle": 0.5 })",
    "innerConeAngle" },
  { "inner above the default outer", R"({ "type": "spot", "position": [0, 0, 1], "innerConeAngle": 1.0 })",
    "innerConeAngle" },
  { "outer above pi/2", R"({ "type": "spot", "position": [0, 0, 1], "outerConeAngle": 1.6 })",
    "outerConeAngle" },
  { "negative inner", R"({ "type": "spot", "position": [0, 0, 1], "innerConeAngle": -0.1 })",
    "innerConeAngle" },
  { "negative outer", R"({ "type": "spot", "position": [0, 0, 1], "outerConeAngle": -0.1 })",
    "innerConeAngle" }, // 0 <= inner < outer: a negative outer is below the inner
  { "glTF's nested cones out of order",
    R"({ "type": "spot", "position": [0, 0, 1], "spot": { "innerConeAngle": 0.7, "outerConeAngle": 0.2 } })",
    "innerConeAngle" },
  { "missing position (point)", R"({ "type": "point", "intensity": 2 })", "position" },
  { "missing position (spot)", R"({ "type": "spot", "direction": [0, 0, -1] })", "position" },
  { "intensity not a number", R"({ "type": "point", "position": [0, 0, 1], "intensity": "bright" })",
    "intensity" },
  { "cone not a number", R"({ "type": "spot", "position": [0, 0, 1], "outerConeAngle": [0.5] })",
    "outerConeAngle" },
  { "position of two numbers", R"({ "type": "point", "position": [0, 1] })", "position" },
  { "position of strings", R"({ "type": "point", "position": ["0", "0", "1"] })", "position" },
  { "colour not an array", R"({ "type": "point", "position": [0, 0, 1], "color": 1 })", "color" },
  { "unknown sky model", R"({ "type": "sky", "model": "cie-clear", "intensity": 100 })", "model" },
  { "sky model not a string", R"({ "type": "sky", "model": 16 })", "model" },
  { "negative sky", R"({ "type": "sky", "model": "uniform", "intensity": -1 })", "intensity" },
  { "zero sky up", R"({ "type": "sky", "model": "uniform", "up": [0, 0, 0] })", "up" },
};

/// JSON has no NaN or infinity: a number too large for a double is the way a
/// file says one. nlohmann::json refuses it while parsing (out_of_range 406,
/// "number overflow parsing '1e999'"), before any light is read, so the
/// SceneError names the file and the number, not a light or field.
const BadCase HugeNumbers[] = {
  { "infinite intensity (1e999)", R"({ "type": "point", "position": [0, 0, 1], "intensity": 1e999 })",
    "intensity" },
  { "infinite colour (1e999)", R"({ "type": "point", "position": [0, 0, 1], "color": [1, 1e999, 1] })",
    "intensity" },
  { "infinite position (1e999)", R"({ "type": "point", "position": [0, 1e999, 1] })", "position" },
  { "infinite direction (-1e999)", R"({ "type": "directional", "direction": [0, 0, -1e999] })",
    "direction" },
  { "infinite sky (1e999)", R"({ "type": "sky", "model": "uniform", "intensity": 1e999 })", "intensity" },
};
}

TEST(LightsJson, EveryBadLightNamesItsIndexAndField)
{
  for (const BadCase& c : BadLights)
  {
    SCOPED_TRACE(c.What);
    const std::string message = Refusal(SecondLight(c.Light));
    ASSERT_FALSE(message.empty()) << "accepted: " << c.Light;
    ExpectNames(message, c.Field);
  }
}

TEST(LightsJson, AHugeNumberIsASceneErrorNamingTheFileAndNumber)
{
  for (const BadCase& c : HugeNumbers)
  {
    SCOPED_TRACE(c.What);
    std::string message;
    try
    {
      message = Refusal(SecondLight(c.Light));
    }
    catch (const std::exception& e)
    {
      FAIL() << "not a SceneError (the command line would exit 1, not 2): " << e.what();
    }
    ASSERT_FALSE(message.empty()) << "accepted: " << c.Light;
    EXPECT_EQ(message.rfind(File, 0), 0u) << message;
    EXPECT_NE(message.find("1e999"), std::string::npos) << message;
  }
}

TEST(LightsJson, ASecondSkyIsRefusedByIndex)
{
  const std::string message = Refusal(R"({ "lights": [ { "type": "sky", "model": "uniform" },
    { "type": "point", "position": [0, 0, 1] }, { "type": "sky", "model": "cie-overcast" } ] })");
  EXPECT_NE(message.find(File), std::string::npos) << message;
  EXPECT_NE(message.find("light 2"), std::string::npos) << message;
  EXPECT_NE(message.find("second sky"), std::string::npos) << message;
}

TEST(LightsJson, DocumentErrorsNameTheFile)
{
  for (const char* text : { "{ \"lights\": [ ", "{ \"light\": [] }", "{ \"lights\": 3 }", "[ 1 ]" })
  {
    SCOPED_TRACE(text);
    const std::string message = Refusal(text);
    ASSERT_FALSE(message.empty());
    EXPECT_EQ(message.rfind(File, 0), 0u) << message;
  }
  const std::string missing = "no-such-dir/lights.json";
  try
  {
    ReadLightsFile(missing);
    ADD_FAILURE() << "a missing file was read";
  }
  catch (const SceneError& e)
  {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
}

TEST(LightsJson, NaNThroughValidateLights)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  LightSet good;
  good.Lights.emplace_back(); // a point light at the origin, valid
  ASSERT_EQ(Refusal(good), "");
  {
    LightSet set = good;
    Light l;
    l.Intensity = RGB(1.0, nan, 1.0);
    set.Lights.push_back(l);
    const std::string m = Refusal(set);
    EXPECT_NE(m.find("light 1"), std::string::npos) << m;
    EXPECT_NE(m.find("'intensity'"), std::string::npos) << m;
  }
  {
    LightSet set = good;
    Light l;
    l.Position = Vec3(nan, 0.0, 0.0);
    set.Lights.push_back(l);
    const std::string m = Refusal(set);
    EXPECT_NE(m.find("light 1"), std::string::npos) << m;
    EXPECT_NE(m.find("'position'"), std::string::npos) << m;
  }
  {
    LightSet set = good;
    Light l;
    l.Type = LightType::Directional;
    l.Direction = Vec3(0.0, nan, -1.0);
    set.Lights.push_back(l);
    const std::string m = Refusal(set);
    EXPECT_NE(m.find("light 1"), std::string::npos) << m;
    EXPECT_NE(m.find("'direction'"), std::string::npos) << m;
  }
  {
    LightSet set = good;
    Light l;
    l.Type = LightType::Spot;
    l.OuterConeAngle = nan;
    set.Lights.push_back(l);
    const std::string m = Refusal(set);
    EXPECT_NE(m.find("light 1"), std::string::npos) << m;
    EXPECT_NE(m.find("'outerConeAngle'"), std::string::npos) << m;
  }
  {
    LightSet set = good;
    set.SkyLight.Model = SkyModel::Uniform;
    set.SkyLight.Radiance = RGB(nan, 1.0, 1.0);
    const std::string m = Refusal(set);
    EXPECT_NE(m.find("sky"), std::string::npos) << m;
    EXPECT_NE(m.find("'intensity'"), std::string::npos) << m;
  }
}

TEST(LightsJson, GoodFileRoundTripsWithGltfDefaults)
{
  // SPEC's example, a light with every field defaulted but the placement,
  // and glTF's nested "spot" object.
  const std::string text = R"({ "lights": [
    { "type": "point", "position": [0, 0, 2], "color": [1, 1, 1], "intensity": 10 },
    { "type": "spot", "position": [0, 0, 2], "direction": [0, 0, -1], "intensity": 10,
      "innerConeAngle": 0.3, "outerConeAngle": 0.6 },
    { "type": "directional", "direction": [0.5, 0, -0.866], "intensity": 800 },
    { "type": "sky", "model": "cie-overcast", "up": [0, 0, 1], "intensity": 3000 },
    { "type": "spot", "position": [1, 2, 3], "name": "lamp" },
    { "type": "spot", "position": [1, 2, 3], "direction": [0, 2, 0], "color": [0.5, 0.25, 1],
      "spot": { "innerConeAngle": 0.1, "outerConeAngle": 1.2 } },
    { "type": "directional" }
  ] })";
  const std::string path = testing::TempDir() + "lights-roundtrip.json";
  std::ofstream(path) << text;
  const LightSet set = ReadLightsFile(path);
  std::remove(path.c_str());
  ASSERT_EQ(set.Lights.size(), 6u);
  const Light& point = set.Lights[0];
  EXPECT_EQ(point.Type, LightType::Point);
  EXPECT_EQ(point.Position, Vec3(0.0, 0.0, 2.0));
  EXPECT_EQ(point.Intensity, RGB(10.0));
  const Light& spot = set.Lights[1];
  EXPECT_EQ(spot.Type, LightType::Spot);
  EXPECT_EQ(spot.Direction, Vec3(0.0, 0.0, -1.0));
  EXPECT_DOUBLE_EQ(spot.InnerConeAngle, 0.3);
  EXPECT_DOUBLE_EQ(spot.OuterConeAngle, 0.6);
  const Light& sun = set.Lights[2];
  EXPECT_EQ(sun.Type, LightType::Directional);
  EXPECT_NEAR(glm::length(sun.Direction), 1.0, 1e-15); // normalised
  EXPECT_NEAR(sun.Direction.x / sun.Direction.z, 0.5 / -0.866, 1e-15);
  EXPECT_EQ(sun.Intensity, RGB(800.0));
  const Light& lamp = set.Lights[3];
  EXPECT_EQ(lamp.Name, "lamp");
  EXPECT_EQ(lamp.Intensity, RGB(1.0)); // glTF: color (1, 1, 1), intensity 1
  EXPECT_EQ(lamp.Direction, Vec3(0.0, 0.0, -1.0)); // glTF: a light points along -z
  EXPECT_EQ(lamp.InnerConeAngle, 0.0);
  EXPECT_DOUBLE_EQ(lamp.OuterConeAngle, Pi / 4.0);
  const Light& nested = set.Lights[4];
  EXPECT_EQ(nested.Intensity, RGB(0.5, 0.25, 1.0));
  EXPECT_EQ(nested.Direction, Vec3(0.0, 1.0, 0.0));
  EXPECT_DOUBLE_EQ(nested.InnerConeAngle, 0.1);
  EXPECT_DOUBLE_EQ(nested.OuterConeAngle, 1.2);
  EXPECT_EQ(set.Lights[5].Direction, Vec3(0.0, 0.0, -1.0));
  EXPECT_EQ(set.Lights[5].Intensity, RGB(1.0));
  EXPECT_EQ(set.SkyLight.Model, SkyModel::CieOvercast);
  EXPECT_EQ(set.SkyLight.Up, Vec3(0.0, 0.0, 1.0));
  EXPECT_EQ(set.SkyLight.Radiance, RGB(3000.0));
  // 7/9 pi L_z for CIE overcast, pi L uniform (SPEC).
  EXPECT_NEAR(UnobstructedHorizontalIrradiance(set.SkyLight).x, 7.0 / 9.0 * Pi * 3000.0, 1e-9);
  // Validating what was read changes nothing (it was validated).
  LightSet again = set;
  ValidateLights(again);
  EXPECT_EQ(again.Lights[2].Direction, sun.Direction);

  // A bare array and an empty list are files too; a sky defaults to uniform, up +z.
  const LightSet bare = ParseLightsJson(R"([ { "type": "sky", "intensity": 2 } ])", File);
  EXPECT_TRUE(bare.Lights.empty());
  EXPECT_EQ(bare.SkyLight.Model, SkyModel::Uniform);
  EXPECT_EQ(bare.SkyLight.Up, Vec3(0.0, 0.0, 1.0));
  EXPECT_NEAR(UnobstructedHorizontalIrradiance(bare.SkyLight).y, Pi * 2.0, 1e-12);
  EXPECT_TRUE(ParseLightsJson(R"({ "lights": [] })", File).Empty());
}
