// The error of a solution against reference irradiance values at probes, the
// one figure the whole project reports (history rows, CLI report, benches,
// tests). Every probe counts:
// - the primary error of a probe is |value - reference| / peak in luminance,
//   where peak is the largest reference luminance of the case, so that light
//   leaking into an exact umbra (reference 0) is measured;
// - the second figure is the per-probe relative error |value - reference| /
//   reference (0 where both are 0, infinite where only the reference is 0);
// - a value that is not finite (NaN, +-inf: a probe the solver could not
//   evaluate) is an infinite error in both figures, never skipped;
// - values and reference of different sizes are an error (std::invalid_argument),
//   as is a reference that is not finite.
#ifndef Radiosity_ErrorMetrics_h
#define Radiosity_ErrorMetrics_h

#include "Radiosity/Common/Types.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace radiosity
{
struct ErrorFigures
{
  /// RMS and maximum over every probe of |v - r| / (peak reference luminance).
  double Rms = std::numeric_limits<double>::quiet_NaN();
  double Max = std::numeric_limits<double>::quiet_NaN();
  /// Probes counted: always the number of probes.
  std::size_t Counted = 0;
  /// RMS and maximum over every probe of the per-probe relative error |v - r| / r.
  double RmsRelative = std::numeric_limits<double>::quiet_NaN();
  double MaxRelative = std::numeric_limits<double>::quiet_NaN();
  /// Probes whose value is not finite (each an infinite error).
  std::size_t NotFinite = 0;
  /// The largest reference luminance (the denominator of Rms and Max).
  double Peak = std::numeric_limits<double>::quiet_NaN();
};

/// |v - r| / d with 0/0 = 0 and x/0 = +inf for x > 0; +inf when v is not finite.
inline double ErrorRatio(double v, double r, double d)
{
  if (!std::isfinite(v))
  {
    return std::numeric_limits<double>::infinity();
  }
  const double difference = std::fabs(v - r);
  if (d > 0.0)
  {
    return difference / d;
  }
  return difference == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
}

/// The error figures of `values` against `reference` (same size; no probes
/// give Counted 0 and NaN figures).
inline ErrorFigures RelativeErrors(const std::vector<RGB>& values, const std::vector<RGB>& reference)
{
  if (values.size() != reference.size())
  {
    throw std::invalid_argument("RelativeErrors: " + std::to_string(values.size()) +
      " values against " + std::to_string(reference.size()) + " reference values");
  }
  ErrorFigures f;
  f.Counted = values.size();
  if (values.empty())
  {
    return f;
  }
  double peak = 0.0;
  for (const RGB& r : reference)
  {
    const double l = Luminance(r);
    if (!std::isfinite(l))
    {
      throw std::invalid_argument("RelativeErrors: a reference value is not finite");
    }
    peak = std::max(peak, l);
  }
  f.Peak = peak;
  double sum = 0.0, worst = 0.0, sumRelative = 0.0, worstRelative = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    const double v = Luminance(values[i]);
    const double r = Luminance(reference[i]);
    f.NotFinite += std::isfinite(v) ? 0 : 1;
    const double e = ErrorRatio(v, r, peak);
    const double relative = ErrorRatio(v, r, std::fabs(r));
    sum += e * e;
    worst = std::max(worst, e);
    sumRelative += relative * relative;
    worstRelative = std::max(worstRelative, relative);
  }
  const double n = static_cast<double>(values.size());
  f.Rms = std::sqrt(sum / n);
  f.Max = worst;
  f.RmsRelative = std::sqrt(sumRelative / n);
  f.MaxRelative = worstRelative;
  return f;
}
} // namespace radiosity

#endif
