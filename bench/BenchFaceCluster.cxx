// Higher-order face cluster radiosity (Gobbetti, Spano & Agus 2003): the
// measurements of the paper's figure 4, ours (solve time, leaf elements,
// energy transfers and solution memory against input size, for constant,
// linear and quadratic irradiance bases, on the bunny room at 100k, 400k and
// 1.5M triangles; the hierarchy build time and memory beside them), and
// error against run time on the standard scenes (the probes and references
// of `vtkradiosity bench`) over a sweep of transfer tolerances. Writes
// <dir>/facecluster.md and <dir>/facecluster-error-vs-time.csv.
//   bench_facecluster <dir> [--quick] [--bunny index.js]
#include "BenchArguments.h"

#include "Radiosity/Scenes/BunnyScene.h"
#include "Radiosity/Common/ErrorMetrics.h"
#include "Radiosity/FaceCluster/FaceClusterRadiosity.h"
#include "Radiosity/Scenes/SceneGenerators.h"
#include "Radiosity/Scenes/StandardScenes.h"
#include "Radiosity/Common/SystemInfo.h"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace radiosity;

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
  args.WriteHeading(md, "Higher-order face cluster radiosity (Gobbetti et al. 2003)");

  if (!bunnyJs.empty())
  {
    md << "## Figure 4, measured\n\n"
          "The bunny room (a 2 m closed room, walls 0.7 and floor 0.5 grey, a 0.5 m ceiling light "
          "of 50 W/m^2, the Stanford bunny 0.5 m high in reflectance 0.7) with the bunny at the "
          "given triangle count. Radiosity basis constant; transfer tolerance 1e-5 of the emitted "
          "power; at most 10 iterations, as the paper; triangles halved below the input at the defaults "
          "(MaxBisections 5), and the linear basis again at the paper's leaves (`linear, leaves`: "
          "MaxBisections 0). `linear, + bulb`: the linear basis at the defaults with a point light of 2 W/sr "
          "above the bunny at (0.6, 1.5, 1.3) m as well (a leaf cluster is opened for it only where it needs to be, "
          "and the output shows its exact light at every vertex). The hierarchy is built once per scene and shared by "
          "the five solves. Memory: the solution's element hierarchy (the paper's "
          "'solution hierarchy'), the face cluster hierarchy, and the process peak so far.\n\n"
          "| triangles | irradiance basis | hierarchy build (s) | solve (s) | iterations | stop | "
          "leaf elements | elements | transfers | solution memory | hierarchy memory | peak memory |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    const Scene bunny = ReadNpmBunny(bunnyJs);
    const std::vector<std::size_t> sizes =
      quick ? std::vector<std::size_t>{ 100000 } : std::vector<std::size_t>{ 100000, 400000, 1500000 };
    for (std::size_t size : sizes)
    {
      const Scene room = MakeBunnyRoomWithTriangles(bunny, size);
      auto hierarchy = FaceClusterHierarchy::Shared(room);
      // The room again with a point light above the bunny (the same
      // surfaces: the same hierarchy).
      Scene lit = room;
      Light bulb;
      bulb.Position = Vec3(0.6, 1.5, 1.3);
      bulb.Intensity = RGB(2.0);
      bulb.Name = "bulb";
      lit.Lighting.Lights.push_back(bulb);
      for (int run = 0; run < 5; ++run)
      {
        // The three bases at the defaults, then the linear one at the
        // paper's leaves (no halving below the input triangles), then the
        // linear one with the bulb.
        const BasisKind kind = run == 0 ? BasisKind::Constant : run == 2 ? BasisKind::Quadratic : BasisKind::Linear;
        FaceClusterSettings settings;
        settings.IrradianceBasis = kind;
        settings.MaxIterations = 10;
        if (run == 3)
        {
          settings.MaxBisections = 0;
        }
        FaceClusterRadiosity solver(run == 4 ? lit : room, settings, hierarchy);
        const SolverStatistics stats = solver.Solve();
        const FaceClusterStatistics& f = solver.Statistics();
        char row[512];
        std::snprintf(row, sizeof row,
          "| %zu | %s | %.2f | %.2f | %lld | %s | %zu | %zu | %zu | %.1f MB | %.1f MB | %.1f MB |\n",
          room.Triangles.size(), run == 3 ? "linear, leaves" : run == 4 ? "linear, + bulb" : BasisName(kind),
          hierarchy->BuildSeconds(), stats.SolveSeconds,
          stats.Iterations, ToString(stats.Stop), f.LeafElements, f.Elements, f.Transfers,
          static_cast<double>(f.SolutionBytes) / 1048576.0,
          static_cast<double>(hierarchy->MemoryBytes()) / 1048576.0,
          static_cast<double>(PeakMemoryBytes()) / 1048576.0);
        md << row;
        std::cout << row << std::flush;
      }
    }
  }

  md << "\n## Error against run time\n\nLinear irradiance and constant radiosity bases, a sweep "
        "over the transfer tolerance (relative to the emitted power); probes, references and errors "
        "(relative to the peak reference irradiance, over every probe) as in `error-vs-time/`. The coarse test scenes (the Cornell box has 32 triangles) need refinement below the input; the rows are at the default (MaxBisections 5: halved below the input where the light a "
        "triangle receives is more than its basis can follow), `leaves` at the paper's leaves (MaxBisections 0), "
        "`x16` the scene with every triangle split in 16 beforehand.\n\n"
        "| scene | reference | transfer tolerance | time (s) | leaf elements | transfers | iterations | "
        "RMS error | max error |\n|---|---|---|---|---|---|---|---|---|\n";
  std::ofstream csv(dir + "/facecluster-error-vs-time.csv");
  csv << "scene,transfer_tolerance,time_s,leaf_elements,transfers,iterations,rms_error,max_rel_error\n";
  const std::vector<double> tolerances =
    quick ? std::vector<double>{ 1e-4 } : std::vector<double>{ 1e-3, 1e-4, 1e-5 };
  struct Case
  {
    std::string Name;
    Scene Geometry;
    std::vector<Probe> Probes;
    std::vector<double> Tolerances;
    int MaxBisections = FaceClusterSettings().MaxBisections;
  };
  std::vector<Case> cases;
  for (const StandardScene& standard : StandardScenes())
  {
    const Scene scene = standard.Make();
    cases.push_back({ standard.Name, scene, standard.Probes(scene), tolerances });
    // The coarse scenes again, each triangle split in 16, at the default
    // tolerance: what the method needs of its input.
    if (!quick && (standard.Name == "cornell" || standard.Name == "shadow" || standard.Name == "contact"))
    {
      cases.push_back({ standard.Name + " x16", SubdividedScene(scene, 2), standard.Probes(scene), { 1e-5 } });
    }
    // The paper's leaves (no halving below the input), for comparison.
    if (!quick && standard.Name != "sphere")
    {
      cases.push_back({ standard.Name + " leaves", scene, standard.Probes(scene), { 1e-5 }, 0 });
    }
  }
  for (const Case& c : cases)
  {
    const Scene& scene = c.Geometry;
    const std::vector<Probe>& probes = c.Probes;
    bool analytic = false;
    const std::vector<RGB> reference =
      StandardReference(scene, probes, quick ? 16384 : 65536, &analytic).Irradiance;
    const std::string kind = analytic ? "analytic" : "path traced";
    for (double tolerance : c.Tolerances)
    {
      FaceClusterSettings settings;
      settings.TransferTolerance = tolerance;
      settings.MaxBisections = c.MaxBisections;
      FaceClusterRadiosity solver(scene, settings);
      const SolverStatistics stats = solver.Solve();
      const ErrorFigures e = RelativeErrors(solver.Evaluate(probes), reference);
      const FaceClusterStatistics& f = solver.Statistics();
      char row[256];
      std::snprintf(row, sizeof row, "| %s | %s | %.0e | %.3f | %zu | %zu | %lld | %.2e | %.2e |\n",
        c.Name.c_str(), kind.c_str(), tolerance, stats.SolveSeconds, f.LeafElements,
        f.Transfers, stats.Iterations, e.Rms, e.Max);
      md << row;
      csv << c.Name << "," << tolerance << "," << stats.SolveSeconds << "," << f.LeafElements
          << "," << f.Transfers << "," << stats.Iterations << "," << e.Rms << "," << e.Max << "\n";
      std::cout << row << std::flush;
    }
  }
  std::ofstream(dir + "/facecluster.md") << md.str();
  std::cout << md.str();
  return 0;
}
