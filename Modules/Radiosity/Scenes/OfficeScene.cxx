#include "Radiosity/Scenes/OfficeScene.h"

#include "Radiosity/Scenes/SceneGenerators.h"

namespace radiosity
{
namespace
{
Material Grey(double rho)
{
  Material m;
  m.Reflectance = RGB(rho);
  return m;
}

/// An axis-aligned box (six faces facing out).
void AppendBox(Scene& scene, const Vec3& lo, const Vec3& hi, const Material& m, const std::string& name)
{
  const Vec3 a(lo.x, lo.y, lo.z), b(hi.x, lo.y, lo.z), c(hi.x, hi.y, lo.z), d(lo.x, hi.y, lo.z);
  const Vec3 e(lo.x, lo.y, hi.z), f(hi.x, lo.y, hi.z), g(hi.x, hi.y, hi.z), h(lo.x, hi.y, hi.z);
  AppendQuad(scene, e, f, g, h, m, 2, name + " top");
  AppendQuad(scene, a, d, c, b, m, 1, name + " bottom");
  AppendQuad(scene, a, b, f, e, m, 1, name + " front");
  AppendQuad(scene, c, d, h, g, m, 1, name + " back");
  AppendQuad(scene, d, a, e, h, m, 1, name + " left");
  AppendQuad(scene, b, c, g, f, m, 1, name + " right");
}
}

Scene MakeOfficeScene(bool lamp, bool sky)
{
  using namespace office;
  Scene scene;
  const Material floor = Grey(0.3), wall = Grey(0.7), ceiling = Grey(0.8), desk = Grey(0.5);
  const double W = Width, D = Depth, H = Height;
  // Inward-facing room: floor, ceiling, three plain walls.
  AppendQuad(scene, Vec3(0, 0, 0), Vec3(W, 0, 0), Vec3(W, D, 0), Vec3(0, D, 0), floor, 8, "floor");
  AppendQuad(scene, Vec3(0, 0, H), Vec3(0, D, H), Vec3(W, D, H), Vec3(W, 0, H), ceiling, 8, "ceiling");
  AppendQuad(scene, Vec3(0, D, 0), Vec3(W, D, 0), Vec3(W, D, H), Vec3(0, D, H), wall, 8, "back wall");
  AppendQuad(scene, Vec3(0, 0, 0), Vec3(0, D, 0), Vec3(0, D, H), Vec3(0, 0, H), wall, 8, "left wall");
  AppendQuad(scene, Vec3(W, 0, 0), Vec3(W, 0, H), Vec3(W, D, H), Vec3(W, D, 0), wall, 8, "right wall");
  // The window wall y = 0 (facing +y) around its opening: below the sill,
  // above the head, and the two piers beside the window.
  AppendQuad(scene, Vec3(0, 0, 0), Vec3(0, 0, Sill), Vec3(W, 0, Sill), Vec3(W, 0, 0), wall, 4, "window wall");
  AppendQuad(scene, Vec3(0, 0, Head), Vec3(0, 0, H), Vec3(W, 0, H), Vec3(W, 0, Head), wall, 4, "window wall");
  AppendQuad(scene, Vec3(0, 0, Sill), Vec3(0, 0, Head), Vec3(WindowX0, 0, Head), Vec3(WindowX0, 0, Sill), wall, 2,
    "window wall");
  AppendQuad(scene, Vec3(WindowX1, 0, Sill), Vec3(WindowX1, 0, Head), Vec3(W, 0, Head), Vec3(W, 0, Sill), wall, 2,
    "window wall");
  AppendBox(scene, Vec3(1.5, 2.2, DeskHeight - 0.04), Vec3(3.3, 3.0, DeskHeight), desk, "desk");
  if (lamp)
  {
    Light spot;
    spot.Type = LightType::Spot;
    spot.Name = "ceiling lamp";
    spot.Position = Vec3(2.4, 2.6, H - 0.05);
    spot.Direction = Vec3(0, 0, -1);
    spot.Intensity = RGB(LampIntensity, 0.9 * LampIntensity, 0.75 * LampIntensity); // warm white
    spot.InnerConeAngle = 0.5;
    spot.OuterConeAngle = 1.0;
    scene.Lighting.Lights.push_back(spot);
  }
  if (sky)
  {
    scene.Lighting.SkyLight.Model = SkyModel::CieOvercast;
    scene.Lighting.SkyLight.Up = Vec3(0, 0, 1);
    scene.Lighting.SkyLight.Radiance = RGB(SkyZenithRadiance);
  }
  return scene;
}

std::vector<Probe> OfficeSensorGrid()
{
  using namespace office;
  std::vector<Probe> probes;
  for (double x = 0.5; x < Width - 0.25; x += 0.5)
  {
    for (double y = 0.5; y < Depth - 0.25; y += 0.5)
    {
      const bool overDesk = x > 1.4 && x < 3.4 && y > 2.1 && y < 3.1;
      if (!overDesk)
      {
        probes.push_back({ Vec3(x, y, DeskHeight), Vec3(0, 0, 1) });
      }
    }
  }
  return probes;
}
} // namespace radiosity
