// The project's error metric (ErrorMetrics.h) on hand-made cases whose
// figures are worked out here: every probe counts, a NaN is an infinite
// error, an umbra is measured against the peak, sizes must agree.
#include "Radiosity/Common/ErrorMetrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

using namespace radiosity;

TEST(ErrorMetrics, ExactValuesHaveNoError)
{
  const std::vector<RGB> reference = { RGB(1.0), RGB(2.0, 3.0, 4.0), RGB(0.0) };
  const ErrorFigures f = RelativeErrors(reference, reference);
  EXPECT_EQ(f.Counted, 3u);
  EXPECT_EQ(f.NotFinite, 0u);
  EXPECT_EQ(f.Rms, 0.0);
  EXPECT_EQ(f.Max, 0.0);
  EXPECT_EQ(f.RmsRelative, 0.0); // the umbra (0 against 0) included
  EXPECT_EQ(f.MaxRelative, 0.0);
}

TEST(ErrorMetrics, AnUmbraIsMeasuredAgainstThePeak)
{
  // Peak 10; the umbra receives 0.1 = 0.01 of the peak; the lit probes are exact.
  const std::vector<RGB> reference = { RGB(10.0), RGB(5.0), RGB(0.0), RGB(10.0) };
  const std::vector<RGB> values = { RGB(10.0), RGB(5.0), RGB(0.1), RGB(10.0) };
  const ErrorFigures f = RelativeErrors(values, reference);
  EXPECT_EQ(f.Counted, 4u);
  EXPECT_NEAR(f.Peak, 10.0, 1e-12);
  EXPECT_NEAR(f.Max, 0.01, 1e-14);
  EXPECT_NEAR(f.Rms, 0.005, 1e-14); // sqrt(0.01^2 / 4)
  // Relative to its own reference 0, the umbra's error is infinite.
  EXPECT_EQ(f.MaxRelative, std::numeric_limits<double>::infinity());
  EXPECT_EQ(f.RmsRelative, std::numeric_limits<double>::infinity());
}

TEST(ErrorMetrics, BothFiguresOnLitProbes)
{
  // Errors 1 (of 10), -1 (of 5), 0.5 (of 2): peak-relative 0.1, 0.1, 0.05;
  // per-probe relative 0.1, 0.2, 0.25.
  const std::vector<RGB> reference = { RGB(10.0), RGB(5.0), RGB(2.0) };
  const std::vector<RGB> values = { RGB(11.0), RGB(4.0), RGB(2.5) };
  const ErrorFigures f = RelativeErrors(values, reference);
  EXPECT_EQ(f.Counted, 3u);
  EXPECT_NEAR(f.Max, 0.1, 1e-12);
  EXPECT_NEAR(f.Rms, std::sqrt((0.01 + 0.01 + 0.0025) / 3.0), 1e-12);
  EXPECT_NEAR(f.MaxRelative, 0.25, 1e-12);
  EXPECT_NEAR(f.RmsRelative, std::sqrt((0.01 + 0.04 + 0.0625) / 3.0), 1e-12);
}

TEST(ErrorMetrics, ErrorIsInLuminance)
{
  // A value of the right luminance in another colour is no error; a grey
  // reference of luminance 1 against 1.2 in green alone is 0.2 * 0.7152.
  const std::vector<RGB> reference = { RGB(1.0) };
  const ErrorFigures f = RelativeErrors({ RGB(1.0, 1.2, 1.0) }, reference);
  EXPECT_NEAR(f.Max, 0.2 * 0.7152, 1e-4);
}

TEST(ErrorMetrics, ANaNIsAnInfiniteErrorAndCounted)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<RGB> reference = { RGB(1.0), RGB(2.0), RGB(3.0) };
  // Against exact values elsewhere: skipping the NaN would give 0.
  const ErrorFigures f = RelativeErrors({ RGB(1.0), RGB(nan, 2.0, 2.0), RGB(3.0) }, reference);
  EXPECT_EQ(f.Counted, 3u);
  EXPECT_EQ(f.NotFinite, 1u);
  EXPECT_EQ(f.Rms, std::numeric_limits<double>::infinity());
  EXPECT_EQ(f.Max, std::numeric_limits<double>::infinity());
  EXPECT_EQ(f.RmsRelative, std::numeric_limits<double>::infinity());
  EXPECT_EQ(f.MaxRelative, std::numeric_limits<double>::infinity());
  // An infinite value as well, and at an umbra.
  const ErrorFigures g = RelativeErrors(
    { RGB(std::numeric_limits<double>::infinity()), RGB(nan) }, { RGB(1.0), RGB(0.0) });
  EXPECT_EQ(g.NotFinite, 2u);
  EXPECT_EQ(g.Max, std::numeric_limits<double>::infinity());
}

TEST(ErrorMetrics, SizesMustAgree)
{
  EXPECT_THROW(RelativeErrors({ RGB(1.0) }, { RGB(1.0), RGB(2.0) }), std::invalid_argument);
  EXPECT_THROW(RelativeErrors({ RGB(1.0), RGB(2.0) }, {}), std::invalid_argument);
  // A reference that is not finite is no reference.
  EXPECT_THROW(RelativeErrors({ RGB(1.0) }, { RGB(std::numeric_limits<double>::quiet_NaN()) }),
    std::invalid_argument);
  // No probes: nothing counted, no figure.
  const ErrorFigures none = RelativeErrors({}, {});
  EXPECT_EQ(none.Counted, 0u);
  EXPECT_TRUE(std::isnan(none.Rms));
  EXPECT_TRUE(std::isnan(none.Max));
}

TEST(ErrorMetrics, ABlackReferenceAcceptsOnlyBlack)
{
  // Peak 0 (a scene without light): exact black is no error, any light infinite.
  EXPECT_EQ(RelativeErrors({ RGB(0.0), RGB(0.0) }, { RGB(0.0), RGB(0.0) }).Max, 0.0);
  EXPECT_EQ(RelativeErrors({ RGB(0.0), RGB(1e-9) }, { RGB(0.0), RGB(0.0) }).Max,
    std::numeric_limits<double>::infinity());
}
