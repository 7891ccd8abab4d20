// MeshlessRadiosity's relighting (Lehtinen et al. 2007, section 6.5): the
// transfer precomputed after a solve, and the relight that applies it to a
// new direct light. The operator itself is MeshlessTransfer.
#include "Radiosity/Meshless/MeshlessRadiosity.h"

#include "Radiosity/Common/DirectLighting.h"
#include "Radiosity/Common/MemoryBudget.h"
#include "Radiosity/Common/Stopwatch.h"
#include "Radiosity/Common/ThreadLimit.h"
#include "Radiosity/Common/Visibility.h"
#include "Radiosity/Meshless/MeshlessNeighbourhoods.h"
#include "Radiosity/Meshless/MeshlessTransfer.h"

#include <tbb/parallel_for.h>

#include <limits>

namespace radiosity
{
bool MeshlessRadiosity::PrecomputeTransfer(const ProgressCallback& progress)
{
  if (!this->HasField())
  {
    throw SceneError("meshless relighting: there is no field to precompute the transfer on (the scene was "
                     "not lit, or the solve was aborted before the points were placed)");
  }
  const Stopwatch clock;
  return RunWithThreads(this->Settings.Threads, [&]() -> bool {
    const PointHierarchy& points = *this->Hierarchy;
    // The receivers: every function the solve gathered to (where its
    // oracle found detail, in the direct light or a bounce), and the two
    // coarsest levels whole, so that light moved elsewhere still finds
    // receivers of the indirect light's scale.
    std::vector<std::uint32_t> receivers;
    const std::size_t coarse = points.NumberOfLevels() > 1 ? points.LevelEnd(1) : points.Points().size();
    for (std::uint32_t j = 0; j < points.Points().size(); ++j)
    {
      if (j < coarse || (j < this->Touched.size() && this->Touched[j]))
      {
        receivers.push_back(j);
      }
    }
    try
    {
      this->Lists = std::make_unique<MeshlessNeighbourhoods>(points,
        [&]() { return ReportProgress(progress, "precomputing the transfer", 0, 1.0, this->Settings.Tolerance); });
      this->Transfer = std::make_unique<MeshlessTransfer>(*this->SourceScene, points, *this->Rays, *this->Lists,
        this->Settings,
        std::move(receivers),
        [&]() { return ReportProgress(progress, "precomputing the transfer", 0, 1.0, this->Settings.Tolerance); },
        ResolveMemoryBudget(this->Settings.MemoryBudgetBytes));
    }
    catch (const PlacementAborted&)
    {
      this->Transfer.reset();
      this->Lists.reset();
      return false;
    }
    // The sky's visibility at every point, cast once: relights then replay
    // the quadrature without rays. Kept even without a sky now (a relight
    // may add one; cast then, once per point).
    {
      const Scene& scene = *this->SourceScene;
      if (!this->Lights)
      {
        this->Lights = std::make_unique<DirectLighting>(scene, this->Settings.SkySamples, this->Rays.get());
      }
      this->SkyMaskWords = this->Lights->SkyMaskWords();
      this->SkyMask.assign(this->SkyMaskWords * points.Points().size(), 0);
      this->SkyKnown.assign(points.Points().size(), 0);
      this->SkyMoment.assign(points.Points().size(), DirectLighting::SkyMoments());
      this->SkyMomentsKnown.assign(points.Points().size(), 0);
      this->SkyMomentUp = scene.Lighting.SkyLight.Up;
      if (this->Lights->HasSky())
      {
        // At every point, not only those the solve's direct light was
        // computed at: a moved light's oracle picks new ones, and their
        // 1024 sky rays each were most of the office's first relights (its
        // direct light 23 to 48 ms, 7 ms with every mask cast; the
        // precomputation 0.6 s longer, of 21 s).
        tbb::parallel_for(std::size_t(0), points.Points().size(),
          [&](std::size_t j) { this->CachedSky(static_cast<std::uint32_t>(j)); });
      }
      if (scene.Lighting.Empty())
      {
        this->Lights.reset(); // the solve's state: no lights
      }
    }
    this->Stats.TransferReceivers = this->Transfer->Receivers();
    this->Stats.TransferEntries = this->Transfer->Entries();
    this->Stats.TransferBytes = this->Transfer->MemoryBytes() + this->Lists->MemoryBytes() +
      this->SkyMask.size() * sizeof(std::uint64_t);
    this->Stats.TransferSeconds = clock.Seconds();
    return true;
  });
}

SolverStatistics MeshlessRadiosity::Relight(const Scene& lit, const ProgressCallback& progress)
{
  if (!this->Transfer)
  {
    throw SceneError("meshless relighting: no transfer was precomputed (PrecomputeTransfer after Solve)");
  }
  std::string why;
  if (!SameSurfaces(*this->SourceScene, lit, &why))
  {
    throw SceneError("meshless relighting: " + why + "; the precomputed transfer no longer applies: solve again");
  }
  const Stopwatch clock;
  return RunWithThreads(this->Settings.Threads, [&]() -> SolverStatistics {
    SolverStatistics stats;
    this->SourceScene = &lit;
    // The caller may release the scene the transfer was built on (the
    // filter does, each request its own scene): its gathers read this one.
    this->Transfer->SetScene(lit);
    this->FindEmitters();
    this->Lights.reset();
    if (!lit.Lighting.Empty())
    {
      // The solve's rays over every triangle serve the shadow rays too.
      this->Lights = std::make_unique<DirectLighting>(lit, this->Settings.SkySamples, this->Rays.get());
    }
    if (lit.Lighting.SkyLight.Up != this->SkyMomentUp)
    {
      // Another Up: another horizon, the moments taken anew from the masks.
      std::fill(this->SkyMomentsKnown.begin(), this->SkyMomentsKnown.end(), 0);
      this->SkyMomentUp = lit.Lighting.SkyLight.Up;
    }
    stats.EmittedPowerW = lit.EmittedPower();
    const PointHierarchy& points = *this->Hierarchy;
    if (!lit.IsLit())
    {
      // No light: the zero solution (not the last one).
      std::fill(this->Solution->Coefficients().begin(), this->Solution->Coefficients().end(), RGB(0.0));
      this->Direct->Coefficients() = this->Solution->Coefficients();
      this->LightFit.reset();
      stats.Stop = StopReason::NoEmitters;
      return stats;
    }
    if (!ReportProgress(progress, "direct light", 0, 1.0, this->Settings.Tolerance))
    {
      stats.Stop = StopReason::Aborted;
      return stats;
    }
    this->ComputeDirect();
    double area = 0.0;
    for (std::size_t t = 0; t < lit.Triangles.size(); ++t)
    {
      area += lit.Area(t);
    }
    const double perPoint = area / static_cast<double>(points.LevelEnd(0));
    if (this->Lights)
    {
      stats.LightPowerW = this->CoarseLightIrradiance() * perPoint;
      stats.EmittedPowerW += stats.LightPowerW;
    }
    this->Stats.RelightDirectSeconds = clock.Seconds();
    if (!ReportProgress(progress, "relighting", 0, 1.0, this->Settings.Tolerance))
    {
      stats.Stop = StopReason::Aborted;
      return stats;
    }
    const MeshlessTransfer::Series series =
      this->Transfer->Indirect(this->Direct->Coefficients(), this->Settings.Tolerance, this->Settings.MaxBounces,
        this->Settings.VariationThreshold * this->Scale, this->Settings.RelightGatherSeconds);
    std::vector<RGB>& b = this->Solution->Coefficients();
    for (std::size_t j = 0; j < b.size(); ++j)
    {
      b[j] += series.Indirect[j];
    }
    this->Stats.RelightIndirectSeconds = clock.Seconds() - this->Stats.RelightDirectSeconds;
    this->Stats.RelightBounces = series.Bounces;
    this->Stats.RelightRowsAdded = series.RowsAdded;
    this->Stats.RelightRowsAddedSeconds = series.RowsAddedSeconds;
    this->Stats.RelightRowsDeferred = series.RowsDeferred;
    if (series.RowsAdded > 0)
    {
      // The transfer grew: its figures as they are now.
      this->Stats.TransferReceivers = this->Transfer->Receivers();
      this->Stats.TransferEntries = this->Transfer->Entries();
      this->Stats.TransferBytes = this->Transfer->MemoryBytes() + this->Lists->MemoryBytes() +
        this->SkyMask.size() * sizeof(std::uint64_t);
    }
    // The history: the direct light, then each bounce's magnitude.
    for (std::size_t k = 0; k < series.Magnitudes.size(); ++k)
    {
      ConvergenceRow r;
      r.Iteration = static_cast<long long>(k);
      r.TimeSeconds = clock.Seconds();
      r.UnshotPowerW = series.Magnitudes[k] * perPoint;
      r.EnergyBalance = std::numeric_limits<double>::quiet_NaN();
      stats.History.Rows.push_back(r);
    }
    stats.Iterations = series.Bounces;
    stats.Stop = series.Converged ? StopReason::Converged : StopReason::IterationLimit;
    stats.Elements = points.Points().size();
    stats.RaysCast = this->Rays->RaysCast() + this->Shadows->RaysCast();
    stats.SolveSeconds = clock.Seconds();
    return stats;
  });
}
} // namespace radiosity
