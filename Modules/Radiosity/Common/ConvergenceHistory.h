// Error against run time: one row per iteration (SPEC.md, ConvergenceHistory).
#ifndef Radiosity_ConvergenceHistory_h
#define Radiosity_ConvergenceHistory_h

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace radiosity
{
struct ConvergenceRow
{
  long long Iteration = 0;
  double TimeSeconds = 0.0;
  double UnshotPowerW = 0.0;
  double EnergyBalance = 0.0; ///< (emitted - absorbed - escaped - unshot) / emitted
  double RmsError = std::numeric_limits<double>::quiet_NaN();
  double MaxRelError = std::numeric_limits<double>::quiet_NaN();
  double OvershootPowerW = 0.0; ///< power shot in advance by the acceleration
};

struct ConvergenceHistory
{
  std::vector<ConvergenceRow> Rows;
  static std::vector<std::string> ColumnNames()
  {
    return { "iteration", "time_s", "unshot_power_W", "energy_balance", "rms_error",
      "max_rel_error", "overshoot_power_W" };
  }
};
} // namespace radiosity

#endif
