// The highly tessellated standard scene: the npm bunny read, subdivided and
// placed in its room.
#include "Radiosity/Scenes/BunnyScene.h"
#include "Radiosity/Common/SceneAnalysis.h"

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

TEST(BunnyScene, ExactTriangleCountKeepsTheShape)
{
  const Scene bunny = ReadNpmBunny(RADIOSITY_BUNNY_JS);
  const Scene reference = MakeBunnyRoom(bunny, 1);
  const Scene room = MakeBunnyRoomWithTriangles(bunny, 25000); // 14,696 after one 4-split, then bisections
  const std::size_t roomTriangles = 6 * 4 * 4 * 2 + 2;
  ASSERT_EQ(room.Triangles.size(), roomTriangles + 25000u);
  ValidateScene(room);
  double area = 0.0, referenceArea = 0.0, volume = 0.0, referenceVolume = 0.0;
  for (std::size_t t = roomTriangles; t < room.Triangles.size(); ++t)
  {
    area += room.Area(t);
    volume += glm::dot(room.Vertex(t, 0), glm::cross(room.Vertex(t, 1), room.Vertex(t, 2)));
  }
  for (std::size_t t = roomTriangles; t < reference.Triangles.size(); ++t)
  {
    referenceArea += reference.Area(t);
    referenceVolume +=
      glm::dot(reference.Vertex(t, 0), glm::cross(reference.Vertex(t, 1), reference.Vertex(t, 2)));
  }
  // Same surface (bisection at midpoints changes no shape) and orientation.
  EXPECT_NEAR(area, referenceArea, 1e-9 * referenceArea);
  EXPECT_NEAR(volume, referenceVolume, 1e-9 * std::abs(referenceVolume));
  EXPECT_GT(volume, 0.0);
}
