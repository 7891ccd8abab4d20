// Meshless hierarchical radiosity (Lehtinen et al. 2007, section 6.3):
// the columns of the paper's Table 1 for the Cornell box and the large bunny
// scene, and error against run time on the standard scenes (the same scenes,
// probes and references as `vtkradiosity bench`). Writes
// <dir>/meshless.md and <dir>/meshless-error-vs-time.csv.
//   bench_meshless <dir> [--quick]
#include "BenchArguments.h"

#include "Radiosity/Scenes/BunnyScene.h"
#include "Radiosity/Common/ErrorMetrics.h"
#include "Radiosity/Meshless/MeshlessRadiosity.h"
#include "Radiosity/Scenes/SceneGenerators.h"
#include "Radiosity/Scenes/StandardScenes.h"
#include "Radiosity/Common/SystemInfo.h"

#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace radiosity;

namespace
{
std::string Table1Row(const std::string& name, const Scene& scene, const MeshlessOptions& options,
  const MeshlessRadiosity& solver, const SolverStatistics& stats)
{
  const MeshlessStatistics& t = solver.Statistics();
  char row[512];
  std::snprintf(row, sizeof row,
    "| %s | %zu | %zu | %zu | %zu | %d | %zu | %.3g | %.3g | %.2f | %.2f | %.2f | %.2f | %.1f MB | %.1f MB |\n",
    name.c_str(), scene.Triangles.size(), t.SamplesGenerated, t.SamplesGatheredTo, t.VisibilityRays,
    t.Levels, t.CoarsestSamples, options.VariationThreshold, options.SolidAngleThreshold,
    t.PlacementSeconds, t.DirectSeconds, t.BounceSeconds, stats.SolveSeconds,
    static_cast<double>(t.MemoryBytes) / 1048576.0, static_cast<double>(PeakMemoryBytes()) / 1048576.0);
  return row;
}
}

int main(int argc, char* argv[])
{
  BenchArguments args;
  if (!args.Parse(argc, argv))
  {
    return 2;
  }
  const std::string& dir = args.Directory;
  const bool quick = args.Quick;
  const std::string& bunnyJs = args.BunnyJs;
  std::ostringstream md;
  args.WriteHeading(md, "Meshless radiosity (Lehtinen et al. 2007)");
  md << "## Table 1 columns\n\n"
        "Default options (5 levels, coarsest Poisson radius 0.1 of the diagonal, 256 gather rays, "
        "epsilon_E 0.01 of the largest direct irradiance, epsilon_Omega pi/10). Times are phases of "
        "our solver: point placement, direct light (exact polygon form factors, 16 shadow rays per "
        "emitter triangle), bounces (gathers: rays plus basis evaluation). Memory: the point "
        "hierarchy and its coefficients, and the process peak.\n\n"
        "| scene | triangles | samples generated | samples gathered to | visibility rays | levels | "
        "coarsest samples | eps_E | eps_Omega | placement (s) | direct (s) | bounces (s) | total (s) | "
        "hierarchy memory | peak memory |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  {
    const Scene box = MakeCornellBox();
    const MeshlessOptions options;
    MeshlessRadiosity solver(box, options);
    const SolverStatistics stats = solver.Solve();
    md << Table1Row("Cornell box", box, options, solver, stats);
  }
  if (!bunnyJs.empty() && !quick)
  {
    // 1.5M bunny triangles in the lit room: 3674 x 4^4 = 940,544 by
    // midpoint subdivision, the rest by bisecting longest edges.
    const Scene bunny = MakeBunnyRoomWithTriangles(ReadNpmBunny(bunnyJs), 1500000);
    MeshlessOptions options;
    options.MaxTimeSeconds = 600;
    MeshlessRadiosity solver(bunny, options);
    const SolverStatistics stats = solver.Solve();
    md << Table1Row(std::string("bunny room (") + ToString(stats.Stop) + ")", bunny, options, solver, stats);
  }

  md << "\n## Error against run time\n\nA sweep over the number of levels (coarsest radius 0.1 of the "
        "diagonal, halved per level); probes, references and errors as in `error-vs-time/` (relative "
        "to the peak reference irradiance, over every probe).\n\n"
        "| scene | reference | levels | time (s) | samples | gathered to | bounces | RMS error | max error |\n"
        "|---|---|---|---|---|---|---|---|---|\n";
  std::ofstream csv(dir + "/meshless-error-vs-time.csv");
  csv << "scene,levels,time_s,samples,gathered_to,bounces,rms_error,max_rel_error\n";
  const std::vector<int> levels = quick ? std::vector<int>{ 3 } : std::vector<int>{ 3, 4, 5 };
  for (const StandardScene& standard : StandardScenes())
  {
    const Scene scene = standard.Make();
    const std::vector<Probe> probes = standard.Probes(scene);
    bool analytic = false;
    const std::vector<RGB> reference =
      StandardReference(scene, probes, quick ? 16384 : 65536, &analytic).Irradiance;
    const std::string kind = analytic ? "analytic" : "path traced";
    for (int l : levels)
    {
      MeshlessOptions options;
      options.Placement.Levels = l;
      MeshlessRadiosity solver(scene, options);
      const SolverStatistics stats = solver.Solve();
      const ErrorFigures e = RelativeErrors(solver.Evaluate(probes), reference);
      const MeshlessStatistics& t = solver.Statistics();
      char row[256];
      std::snprintf(row, sizeof row, "| %s | %s | %d | %.3f | %zu | %zu | %lld | %.2e | %.2e |\n",
        standard.Name.c_str(), kind.c_str(), l, stats.SolveSeconds, t.SamplesGenerated,
        t.SamplesGatheredTo, stats.Iterations, e.Rms, e.Max);
      md << row;
      csv << standard.Name << "," << l << "," << stats.SolveSeconds << "," << t.SamplesGenerated << ","
          << t.SamplesGatheredTo << "," << stats.Iterations << "," << e.Rms << "," << e.Max << "\n";
      std::cout << row << std::flush;
    }
  }
  std::ofstream(dir + "/meshless.md") << md.str();
  std::cout << md.str();
  return 0;
}
