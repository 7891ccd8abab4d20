// Checks a glTF 2.0 file (.gltf or .glb) before vtkGLTFImporter sees it
// (SPEC, Scenes and Lights: bad input is refused with a message naming the
// file and what is wrong, never a crash or a hang). VTK 9.2's glTF loader
// trusts much of its input: it indexes scenes, nodes, meshes and buffers by
// the file's numbers, follows node children recursively (a node that is its
// own descendant never ends), reads accessors as far as their counts say
// and index buffers as they come, and replaces bad light and material values
// by defaults with a warning. So the JSON (or the .glb's JSON chunk) is parsed
// here and every index, length and value the importer and the solve use is
// checked: the .glb header and chunk lengths against the file's size, every
// buffer's bytes (a data: URI, a file beside the .gltf or the .glb's BIN
// chunk) against its byteLength, buffer views and accessors inside them,
// triangle indices below the vertex count, the node graph a forest, material
// factors (baseColorFactor in [0, 1], emissiveFactor finite and >= 0) and
// KHR_lights_punctual lights (type, colour, intensity, range, cone angles as
// SPEC "Lights and sky" says).
//
// Errors are "FILE: what, where, the value", e.g. "box.gltf: light 0
// ('lamp'): field 'intensity' is -2 (must be finite and >= 0)".
#ifndef vtkradiosity_GltfFileCheck_h
#define vtkradiosity_GltfFileCheck_h

#include <string>
#include <vector>

namespace radiosity
{
namespace cli
{
/// A KHR_lights_punctual light as the file defines it (defaults filled in:
/// colour (1, 1, 1), intensity 1, cones 0 and pi/4).
struct GltfLight
{
  std::string Name;
  std::string Type; ///< "point", "spot" or "directional"
  double Color[3] = { 1.0, 1.0, 1.0 };
  double Intensity = 1.0;
  double Range = 0.0; ///< 0: none
  double InnerConeAngle = 0.0;
  double OuterConeAngle = 0.78539816339744830962;
};

/// What the checked file holds, for the importer path and its report.
struct GltfSummary
{
  std::size_t Cameras = 0;
  std::size_t Meshes = 0;
  std::size_t Materials = 0;
  std::size_t Triangles = 0; ///< in the default scene's primitives of mode TRIANGLES (4)
  std::size_t TexturedMaterials = 0; ///< with a baseColorTexture (solved by its mean per triangle, vtkRadiosityTextureColour)
  std::vector<GltfLight> Lights;
  /// The glTF light index of each vtkLight vtkGLTFImporter (VTK 9.2) adds to
  /// the renderer, in the order it adds them (its depth-first walk of the
  /// default scene with a stack: the last root first). Empty when the file
  /// does not list KHR_lights_punctual in extensionsUsed (VTK then imports
  /// no light).
  std::vector<int> ImportedLightOrder;
};

/// `bytes` is the whole file. False with `error` set when VTK's importer
/// cannot safely read it or the solve would refuse what it defines.
/// `warnings` get what is read but not used (textures, a light's range).
bool CheckGltf(const std::string& file, const std::string& bytes, GltfSummary& summary,
  std::string& error, std::vector<std::string>& warnings);

/// Decodes base64 (RFC 4648, padding optional, no line breaks); false on a
/// character outside the alphabet.
bool DecodeBase64(const std::string& text, std::string& out);
}
}

#endif
