// The importer path of the command line (ImportedScene.h, GltfFileCheck.h):
// glTF files written here import into a renderer with their lights where
// the file puts them and at the file's intensity, the first camera, and the
// spot's inner cone kept; malformed files are refused with the file and
// what is wrong named, before VTK's importer reads them.
#include "CliTestSupport.h"
#include "GltfFileCheck.h"
#include "ImportedScene.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkInformation.h"
#include "vtkProperty.h"
#include "vtkRadiosityRendererNode.h"
#include "vtkRadiositySceneConverter.h"

#include <nlohmann/json.hpp>

#include <cstring>
#include <functional>

namespace
{
using namespace radiosity;
using namespace radiosity::cli;
using json = nlohmann::json;

std::string Base64(const std::string& bytes)
{
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  unsigned int acc = 0;
  int bits = 0;
  for (unsigned char c : bytes)
  {
    acc = (acc << 8) | c;
    bits += 8;
    while (bits >= 6)
    {
      bits -= 6;
      out.push_back(alphabet[(acc >> bits) & 63]);
    }
  }
  if (bits > 0)
  {
    out.push_back(alphabet[(acc << (6 - bits)) & 63]);
  }
  while (out.size() % 4)
  {
    out.push_back('=');
  }
  return out;
}

// A 4 m x 4 m floor at y = 0 facing +y (glTF is y-up), its buffer inline:
// 4 float positions (48 bytes) then 6 uint16 indices (12 bytes).
json FloorGltf()
{
  const float p[12] = { -2, 0, -2, -2, 0, 2, 2, 0, 2, 2, 0, -2 };
  const std::uint16_t i[6] = { 0, 1, 2, 0, 2, 3 };
  std::string bytes(reinterpret_cast<const char*>(p), sizeof p);
  bytes.append(reinterpret_cast<const char*>(i), sizeof i);
  json g;
  g["asset"] = { { "version", "2.0" } };
  g["buffers"] = json::array(
    { { { "byteLength", bytes.size() }, { "uri", "data:application/octet-stream;base64," + Base64(bytes) } } });
  g["bufferViews"] = json::array({ { { "buffer", 0 }, { "byteOffset", 0 }, { "byteLength", 48 } },
    { { "buffer", 0 }, { "byteOffset", 48 }, { "byteLength", 12 } } });
  g["accessors"] = json::array({ { { "bufferView", 0 }, { "componentType", 5126 }, { "count", 4 },
                                   { "type", "VEC3" }, { "min", { -2, 0, -2 } }, { "max", { 2, 0, 2 } } },
    { { "bufferView", 1 }, { "componentType", 5123 }, { "count", 6 }, { "type", "SCALAR" } } });
  g["materials"] = json::array({ { { "name", "grey" },
    { "pbrMetallicRoughness", { { "baseColorFactor", { 0.5, 0.25, 0.125, 1 } }, { "metallicFactor", 0 } } },
    { "emissiveFactor", { 0, 0, 0 } } } });
  g["meshes"] = json::array(
    { { { "primitives", json::array({ { { "attributes", { { "POSITION", 0 } } }, { "indices", 1 }, { "material", 0 } } }) } } });
  g["nodes"] = json::array({ { { "mesh", 0 } } });
  g["scenes"] = json::array({ { { "nodes", { 0 } } } });
  g["scene"] = 0;
  return g;
}

// Adds KHR_lights_punctual `lights`, each on a node under a parent node
// translated by (0, 0.5, 0), the light's node by `at` (so the light is at
// at + (0, 0.5, 0)).
void AddLights(json& g, const json& lights, const std::vector<std::array<double, 3>>& at)
{
  g["extensionsUsed"] = { "KHR_lights_punctual" };
  g["extensions"]["KHR_lights_punctual"]["lights"] = lights;
  json parent = { { "translation", { 0, 0.5, 0 } }, { "children", json::array() } };
  for (std::size_t k = 0; k < at.size(); ++k)
  {
    parent["children"].push_back(g["nodes"].size() + 1 + k);
  }
  g["nodes"].push_back(parent);
  for (std::size_t k = 0; k < at.size(); ++k)
  {
    json node = { { "translation", { at[k][0], at[k][1], at[k][2] } } };
    node["extensions"]["KHR_lights_punctual"]["light"] = k;
    // A spot points along the node's -z: rotate -z onto -y (-90 degrees about x).
    node["rotation"] = { -0.70710678118654752, 0, 0, 0.70710678118654752 };
    g["nodes"].push_back(node);
  }
  g["scenes"][0]["nodes"].push_back(g["nodes"].size() - at.size() - 1);
}

class ImportedSceneTest : public clitest::TempDir
{
protected:
  bool Import(const std::string& name, const std::string& text, ImportedScene& scene)
  {
    const std::string file = this->Write(name, text);
    this->Error.clear();
    this->Warnings.clear();
    std::vector<std::string> notes;
    return ImportScene(file, scene, this->Error, this->Warnings, notes);
  }
  std::string Error;
  std::vector<std::string> Warnings;
};

TEST_F(ImportedSceneTest, PointLightWhereTheFilePutsItAtItsIntensity)
{
  json g = FloorGltf();
  AddLights(g, json::array({ { { "type", "point" }, { "color", { 1, 0.5, 0.25 } }, { "intensity", 2 } } }),
    { { 0, 0.5, 0 } });
  ImportedScene scene;
  ASSERT_TRUE(this->Import("point.gltf", g.dump(), scene)) << this->Error;
  EXPECT_EQ(scene.Importer, "vtkGLTFImporter");
  EXPECT_EQ(scene.Actors, 1u);
  EXPECT_EQ(scene.Polygons, 2u);
  EXPECT_EQ(scene.LightScale, 1.0);
  EXPECT_FALSE(scene.HasCamera);
  ASSERT_EQ(scene.Renderer->GetLights()->GetNumberOfItems(), 1);
  vtkLight* light = vtkLight::SafeDownCast(scene.Renderer->GetLights()->GetItemAsObject(0));
  // The SPEC light the pass makes of it (ToLight with the scene's LightScale):
  // at (0, 1, 0), the parent's and the node's translations, 2 W/sr x colour.
  const Light spec = vtkRadiositySceneConverter::ToLight(light, scene.LightScale);
  EXPECT_EQ(spec.Type, LightType::Point);
  EXPECT_NEAR(spec.Position.x, 0.0, 1e-12);
  EXPECT_NEAR(spec.Position.y, 1.0, 1e-12);
  EXPECT_NEAR(spec.Position.z, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(spec.Intensity.r, 2.0);
  EXPECT_DOUBLE_EQ(spec.Intensity.g, 1.0);
  EXPECT_DOUBLE_EQ(spec.Intensity.b, 0.5);
  // The floor's material: baseColorFactor as the colour, metallic 0, one-sided.
  vtkActor* actor = scene.Renderer->GetActors()->GetLastActor();
  double c[3];
  actor->GetProperty()->GetDiffuseColor(c);
  EXPECT_DOUBLE_EQ(c[0], 0.5);
  EXPECT_DOUBLE_EQ(c[1], 0.25);
  EXPECT_EQ(actor->GetProperty()->GetMetallic(), 0.0);
  EXPECT_TRUE(actor->GetProperty()->GetBackfaceCulling());
}

TEST_F(ImportedSceneTest, SpotWithAnInnerConeKeepsBothCones)
{
  json g = FloorGltf();
  AddLights(g,
    json::array({ { { "type", "spot" }, { "intensity", 5 }, { "spot", { { "innerConeAngle", 0.2 }, { "outerConeAngle", 0.5 } } } },
      { { "type", "spot" }, { "intensity", 3 }, { "spot", { { "outerConeAngle", 0.4 } } } } }),
    { { 1, 1, 0 }, { -1, 1, 0 } });
  ImportedScene scene;
  ASSERT_TRUE(this->Import("spots.gltf", g.dump(), scene)) << this->Error;
  // The spot with an inner cone leaves the renderer for ExtraLights.
  ASSERT_EQ(scene.ExtraLights.Lights.size(), 1u);
  const Light& s = scene.ExtraLights.Lights[0];
  EXPECT_EQ(s.Type, LightType::Spot);
  EXPECT_NEAR(s.Position.x, 1.0, 1e-12);
  EXPECT_NEAR(s.Position.y, 1.5, 1e-12);
  EXPECT_NEAR(s.Direction.y / glm::length(s.Direction), -1.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.Intensity.r, 5.0);
  EXPECT_DOUBLE_EQ(s.InnerConeAngle, 0.2);
  EXPECT_DOUBLE_EQ(s.OuterConeAngle, 0.5);
  // The other stays a vtkLight: a spot of cone 0.4 rad pointing down.
  ASSERT_EQ(scene.Renderer->GetLights()->GetNumberOfItems(), 1);
  const Light other = vtkRadiositySceneConverter::ToLight(
    vtkLight::SafeDownCast(scene.Renderer->GetLights()->GetItemAsObject(0)), scene.LightScale);
  EXPECT_EQ(other.Type, LightType::Spot);
  EXPECT_NEAR(other.Position.x, -1.0, 1e-12);
  EXPECT_NEAR(other.Position.y, 1.5, 1e-12);
  EXPECT_NEAR(other.OuterConeAngle, 0.4, 1e-12);
  EXPECT_DOUBLE_EQ(other.Intensity.r, 3.0);
}

TEST_F(ImportedSceneTest, FirstCamera)
{
  json g = FloorGltf();
  g["cameras"] = json::array({ { { "type", "perspective" }, { "perspective", { { "yfov", 0.5 }, { "znear", 0.1 } } } },
    { { "type", "perspective" }, { "perspective", { { "yfov", 1.0 }, { "znear", 0.1 } } } } });
  g["nodes"].push_back({ { "camera", 0 }, { "translation", { 0, 1, 5 } } });
  g["scenes"][0]["nodes"].push_back(1);
  ImportedScene scene;
  ASSERT_TRUE(this->Import("camera.gltf", g.dump(), scene)) << this->Error;
  ASSERT_TRUE(scene.HasCamera);
  EXPECT_NEAR(scene.Camera.Position[1], 1.0, 1e-12);
  EXPECT_NEAR(scene.Camera.Position[2], 5.0, 1e-12);
  EXPECT_NEAR(scene.Camera.FocalPoint[2], 4.0, 1e-12);
  EXPECT_NEAR(scene.Camera.ViewAngle, 0.5 * 180.0 / 3.14159265358979323846, 1e-9);
}

// A file's degenerate lights are left out with a warning naming each, and the
// rest of the scene is imported (issue 53: a .3ds sun whose position equals
// its target refused the whole file). Here a directional light on a node
// scaled to zero (its direction collapses to zero, as a .3ds light whose
// position is its target) and a point light of zero intensity, beside a good
// point light.
TEST_F(ImportedSceneTest, DegenerateLightsAreLeftOutWithAWarning)
{
  json g = FloorGltf();
  AddLights(g,
    json::array({ { { "type", "point" }, { "intensity", 2 } }, { { "type", "directional" }, { "intensity", 3 }, { "name", "sun" } },
      { { "type", "point" }, { "intensity", 0 }, { "name", "off" } } }),
    { { 0, 0.5, 0 }, { 1, 1, 0 }, { -1, 1, 0 } });
  g["nodes"][g["nodes"].size() - 2]["scale"] = { 0, 0, 0 };
  ImportedScene scene;
  ASSERT_TRUE(this->Import("degenerate.gltf", g.dump(), scene)) << this->Error;
  EXPECT_EQ(scene.FileLights, 3u);
  EXPECT_EQ(scene.LightsLeftOut, 2u);
  ASSERT_EQ(scene.Renderer->GetLights()->GetNumberOfItems(), 1);
  const Light kept = vtkRadiositySceneConverter::ToLight(
    vtkLight::SafeDownCast(scene.Renderer->GetLights()->GetItemAsObject(0)), scene.LightScale);
  EXPECT_EQ(kept.Type, LightType::Point);
  EXPECT_DOUBLE_EQ(kept.Intensity.r, 2.0);
  std::string all;
  for (const std::string& w : this->Warnings)
  {
    all += w + "\n";
  }
  EXPECT_NE(all.find("degenerate.gltf: light 1 ('sun') (directional): field 'direction' is a zero vector"), std::string::npos)
    << all;
  EXPECT_NE(all.find("degenerate.gltf: light 2 ('off') (point): its intensity is zero: that light is left out"),
    std::string::npos)
    << all;
}

// glTF's doubleSided: the actor is solved on both sides (TWO_SIDED in its
// PropertyKeys, which the pass's mapper node reads); a one-sided material's
// actor is not marked.
TEST_F(ImportedSceneTest, DoubleSidedMaterialsAreSolvedOnBothSides)
{
  json g = FloorGltf();
  ImportedScene one;
  ASSERT_TRUE(this->Import("one.gltf", g.dump(), one)) << this->Error;
  EXPECT_EQ(one.TwoSidedActors, 0u);
  vtkActor* actor = one.Renderer->GetActors()->GetLastActor();
  EXPECT_FALSE(actor->GetPropertyKeys() && actor->GetPropertyKeys()->Has(vtkRadiosityRendererNode::TWO_SIDED()));
  g["materials"][0]["doubleSided"] = true;
  ImportedScene two;
  ASSERT_TRUE(this->Import("two.gltf", g.dump(), two)) << this->Error;
  EXPECT_EQ(two.TwoSidedActors, 1u);
  actor = two.Renderer->GetActors()->GetLastActor();
  ASSERT_NE(actor->GetPropertyKeys(), nullptr);
  EXPECT_EQ(actor->GetPropertyKeys()->Get(vtkRadiosityRendererNode::TWO_SIDED()), 1);
}

TEST_F(ImportedSceneTest, BadFilesAreRefusedByName)
{
  struct Case
  {
    const char* What;
    std::function<void(json&)> Break;
    const char* Message;
  };
  const std::vector<Case> cases = {
    { "negative colour", [](json& g) { g["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"][1] = -0.5; },
      "material 0 ('grey'): field 'baseColorFactor' component 1 is -0.5" },
    { "negative emission", [](json& g) { g["materials"][0]["emissiveFactor"][2] = -1; },
      "field 'emissiveFactor' component 2 is -1" },
    { "negative intensity",
      [](json& g) { AddLights(g, json::array({ { { "type", "point" }, { "intensity", -2 } } }), { { 0, 1, 0 } }); },
      "light 0: field 'intensity' is -2" },
    { "unknown light",
      [](json& g) { AddLights(g, json::array({ { { "type", "laser" } } }), { { 0, 1, 0 } }); },
      "light 0: field 'type' is \"laser\"" },
    { "cones out of order",
      [](json& g) {
        AddLights(g, json::array({ { { "type", "spot" }, { "spot", { { "innerConeAngle", 0.6 }, { "outerConeAngle", 0.3 } } } } }),
          { { 0, 1, 0 } });
      },
      "field 'innerConeAngle' is 0.6" },
    { "index out of range", [](json& g) { g["accessors"][1]["count"] = 7; }, "accessor 1: 7 elements" },
    { "missing buffer", [](json& g) { g["buffers"][0]["uri"] = "floor.bin"; }, "buffer 0: missing buffer file" },
    { "short buffer", [](json& g) { g["buffers"][0]["byteLength"] = 600; }, "byteLength is 600 but its data holds 60" },
    { "node cycle",
      [](json& g) {
        g["nodes"].push_back({ { "children", { 2 } } });
        g["nodes"].push_back({ { "children", { 1 } } });
      },
      "the node graph must be a tree" },
    { "no scene", [](json& g) { g.erase("scenes"); g.erase("scene"); }, "no scene" },
    { "glTF 1", [](json& g) { g["asset"]["version"] = "1.0"; }, "glTF version '1.0'" },
    { "draco", [](json& g) { g["extensionsRequired"] = { "KHR_draco_mesh_compression" }; }, "KHR_draco_mesh_compression" },
  };
  for (const Case& c : cases)
  {
    json g = FloorGltf();
    c.Break(g);
    ImportedScene scene;
    EXPECT_FALSE(this->Import("bad.gltf", g.dump(), scene)) << c.What;
    EXPECT_NE(this->Error.find("bad.gltf: "), std::string::npos) << c.What << ": " << this->Error;
    EXPECT_NE(this->Error.find(c.Message), std::string::npos) << c.What << ": " << this->Error;
  }
  // Text that is not JSON: a NaN (JSON has none) and a truncated file.
  ImportedScene scene;
  std::string text = FloorGltf().dump();
  EXPECT_FALSE(this->Import("nan.gltf", text.substr(0, text.size() - 1) + ",\"x\":NaN}", scene));
  EXPECT_NE(this->Error.find("nan.gltf: not valid JSON"), std::string::npos) << this->Error;
  EXPECT_FALSE(this->Import("cut.gltf", text.substr(0, text.size() / 2), scene));
  EXPECT_NE(this->Error.find("cut.gltf: not valid JSON"), std::string::npos) << this->Error;
  EXPECT_FALSE(this->Import("huge.gltf", text.substr(0, text.size() - 1) + ",\"x\":1e999}", scene));
  EXPECT_NE(this->Error.find("huge.gltf: not valid JSON"), std::string::npos) << this->Error;
  // A .glb cut short, and one whose header says more than it holds.
  std::string glb = "glTF";
  const std::uint32_t header[2] = { 2, 1000 };
  glb.append(reinterpret_cast<const char*>(header), sizeof header);
  const std::uint32_t chunk[2] = { static_cast<std::uint32_t>(text.size()), 0x4E4F534Au };
  glb.append(reinterpret_cast<const char*>(chunk), sizeof chunk);
  glb += text;
  EXPECT_FALSE(this->Import("long.glb", glb, scene));
  EXPECT_NE(this->Error.find("long.glb: the header says 1000 bytes"), std::string::npos) << this->Error;
  EXPECT_FALSE(this->Import("short.glb", "glTF\x02", scene));
  EXPECT_NE(this->Error.find("short.glb: a .glb needs"), std::string::npos) << this->Error;
  // The other importers' files: empty, or not of their kind.
  EXPECT_FALSE(this->Import("empty.3ds", "", scene));
  EXPECT_NE(this->Error.find("empty.3ds: the file is empty"), std::string::npos) << this->Error;
  EXPECT_FALSE(this->Import("text.3ds", "hello world", scene));
  EXPECT_NE(this->Error.find("text.3ds: not a 3D Studio file"), std::string::npos) << this->Error;
  EXPECT_FALSE(this->Import("v1.wrl", "#VRML V1.0 ascii\n", scene));
  EXPECT_NE(this->Error.find("v1.wrl: not a VRML 2.0 file"), std::string::npos) << this->Error;
}

TEST(GltfFileCheckTest, Base64)
{
  std::string out;
  ASSERT_TRUE(DecodeBase64("aGVsbG8=", out));
  EXPECT_EQ(out, "hello");
  ASSERT_TRUE(DecodeBase64(Base64(std::string("\x00\xff\x10", 3)), out));
  EXPECT_EQ(out, std::string("\x00\xff\x10", 3));
  EXPECT_FALSE(DecodeBase64("a*b", out));
}
}
