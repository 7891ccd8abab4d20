#include "GltfFileCheck.h"
#include "GltfFileCheckJson.h"

#include <set>

namespace radiosity
{
namespace cli
{
using namespace gltf;

namespace
{

void CheckMaterials(const json& root, GltfSummary& summary, std::vector<std::string>& warnings,
  const std::string& file)
{
  const json& list = ArrayOf(root, "materials", "");
  summary.Materials = list.size();
  std::size_t translucent = 0;
  for (std::size_t i = 0; i < list.size(); ++i)
  {
    const json& m = list[i];
    const std::string where = Named("material", i, m) + ": ";
    if (!m.is_object())
    {
      throw Refusal(where + "not an object");
    }
    if (m.contains("pbrMetallicRoughness"))
    {
      const json& pbr = m["pbrMetallicRoughness"];
      double base[4] = { 1, 1, 1, 1 };
      NumbersField(pbr, "baseColorFactor", 4, base, where);
      for (int c = 0; c < 4; ++c)
      {
        if (base[c] < 0 || base[c] > 1)
        {
          throw Refusal(where + "field 'baseColorFactor' component " + std::to_string(c) + " is " +
            Shown(base[c]) + " (a colour in [0, 1])");
        }
      }
      for (const char* key : { "metallicFactor", "roughnessFactor" })
      {
        const double v = NumberField(pbr, key, 1.0, where);
        if (v < 0 || v > 1)
        {
          throw Refusal(where + "field '" + key + "' is " + Shown(v) + " (must be in [0, 1])");
        }
      }
      if (pbr.contains("baseColorTexture"))
      {
        ++summary.TexturedMaterials;
      }
    }
    double emissive[3] = { 0, 0, 0 };
    NumbersField(m, "emissiveFactor", 3, emissive, where);
    for (int c = 0; c < 3; ++c)
    {
      if (emissive[c] < 0)
      {
        throw Refusal(where + "field 'emissiveFactor' component " + std::to_string(c) + " is " +
          Shown(emissive[c]) + " (an emission, W/m^2, must be >= 0)");
      }
    }
    if (m.contains("alphaMode") && m["alphaMode"] != "OPAQUE")
    {
      ++translucent;
    }
  }
  if (translucent > 0)
  {
    warnings.push_back(file + ": " + std::to_string(translucent) +
      " material(s) with alphaMode MASK or BLEND: VTK imports them as translucent actors, which are not solved");
  }
}

void CheckLights(const json& root, GltfSummary& summary, std::vector<std::string>& warnings,
  const std::string& file)
{
  if (!root.contains("extensions") || !root["extensions"].is_object() ||
    !root["extensions"].contains("KHR_lights_punctual"))
  {
    return;
  }
  const json& ext = root["extensions"]["KHR_lights_punctual"];
  const json& list = ArrayOf(ext, "lights", "extension KHR_lights_punctual: ");
  for (std::size_t i = 0; i < list.size(); ++i)
  {
    const json& l = list[i];
    const std::string where = Named("light", i, l) + ": ";
    if (!l.is_object())
    {
      throw Refusal(where + "not an object");
    }
    GltfLight light;
    if (l.contains("name") && l["name"].is_string())
    {
      light.Name = l["name"].get<std::string>();
    }
    if (!l.contains("type") || !l["type"].is_string() ||
      (l["type"] != "point" && l["type"] != "spot" && l["type"] != "directional"))
    {
      throw Refusal(where + "field 'type' is " + (l.contains("type") ? Shown(l["type"]) : "missing") +
        " (point, spot or directional)");
    }
    light.Type = l["type"].get<std::string>();
    NumbersField(l, "color", 3, light.Color, where);
    for (int c = 0; c < 3; ++c)
    {
      if (light.Color[c] < 0)
      {
        throw Refusal(where + "field 'color' component " + std::to_string(c) + " is " +
          Shown(light.Color[c]) + " (must be >= 0)");
      }
    }
    light.Intensity = NumberField(l, "intensity", 1.0, where);
    if (light.Intensity < 0)
    {
      throw Refusal(where + "field 'intensity' is " + Shown(light.Intensity) + " (must be finite and >= 0)");
    }
    light.Range = NumberField(l, "range", 0.0, where);
    if (l.contains("range") && !(light.Range > 0))
    {
      throw Refusal(where + "field 'range' is " + Shown(light.Range) + " (must be > 0)");
    }
    if (l.contains("range"))
    {
      warnings.push_back(file + ": " + where + "its range " + Shown(light.Range) +
        " is ignored (SPEC: inverse-square, no cut-off)");
    }
    if (light.Type == "spot")
    {
      if (!l.contains("spot") || !l["spot"].is_object())
      {
        throw Refusal(where + "field 'spot' is missing for a spot light");
      }
      light.OuterConeAngle = NumberField(l["spot"], "outerConeAngle", light.OuterConeAngle, where + "spot ");
      light.InnerConeAngle = NumberField(l["spot"], "innerConeAngle", 0.0, where + "spot ");
      if (!(light.OuterConeAngle > 0 && light.OuterConeAngle <= Pi / 2))
      {
        throw Refusal(where + "field 'outerConeAngle' is " + Shown(light.OuterConeAngle) +
          " (radians, in (0, pi/2])");
      }
      if (!(light.InnerConeAngle >= 0 && light.InnerConeAngle < light.OuterConeAngle))
      {
        throw Refusal(where + "field 'innerConeAngle' is " + Shown(light.InnerConeAngle) +
          " (radians, in [0, outerConeAngle = " + Shown(light.OuterConeAngle) + "))");
      }
    }
    summary.Lights.push_back(light);
  }
}

bool Uses(const json& root, const char* list, const std::string& extension)
{
  if (!root.contains(list) || !root[list].is_array())
  {
    return false;
  }
  for (const json& e : root[list])
  {
    if (e.is_string() && e.get<std::string>() == extension)
    {
      return true;
    }
  }
  return false;
}

// Nodes: indices in range, finite transforms, each node the child of at most
// one node and never its own ancestor; the default scene's walk.
void CheckNodes(const json& root, GltfSummary& summary, const std::vector<std::size_t>& meshTriangles)
{
  const json& nodes = ArrayOf(root, "nodes", "");
  const std::size_t cameras = ArrayOf(root, "cameras", "").size();
  const std::size_t skins = ArrayOf(root, "skins", "").size();
  std::vector<long long> parent(nodes.size(), -1);
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    const json& n = nodes[i];
    const std::string where = Named("node", i, n) + ": ";
    if (!n.is_object())
    {
      throw Refusal(where + "not an object");
    }
    IndexField(n, "mesh", meshTriangles.size(), where, "meshes");
    IndexField(n, "camera", cameras, where, "cameras");
    IndexField(n, "skin", skins, where, "skins");
    double m[16];
    NumbersField(n, "matrix", 16, m, where);
    NumbersField(n, "translation", 3, m, where);
    NumbersField(n, "rotation", 4, m, where);
    NumbersField(n, "scale", 3, m, where);
    if (n.contains("extensions") && n["extensions"].is_object() &&
      n["extensions"].contains("KHR_lights_punctual"))
    {
      const json& e = n["extensions"]["KHR_lights_punctual"];
      if (!e.is_object() || !e.contains("light"))
      {
        throw Refusal(where + "its KHR_lights_punctual extension has no field 'light'");
      }
      IndexField(e, "light", summary.Lights.size(), where + "KHR_lights_punctual ", "lights");
    }
    for (const json& c : ArrayOf(n, "children", where))
    {
      const std::uint64_t child = Unsigned(c, where + "a child");
      if (child >= nodes.size())
      {
        throw Refusal(where + "child " + std::to_string(child) + " but the file has " +
          std::to_string(nodes.size()) + " nodes");
      }
      if (child == i || parent[child] >= 0)
      {
        throw Refusal(where + "node " + std::to_string(child) +
          (child == i ? " is its own child" : " has two parents") + " (the node graph must be a tree)");
      }
      parent[child] = static_cast<long long>(i);
    }
  }
  // A cycle among children: following parents from a node comes back to it.
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    long long p = parent[i];
    for (std::size_t steps = 0; p >= 0; ++steps)
    {
      if (steps > nodes.size() || static_cast<std::size_t>(p) == i)
      {
        throw Refusal(Named("node", i, nodes[i]) + " is its own ancestor (the node graph must be a tree)");
      }
      p = parent[p];
    }
  }
  const json& scenes = ArrayOf(root, "scenes", "");
  if (scenes.empty())
  {
    throw Refusal("no scene ('scenes' is empty or missing): nothing to import");
  }
  const long long scene = root.contains("scene") ? IndexField(root, "scene", scenes.size(), "", "scenes") : 0;
  std::vector<std::size_t> stack;
  for (std::size_t s = 0; s < scenes.size(); ++s)
  {
    for (const json& r : ArrayOf(scenes[s], "nodes", Named("scene", s, scenes[s]) + ": "))
    {
      const std::uint64_t node = Unsigned(r, Named("scene", s, scenes[s]) + ": a node");
      if (node >= nodes.size())
      {
        throw Refusal(Named("scene", s, scenes[s]) + ": node " + std::to_string(node) +
          " but the file has " + std::to_string(nodes.size()) + " nodes");
      }
      if (static_cast<long long>(s) == scene)
      {
        stack.push_back(node);
      }
    }
  }
  // VTK's walk (vtkGLTFImporter::ImportLights): a stack of the roots, the top popped, its children pushed.
  const bool lightsUsed = Uses(root, "extensionsUsed", "KHR_lights_punctual");
  std::set<std::size_t> seen;
  while (!stack.empty())
  {
    const std::size_t n = stack.back();
    stack.pop_back();
    if (!seen.insert(n).second)
    {
      throw Refusal("scene " + std::to_string(scene) + ": node " + std::to_string(n) +
        " is reached twice (a root that is also a child)");
    }
    const json& node = nodes[n];
    if (node.contains("mesh"))
    {
      summary.Triangles += meshTriangles[node["mesh"].get<std::size_t>()];
    }
    if (lightsUsed && node.contains("extensions") && node["extensions"].contains("KHR_lights_punctual"))
    {
      summary.ImportedLightOrder.push_back(node["extensions"]["KHR_lights_punctual"]["light"].get<int>());
    }
    for (const json& c : ArrayOf(node, "children", ""))
    {
      stack.push_back(c.get<std::size_t>());
    }
  }
}

void CheckCameras(const json& root, GltfSummary& summary)
{
  const json& list = ArrayOf(root, "cameras", "");
  summary.Cameras = list.size();
  for (std::size_t i = 0; i < list.size(); ++i)
  {
    const json& c = list[i];
    const std::string where = Named("camera", i, c) + ": ";
    if (!c.is_object() || !c.contains("type") || (c["type"] != "perspective" && c["type"] != "orthographic"))
    {
      throw Refusal(where + "field 'type' is not 'perspective' or 'orthographic'");
    }
    const std::string type = c["type"].get<std::string>();
    if (!c.contains(type) || !c[type].is_object())
    {
      throw Refusal(where + "has no '" + type + "' object");
    }
    const json& p = c[type];
    if (type == "perspective")
    {
      const double yfov = NumberField(p, "yfov", 0.0, where);
      const double znear = NumberField(p, "znear", 0.0, where);
      if (!(yfov > 0 && yfov < Pi) || !(znear > 0))
      {
        throw Refusal(where + "needs yfov in (0, pi) and znear > 0 (yfov " + Shown(yfov) + ", znear " +
          Shown(znear) + ")");
      }
      if (p.contains("zfar") && !(NumberField(p, "zfar", 0.0, where) > znear))
      {
        throw Refusal(where + "zfar is not beyond znear");
      }
    }
    else
    {
      const double znear = NumberField(p, "znear", -1.0, where);
      const double zfar = NumberField(p, "zfar", -1.0, where);
      if (!(NumberField(p, "ymag", 0.0, where) != 0) || !(znear >= 0) || !(zfar > znear))
      {
        throw Refusal(where + "needs ymag != 0 and 0 <= znear < zfar");
      }
    }
  }
}
} // namespace

