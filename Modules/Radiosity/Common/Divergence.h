// Convergence that tells the truth (issue 53): an iteration whose residual
// grows where the physics makes it shrink is stopped and reported as
// diverged, never as solved.
//
// Why a growing series is a bug: with every reflectance below 1, the power a
// bounce sends on is at most max(rho) times the power it received, and what
// a surface receives is at most what was sent (form factors from a patch sum
// to at most 1). So each bounce's power is below the one before; a growth
// means transfers that create energy (form factors summing above 1 between
// touching or interpenetrating parts, a quadrature off its singularity).
#ifndef Radiosity_Divergence_h
#define Radiosity_Divergence_h

#include "Radiosity/Common/SolverTypes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace radiosity
{
/// Growth by more than this factor in one bounce is divergence at once.
constexpr double DivergenceJump = 2.0;
/// Growth (by more than DivergenceSlack) this many bounces in a row is divergence.
constexpr int DivergenceRun = 3;
/// A bounce ratio up to 1 + DivergenceSlack counts as steady (the rounding of a
/// closed scene of reflectance 0.999 whose bounces decay by 1e-3).
constexpr double DivergenceSlack = 1e-3;
/// Growth below this share of the largest bounce so far is not divergence:
/// near convergence a refinement can move a bounce of 1e-5 of the first by
/// a factor 2 (the classroom's face clusters at their 17th bounce: 0.023 W
/// to 0.059 W after 2.8 kW), and that changes the answer by nothing.
constexpr double DivergenceFloor = 1e-2;

/**
 * True, with stats.Stop = Diverged and stats.StopDetail saying what grew,
 * when the series of bounce powers `powers` (W, one per iteration, the
 * latest last) is not finite, jumped by DivergenceJump in one bounce, or grew
 * DivergenceRun bounces in a row, to above DivergenceFloor of the largest
 * bounce before it. `what` names the series and the method
 * ("face cluster radiosity's bounce power").
 */
inline bool SeriesDiverges(const std::vector<double>& powers, const std::string& what, SolverStatistics& stats)
{
  const std::size_t k = powers.size();
  if (k == 0)
  {
    return false;
  }
  const auto at = [&](std::size_t i) { return std::to_string(i + 1); };
  const auto number = [](double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", v);
    return std::string(text);
  };
  std::string why;
  double largest = 0.0;
  for (std::size_t i = 0; i + 1 < k; ++i)
  {
    largest = std::max(largest, powers[i]);
  }
  const bool significant = !(powers[k - 1] <= DivergenceFloor * largest);
  if (!std::isfinite(powers[k - 1]))
  {
    why = what + " is not finite at iteration " + at(k - 1);
  }
  else if (significant && k >= 2 && powers[k - 2] > 0.0 && powers[k - 1] > DivergenceJump * powers[k - 2])
  {
    why = what + " grew from " + number(powers[k - 2]) + " W to " + number(powers[k - 1]) + " W at iteration " +
      at(k - 1);
  }
  else if (significant && k >= static_cast<std::size_t>(DivergenceRun) + 1)
  {
    bool growing = true;
    for (std::size_t i = k - DivergenceRun; i < k && growing; ++i)
    {
      growing = powers[i - 1] > 0.0 && powers[i] > (1.0 + DivergenceSlack) * powers[i - 1];
    }
    if (growing)
    {
      why = what + " grew " + std::to_string(DivergenceRun) + " iterations in a row, from " +
        number(powers[k - 1 - DivergenceRun]) + " W at iteration " + at(k - 1 - DivergenceRun) + " to " +
        number(powers[k - 1]) + " W at iteration " + at(k - 1);
    }
  }
  if (why.empty())
  {
    return false;
  }
  stats.Stop = StopReason::Diverged;
  stats.StopDetail = why + ": with every reflectance below 1 each bounce carries less power than the one "
                           "before, so the transfers create energy and the answer would be wrong";
  return true;
}
/// A residual that rose by more than this share of its scale (the emitted
/// power) above the lowest it reached is divergence.
constexpr double DivergenceRise = 0.5;

/**
 * For a residual that may rise for a while, but never by much (progressive
 * refinement's signed unshot power: each shot of u lowers it by (1 - r) u,
 * r = sum of rho F over the receivers <= max rho; it rises only where
 * overshooting's negative shots take back what was shot in advance, by at
 * most that advance): true, with stats.Stop = Diverged and stats.StopDetail,
 * when `residual` (W) is not finite or lies more than DivergenceRise x
 * `scale` (W) above `lowest`, the lowest residual so far (updated here).
 * The unsigned unshot power is no such residual: overshooting raises it
 * legitimately (a closed cube of emitting walls, reflectance 0.9: 6 W to
 * 9 W in eight shots).
 */
inline bool ResidualRoseAboveItsLowest(double residual, double& lowest, double scale, long long iteration,
  const std::string& what, SolverStatistics& stats)
{
  if (std::isfinite(residual) && !(residual > lowest + DivergenceRise * scale))
  {
    lowest = std::min(lowest, residual);
    return false;
  }
  char text[200];
  std::snprintf(text, sizeof text,
    " rose to %.4g W at iteration %lld, %.4g W above the lowest it reached (%.4g W): more than %.2g of the "
    "emitted %.4g W",
    residual, iteration, residual - lowest, lowest, DivergenceRise, scale);
  stats.Stop = StopReason::Diverged;
  stats.StopDetail = what + text + ": a shot hands on at most what it sends, so the transfers create energy and "
                                   "the answer would be wrong";
  return true;
}
} // namespace radiosity

#endif
