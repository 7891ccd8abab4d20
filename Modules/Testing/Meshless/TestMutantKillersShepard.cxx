// Tests added for the survivors of the mutation check (Testing/Mutation,
// issue 16): the multilevel Shepard fit (Lehtinen et al. 2007, eq. 10).
#include "Radiosity/Meshless/ShepardField.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace radiosity;

// Mutant "eq. 10 off by one" (the residual at a level-L point taken against
// levels 0..L instead of 0..L-1) survived: on constant or smooth data every
// finer coefficient is 0 either way. Eq. 10 makes a level-L coefficient
// alpha_j = v_j - F_{<L}(x_j), which does not depend on the values at the
// other level-L points: changing v_j by delta moves alpha_j by delta and no
// other coefficient of its level. The mutant lets alpha_j leak into every
// later point of the level within its support.
TEST(MutantKillersShepard, FinerCoefficientsDependOnlyOnCoarserLevels)
{
  Scene s;
  Material m;
  AppendQuad(s, Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), m, 8, "square");
  PointPlacementOptions options;
  options.Levels = 3;
  PointHierarchy h(s, options, nullptr);
  ASSERT_EQ(h.NumberOfLevels(), 3);
  const std::size_t j = h.LevelBegin(1);
  ASSERT_LT(j + 1, h.LevelEnd(1));
  const MeshlessPoint& pj = h.Points()[j];
  // The premise: later points of level 1 lie in point j's support.
  int neighbours = 0;
  for (std::size_t k = j + 1; k < h.LevelEnd(1); ++k)
  {
    neighbours += ShepardWeight(pj, h.Points()[k].Position, h.Points()[k].Normal) > 0.0;
  }
  ASSERT_GT(neighbours, 0);

  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<RGB> values(h.Points().size());
  for (RGB& v : values)
  {
    v = RGB(u(rng));
  }
  ShepardField f(h);
  f.Fit(values);
  const std::vector<RGB> before = f.Coefficients();
  const double delta = 0.75;
  values[j] += RGB(delta);
  f.Fit(values);
  const std::vector<RGB>& after = f.Coefficients();
  // Measured: alpha_j moves by exactly 0.75 (difference 0; the bound is a few
  // roundings of numbers below 2), and the other coefficients of levels 0
  // and 1 do not move at all (the same arithmetic on the same inputs). The
  // mutant moves coefficient 45 of level 1.
  EXPECT_NEAR(after[j].x - before[j].x, delta, 1e-15);
  for (std::size_t k = 0; k < h.LevelEnd(1); ++k)
  {
    if (k != j)
    {
      ASSERT_EQ(after[k].x, before[k].x) << "coefficient " << k << " of level " << h.Points()[k].Level;
    }
  }
}

// Mutant "the weight's normal factor max(0, n . n_j) dropped" (the sign test
// kept) survived: on flat walls every point of a group shares the normal, and
// on the sphere the supports are small against the curvature (n . n_j near 1).
// Eq. 12 at r = 0.3 with the normals 60 degrees apart: K(0.3) = 2 (0.027) -
// 3 (0.09) + 1 = 0.784, times cos 60 = 0.5, is 0.392.
TEST(MutantKillersShepard, WeightCarriesTheNormalsCosine)
{
  MeshlessPoint p;
  p.Position = Vec3(0.0);
  p.Normal = Vec3(0, 0, 1);
  p.Radius = 1.0;
  const double s = std::sqrt(3.0) / 2.0;
  // Measured: 0.392 exactly (difference 0; the bound is rounding); the mutant
  // gives 0.784.
  EXPECT_NEAR(ShepardWeight(p, Vec3(0.3, 0, 0), Vec3(s, 0, 0.5)), 0.392, 1e-15);
}
