// Tests added for the survivors of the mutation check (Testing/Mutation,
// issue 16): each compares a kernel with an independent closed form where
// the existing tests left a one-token change of it unseen.
#include "Radiosity/Common/ClosedFormFactors.h"
#include "Radiosity/Common/FormFactor.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace radiosity;

// Mutant "the disc's area term dropped" (area cos cos / (pi r^2 + area) ->
// area cos cos / (pi r^2)) survived: DiscApproximationConvergesFarAway looks
// only where area << pi r^2. Coaxial and near, the disc approximation is
// exactly Howell's B-13 (pi R^2 / (pi h^2 + pi R^2) = R^2 / (R^2 + h^2)), so
// the bound is rounding; the mutant is off by a factor 1 + (R/h)^2.
TEST(MutantKillersFormFactor, DiscApproximationIsTheCoaxialDiscClosedForm)
{
  const double cases[][2] = { { 0.7, 0.3 }, { 2.0, 0.1 }, { 0.05, 1.0 } };
  for (const auto& c : cases)
  {
    const double r = c[0], h = c[1];
    const double disc =
      DiscFormFactor(Vec3(0.0), Vec3(0, 0, 1), Vec3(0, 0, h), Vec3(0, 0, -1), Pi * r * r);
    const double exact = closedform::PointToCoaxialDisc(r, h);
    // Measured: relative differences 1.3e-16, 0 and 1.7e-16 (a few roundings);
    // the bound, 1e-15 (about 4 ulps, 6x the largest measured), leaves room for
    // another compiler's contractions; the mutant is off by factors 6.4, 401
    // and 1.002.
    EXPECT_NEAR(disc, exact, 1e-15 * exact) << "R " << r << " h " << h;
  }
}
