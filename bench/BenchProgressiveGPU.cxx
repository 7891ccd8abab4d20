// Progressive radiosity on the GPU against the CPU solver (issue: the GPU
// solver of Coombe et al.): seconds per shot and to convergence on the
// Cornell box at two element sizes and on the Cornell box subdivided to
// 131,072 triangles, with the paper's Table 1 columns (texels, seconds per
// shot) beside ours. Writes progressive-gpu.md into argv[1]; needs an
// OpenGL context (xvfb-run for llvmpipe); the machine line names the
// OpenGL renderer that ran.
#include "BenchArguments.h"
#include "ProgressiveGPUMethod.h"
#include "Radiosity/Common/SystemInfo.h"
#include "Radiosity/Progressive/ProgressiveMethod.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

using namespace radiosity;

namespace
{
struct Row
{
  std::string Case, Method;
  SolverStatistics Stats;
  std::size_t Triangles = 0;
};

template <typename Method>
Row Solve(const std::string& name, const char* method, const Scene& scene, const ProgressiveGPUOptions& options,
  std::string* renderer = nullptr)
{
  Row row;
  row.Case = name;
  row.Method = method;
  row.Triangles = scene.Triangles.size();
  auto shared = std::make_shared<const Scene>(scene);
  std::unique_ptr<Method> solver;
  if constexpr (std::is_same_v<Method, ProgressiveGPUMethod>)
  {
    solver = std::make_unique<Method>(shared, options);
  }
  else
  {
    solver = std::make_unique<Method>(shared, static_cast<const ProgressiveOptions&>(options));
  }
  row.Stats = solver->Solve({});
  if constexpr (std::is_same_v<Method, ProgressiveGPUMethod>)
  {
    if (renderer)
    {
      *renderer = solver->Renderer();
    }
  }
  std::cerr << name << " " << method << ": " << ToString(row.Stats.Stop) << " " << row.Stats.Iterations
            << " shots " << row.Stats.SolveSeconds << " s\n";
  return row;
}
} // namespace

int main(int argc, char* argv[])
{
  BenchArguments args;
  if (!args.Parse(argc, argv))
  {
    return 2;
  }
  std::vector<Row> rows;
  std::string renderer;
  const Scene box = MakeCornellBox();
  ProgressiveGPUOptions options;
  options.Tolerance = 1e-3;
  rows.push_back(Solve<ProgressiveGPUMethod>("Cornell box, elements 1/16", "GPU", box, options, &renderer));
  rows.push_back(Solve<ProgressiveMethod>("Cornell box, elements 1/16", "CPU", box, options));
  ProgressiveGPUOptions fine = options;
  fine.InitialElementSize = 1.0 / 64.0;
  rows.push_back(Solve<ProgressiveGPUMethod>("Cornell box, elements 1/64", "GPU", box, fine));
  rows.push_back(Solve<ProgressiveMethod>("Cornell box, elements 1/64", "CPU", box, fine));
  // 131,072 input triangles, each its own shooter: seconds per shot over a
  // fixed number of shots, and how far a time-limited run gets.
  const Scene large = SubdividedScene(box, args.Quick ? 4 : 6);
  ProgressiveGPUOptions shots = options;
  shots.MaxIterations = args.Quick ? 20 : 100;
  rows.push_back(Solve<ProgressiveGPUMethod>("subdivided Cornell box, 100 shots", "GPU", large, shots));
  rows.push_back(Solve<ProgressiveMethod>("subdivided Cornell box, 100 shots", "CPU", large, shots));
  ProgressiveGPUOptions limited = options;
  limited.Tolerance = 1e-2;
  limited.MaxTimeSeconds = args.Quick ? 20 : 120;
  rows.push_back(Solve<ProgressiveGPUMethod>("subdivided Cornell box, to 1e-2", "GPU", large, limited));
  rows.push_back(Solve<ProgressiveMethod>("subdivided Cornell box, to 1e-2", "CPU", large, limited));

  std::ostringstream md;
  args.WriteHeading(md, "Progressive radiosity on the GPU against the CPU");
  md << "OpenGL renderer: " << renderer << " (a software rasteriser: no GPU was at hand).\n\n"
     << "GPU: `ProgressiveGPUMethod` (Rendering/GPU, Coombe et al. 2004 sections 3 and 4: texel atlases, "
        "item buffers, the gradient split on the GPU); CPU: `ProgressiveRadiosity` (the same quadtrees and "
        "criterion, Embree rays). Same options: tolerance on the relative unshot power, `InitialElementSize`, "
        "shooters of 1/4 of the diagonal, two adaptive levels. Seconds are the solve's own (`SolveSeconds`), "
        "the GPU's including its context and upload.\n\n"
     << "| case | method | triangles | elements (texels) | stop | shots | solve (s) | s per shot | rel. unshot |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows)
  {
    char line[512];
    const double perShot = r.Stats.Iterations > 0 ? r.Stats.SolveSeconds / static_cast<double>(r.Stats.Iterations) : 0.0;
    std::snprintf(line, sizeof line, "| %s | %s | %zu | %zu | %s | %lld | %.3f | %.4f | %.2e |\n", r.Case.c_str(),
      r.Method.c_str(), r.Triangles, r.Stats.Elements, ToString(r.Stats.Stop), r.Stats.Iterations,
      r.Stats.SolveSeconds, perShot, r.Stats.UnshotPowerW / std::max(r.Stats.EmittedPowerW, 1e-300));
    md << line;
  }
  md << "\nThe paper's Table 1 (NVIDIA GeForce FX, 2004), uniform textures: Cornell 31K texels, 0.25 s per "
        "shot; Museum 172K, 1.1 s; Grotto 1.6M, 6.45 s (adaptive: 18K/0.17 s, 25K/1.41 s, 225K/10.27 s).\n";
  const std::string path = args.Directory + "/progressive-gpu.md";
  std::ofstream(path) << md.str();
  std::cout << md.str();
  return 0;
}
