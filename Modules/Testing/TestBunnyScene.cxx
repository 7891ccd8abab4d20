// The highly tessellated standard scene: the npm bunny read, subdivided and
// placed in its room.
#include "Radiosity/BunnyScene.h"
#include "Radiosity/SceneAnalysis.h"

#include <gtest/gtest.h>

using namespace radiosity;

TEST(BunnyScene, ReadSubdivideAndPlace)
{
  const Scene bunny = ReadNpmBunny(RADIOSITY_BUNNY_JS);
  EXPECT_EQ(bunny.Points.size(), 1839u);
  EXPECT_EQ(bunny.Triangles.size(), 3674u);
  const Scene room = MakeBunnyRoom(bunny, 3); // 235k triangles in the bunny
  const std::size_t roomTriangles = 6 * 4 * 4 * 2 + 2;
  EXPECT_EQ(room.Triangles.size(), roomTriangles + 3674u * 64u);
  ValidateScene(room);
  double bunnyArea = 0.0;
  Vec3 lo(1e9), hi(-1e9);
  for (std::size_t t = roomTriangles; t < room.Triangles.size(); ++t)
  {
    bunnyArea += room.Area(t);
    for (int k = 0; k < 3; ++k)
    {
      lo = glm::min(lo, room.Vertex(t, k));
      hi = glm::max(hi, room.Vertex(t, k));
    }
  }
  EXPECT_NEAR(hi.y - lo.y, 0.5, 1e-9); // 0.5 m high, standing on the floor
  EXPECT_NEAR(lo.y, 0.0, 1e-9);
  EXPECT_GT(bunnyArea, 0.1);
  EXPECT_EQ(room.ObjectNames.back(), "bunny");
  EXPECT_THROW(ReadNpmBunny("/nonexistent/index.js"), SceneError);
}
