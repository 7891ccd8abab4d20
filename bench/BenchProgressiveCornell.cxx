// Benchmark of the foundation issue: the Cornell box to a relative unshot
// power of 1e-3 (target: under 2 s on the 2-core CI machine), with and
// without overshooting, and the closed room of reflectance 0.999 that only
// converges with the acceleration. Writes a markdown table and the
// convergence histories (CSV) into the directory given as argv[1].
#include "Radiosity/Progressive/ProgressiveRadiosity.h"
#include "Radiosity/Scenes/SceneGenerators.h"
#include "Radiosity/Common/SystemInfo.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace radiosity;

namespace
{
struct Run
{
  std::string Case;
  double Seconds = 0;
  SolverStatistics Stats;
};

Run Solve(const std::string& name, const Scene& scene, const ProgressiveOptions& options)
{
  Run run;
  run.Case = name;
  const auto start = std::chrono::steady_clock::now();
  ProgressiveRadiosity solver(scene, options);
  run.Stats = solver.Solve();
  run.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

void WriteHistory(const std::string& file, const ConvergenceHistory& h)
{
  std::ofstream out(file);
  out << "iteration,time_s,unshot_power_W,energy_balance,overshoot_power_W\n";
  // At most ~2000 rows (and always the last): enough for a plot, small to commit.
  const std::size_t stride = std::max<std::size_t>(1, h.Rows.size() / 2000);
  for (std::size_t i = 0; i < h.Rows.size(); ++i)
  {
    if (i % stride != 0 && i + 1 != h.Rows.size())
    {
      continue;
    }
    const auto& r = h.Rows[i];
    out << r.Iteration << "," << r.TimeSeconds << "," << r.UnshotPowerW << "," << r.EnergyBalance
        << "," << r.OvershootPowerW << "\n";
  }
}
}

int main(int argc, char* argv[])
{
  const std::string dir = argc > 1 ? argv[1] : ".";
  const int repetitions = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
  const Scene cornell = MakeCornellBox();
  std::vector<Run> runs;

  ProgressiveOptions options; // the defaults users get
  Run best;
  best.Seconds = 1e300;
  for (int i = 0; i < repetitions; ++i)
  {
    Run r = Solve("Cornell box, defaults, tolerance 1e-3", cornell, options);
    if (r.Seconds < best.Seconds)
    {
      best = r;
    }
  }
  runs.push_back(best);
  WriteHistory(dir + "/cornell_progressive_history.csv", best.Stats.History);

  ProgressiveOptions plain = options;
  plain.Overshooting = false;
  runs.push_back(Solve("Cornell box, no overshooting, tolerance 1e-3", cornell, plain));

  const Scene room = MakeClosedCube(1.0, 2, 0.999, 1.0);
  ProgressiveOptions roomOptions;
  roomOptions.ShooterElementSize = 0.4;
  roomOptions.InitialElementSize = 0.2;
  runs.push_back(Solve("closed room rho 0.999, overshooting", room, roomOptions));
  WriteHistory(dir + "/room0999_overshooting_history.csv", runs.back().Stats.History);
  roomOptions.Overshooting = false;
  roomOptions.MaxTimeSeconds = 20;
  runs.push_back(Solve("closed room rho 0.999, no overshooting (20 s cap)", room, roomOptions));
  WriteHistory(dir + "/room0999_plain_history.csv", runs.back().Stats.History);

  std::ostringstream md;
  md << "# Progressive refinement radiosity benchmark\n\n"
     << "Machine: " << CpuModel() << ", " << std::thread::hardware_concurrency()
     << " hardware threads. Best of " << repetitions << " runs for the first row.\n"
     << "Peak memory of the whole benchmark process: " << PeakMemoryBytes() / (1 << 20)
     << " MiB.\n\n"
     << "| case | stop | time (s) | iterations | elements | rays | rays/s | rel. unshot | energy balance |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  for (const Run& r : runs)
  {
    const auto& s = r.Stats;
    char line[512];
    std::snprintf(line, sizeof line, "| %s | %s | %.3f | %lld | %zu | %zu | %.3g | %.2e | %.1e |\n",
      r.Case.c_str(), ToString(s.Stop), r.Seconds, s.Iterations, s.Elements, s.RaysCast,
      s.SolveSeconds > 0 ? s.RaysCast / s.SolveSeconds : 0.0, s.UnshotPowerW / s.EmittedPowerW,
      s.History.Rows.empty() ? 0.0 : s.History.Rows.back().EnergyBalance);
    md << line;
  }
  std::ofstream(dir + "/progressive.md") << md.str();
  std::cout << md.str();
  return 0;
}
