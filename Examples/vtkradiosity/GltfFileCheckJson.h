// What the glTF checks (GltfFileCheck.cxx, GltfFileCheckData.cxx) share:
// refusals, reading JSON fields with their checks, and the binary data
// checks. Internal to the checks, not an interface.
#ifndef vtkradiosity_GltfFileCheckJson_h
#define vtkradiosity_GltfFileCheckJson_h

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace radiosity
{
namespace cli
{
namespace gltf
{
using json = nlohmann::json;

// A refusal, with the file name added by CheckGltf.
struct Refusal : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

constexpr double Pi = 3.14159265358979323846;

inline std::string Shown(double v)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", v);
  return text;
}

inline std::string Shown(const json& v)
{
  std::string s = v.dump();
  return s.size() > 40 ? s.substr(0, 40) + "..." : s;
}

// "material 2 ('red')": the object's kind, index and name, for messages.
inline std::string Named(const std::string& kind, std::size_t index, const json& object)
{
  std::string s = kind + " " + std::to_string(index);
  if (object.is_object() && object.contains("name") && object["name"].is_string())
  {
    s += " ('" + object["name"].get<std::string>().substr(0, 40) + "')";
  }
  return s;
}

// The array `key` of `object` (empty when absent); refused when not an array.
inline const json& ArrayOf(const json& object, const char* key, const std::string& where)
{
  static const json empty = json::array();
  if (!object.is_object() || !object.contains(key))
  {
    return empty;
  }
  const json& a = object[key];
  if (!a.is_array())
  {
    throw Refusal(where + "field '" + key + "' is " + Shown(a) + ", not an array");
  }
  return a;
}

// A glTF index or count: a non-negative integer.
inline std::uint64_t Unsigned(const json& v, const std::string& what)
{
  if (v.is_number_unsigned())
  {
    return v.get<std::uint64_t>();
  }
  if (v.is_number_integer() && v.get<std::int64_t>() >= 0)
  {
    return static_cast<std::uint64_t>(v.get<std::int64_t>());
  }
  throw Refusal(what + " is " + Shown(v) + ", not a non-negative integer");
}

// The index `key` of `object` into an array of `size`; -1 when absent.
inline long long IndexField(const json& object, const char* key, std::size_t size, const std::string& where,
  const char* into)
{
  if (!object.contains(key))
  {
    return -1;
  }
  const std::uint64_t i = Unsigned(object[key], where + "field '" + key + "'");
  if (i >= size)
  {
    throw Refusal(where + "field '" + key + "' is " + std::to_string(i) + " but the file has " +
      std::to_string(size) + " " + into);
  }
  return static_cast<long long>(i);
}

// A finite number `key` of `object`, `fallback` when absent.
inline double NumberField(const json& object, const char* key, double fallback, const std::string& where)
{
  if (!object.contains(key))
  {
    return fallback;
  }
  const json& v = object[key];
  if (!v.is_number() || !std::isfinite(v.get<double>()))
  {
    throw Refusal(where + "field '" + key + "' is " + Shown(v) + ", not a finite number");
  }
  return v.get<double>();
}

// `n` finite numbers `key` of `object` into `out` (left as is when absent).
inline bool NumbersField(const json& object, const char* key, std::size_t n, double* out, const std::string& where)
{
  if (!object.contains(key))
  {
    return false;
  }
  const json& v = object[key];
  if (!v.is_array() || v.size() != n)
  {
    throw Refusal(where + "field '" + key + "' is " + Shown(v) + ", not " + std::to_string(n) + " numbers");
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    if (!v[i].is_number() || !std::isfinite(v[i].get<double>()))
    {
      throw Refusal(where + "field '" + key + "' component " + std::to_string(i) + " is " +
        Shown(v[i]) + ", not a finite number");
    }
    out[i] = v[i].get<double>();
  }
  return true;
}

struct View
{
  std::size_t Buffer, Offset, Length, Stride;
};

struct Accessor
{
  long long View = -1;
  std::size_t Offset = 0, Count = 0, ComponentType = 0, Components = 0, ComponentSize = 0;
};

/// The .glb container: the JSON chunk's text and the BIN chunk (if any).
void SplitGlb(const std::string& bytes, std::string& text, std::string& bin, bool& hasBin);
/// Every buffer's bytes (at least byteLength of them): a data: URI, a file
/// beside `file` or the .glb's BIN chunk.
std::vector<std::string> LoadBuffers(const json& root, const std::string& file, const std::string& bin,
  bool hasBin, bool glb);
std::vector<View> CheckViews(const json& root, const std::vector<std::string>& buffers);
std::vector<Accessor> CheckAccessors(const json& root, const std::vector<View>& views);
/// Primitives: attributes, indices below the vertex count, materials; the
/// triangles of each mesh into `triangles`.
void CheckMeshes(const json& root, const std::vector<Accessor>& accessors, const std::vector<View>& views,
  const std::vector<std::string>& buffers, std::size_t materials, std::vector<std::size_t>& triangles);
} // namespace gltf
} // namespace cli
} // namespace radiosity

#endif
