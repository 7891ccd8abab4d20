// The standard scenes of the benchmarks (error against run time for every
// method): the Cornell box, the scenes with exact answers, and the bunny
// room, each with its probes.
#ifndef Radiosity_StandardScenes_h
#define Radiosity_StandardScenes_h

#include "Radiosity/Reference/AnalyticReference.h"
#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Common/Scene.h"

#include <functional>
#include <string>
#include <vector>

namespace radiosity
{
struct StandardScene
{
  std::string Name;
  std::function<Scene()> Make;
  /// Sensor points; empty means a sample of triangle centroids.
  std::function<std::vector<Probe>(const Scene&)> Probes;
  bool FullOnly = false; ///< too slow for --quick
  /// Hierarchical radiosity links every pair of input triangles first: the
  /// sphere (1280 triangles, 1.6 million links) is left out of --quick, the
  /// bunny (235k triangles, 2.8e10 initial links) out of every run.
  bool HierarchicalInQuick = true;
  /// Clustered hierarchical radiosity in the full run (not on the 235k
  /// bunny: at 100k triangles one setting takes minutes).
  bool ClusteredInFull = true;
};

/// About 40 triangle centroids with their normals.
std::vector<Probe> CentroidSample(const Scene& scene);

/**
 * The reference irradiance at `probes`: the closed form where the scene has
 * one (ComputeAnalyticReference), else the path tracer (MIS, fixed seed) with
 * `pathsPerProbe` paths, its Kind then naming the paths and the largest
 * relative standard error. `analytic`, when given, tells which.
 */
AnalyticReference StandardReference(const Scene& scene, const std::vector<Probe>& probes,
  std::size_t pathsPerProbe, bool* analytic = nullptr);

/// The standard scenes; `bunnyJs` (the npm package's index.js) adds the
/// bunny room as the source has it (3,868 triangles with the room) and
/// subdivided to 235k triangles; an empty string leaves both out.
std::vector<StandardScene> StandardScenes(const std::string& bunnyJs = "");
} // namespace radiosity

#endif
