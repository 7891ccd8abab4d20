// Relighting (Lehtinen et al. 2007, section 6.5): the precomputed transfer's
// time and memory, and the time of a relight (the new direct light, then
// the transfer) while a light moves, on the Cornell box, the office and,
// with --bunny, the 1.5M-triangle bunny room; each scene's last relight
// against a fresh solve of the same lighting. Writes <dir>/relight.md.
// --facecluster: face cluster radiosity's relights over its kept transfer
// couplings instead, on the Cornell box and the office
// (<dir>/relight-facecluster.md).
//   bench_relight <dir> [--quick] [--bunny index.js [--bunny-only]] [--facecluster]
#include "BenchArguments.h"

#include "Radiosity/Common/ErrorMetrics.h"
#include "Radiosity/Common/Stopwatch.h"
#include "Radiosity/Common/SystemInfo.h"
#include "Radiosity/FaceCluster/FaceClusterMethod.h"
#include "Radiosity/Meshless/MeshlessMethod.h"
#include "Radiosity/Scenes/BunnyScene.h"
#include "Radiosity/Scenes/OfficeScene.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace radiosity;

namespace
{
/// The scene's lighting at step k of the light's path.
using LightPath = std::function<Scene(const Scene& base, int step)>;

/// A point light circling in the upper middle of the scene's box, its
/// colour turning; the scene's own emitters and lights kept.
Scene CirclingBulb(const Scene& base, int step, double intensity)
{
  Scene lit = base;
  Vec3 low, high;
  base.BoundingBox(low, high);
  const double angle = 0.7 * step;
  Light bulb;
  bulb.Position = low + (high - low) * Vec3(0.5 + 0.25 * std::cos(angle), 0.5 + 0.25 * std::sin(angle), 0.7);
  bulb.Intensity = intensity * RGB(1.0, 0.8 + 0.2 * std::cos(angle), 0.6 + 0.4 * std::sin(angle));
  lit.Lighting.Lights.push_back(bulb);
  return lit;
}

/// Sensors at the triangles' centroids, at most about 20,000 of them.
std::vector<Probe> CentroidSensors(const Scene& scene)
{
  std::vector<Probe> probes;
  const std::size_t stride = std::max<std::size_t>(1, scene.Triangles.size() / 20000);
  for (std::size_t tri = 0; tri < scene.Triangles.size(); tri += stride)
  {
    probes.push_back({ scene.Centroid(tri), scene.Normal(tri) });
  }
  return probes;
}

std::string Row(const std::string& name, const Scene& scene, const LightPath& path, int relights,
  double gatherSeconds = 0.0)
{
  MeshlessOptions options;
  options.RelightGatherSeconds = gatherSeconds;
  auto first = std::make_shared<const Scene>(path(scene, 0));
  MeshlessMethod method(first, options);
  const Stopwatch solveClock;
  method.Solve({});
  const double solveSeconds = solveClock.Seconds();
  const Stopwatch precomputeClock;
  method.PrecomputeRelighting({});
  const double precomputeSeconds = precomputeClock.Seconds();
  const MeshlessStatistics& t = method.GetInstance().Statistics();
  std::vector<double> total, direct, transfer;
  std::shared_ptr<const Scene> lit;
  int bounces = 0;
  const std::size_t precomputedReceivers = t.TransferReceivers;
  std::size_t added = 0, deferred = 0;
  double addMs = 0.0;
  for (int k = 1; k <= relights; ++k)
  {
    lit = std::make_shared<const Scene>(path(scene, k));
    const Stopwatch clock;
    method.Relight(lit, {});
    total.push_back(clock.Seconds() * 1e3);
    direct.push_back(t.RelightDirectSeconds * 1e3);
    transfer.push_back(t.RelightIndirectSeconds * 1e3);
    bounces = t.RelightBounces;
    added += t.RelightRowsAdded;
    addMs += t.RelightRowsAddedSeconds * 1e3;
    deferred = t.RelightRowsDeferred;
    std::cout << name << ": relight " << k << " " << total.back() << " ms (direct " << direct.back()
              << ", transfer " << transfer.back() << ", " << t.RelightRowsAdded << " receivers added, "
              << t.RelightRowsDeferred << " deferred)\n";
  }
  const auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  // The last relight against a fresh solve of its lighting, at the centroids.
  const std::vector<Probe> probes = CentroidSensors(scene);
  const std::vector<RGB> relit = method.EvaluateProbes(probes);
  MeshlessMethod fresh(lit, options);
  const Stopwatch freshClock;
  fresh.Solve({});
  const double freshSeconds = freshClock.Seconds();
  const ErrorFigures e = RelativeErrors(relit, fresh.EvaluateProbes(probes));
  char row[512];
  std::snprintf(row, sizeof row,
    "| %s | %zu | %zu | %.1f | %.1f | %zu | %zu (%.0f ms) | %zu | %zu | %.1f MB | %.1f | %.1f | %.1f | %d | %.2g / %.2g | %.1f | %.0f MB |\n",
    name.c_str(), scene.Triangles.size(), t.SamplesGenerated, solveSeconds, precomputeSeconds, precomputedReceivers,
    added, addMs, deferred, t.TransferEntries, static_cast<double>(t.TransferBytes) / 1048576.0, median(total), median(direct),
    median(transfer), bounces, e.Max, e.Rms, freshSeconds, static_cast<double>(PeakMemoryBytes()) / 1048576.0);
  std::cout << row;
  return row;
}

/// Face cluster radiosity: a solve keeping its transfer couplings, then
/// `relights` steps of the path, then the last lighting once more.
std::string FaceClusterRow(const std::string& name, const Scene& scene, const LightPath& path, int relights)
{
  FaceClusterSettings settings;
  settings.KeepTransfers = true;
  auto first = std::make_shared<const Scene>(path(scene, 0));
  FaceClusterMethod method(first, settings);
  const Stopwatch solveClock;
  method.Solve({});
  const double solveSeconds = solveClock.Seconds();
  const FaceClusterStatistics& t = method.GetInstance().Statistics();
  const std::size_t keptAfterSolve = t.KeptCouplings;

  std::vector<double> total, fresh;
  double firstMs = 0.0;
  std::shared_ptr<const Scene> lit;
  std::size_t reused = 0, computed = 0;
  for (int k = 1; k <= relights; ++k)
  {
    lit = std::make_shared<const Scene>(path(scene, k));
    const Stopwatch clock;
    method.Relight(lit, {});
    total.push_back(clock.Seconds() * 1e3);
    firstMs = k == 1 ? total.back() : firstMs;
    reused += t.CouplingsReused;
    computed += t.CouplingsComputed;
    // A fresh solve of the same lighting, for the time a relight saves.
    FaceClusterMethod alone(lit, FaceClusterSettings());
    const Stopwatch aloneClock;
    alone.Solve({});
    fresh.push_back(aloneClock.Seconds() * 1e3);
    std::cout << name << ": relight " << k << " " << total.back() << " ms (" << t.CouplingsReused << " reused, "
              << t.CouplingsComputed << " computed), a fresh solve " << fresh.back() << " ms\n";
  }
  const Stopwatch againClock;
  method.Relight(lit, {});
  const double againMs = againClock.Seconds() * 1e3;
  std::sort(total.begin(), total.end());
  std::sort(fresh.begin(), fresh.end());
  const std::vector<RGB> relit = method.EvaluateProbes(CentroidSensors(scene));
  FaceClusterMethod last(lit, FaceClusterSettings());
  last.Solve({});
  const ErrorFigures e = RelativeErrors(relit, last.EvaluateProbes(CentroidSensors(scene)));
  char row[512];
  std::snprintf(row, sizeof row,
    "| %s | %zu | %.1f | %zu | %.1f MB | %.0f | %.0f | %.0f | %.0f%% | %.0f | %.2g / %.2g | %.0f | %.0f MB |\n",
    name.c_str(), scene.Triangles.size(), solveSeconds, keptAfterSolve,
    static_cast<double>(t.KeptBytes) / 1048576.0, firstMs, total[total.size() / 2], total.back(),
    100.0 * static_cast<double>(reused) / std::max<double>(1.0, static_cast<double>(reused + computed)), againMs, e.Max,
    e.Rms, fresh[fresh.size() / 2], static_cast<double>(PeakMemoryBytes()) / 1048576.0);
  std::cout << row;
  return row;
}

std::string FaceClusterTable(int relights, const std::string& bunnyJs)
{
  std::ostringstream md;
  md << "Face cluster radiosity at default settings, keeping its transfers' couplings (KeepTransfers: what a "
        "transfer owes to its two elements, not to the light; FaceClusterRelight.cxx), then "
     << relights
     << " relights while a point light circles in the upper middle of the scene, its colour turning (the "
        "office keeps its spot and sky, the Cornell box its lamp), then the last lighting once more. A "
        "relight is a solve of the new lighting whose transfers come from the kept couplings where a solve "
        "made the same pair before: the oracle, the lights at the nodes (the sky from kept masks) and the "
        "push-pull run, and only pairs no solve made are computed (and kept). Kept: the couplings and sky "
        "masks after the relights. Times: the first relight, the median and the slowest; reused: the share "
        "of the relights' transfers from kept couplings; again: the last lighting relit once more. Error: "
        "the last relight against a fresh solve of its lighting at the triangles' centroids (at most 20,000; "
        "max / RMS of the peak); fresh solve: the median time of a solve (not keeping) of each relight's lighting.\n\n"
        "| scene | triangles | solve s (keeping) | couplings kept by the solve | kept after the relights | "
        "first relight ms | median relight ms | slowest ms | reused | again ms | vs fresh solve | fresh solve ms "
        "| peak memory |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  md << FaceClusterRow("Cornell box", MakeCornellBox(),
    [](const Scene& s, int k) { return k == 0 ? s : CirclingBulb(s, k, 2.0); }, relights);
  md << FaceClusterRow("office", MakeOfficeScene(),
    [](const Scene& s, int k) { return k == 0 ? s : CirclingBulb(s, k, 100.0); }, relights);
  if (!bunnyJs.empty())
  {
    md << FaceClusterRow("bunny room", MakeBunnyRoomWithTriangles(ReadNpmBunny(bunnyJs), 1500000),
      [](const Scene& s, int k) { return k == 0 ? s : CirclingBulb(s, k, 2.0); }, relights);
  }
  return md.str();
}
}

