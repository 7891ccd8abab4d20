// Surfaces modelled the wrong way round (FacingAway.h, issue 53): a floor
// whose normal points down under a lamp is found and warned about, naming
// its object and share; a closed box's underside (its back sees the inside
// of the box, not the lamp) and a correctly modelled room are not.
#include "Radiosity/Common/FacingAway.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <gtest/gtest.h>

using namespace radiosity;

namespace
{
// A 4 m closed room (faces inward, 2 x 2 quads a face) lit by a point lamp
// 3 m up, with a closed box (faces outward) hung above the lamp, 0.5 m high.
Scene LitRoomWithBox()
{
  Scene room = MakeClosedCube(4.0, 2, 0.5, 0.0);
  Scene box = MakeClosedCube(1.0, 1, 0.5, 0.0);
  for (Vec3& p : box.Points)
  {
    p = Vec3(1.5 + p.x, 1.5 + p.y, 3.3 + 0.5 * p.z);
  }
  for (Triangle& t : box.Triangles)
  {
    std::swap(t.V[1], t.V[2]); // outward
  }
  AppendScene(room, box);
  Light lamp;
  lamp.Type = LightType::Point;
  lamp.Position = Vec3(2.0, 2.0, 3.0);
  lamp.Intensity = RGB(10.0);
  room.Lighting.Lights.push_back(lamp);
  return room;
}
}

TEST(FacingAway, ACorrectRoomAndABoxUndersideAreNotWarnedAbout)
{
  const Scene scene = LitRoomWithBox();
  const FacingAway away = FindFacingAway(scene);
  // The room's ceiling faces the lamp below it; the box's top and sides
  // face away from it, but their backs see the inside of the box.
  EXPECT_EQ(away.Triangles, 0u);
  EXPECT_EQ(away.Area, 0.0);
  EXPECT_NEAR(away.TotalArea, 6 * 16.0 + 2 * 1.0 + 4 * 0.5, 1e-9);
  EXPECT_TRUE(FacingAwayWarning(scene).empty());
}

TEST(FacingAway, AFloorModelledUpsideDownIsWarnedAbout)
{
  Scene scene = LitRoomWithBox();
  std::size_t flipped = 0;
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    if (scene.ObjectNames[scene.ObjectIds[t]] == "z0" && scene.Vertex(t, 0).z < 1e-9 &&
      scene.Vertex(t, 1).z < 1e-9 && scene.Vertex(t, 2).z < 1e-9)
    {
      std::swap(scene.Triangles[t].V[1], scene.Triangles[t].V[2]);
      ++flipped;
    }
  }
  ASSERT_EQ(flipped, 8u); // the room's floor: 2 x 2 quads
  const FacingAway away = FindFacingAway(scene);
  EXPECT_EQ(away.Triangles, flipped);
  EXPECT_NEAR(away.Area, 16.0, 1e-9); // every floor triangle's centre sees the lamp
  const std::string warning = FacingAwayWarning(scene);
  EXPECT_NE(warning.find("8 triangles (16.0% of the surface area, most of them in 'z0')"), std::string::npos)
    << warning;
  EXPECT_NE(warning.find("--two-sided"), std::string::npos) << warning;
  // A sun is no such light: the back of a one-sided room's walls (outside)
  // sees it, and that is how rooms are modelled.
  scene.Lighting.Lights[0].Type = LightType::Directional;
  scene.Lighting.Lights[0].Direction = Vec3(0.0, 0.0, -1.0);
  EXPECT_EQ(FindFacingAway(scene).Triangles, 0u);
}
