// What every solver shares: progress reporting with abort, and the statistics
// the report states.
#ifndef Radiosity_SolverTypes_h
#define Radiosity_SolverTypes_h

#include "Radiosity/Common/ConvergenceHistory.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

namespace radiosity
{
struct ProgressStatus
{
  std::string Phase;
  long long Iteration = 0;
  double Residual = 0.0; ///< relative unshot power
  double Fraction = 0.0; ///< 0..1, an estimate
};

/// Called from the solver's thread; return false to abort.
using ProgressCallback = std::function<bool(const ProgressStatus&)>;

/// Reports a phase and residual to `progress` (when set), the fraction done
/// estimated on a log scale from 1 down to `tolerance`; false means abort.
inline bool ReportProgress(const ProgressCallback& progress, const char* phase,
  long long iteration, double residual, double tolerance)
{
  if (!progress)
  {
    return true;
  }
  ProgressStatus status;
  status.Phase = phase;
  status.Iteration = iteration;
  status.Residual = residual;
  // The fraction of the way from residual 1 to the tolerance on a log scale;
  // a tolerance of 1 (or a non-finite residual) has no way to go: 0 or 1, never 0/0.
  const double logTolerance = tolerance > 0 && tolerance < 1 ? std::log(tolerance) : 0.0;
  const double done = logTolerance < 0 ? std::log(std::max(residual, 1e-300)) / logTolerance
                                       : (residual <= tolerance ? 1.0 : 0.0);
  status.Fraction = !(done > 0) ? 0.0 : (done > 1 ? 1.0 : done);
  return progress(status);
}

enum class StopReason
{
  Converged,
  IterationLimit,
  TimeLimit,
  Aborted,
  NoEmitters,
  /// The iteration's residual grew where the physics makes it shrink (a
  /// reflectance below 1 makes every bounce carry less power than the one
  /// before): the answer would be a plausible wrong one, so the solve stops
  /// and says so (SolverStatistics::StopDetail) instead of "converged".
  Diverged
};

inline const char* ToString(StopReason r)
{
  switch (r)
  {
    case StopReason::Converged:
      return "converged";
    case StopReason::IterationLimit:
      return "iteration limit";
    case StopReason::TimeLimit:
      return "time limit";
    case StopReason::Aborted:
      return "aborted";
    case StopReason::NoEmitters:
      return "no emitters";
    case StopReason::Diverged:
      return "diverged";
  }
  return "unknown";
}

/// The iteration and time limits every iterative solver checks: true, with
/// `stop` set, when one is reached (a zero time limit means none).
inline bool ReachedLimit(
  long long iteration, long long maxIterations, double elapsed, double maxSeconds, StopReason& stop)
{
  if (iteration >= maxIterations)
  {
    stop = StopReason::IterationLimit;
    return true;
  }
  if (maxSeconds > 0 && elapsed >= maxSeconds)
  {
    stop = StopReason::TimeLimit;
    return true;
  }
  return false;
}

struct SolverStatistics
{
  StopReason Stop = StopReason::Converged;
  std::string StopDetail; ///< for Diverged: what grew, from what to what, at which iteration
  long long Iterations = 0;
  std::size_t Elements = 0;      ///< leaf elements at the end
  std::size_t Subdivisions = 0;
  std::size_t RaysCast = 0;
  std::size_t AnalyticFormFactors = 0;
  std::size_t DiscFormFactors = 0;
  std::size_t PairsFacingAway = 0;   ///< element pairs skipped: no transfer possible
  std::size_t PairsUnoccludable = 0; ///< visible pairs that needed no ray
  std::size_t Occluders = 0;         ///< input triangles that can block a transfer
  std::size_t Links = 0;             ///< hierarchical: node-to-node transfers
  std::size_t ClusterLinks = 0;      ///< hierarchical: links with a cluster at one end (part of Links)
  std::size_t PartialLinks = 0;      ///< hierarchical: links with recorded blockers
  std::size_t HiddenLinks = 0;       ///< hierarchical: links found fully occluded
  /// hierarchical: links with more candidate blockers than MaxBlockersPerLink
  /// that kept only those the rays between the nodes meet (visibility there
  /// is approximate; reported as a warning)
  std::size_t LinksWithBlockersCut = 0;
  double EmittedPowerW = 0.0; ///< emitting triangles' power plus LightPowerW
  /// Power the punctual lights and the sky deliver to the surfaces (SPEC
  /// "Lights and sky"); part of EmittedPowerW, the energy balance's input.
  double LightPowerW = 0.0;
  double UnshotPowerW = 0.0;
  double AbsorbedPowerW = 0.0;
  double EscapedPowerW = 0.0;
  std::size_t ErrorProbesTracked = 0; ///< reference probes found on a surface
  double PreprocessSeconds = 0.0;
  double SolveSeconds = 0.0;
  ConvergenceHistory History;
};
} // namespace radiosity

#endif
