// The hard shadow scene of the filters' tests: a black square plate above a
// grey floor lit by one point light, no emitting triangle, and the floor's
// exact irradiance (it is flat and the plate black, so it sees only the
// lamp).
#ifndef HardShadowScene_h
#define HardShadowScene_h

#include "Radiosity/Common/Scene.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <cmath>

namespace HardShadowScene
{
constexpr double PlateZ = 0.5, PlateHalf = 0.4, Intensity = 10.0;
const radiosity::Vec3 LampAt(0.3, 0.1, 1.5);

/// The floor [-2, 2]^2 as floorSquares^2 squares and the plate, one square
/// each side, black below. `plateTop` given: the plate is only its top, of
/// that reflectance (a one-sided surface: the floor does not see it, and a
/// view from above draws it, not a black bottom in the same plane).
inline radiosity::Scene Make(int floorSquares, const radiosity::RGB* plateTop = nullptr)
{
  using radiosity::Vec3;
  radiosity::Scene scene;
  radiosity::Material floor, black, top;
  floor.Reflectance = radiosity::RGB(0.75, 0.7, 0.6);
  black.Reflectance = radiosity::RGB(0.0);
  top.Reflectance = plateTop ? *plateTop : radiosity::RGB(0.0);
  radiosity::AppendQuad(
    scene, Vec3(-2, -2, 0), Vec3(2, -2, 0), Vec3(2, 2, 0), Vec3(-2, 2, 0), floor, floorSquares, "floor");
  const double h = PlateHalf;
  radiosity::AppendQuad(scene, Vec3(-h, -h, PlateZ), Vec3(h, -h, PlateZ), Vec3(h, h, PlateZ), Vec3(-h, h, PlateZ),
    top, 1, "plate top");
  if (!plateTop)
  {
    radiosity::AppendQuad(scene, Vec3(-h, -h, PlateZ), Vec3(-h, h, PlateZ), Vec3(h, h, PlateZ), Vec3(h, -h, PlateZ),
      black, 1, "plate bottom");
  }
  return scene;
}

/// The point light of the scene.
inline radiosity::LightSet Lamp()
{
  radiosity::LightSet lights;
  radiosity::Light lamp;
  lamp.Type = radiosity::LightType::Point;
  lamp.Position = LampAt;
  lamp.Intensity = radiosity::RGB(Intensity);
  lights.Lights.push_back(lamp);
  return lights;
}

/// The floor's irradiance at x: I h / d^3 where the segment to the lamp
/// misses the plate, else 0. `edge`, when given: the distance (in the
/// plate's plane) of the segment's crossing from the plate's boundary.
inline double Exact(const radiosity::Vec3& x, double* edge = nullptr)
{
  const radiosity::Vec3 crossing = x + (LampAt - x) * (PlateZ / LampAt.z);
  const double ax = std::fabs(crossing.x) - PlateHalf, ay = std::fabs(crossing.y) - PlateHalf;
  if (edge)
  {
    *edge = ax <= 0.0 && ay <= 0.0 ? std::min(-ax, -ay) : std::hypot(std::max(ax, 0.0), std::max(ay, 0.0));
  }
  if (ax <= 0.0 && ay <= 0.0)
  {
    return 0.0;
  }
  const double d = glm::length(LampAt - x);
  return Intensity * LampAt.z / (d * d * d);
}
}

#endif