bool CheckGltf(const std::string& file, const std::string& bytes, GltfSummary& summary,
  std::string& error, std::vector<std::string>& warnings)
{
  summary = GltfSummary();
  try
  {
    const bool glb = bytes.compare(0, 4, "glTF") == 0;
    std::string text, bin;
    bool hasBin = false;
    if (glb)
    {
      SplitGlb(bytes, text, bin, hasBin);
    }
    else
    {
      text = bytes;
    }
    json root;
    try
    {
      root = json::parse(text);
    }
    catch (const json::exception& e)
    {
      std::string what = e.what();
      const auto bracket = what.find("] ");
      throw Refusal("not valid JSON: " + (bracket == std::string::npos ? what : what.substr(bracket + 2)));
    }
    if (!root.is_object())
    {
      throw Refusal("the JSON is not an object");
    }
    if (!root.contains("asset") || !root["asset"].is_object() || !root["asset"].contains("version") ||
      !root["asset"]["version"].is_string())
    {
      throw Refusal("no asset.version (a glTF 2.0 file has one)");
    }
    const std::string version = root["asset"]["version"].get<std::string>();
    if (version.compare(0, 2, "2.") != 0)
    {
      throw Refusal("glTF version '" + version.substr(0, 20) + "' (VTK's importer reads glTF 2.0)");
    }
    static const std::set<std::string> supported = { "KHR_lights_punctual", "KHR_materials_unlit",
      "KHR_texture_transform" };
    for (const json& e : ArrayOf(root, "extensionsRequired", ""))
    {
      if (!e.is_string() || supported.count(e.get<std::string>()) == 0)
      {
        throw Refusal("requires the extension " + Shown(e) + ", which VTK 9.2's glTF importer does not read");
      }
    }
    const std::vector<std::string> buffers = LoadBuffers(root, file, bin, hasBin, glb);
    const std::vector<View> views = CheckViews(root, buffers);
    const std::vector<Accessor> accessors = CheckAccessors(root, views);
    CheckMaterials(root, summary, warnings, file);
    std::vector<std::size_t> meshTriangles;
    CheckMeshes(root, accessors, views, buffers, summary.Materials, meshTriangles);
    summary.Meshes = meshTriangles.size();
    CheckLights(root, summary, warnings, file);
    CheckCameras(root, summary);
    CheckNodes(root, summary, meshTriangles);
    if (!summary.Lights.empty() && !Uses(root, "extensionsUsed", "KHR_lights_punctual"))
    {
      warnings.push_back(file + ": defines KHR_lights_punctual lights but does not list the extension in "
                                "extensionsUsed: VTK's importer ignores them");
    }
    return true;
  }
  catch (const Refusal& e)
  {
    error = file + ": " + e.what();
  }
  catch (const json::exception& e)
  {
    // A value of an unexpected type the checks did not foresee.
    error = file + ": not a glTF file VTK can read: " + e.what();
  }
  return false;
}
}
}
