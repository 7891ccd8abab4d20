// Error of a solution against reference irradiance values at probes: the
// relative error of each probe's luminance (probes whose reference is below
// 1e-12 of the largest are left out, their relative error is undefined, and
// so are probes without a value, NaN).
#ifndef Radiosity_ErrorMetrics_h
#define Radiosity_ErrorMetrics_h

#include "Radiosity/Common/Types.h"

#include <cmath>
#include <limits>
#include <vector>

namespace radiosity
{
struct ErrorFigures
{
  double Rms = std::numeric_limits<double>::quiet_NaN();
  double Max = std::numeric_limits<double>::quiet_NaN();
  std::size_t Counted = 0;
};

inline ErrorFigures RelativeErrors(const std::vector<RGB>& values, const std::vector<RGB>& reference)
{
  ErrorFigures f;
  double largest = 0.0;
  for (const RGB& r : reference)
  {
    largest = std::max(largest, Luminance(r));
  }
  double sum = 0.0, worst = 0.0;
  for (std::size_t i = 0; i < values.size() && i < reference.size(); ++i)
  {
    const double ref = Luminance(reference[i]);
    if (!(ref > 1e-12 * largest) || !std::isfinite(Luminance(values[i])))
    {
      continue;
    }
    const double e = std::fabs(Luminance(values[i]) - ref) / ref;
    sum += e * e;
    worst = std::max(worst, e);
    ++f.Counted;
  }
  if (f.Counted > 0)
  {
    f.Rms = std::sqrt(sum / static_cast<double>(f.Counted));
    f.Max = worst;
  }
  return f;
}
} // namespace radiosity

#endif
