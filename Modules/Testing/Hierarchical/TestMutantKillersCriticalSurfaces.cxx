// Tests added for the survivors of the mutation check (Testing/Mutation,
// issue 16): the Hardt-Teller weight of VE critical surfaces.
#include "Radiosity/Hierarchical/CriticalSurfaces.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace radiosity;

// Mutant "the weight from the weaker of the two pairs" (max -> min over the
// blocker edge's two ends) survived: CriticalSurfaces.WeightIsTheDistanceRatio
// counts strong and weak segments together with the EV ones, and the EV
// surfaces of the lower vertex carry the strong weight too. With the EV
// surfaces off (sourceEdges all false) only VE surfaces remain, and each must
// carry d_sb / d_br of the edge's end nearer to the floor: light at z = 1,
// that end at z = 0.3, 0.7 / 0.3 by similar triangles (the upper end's
// 0.1 / 0.9 is what the mutant gives).
TEST(MutantKillersCriticalSurfaces, VeWeightIsTheStrongerEndsDistanceRatio)
{
  const std::array<Vec3, 3> floor = { Vec3(-20, -10, 0), Vec3(20, -10, 0), Vec3(0, 30, 0) };
  const std::array<Vec3, 3> light = { Vec3(0, 0, 1), Vec3(0, 1, 1), Vec3(1, 1, 1) }; // facing down
  const std::vector<BlockerEdge> tilted = { { Vec3(0.5, 0.5, 0.9), Vec3(0.6, 0.4, 0.3) } };
  std::vector<DiscontinuitySegment> out;
  FindCriticalSegments(floor, Vec3(0, 0, 1), light, 1.0, tilted, 0.0, out, { false, false, false });
  // One VE surface per light vertex, each reaching the floor.
  ASSERT_EQ(out.size(), 3u);
  for (const auto& s : out)
  {
    // Measured -4.4e-16 (one ulp of 2.33) on all three; the bound, about four
    // ulps, leaves room for another compiler's roundings; the mutant is 2.2
    // below.
    EXPECT_NEAR(s.Weight, 0.7 / 0.3, 2e-15) << s.Weight;
  }
}
