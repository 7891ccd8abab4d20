// The discontinuity mesher's cost against the hierarchical solve's on the
// standard scenes (issue 21: "the interpolants cost less than the solve").
//
//   bench_meshing <output dir> [--quick] [--reps N] [--scene cornell|office] [--threads T]
//
// Each repetition solves and then meshes in the same process, one right after
// the other, so their ratio is measured on the same machine speed: a shared
// machine's speed drifts by 10% and more within minutes, which two separate
// runs (or two builds timed one after the other) cannot tell from a change.
// The table has each scene's medians; a checksum of the mesh's point
// irradiance tells two builds' meshes apart. Two builds compared at one
// thread each, run at the same time (one per core), see the same machine.
#include "BenchArguments.h"

#include "Radiosity/Common/Stopwatch.h"
#include "Radiosity/Hierarchical/DiscontinuityMesher.h"
#include "Radiosity/Hierarchical/HierarchicalRadiosity.h"
#include "Radiosity/Scenes/OfficeScene.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
} // namespace

int main(int argc, char* argv[])
{
  using namespace radiosity;
  BenchArguments args;
  if (!args.Parse(argc, argv))
  {
    return 2;
  }
  int reps = args.Quick ? 3 : 7;
  std::vector<std::string> scenes = { "cornell", "office" };
  int threads = 0;
  for (int i = 2; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--reps" && i + 1 < argc)
    {
      reps = std::max(1, std::atoi(argv[++i]));
    }
    else if (a == "--threads" && i + 1 < argc)
    {
      threads = std::max(0, std::atoi(argv[++i]));
    }
    else if (a == "--scene" && i + 1 < argc)
    {
      scenes = { argv[++i] };
    }
  }
  std::ostringstream md;
  args.WriteHeading(md, "The discontinuity mesher against the hierarchical solve");
  md << "Each repetition solves (`HierarchicalOptions()`, the command line's defaults) and then meshes "
        "(`DiscontinuityMeshOptions()`) in one process; medians of "
     << reps
     << " repetitions" << (threads > 0 ? " at " + std::to_string(threads) + " thread(s)" : std::string())
     << ". The ratio is each repetition's meshing over its own solve, so a drift of the "
        "machine's speed between repetitions cancels.\n\n"
        "| scene | solve (s) | meshing (s) | of it: samples (s) | meshing / solve | points | "
        "irradiance checksum |\n|---|---|---|---|---|---|---|\n";
  for (const std::string& name : scenes)
  {
    if (name != "cornell" && name != "office")
    {
      std::cerr << argv[0] << ": unknown scene " << name << " (cornell or office)\n";
      return 2;
    }
    const Scene scene = name == "office" ? MakeOfficeScene() : MakeCornellBox();
    std::vector<double> solve, meshing, samples, ratio;
    std::size_t points = 0;
    double checksum = 0.0;
    for (int r = 0; r < reps; ++r)
    {
      const Stopwatch clock;
      HierarchicalOptions options;
      options.Threads = threads;
      HierarchicalRadiosity solver(scene, options);
      solver.Solve();
      solve.push_back(clock.Seconds());
      const Stopwatch meshClock;
      DiscontinuityMeshOptions meshOptions;
      meshOptions.Threads = threads;
      const DiscontinuityMesh mesh = BuildDiscontinuityMesh(solver, meshOptions);
      meshing.push_back(meshClock.Seconds());
      samples.push_back(mesh.SampleSeconds);
      ratio.push_back(meshing.back() / solve.back());
      points = mesh.Points.size();
      checksum = 0.0;
      for (const RGB& e : mesh.PointIrradiance)
      {
        checksum += e.x + e.y + e.z;
      }
      std::fprintf(stderr, "%s %d: solve %.3f s, meshing %.3f s (samples %.3f s), ratio %.3f\n", name.c_str(), r,
        solve.back(), meshing.back(), samples.back(), ratio.back());
    }
    char row[512];
    std::snprintf(row, sizeof row, "| %s | %.3f | %.3f | %.3f | %.3f | %zu | %.15g |\n", name.c_str(), Median(solve),
      Median(meshing), Median(samples), Median(ratio), points, checksum);
    md << row;
    std::cout << row << std::flush;
  }
  std::ofstream(args.Directory + "/meshing.md") << md.str();
  return 0;
}