int main(int argc, char* argv[])
{
  BenchArguments args;
  if (!args.Parse(argc, argv))
  {
    return 2;
  }
  const int relights = args.Quick ? 3 : 7;
  std::ostringstream md;
  for (int i = 2; i < argc; ++i)
  {
    if (std::string(argv[i]) == "--facecluster")
    {
      args.WriteHeading(md, "Face cluster relighting");
      md << FaceClusterTable(relights, args.BunnyJs);
      const std::string path = args.Directory + "/relight-facecluster.md";
      std::ofstream(path) << md.str();
      std::cout << md.str() << "written to " << path << "\n";
      return 0;
    }
  }
  args.WriteHeading(md, "Relighting (Lehtinen et al. 2007, section 6.5)");
  md << "Meshless radiosity at default settings: solve, precompute the transfer (the one-bounce operator "
        "on the receivers the solve gathered to and the two coarsest levels, MeshlessTransfer.h), then "
     << relights
     << " relights while a point light circles in the upper middle of the scene, its colour turning (the "
        "office keeps its spot and sky, the Cornell box its lamp). A relight is the new direct light (exact "
        "lights and emitters at the basis points, the receiver oracle, the fit) and the transfer's series. "
        "Times are medians; error: the last relight against a fresh solve of its lighting at the triangles' "
        "centroids (max / RMS of the peak). Receivers: the precomputed rows, then those the relights' "
        "lightings wanted beyond them, gathered when first asked for (their time, in all, is part of the "
        "transfer's); `20 ms of gathers`: at most that per relight (RelightGatherSeconds), the rest deferred to "
        "the next relights (deferred: those the last relight left). Entries and transfer memory: after the "
        "relights. Peak memory is the process's so far.\n\n"
        "| scene | triangles | points | solve s | precompute s | receivers | added (time) | deferred | entries | "
        "transfer | relight ms | direct ms | transfer ms | bounces | vs fresh solve | fresh solve s | peak memory |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  // --bunny-only: the bunny room's row alone (the others take minutes).
  const bool bunnyOnly = !args.BunnyJs.empty() && std::string(argv[argc - 1]) == "--bunny-only";
  if (!bunnyOnly)
  {
    for (double gather : { 0.0, 0.02 })
    {
      md << Row(gather > 0.0 ? "Cornell box, 20 ms of gathers" : "Cornell box", MakeCornellBox(),
        [](const Scene& s, int k) { return k == 0 ? s : CirclingBulb(s, k, 2.0); }, relights, gather);
    }
  }
  if (!args.Quick)
  {
    if (!bunnyOnly)
    {
      for (double gather : { 0.0, 0.02 })
      {
        md << Row(gather > 0.0 ? "office, 20 ms of gathers" : "office", MakeOfficeScene(),
          [](const Scene& s, int k) { return k == 0 ? s : CirclingBulb(s, k, 100.0); }, relights, gather);
      }
    }
    if (!args.BunnyJs.empty())
    {
      md << Row("bunny room", MakeBunnyRoomWithTriangles(ReadNpmBunny(args.BunnyJs), 1500000),
        [](const Scene& s, int k) { return k == 0 ? s : CirclingBulb(s, k, 2.0); }, relights);
    }
  }
  const std::string path = args.Directory + (bunnyOnly ? "/relight-bunny.md" : "/relight.md");
  std::ofstream(path) << md.str();
  std::cout << md.str() << "written to " << path << "\n";
  return 0;
}
