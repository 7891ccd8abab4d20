// SceneIsEnclosed (Common/Enclosure.h): the face cluster solver balances
// each bounce's energy only in scenes it says are enclosed, so an open
// scene taken for enclosed would have light that escapes put back.
#include "Radiosity/Common/Enclosure.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <gtest/gtest.h>

using namespace radiosity;

namespace
{
/// `scene` without the triangles whose centroids lie on the plane x = x0.
Scene WithoutFace(const Scene& scene, double x0)
{
  Scene out = scene;
  out.Triangles.clear();
  out.Materials.clear();
  out.ObjectIds.clear();
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    if (std::abs(scene.Centroid(t).x - x0) > 1e-9)
    {
      out.Triangles.push_back(scene.Triangles[t]);
      out.Materials.push_back(scene.Materials[t]);
      out.ObjectIds.push_back(scene.ObjectIds[t]);
    }
  }
  return out;
}
}

TEST(Enclosure, ClosedSurfacesAreEnclosedAtEveryScale)
{
  for (double size : { 1e-4, 1.0, 1e4 })
  {
    EXPECT_TRUE(SceneIsEnclosed(MakeClosedCube(size, 4, 0.5, 1.0))) << size;
    EXPECT_TRUE(SceneIsEnclosed(MakeSphereInterior(size, 2, 0.5, RGB(1.0)))) << size;
  }
}

TEST(Enclosure, OpenScenesAreNot)
{
  // The Cornell box is open at the front; a cube without one face; a single
  // pair of parallel squares.
  EXPECT_FALSE(SceneIsEnclosed(MakeCornellBox()));
  const Scene cube = MakeClosedCube(1.0, 4, 0.5, 1.0);
  double xmax = -1e30;
  for (std::size_t t = 0; t < cube.Triangles.size(); ++t)
  {
    xmax = std::max(xmax, cube.Centroid(t).x);
  }
  EXPECT_FALSE(SceneIsEnclosed(WithoutFace(cube, xmax)));
  EXPECT_FALSE(SceneIsEnclosed(MakeParallelSquares(1.0, 1.0, 2, 0.5, 1.0)));
  // Sampled: a 2048-sample check of a large cube without a face still sees
  // the opening (one sixth of the area).
  const Scene fine = MakeClosedCube(1.0, 32, 0.5, 1.0);
  EXPECT_GT(fine.Triangles.size(), 2048u);
  double fineMax = -1e30;
  for (std::size_t t = 0; t < fine.Triangles.size(); ++t)
  {
    fineMax = std::max(fineMax, fine.Centroid(t).x);
  }
  EXPECT_TRUE(SceneIsEnclosed(fine));
  EXPECT_FALSE(SceneIsEnclosed(WithoutFace(fine, fineMax)));
  EXPECT_FALSE(SceneIsEnclosed(Scene()));
}
