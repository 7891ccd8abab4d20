// The scene model of the core: triangles with per-triangle materials, grouped
// into objects (blocks), as SPEC.md "Scenes" defines them.
#ifndef Radiosity_Scene_h
#define Radiosity_Scene_h

#include "Radiosity/Common/Lights.h"
#include "Radiosity/Common/Types.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace radiosity
{
/// Bad input: the message names the array, cell or point and the value.
/// Programs turn it into exit status 2 with nothing written.
class SceneError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

struct Material
{
  RGB Reflectance{ 0.5, 0.5, 0.5 };
  RGB Emission{ 0.0, 0.0, 0.0 }; ///< radiant exitance, W/m^2
  RGB Specular{ 0.0, 0.0, 0.0 };
  double Shininess = 0.0;
};

struct Scene
{
  std::vector<Vec3> Points;
  std::vector<Triangle> Triangles;
  std::vector<Material> Materials; ///< one per triangle
  std::vector<int> ObjectIds;      ///< one per triangle: the block it came from
  std::vector<long long> SourceCells; ///< input cell index, for messages
  std::vector<std::string> ObjectNames;
  LightSet Lighting; ///< punctual lights and the sky (SPEC "Lights and sky")

  std::size_t NumberOfTriangles() const { return Triangles.size(); }
  Vec3 Vertex(std::size_t tri, int k) const { return Points[Triangles[tri].V[k]]; }
  double Area(std::size_t tri) const;
  Vec3 Normal(std::size_t tri) const; ///< unit normal (right-hand rule)
  Vec3 Centroid(std::size_t tri) const;

  void BoundingBox(Vec3& lo, Vec3& hi) const;
  double Diagonal() const;
  bool HasEmitters() const; ///< emitting triangles (lights not counted)
  /// Some light: an emitting triangle, a punctual light or an enabled sky.
  bool IsLit() const { return this->HasEmitters() || !this->Lighting.Empty(); }
  std::size_t NumberOfEmitters() const; ///< triangles with a non-zero emission
  double EmittedPower() const; ///< sum of luminance-free RGB power: sum of (r+g+b)/3 * area
};

/**
 * Whether `b` has the surfaces of `a`: the same points, triangles, objects,
 * reflectance and specular colour (emission, lights and sky may differ).
 * What a precomputed light transfer depends on; otherwise false, with `why`
 * naming the first difference (the triangle or point and the values).
 */
bool SameSurfaces(const Scene& a, const Scene& b, std::string* why = nullptr);

struct SceneCleanupReport
{
  std::size_t DegenerateTrianglesDropped = 0;
  std::size_t UnreferencedPoints = 0;
};

/**
 * Checks a scene against SPEC.md: finite coordinates, reflectance in [0, 1),
 * emission >= 0, finite material values, at least one triangle, valid lights
 * (ValidateLights on a copy: the caller normalises its own). Throws
 * SceneError naming the offending cell or point and value.
 */
void ValidateScene(const Scene& scene);

/**
 * Drops zero-area triangles (they never crash a solver; SPEC: dropped with a
 * count in the log). Returns what was removed; `kept`, when given, receives
 * the former index of every triangle kept.
 */
SceneCleanupReport DropDegenerateTriangles(Scene& scene, std::vector<std::uint32_t>* kept = nullptr);

/// Appends `other` to `scene`, offsetting point indices and object ids.
void AppendScene(Scene& scene, const Scene& other);
} // namespace radiosity

#endif
