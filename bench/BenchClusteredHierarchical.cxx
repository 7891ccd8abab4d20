// Clustered hierarchical radiosity (Hierarchical/ClusterLinks.h): the closed
// tessellated sphere against its exact answer, clustered and plain, and the
// bunny room at growing triangle counts (solve, discontinuity meshing, links,
// leaves, interpolant triangles, peak memory), beside face cluster's figure 4.
// Writes <dir>/clustered-hierarchical.md.
//   bench_clustered_hierarchical <dir> [--quick] [--bunny index.js] [--sizes 30000,100000] [--phases]
// --phases prints each progress report's phase, sweep and time to stderr, and
// the meshing's, so that a slow row's time has names.
#include "BenchArguments.h"

#include "Radiosity/Common/ErrorMetrics.h"
#include "Radiosity/Common/Stopwatch.h"
#include "Radiosity/Common/SystemInfo.h"
#include "Radiosity/Hierarchical/DiscontinuityMesher.h"
#include "Radiosity/Hierarchical/HierarchicalRadiosity.h"
#include "Radiosity/Reference/AnalyticReference.h"
#include "Radiosity/Scenes/BunnyScene.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace radiosity;

int main(int argc, char* argv[])
{
  BenchArguments args;
  if (!args.Parse(argc, argv))
  {
    return 2;
  }
  bool phases = false;
  std::vector<std::size_t> sizes = args.Quick ? std::vector<std::size_t>{ 30000 }
                                              : std::vector<std::size_t>{ 30000, 100000, 400000, 1500000 };
  for (int i = 2; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == "--sizes")
    {
      sizes.clear();
      std::stringstream list(argv[i + 1]);
      for (std::string item; std::getline(list, item, ',');)
      {
        sizes.push_back(static_cast<std::size_t>(std::stoull(item)));
      }
    }
  }
  for (int i = 2; i < argc; ++i)
  {
    phases = phases || std::string(argv[i]) == "--phases";
  }
  std::ostringstream md;
  args.WriteHeading(md, "Clustered hierarchical radiosity");
  md << "## The inside of a closed sphere\n\n"
        "An icosphere of radius 1 seen from inside, emission (1, 2, 3) on the cap z > 0.5, uniform "
        "reflectance; errors against the exact answer (`ComputeAnalyticReference`) at about 500 "
        "triangle centroids, relative to the peak. Default settings (link tolerance 0.05, solver "
        "tolerance 1e-4). Plain hierarchical radiosity links every facing pair first.\n\n"
        "| triangles | reflectance | clustering | time (s) | links | with a cluster | sweeps | max error | "
        "RMS error | peak memory |\n|---|---|---|---|---|---|---|---|---|---|\n";
  const std::vector<int> levels = args.Quick ? std::vector<int>{ 3, 4 } : std::vector<int>{ 3, 4, 5 };
  for (int level : levels)
  {
    for (double rho : { 0.8, 0.99 })
    {
      const Scene sphere = MakeSphereInterior(1.0, level, rho, RGB(1.0, 2.0, 3.0));
      const std::vector<Probe> probes = CentroidProbes(sphere, 500);
      AnalyticReference reference;
      std::string why;
      if (!ComputeAnalyticReference(sphere, probes, reference, why))
      {
        std::cerr << why << "\n";
        return 1;
      }
      for (HierarchicalClustering clustering : { HierarchicalClustering::Off, HierarchicalClustering::On })
      {
        if (clustering == HierarchicalClustering::Off && level > 3)
        {
          continue; // 5,120 triangles: 26 million initial links; 20,480: refused
        }
        HierarchicalOptions options;
        options.Tolerance = 1e-4;
        options.Clustering = clustering;
        options.ErrorProbes = probes;
        options.ErrorReference = reference.Irradiance;
        const Stopwatch clock;
        HierarchicalRadiosity solver(sphere, options);
        const SolverStatistics stats = solver.Solve();
        const double seconds = clock.Seconds();
        char row[512];
        std::snprintf(row, sizeof row, "| %zu | %.2f | %s | %.2f | %zu | %zu | %lld | %.2e | %.2e | %.0f MB |\n",
          sphere.Triangles.size(), rho, clustering == HierarchicalClustering::On ? "on" : "off", seconds, stats.Links,
          stats.ClusterLinks, stats.Iterations, stats.History.Rows.back().MaxRelError,
          stats.History.Rows.back().RmsError, PeakMemoryBytes() / 1048576.0);
        md << row;
        std::cout << row << std::flush;
      }
    }
  }
  if (!args.BunnyJs.empty())
  {
    md << "\n## The bunny room\n\n"
          "Face cluster's figure 4 scene (`MakeBunnyRoomWithTriangles`; bench/results/facecluster.md): "
          "clustered hierarchical radiosity at its defaults, then discontinuity meshing at its "
          "defaults. Peak memory is the process's, so it never falls from one row to the next.\n\n"
          "| triangles | solve (s) | sweeps | links | with a cluster | partial (blockers) | leaves | "
          "meshing (s) | interpolant triangles | peak memory |\n|---|---|---|---|---|---|---|---|---|---|\n";
    const Scene bunny = ReadNpmBunny(args.BunnyJs);
    for (std::size_t size : sizes)
    {
      const Scene room = MakeBunnyRoomWithTriangles(bunny, size);
      const Stopwatch clock;
      std::string last;
      const auto trace = [&](const ProgressStatus& status) {
        const std::string now = status.Phase + " " + std::to_string(status.Iteration);
        if (phases && now != last)
        {
          std::fprintf(stderr, "%8.2f s  %s\n", clock.Seconds(), now.c_str());
          last = now;
        }
        return true;
      };
      HierarchicalRadiosity solver(room, HierarchicalOptions());
      const SolverStatistics stats = solver.Solve(trace);
      const double solve = clock.Seconds();
      const Stopwatch meshClock;
      const DiscontinuityMesh mesh = BuildDiscontinuityMesh(solver, DiscontinuityMeshOptions(), trace);
      const double meshing = meshClock.Seconds();
      char row[512];
      std::snprintf(row, sizeof row, "| %zu | %.1f | %lld | %zu | %zu | %zu | %zu | %.1f | %zu | %.0f MB |\n",
        room.Triangles.size(), solve, stats.Iterations, stats.Links, stats.ClusterLinks, stats.PartialLinks,
        stats.Elements, meshing, mesh.Triangles.size(), PeakMemoryBytes() / 1048576.0);
      md << row;
      std::cout << row << std::flush;
    }
  }
  std::ofstream(args.Directory + "/clustered-hierarchical.md") << md.str();
  return 0;
}
