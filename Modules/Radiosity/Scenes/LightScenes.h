// Scenes lit by lights (SPEC.md "Lights and sky") whose irradiance has a
// closed form (Reference/AnalyticLights.h gives it; ComputeAnalyticReference
// recognises each), with the probes the tests read. Every scene has a
// `scale`: lengths times scale, the same light (so irradiance scales as
// 1 / scale^2 for point and spot lights and stays for the sun and the sky).
// No triangle emits: the lights alone light them.
#ifndef Radiosity_LightScenes_h
#define Radiosity_LightScenes_h

#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Common/Scene.h"

#include <string>
#include <vector>

namespace radiosity
{
namespace lightscenes
{
/// Height of the point and spot lights over the floor (times scale).
constexpr double LightHeight = 1.0;
constexpr double PointIntensity = 10.0;  ///< W/sr
constexpr double SpotInner = 0.3, SpotOuter = 0.6;
constexpr double SunIrradiance = 1000.0; ///< W/m^2 on a surface facing the sun
constexpr double SkyRadiance = 100.0;    ///< W/(m^2 sr): uniform L, or the CIE zenith L_z
constexpr double PlateHeight = 0.5;      ///< the sun scene's plate (times scale)
constexpr double PlateHalfSide = 0.4;
constexpr double WallHalfWidth = 3.0, WallHeight = 3.0; ///< the sky scene's wall at y = 0
} // namespace lightscenes

/// A floor [-2, 2]^2 x scale at z = 0 facing up (n x n quads, reflectance
/// `reflectance`) under a point light of intensity PointIntensity at
/// (0, 0, LightHeight) x scale. A single plane never sees itself, so any
/// reflectance gives H = I h / d^3.
Scene MakePointLightOverPlane(double scale = 1.0, double reflectance = 0.0, int n = 8);

/// The same floor under a spot at (0, 0, LightHeight) x scale pointing along
/// (0.3, 0, -1) (tilted, so the falloff's rings are not centred under it),
/// inner and outer cone SpotInner, SpotOuter.
Scene MakeSpotOverPlane(double scale = 1.0, double reflectance = 0.0, int n = 8);

/// The sun, SunIrradiance travelling along (0.5, 0.25, -1) (normalised), over a
/// black floor [-2, 2]^2 with a black square plate (half side PlateHalfSide,
/// both faces) at height PlateHeight: an exact hard shadow.
Scene MakeSunOverPlate(double scale = 1.0, int n = 8);
/// The plate's corners (counter-clockwise seen from above), times scale.
std::vector<Vec3> SunPlateCorners(double scale = 1.0);

/// The inside of an icosphere (MakeSphereInterior: `levels` subdivisions,
/// faces inward) of radius `radius` and reflectance `reflectance`, with a
/// point light of intensity PointIntensity at (0.3, 0.1, -0.2) x radius.
Scene MakePointLightInSphere(double radius = 1.0, int levels = 3, double reflectance = 0.5);

/// A uniform sky of radiance SkyRadiance (up +z) over a floor [-2, 2]^2 x scale.
Scene MakeUniformSkyOverPlane(double scale = 1.0, double reflectance = 0.0, int n = 4);

/// A uniform sky beside a black wall (the plane y = 0, x in [-WallHalfWidth,
/// WallHalfWidth], z in [0, WallHeight], facing -y) standing on a black floor
/// x in [-4, 4], y in [-4, 0] (times scale): H = pi L (1 - F_wall).
Scene MakeUniformSkyBesideWall(double scale = 1.0, int n = 4);
/// The wall's corners, times scale.
std::vector<Vec3> SkyWallCorners(double scale = 1.0);

/// A CIE overcast sky of zenith radiance SkyRadiance over the floor [-2, 2]^2 x scale.
Scene MakeCieSkyOverPlane(double scale = 1.0, double reflectance = 0.0, int n = 4);

/// A light case: the scene, its probes, and what kind of answer it has.
struct LightCase
{
  std::string Name;
  Scene Geometry;
  std::vector<Probe> Probes;
  /// Punctual lights only and nothing reflects onto the probes: the answer is
  /// the direct light alone (the cases held to 1e-4 of the peak).
  bool DirectPunctual = false;
  /// A sky lights the scene (the direct part is a hemisphere integral).
  bool HasSky = false;
};

/// Every case above, with probes on the lit surfaces (floor probes facing up
/// at several distances, across the shadow edge for the sun, facet centroids
/// for the sphere, at several distances from the wall). `scale` as above.
std::vector<LightCase> AnalyticLightCases(double scale = 1.0);

/// Another lighting of `scene`'s surfaces, for a relight to start from:
/// every light's intensity and the sky's radiance times (0.3, 0.6, 1), the
/// lights moved by a tenth of the scene's diagonal (along x, and half that
/// along y).
Scene WithOtherLighting(const Scene& scene);
} // namespace radiosity

#endif
