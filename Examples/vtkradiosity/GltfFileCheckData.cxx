// The binary side of a glTF file (GltfFileCheck.h): the .glb container,
// buffers, buffer views, accessors and mesh primitives, each checked against
// the bytes that are there.
#include "GltfFileCheck.h"
#include "GltfFileCheckJson.h"

#include "SceneFileCheck.h"

#include <algorithm>

namespace radiosity
{
namespace cli
{
namespace gltf
{
namespace
{
std::uint32_t Le32(const std::string& bytes, std::size_t at)
{
  const auto* b = reinterpret_cast<const unsigned char*>(bytes.data()) + at;
  return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 |
    std::uint32_t(b[3]) << 24;
}

std::string Directory(const std::string& file)
{
  const auto slash = file.find_last_of('/');
  return slash == std::string::npos ? std::string() : file.substr(0, slash + 1);
}

std::size_t ComponentSize(std::uint64_t type)
{
  switch (type)
  {
    case 5120: case 5121: return 1;
    case 5122: case 5123: return 2;
    case 5125: case 5126: return 4;
    default: return 0;
  }
}

std::size_t Components(const std::string& type)
{
  static const std::pair<const char*, std::size_t> types[] = { { "SCALAR", 1 }, { "VEC2", 2 },
    { "VEC3", 3 }, { "VEC4", 4 }, { "MAT2", 4 }, { "MAT3", 9 }, { "MAT4", 16 } };
  for (const auto& t : types)
  {
    if (type == t.first)
    {
      return t.second;
    }
  }
  return 0;
}

// The largest index an index accessor holds.
std::uint64_t LargestIndex(const Accessor& a, const std::vector<View>& views,
  const std::vector<std::string>& buffers)
{
  const View& view = views[a.View];
  const std::size_t stride = view.Stride ? view.Stride : a.ComponentSize;
  const auto* base = reinterpret_cast<const unsigned char*>(buffers[view.Buffer].data()) + view.Offset + a.Offset;
  std::uint64_t largest = 0;
  for (std::size_t k = 0; k < a.Count; ++k)
  {
    const unsigned char* p = base + k * stride;
    std::uint64_t value = p[0];
    if (a.ComponentSize >= 2)
    {
      value |= std::uint64_t(p[1]) << 8;
    }
    if (a.ComponentSize == 4)
    {
      value |= std::uint64_t(p[2]) << 16 | std::uint64_t(p[3]) << 24;
    }
    largest = std::max(largest, value);
  }
  return largest;
}
} // namespace

void SplitGlb(const std::string& bytes, std::string& text, std::string& bin, bool& hasBin)
{
  if (bytes.size() < 20)
  {
    throw Refusal("a .glb needs a 12-byte header and a chunk header, the file holds " +
      ByteSize(bytes.size()));
  }
  if (bytes.compare(0, 4, "glTF") != 0)
  {
    throw Refusal("not a binary glTF: the first 4 bytes are not 'glTF'");
  }
  const std::uint32_t version = Le32(bytes, 4), length = Le32(bytes, 8);
  if (version != 2)
  {
    throw Refusal("binary glTF version " + std::to_string(version) + " (VTK reads version 2)");
  }
  if (length != bytes.size())
  {
    throw Refusal("the header says " + std::to_string(length) + " bytes but the file holds " +
      std::to_string(bytes.size()) + (length > bytes.size() ? " (truncated)" : ""));
  }
  std::size_t at = 12;
  const std::uint32_t jsonLength = Le32(bytes, at), jsonType = Le32(bytes, at + 4);
  if (jsonType != 0x4E4F534Au)
  {
    throw Refusal("the first chunk is not of type JSON");
  }
  if (jsonLength > bytes.size() - 20)
  {
    throw Refusal("the JSON chunk of " + std::to_string(jsonLength) + " bytes runs past the end of the file");
  }
  text = bytes.substr(20, jsonLength);
  at = 20 + jsonLength;
  hasBin = false;
  if (at + 8 <= bytes.size())
  {
    const std::uint32_t binLength = Le32(bytes, at), binType = Le32(bytes, at + 4);
    if (binType == 0x004E4942u)
    {
      if (binLength > bytes.size() - at - 8)
      {
        throw Refusal("the BIN chunk of " + std::to_string(binLength) +
          " bytes runs past the end of the file (truncated)");
      }
      bin = bytes.substr(at + 8, binLength);
      hasBin = true;
    }
  }
}


std::vector<std::string> LoadBuffers(const json& root, const std::string& file, const std::string& bin,
  bool hasBin, bool glb)
{
  std::vector<std::string> buffers;
  const json& list = ArrayOf(root, "buffers", "");
  for (std::size_t i = 0; i < list.size(); ++i)
  {
    const json& b = list[i];
    const std::string where = Named("buffer", i, b) + ": ";
    if (!b.is_object() || !b.contains("byteLength"))
    {
      throw Refusal(where + "no field 'byteLength'");
    }
    const std::uint64_t length = Unsigned(b["byteLength"], where + "field 'byteLength'");
    std::string data;
    if (!b.contains("uri"))
    {
      if (!glb || i != 0 || !hasBin)
      {
        throw Refusal(where + "has no 'uri' and the file no BIN chunk for it");
      }
      data = bin;
    }
    else if (!b["uri"].is_string())
    {
      throw Refusal(where + "field 'uri' is " + Shown(b["uri"]) + ", not a string");
    }
    else
    {
      const std::string uri = b["uri"].get<std::string>();
      if (uri.compare(0, 5, "data:") == 0)
      {
        const auto comma = uri.find(";base64,");
        if (comma == std::string::npos || !DecodeBase64(uri.substr(comma + 8), data))
        {
          throw Refusal(where + "its data: URI is not base64 data");
        }
      }
      else
      {
        if (uri.find("://") != std::string::npos)
        {
          throw Refusal(where + "uri '" + uri.substr(0, 60) + "' is not a local file");
        }
        std::string why;
        if (!ReadFileBytes(Directory(file) + uri, data, why))
        {
          throw Refusal(where + "missing buffer file: " + why);
        }
      }
    }
    if (data.size() < length)
    {
      throw Refusal(where + "byteLength is " + std::to_string(length) + " but its data holds " +
        std::to_string(data.size()) + " bytes (truncated)");
    }
    buffers.push_back(data);
  }
  return buffers;
}



std::vector<View> CheckViews(const json& root, const std::vector<std::string>& buffers)
{
  std::vector<View> views;
  const json& list = ArrayOf(root, "bufferViews", "");
  for (std::size_t i = 0; i < list.size(); ++i)
  {
    const json& v = list[i];
    const std::string where = Named("bufferView", i, v) + ": ";
    if (!v.is_object() || !v.contains("buffer") || !v.contains("byteLength"))
    {
      throw Refusal(where + "needs the fields 'buffer' and 'byteLength'");
    }
    View view;
    view.Buffer = IndexField(v, "buffer", buffers.size(), where, "buffers");
    view.Offset = v.contains("byteOffset") ? Unsigned(v["byteOffset"], where + "field 'byteOffset'") : 0;
    view.Length = Unsigned(v["byteLength"], where + "field 'byteLength'");
    view.Stride = v.contains("byteStride") ? Unsigned(v["byteStride"], where + "field 'byteStride'") : 0;
    if (view.Offset > buffers[view.Buffer].size() || view.Length > buffers[view.Buffer].size() - view.Offset)
    {
      throw Refusal(where + "bytes " + std::to_string(view.Offset) + " to " +
        std::to_string(view.Offset + view.Length) + " lie outside buffer " +
        std::to_string(view.Buffer) + " of " + std::to_string(buffers[view.Buffer].size()) + " bytes");
    }
    if (view.Stride != 0 && (view.Stride < 4 || view.Stride > 252))
    {
      throw Refusal(where + "byteStride " + std::to_string(view.Stride) + " is outside [4, 252]");
    }
    views.push_back(view);
  }
  return views;
}

std::vector<Accessor> CheckAccessors(const json& root, const std::vector<View>& views)
{
  std::vector<Accessor> accessors;
  const json& list = ArrayOf(root, "accessors", "");
  for (std::size_t i = 0; i < list.size(); ++i)
  {
    const json& a = list[i];
    const std::string where = Named("accessor", i, a) + ": ";
    if (!a.is_object() || !a.contains("componentType") || !a.contains("count") || !a.contains("type") ||
      !a["type"].is_string())
    {
      throw Refusal(where + "needs the fields 'componentType', 'count' and 'type'");
    }
    if (a.contains("sparse"))
    {
      throw Refusal(where + "is sparse, which VTK 9.2's glTF importer does not read");
    }
    Accessor accessor;
    accessor.ComponentType = Unsigned(a["componentType"], where + "field 'componentType'");
    accessor.ComponentSize = ComponentSize(accessor.ComponentType);
    accessor.Components = Components(a["type"].get<std::string>());
    if (accessor.ComponentSize == 0 || accessor.Components == 0)
    {
      throw Refusal(where + "componentType " + Shown(a["componentType"]) + " / type " +
        Shown(a["type"]) + " is not a glTF accessor type");
    }
    accessor.Count = Unsigned(a["count"], where + "field 'count'");
    accessor.Offset = a.contains("byteOffset") ? Unsigned(a["byteOffset"], where + "field 'byteOffset'") : 0;
    accessor.View = IndexField(a, "bufferView", views.size(), where, "bufferViews");
    if (accessor.View < 0)
    {
      throw Refusal(where + "has no bufferView (its values would all be zero)");
    }
    const View& view = views[accessor.View];
    const std::size_t element = accessor.ComponentSize * accessor.Components;
    const std::size_t stride = view.Stride ? view.Stride : element;
    if (accessor.Count > 0 &&
      (accessor.Offset > view.Length || accessor.Count - 1 > (view.Length - accessor.Offset) / stride ||
        accessor.Offset + (accessor.Count - 1) * stride + element > view.Length))
    {
      throw Refusal(where + std::to_string(accessor.Count) + " elements of " + std::to_string(element) +
        " bytes from byte " + std::to_string(accessor.Offset) + " run past bufferView " +
        std::to_string(accessor.View) + " of " + std::to_string(view.Length) + " bytes");
    }
    accessors.push_back(accessor);
  }
  return accessors;
}


void CheckMeshes(const json& root, const std::vector<Accessor>& accessors, const std::vector<View>& views,
  const std::vector<std::string>& buffers, std::size_t materials, std::vector<std::size_t>& triangles)
{
  const json& list = ArrayOf(root, "meshes", "");
  for (std::size_t i = 0; i < list.size(); ++i)
  {
    const json& m = list[i];
    const std::string mesh = Named("mesh", i, m);
    const json& primitives = ArrayOf(m, "primitives", mesh + ": ");
    std::size_t meshTriangles = 0;
    for (std::size_t p = 0; p < primitives.size(); ++p)
    {
      const json& prim = primitives[p];
      const std::string where = mesh + " primitive " + std::to_string(p) + ": ";
      if (!prim.is_object() || !prim.contains("attributes") || !prim["attributes"].is_object() ||
        !prim["attributes"].contains("POSITION"))
      {
        throw Refusal(where + "no POSITION attribute");
      }
      for (auto it = prim["attributes"].begin(); it != prim["attributes"].end(); ++it)
      {
        IndexField(prim["attributes"], it.key().c_str(), accessors.size(), where + "attribute ", "accessors");
      }
      const Accessor& position = accessors[IndexField(prim["attributes"], "POSITION", accessors.size(),
        where + "attribute ", "accessors")];
      if (position.Components != 3 || position.ComponentType != 5126)
      {
        throw Refusal(where + "POSITION is not VEC3 of floats");
      }
      for (const json& target : ArrayOf(prim, "targets", where))
      {
        if (!target.is_object())
        {
          throw Refusal(where + "a morph target is not an object");
        }
        for (auto it = target.begin(); it != target.end(); ++it)
        {
          IndexField(target, it.key().c_str(), accessors.size(), where + "morph target ", "accessors");
        }
      }
      IndexField(prim, "material", materials, where, "materials");
      const long long mode = prim.contains("mode") ? static_cast<long long>(Unsigned(prim["mode"], where + "field 'mode'")) : 4;
      if (mode > 6)
      {
        throw Refusal(where + "mode " + std::to_string(mode) + " is not a glTF primitive mode (0 to 6)");
      }
      std::size_t vertices = position.Count;
      const long long indices = IndexField(prim, "indices", accessors.size(), where, "accessors");
      if (indices >= 0)
      {
        const Accessor& a = accessors[indices];
        if (a.Components != 1 || (a.ComponentType != 5121 && a.ComponentType != 5123 && a.ComponentType != 5125))
        {
          throw Refusal(where + "its indices are not unsigned integer scalars");
        }
        const std::uint64_t largest = a.Count ? LargestIndex(a, views, buffers) : 0;
        if (a.Count && largest >= position.Count)
        {
          throw Refusal(where + "index " + std::to_string(largest) + " is out of range: it has " +
            std::to_string(position.Count) + " vertices");
        }
        vertices = a.Count;
      }
      if (mode == 4)
      {
        meshTriangles += vertices / 3;
      }
      else if (mode == 5 || mode == 6)
      {
        meshTriangles += vertices >= 3 ? vertices - 2 : 0;
      }
    }
    triangles.push_back(meshTriangles);
  }
}
} // namespace gltf

bool DecodeBase64(const std::string& text, std::string& out)
{
  out.clear();
  out.reserve(text.size() / 4 * 3 + 3);
  unsigned int accumulator = 0;
  int bits = 0;
  std::size_t end = text.size();
  while (end > 0 && text[end - 1] == '=')
  {
    --end;
  }
  for (std::size_t i = 0; i < end; ++i)
  {
    const char c = text[i];
    int v;
    if (c >= 'A' && c <= 'Z')
      v = c - 'A';
    else if (c >= 'a' && c <= 'z')
      v = c - 'a' + 26;
    else if (c >= '0' && c <= '9')
      v = c - '0' + 52;
    else if (c == '+' || c == '-')
      v = 62;
    else if (c == '/' || c == '_')
      v = 63;
    else
      return false;
    accumulator = (accumulator << 6) | static_cast<unsigned int>(v);
    bits += 6;
    if (bits >= 8)
    {
      bits -= 8;
      out.push_back(static_cast<char>((accumulator >> bits) & 0xFF));
    }
  }
  return true;
}
} // namespace cli
} // namespace radiosity
