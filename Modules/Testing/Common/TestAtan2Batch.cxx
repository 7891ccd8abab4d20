// Atan2Batch against libm's atan2, including the quadrant boundaries and the
// odd tail of a batch (issue 21: the contour sums of the discontinuity
// mesher's samples take their angles in batches).
#include "Radiosity/Common/Atan2Batch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace radiosity;

TEST(Atan2Batch, EqualsLibmToTwoUlps)
{
  std::vector<double> y, x;
  // The axes and the diagonals, signed zeros included (Lambert's formula
  // passes sin >= 0 and a cosine of either sign).
  const double special[] = { 0.0, -0.0, 1.0, -1.0, 1e-300, -1e-300, 1e300, -1e300 };
  for (double a : special)
  {
    for (double b : special)
    {
      y.push_back(a);
      x.push_back(b);
    }
  }
  std::mt19937_64 random(21);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> exponent(-200.0, 200.0);
  for (int k = 0; k < 100001; ++k) // odd: the last one takes the scalar path
  {
    y.push_back(unit(random) * std::pow(10.0, exponent(random) * (k % 3 == 0)));
    x.push_back(unit(random) * std::pow(10.0, exponent(random) * (k % 5 == 0)));
  }
  std::vector<double> out(y.size());
  Atan2Batch(y.data(), x.data(), out.data(), y.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < y.size(); ++k)
  {
    const double expected = std::atan2(y[k], x[k]);
    ASSERT_FALSE(std::isnan(out[k])) << y[k] << ", " << x[k];
    if (expected == 0.0)
    {
      EXPECT_EQ(out[k], 0.0) << y[k] << ", " << x[k];
      EXPECT_EQ(std::signbit(out[k]), std::signbit(expected)) << y[k] << ", " << x[k];
      continue;
    }
    worst = std::max(worst, std::fabs(out[k] - expected) / std::fabs(expected));
  }
  // Measured: 2.2e-16 (one ulp); the bound is two.
  EXPECT_LE(worst, 4.5e-16);
  // In place, as the contour sums call it.
  std::vector<double> inPlace = y;
  Atan2Batch(inPlace.data(), x.data(), inPlace.data(), inPlace.size());
  EXPECT_EQ(inPlace, out);
}
