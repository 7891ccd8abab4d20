// Bad input gives the documented errors (SPEC.md, Scenes).
#include "Radiosity/Common/Scene.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <gtest/gtest.h>

#include <limits>

using namespace radiosity;

namespace
{
std::string ErrorOf(const Scene& s)
{
  try
  {
    ValidateScene(s);
  }
  catch (const SceneError& e)
  {
    return e.what();
  }
  return "";
}
}

TEST(SceneValidation, AcceptsTheCornellBox)
{
  EXPECT_EQ(ErrorOf(MakeCornellBox()), "");
}

TEST(SceneValidation, NaNPoint)
{
  Scene s = MakeCornellBox();
  s.Points[5].y = std::numeric_limits<double>::quiet_NaN();
  const std::string e = ErrorOf(s);
  EXPECT_NE(e.find("point 5"), std::string::npos) << e;
  EXPECT_NE(e.find("nan"), std::string::npos) << e;
}

TEST(SceneValidation, ReflectanceAboveOne)
{
  Scene s = MakeCornellBox();
  s.Materials[3].Reflectance = RGB(0.5, 1.2, 0.5);
  const std::string e = ErrorOf(s);
  EXPECT_NE(e.find("Reflectance"), std::string::npos) << e;
  EXPECT_NE(e.find("cell 3"), std::string::npos) << e;
  EXPECT_NE(e.find("1.2"), std::string::npos) << e;
}

TEST(SceneValidation, NegativeEmission)
{
  Scene s = MakeCornellBox();
  s.Materials[0].Emission = RGB(-1, 0, 0);
  EXPECT_NE(ErrorOf(s).find("Emission"), std::string::npos);
}

TEST(SceneValidation, EmptyMesh)
{
  const Scene s;
  EXPECT_NE(ErrorOf(s).find("empty"), std::string::npos);
}

TEST(SceneValidation, DegenerateTrianglesDropped)
{
  Scene s = MakeClosedCube(1.0, 1, 0.5, 1.0);
  const std::size_t before = s.Triangles.size();
  s.Triangles.push_back({ { 0, 0, 1 } });
  s.Triangles.push_back({ { 0, 1, 1 } });
  s.Materials.resize(s.Triangles.size());
  s.ObjectIds.resize(s.Triangles.size(), 0);
  s.SourceCells.resize(s.Triangles.size());
  const SceneCleanupReport r = DropDegenerateTriangles(s);
  EXPECT_EQ(r.DegenerateTrianglesDropped, 2u);
  EXPECT_EQ(s.Triangles.size(), before);
}
