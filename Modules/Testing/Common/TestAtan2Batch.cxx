// Atan2Batch against libm's atan2, including the quadrant boundaries and the
// odd tail of a batch (issue 21: the contour sums of the discontinuity
// mesher's samples take their angles in batches).
#include "Radiosity/Common/Atan2Batch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
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
  for (int k = 0; k < 100001; ++k)
  {
    y.push_back(unit(random) * std::pow(10.0, exponent(random) * (k % 3 == 0)));
    x.push_back(unit(random) * std::pow(10.0, exponent(random) * (k % 5 == 0)));
  }
  // Each kernel (the four-lane one where this processor has AVX2 and FMA)
  // and the dispatcher, over lengths whose tails leave 0 to 3 of a vector.
  using Kernel = void (*)(const double*, const double*, double*, std::size_t);
  std::vector<std::pair<const char*, Kernel>> kernels = { { "Atan2Batch", &Atan2Batch },
    { "two lanes", &atan2_batch_detail::Atan2BatchTwoLanes } };
  if (atan2_batch_detail::Avx2Available())
  {
    kernels.emplace_back("four lanes", &atan2_batch_detail::Atan2BatchAvx2);
  }
  for (const auto& [name, kernel] : kernels)
  {
    for (std::size_t trim = 0; trim < 4; ++trim)
    {
      const std::size_t count = y.size() - trim;
      std::vector<double> out(count);
      kernel(y.data(), x.data(), out.data(), count);
      double worst = 0.0;
      for (std::size_t k = 0; k < count; ++k)
      {
        const double expected = std::atan2(y[k], x[k]);
        ASSERT_FALSE(std::isnan(out[k])) << name << ": " << y[k] << ", " << x[k];
        if (expected == 0.0)
        {
          EXPECT_EQ(out[k], 0.0) << name << ": " << y[k] << ", " << x[k];
          EXPECT_EQ(std::signbit(out[k]), std::signbit(expected)) << name << ": " << y[k] << ", " << x[k];
          continue;
        }
        worst = std::max(worst, std::fabs(out[k] - expected) / std::fabs(expected));
      }
      // Measured: 2.2e-16 (one ulp) for each kernel; the bound is two.
      EXPECT_LE(worst, 4.5e-16) << name << ", " << count << " angles";
      // In place, as the contour sums call it.
      std::vector<double> inPlace(y.begin(), y.begin() + static_cast<std::ptrdiff_t>(count));
      kernel(inPlace.data(), x.data(), inPlace.data(), count);
      EXPECT_EQ(inPlace, out) << name << ", " << count << " angles";
    }
  }
}
