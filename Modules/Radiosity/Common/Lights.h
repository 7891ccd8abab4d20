// Lights and sky (SPEC.md "Lights and sky"): punctual lights after glTF 2.0's
// KHR_lights_punctual (point, spot with glTF's reference falloff, directional)
// and a sky (uniform, or the CIE standard overcast sky, CIE S 011/E:2003 type
// 16: L = L_z (1 + 2 cos theta) / 3). Units are radiometric: a point or spot
// gives radiant intensity in W/sr, a directional light irradiance in W/m^2 on
// a surface facing it, a sky radiance in W/(m^2 sr). Lights are not geometry:
// they are never seen and never cast a shadow themselves.
#ifndef Radiosity_Lights_h
#define Radiosity_Lights_h

#include "Radiosity/Common/Types.h"

#include <string>
#include <vector>

namespace radiosity
{
enum class LightType
{
  Point,
  Spot,
  Directional
};

struct Light
{
  LightType Type = LightType::Point;
  Vec3 Position{ 0.0, 0.0, 0.0 };   ///< point and spot
  Vec3 Direction{ 0.0, 0.0, -1.0 }; ///< spot: where it points; directional: where the light travels
  RGB Intensity{ 1.0, 1.0, 1.0 };   ///< colour x intensity: W/sr (point, spot) or W/m^2 (directional)
  double InnerConeAngle = 0.0;      ///< spot, radians
  double OuterConeAngle = Pi / 4.0; ///< spot, radians
  std::string Name;                 ///< for messages and the report; may be empty
};

enum class SkyModel
{
  None,
  Uniform,
  CieOvercast
};

struct Sky
{
  SkyModel Model = SkyModel::None;
  Vec3 Up{ 0.0, 0.0, 1.0 };
  RGB Radiance{ 0.0, 0.0, 0.0 }; ///< uniform radiance, or the zenith radiance L_z
  bool Enabled() const { return this->Model != SkyModel::None && MaxComponent(this->Radiance) > 0.0; }
};

/// The lights of a scene: any number of punctual lights and at most one sky.
struct LightSet
{
  std::vector<Light> Lights;
  Sky SkyLight;
  bool Empty() const { return this->Lights.empty() && !this->SkyLight.Enabled(); }
};

const char* LightTypeName(LightType type);
const char* SkyModelName(SkyModel model);

/// glTF's reference spot falloff: the square of the linear ramp in the cosine
/// of the angle to the axis, 1 inside the inner cone and 0 outside the outer.
double SpotFalloff(const Light& spot, double cosAngleToAxis);

/**
 * The closed form of the direct irradiance of a punctual light at x on a
 * surface of unit normal n, without visibility: I cos(theta) / d^2 (times the
 * spot falloff) for point and spot lights, E cos(theta) for a directional one;
 * zero behind the surface (one-sided surfaces, SPEC "Scenes").
 */
RGB UnshadowedIrradiance(const Light& light, const Vec3& x, const Vec3& n);

/// The point a shadow ray from x goes to: the light's position, or a point
/// `farDistance` towards the light for a directional light.
Vec3 ShadowRayTarget(const Light& light, const Vec3& x, double farDistance);

/// Radiance of the sky seen towards the unit direction `towards` (zero below
/// the horizon of Up).
RGB SkyRadiance(const Sky& sky, const Vec3& towards);

/// Irradiance on an unobstructed horizontal surface: pi L (uniform) or
/// 7/9 pi L_z (CIE overcast). The daylight factor's denominator.
RGB UnobstructedHorizontalIrradiance(const Sky& sky);

/**
 * Radiant power a punctual light emits: 4 pi I for a point light, for a spot
 * 2 pi I ((1 - cos inner) + (cos inner - cos outer) / 3) (the integral of the
 * falloff over the sphere). A directional light has no finite power of its
 * own; it returns 0 and the report gives what reaches the scene instead.
 */
RGB EmittedPower(const Light& light);

/**
 * Checks lights as SPEC asks: finite values, non-negative intensities, a
 * non-zero direction where one is needed, 0 <= inner < outer <= pi/2, an
 * enabled sky with a non-zero up. Throws SceneError naming the light's index
 * (in `lights`, or "the sky") and the field. Directions are normalised.
 */
void ValidateLights(LightSet& lights);

/**
 * Parses a LIGHTS.json text (SPEC: KHR_lights_punctual's field names and
 * defaults, with explicit position and direction; "sky" entries with model,
 * up and intensity). Throws SceneError naming `fileName`, the light's index
 * in the file and the field. The result is validated.
 */
LightSet ParseLightsJson(const std::string& text, const std::string& fileName);

/// Reads and parses a LIGHTS.json file; a missing or unreadable file is a SceneError.
LightSet ReadLightsFile(const std::string& fileName);
} // namespace radiosity

#endif
