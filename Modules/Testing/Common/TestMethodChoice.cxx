// --method auto's rules (MethodChoice.h): the scene's figures that choose,
// at their boundaries, and the sentence that says why. What each rule buys
// is measured by the error-against-run-time bench (vtkradiosity.bench-quick
// checks auto within 1.5x of the best at equal time).
#include "Radiosity/Common/MethodChoice.h"
#include "Radiosity/Scenes/OfficeScene.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace radiosity;

namespace
{
/// The first `n` triangles of a closed cube of 2,352 (they need not close).
Scene FirstTriangles(std::size_t n)
{
  Scene scene = MakeClosedCube(1.0, 14, 0.5, 1.0);
  EXPECT_GE(scene.Triangles.size(), n);
  scene.Triangles.resize(n);
  scene.Materials.resize(n);
  scene.ObjectIds.resize(n);
  scene.SourceCells.resize(std::min(scene.SourceCells.size(), n));
  return scene;
}
}

TEST(MethodChoice, SmallMatteScenesAreSolvedByClusteredHierarchicalRadiosity)
{
  for (const Scene& scene : { MakeCornellBox(), MakeSphereInterior(1.0, 3, 0.9, RGB(10.0)),
         FirstTriangles(AutoHierarchicalMaxTriangles) })
  {
    const MethodChoice choice = ChooseMethod(scene);
    EXPECT_EQ(choice.Method, SolutionMethod::Hierarchical) << scene.Triangles.size() << " triangles";
    EXPECT_TRUE(choice.Clustered);
    EXPECT_EQ(choice.Rule, "small");
    // The sentence names the scene's figure and the bound.
    EXPECT_NE(choice.Why.find(std::to_string(scene.Triangles.size()) + " triangles"), std::string::npos)
      << choice.Why;
    EXPECT_NE(choice.Why.find("2048"), std::string::npos) << choice.Why;
  }
}

TEST(MethodChoice, LargeScenesAreSolvedByMeshlessRadiosity)
{
  for (std::size_t n : { AutoHierarchicalMaxTriangles + 1, std::size_t(2352) })
  {
    const MethodChoice choice = ChooseMethod(FirstTriangles(n));
    EXPECT_EQ(choice.Method, SolutionMethod::Meshless) << n << " triangles";
    EXPECT_EQ(choice.Rule, "large");
    EXPECT_NE(choice.Why.find(std::to_string(n) + " triangles, more than 2048"), std::string::npos)
      << choice.Why;
  }
}

TEST(MethodChoice, DaylitScenesAreSolvedByMeshlessRadiosity)
{
  // The office: 738 triangles, a lamp and a CIE overcast sky, no emitter.
  const Scene office = MakeOfficeScene();
  const MethodChoice choice = ChooseMethod(office);
  EXPECT_EQ(choice.Method, SolutionMethod::Meshless);
  EXPECT_EQ(choice.Rule, "sky");
  EXPECT_NE(choice.Why.find(std::to_string(office.Triangles.size()) + " triangles lit by a sky"), std::string::npos)
    << choice.Why;
  // Its lamp alone (no sky): the small-scene rule.
  Scene lamp = office;
  lamp.Lighting.SkyLight = Sky();
  EXPECT_EQ(ChooseMethod(lamp).Rule, "small");
  // A sky over a scene with an emitting triangle: the emitters' rules.
  Scene both = MakeCornellBox();
  both.Lighting.SkyLight = office.Lighting.SkyLight;
  EXPECT_EQ(ChooseMethod(both).Rule, "small");
}

TEST(MethodChoice, AGlossyPartIsDrawnFromFaceClusterRadiosity)
{
  // One glossy triangle, in a small scene and in a large one, in one channel.
  for (std::size_t n : { std::size_t(32), std::size_t(2352) })
  {
    Scene scene = n == 32 ? MakeCornellBox() : FirstTriangles(n);
    scene.Materials[5].Specular = RGB(0.0, 0.0, 0.2);
    const MethodChoice choice = ChooseMethod(scene);
    EXPECT_EQ(choice.Method, SolutionMethod::FaceCluster) << n << " triangles";
    EXPECT_EQ(choice.Rule, "glossy");
    EXPECT_NE(choice.Why.find("1 of the " + std::to_string(n) + " triangles"), std::string::npos)
      << choice.Why;
  }
  // Shininess alone, without a specular colour, is not glossy.
  Scene matte = MakeCornellBox();
  matte.Materials[5].Shininess = 40.0;
  EXPECT_EQ(ChooseMethod(matte).Method, SolutionMethod::Hierarchical);
}

TEST(MethodChoice, NamesAreTheCommandLines)
{
  EXPECT_STREQ(SolutionMethodName(SolutionMethod::Progressive), "progressive");
  EXPECT_STREQ(SolutionMethodName(SolutionMethod::Hierarchical), "hierarchical");
  EXPECT_STREQ(SolutionMethodName(SolutionMethod::Meshless), "meshless");
  EXPECT_STREQ(SolutionMethodName(SolutionMethod::FaceCluster), "facecluster");
}
