// Progressive radiosity on the GPU (ProgressiveGPUMethod) against exact
// answers and against the CPU progressive solver on the same element mesh:
// the closed cube B = E / (1 - rho) for rho 0.5 to 0.999 (the paper's
// solver with the CPU solver's overshooting), the same at 1e-4 m and 1e4 m,
// the Cornell box against the CPU solver, the exact penumbra and the contact
// edge against their closed forms beside the CPU solver's error (what the
// hemicube's aliasing adds is printed and bounded).
#include "ProgressiveGPUMethod.h"
#include "vtkFloatingPointExceptions.h"

#include "Radiosity/Common/ElementMesh.h"
#include "Radiosity/Common/ErrorMetrics.h"
#include "Radiosity/Common/SolutionMesh.h"
#include "Radiosity/Progressive/ProgressiveMethod.h"
#include "Radiosity/Reference/AnalyticReference.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

using namespace radiosity;

namespace
{
bool Check(bool ok, const std::string& what)
{
  if (!ok)
  {
    std::cerr << "FAILED: " << what << "\n";
  }
  return ok;
}

/// Largest |B - exact| / exact over the solution's cells.
double MaxCellError(const SolutionMesh& s, double exact)
{
  double worst = 0.0;
  for (const RGB& b : s.CellRadiosity)
  {
    worst = std::max(worst, std::fabs(Mean(b) - exact) / exact);
  }
  return s.CellRadiosity.empty() ? 1.0 : worst;
}

/// Area-weighted mean irradiance (luminance) per input triangle.
std::vector<double> TriangleMeans(const SolutionMesh& s, std::size_t triangles)
{
  std::vector<double> sum(triangles, 0.0), area(triangles, 0.0);
  for (std::size_t c = 0; c < s.Triangles.size(); ++c)
  {
    const Vec3 a = s.Points[s.Triangles[c].V[0]], b = s.Points[s.Triangles[c].V[1]],
               d = s.Points[s.Triangles[c].V[2]];
    const double A = 0.5 * glm::length(glm::cross(b - a, d - a));
    sum[s.SourceTriangle[c]] += Luminance(s.CellIrradiance[c]) * A;
    area[s.SourceTriangle[c]] += A;
  }
  for (std::size_t t = 0; t < triangles; ++t)
  {
    sum[t] = area[t] > 0.0 ? sum[t] / area[t] : 0.0;
  }
  return sum;
}

/// Max error at probes relative to the peak of the reference.
double ProbeError(const RadiositySolver& solver, const std::vector<Probe>& probes, const std::vector<RGB>& exact)
{
  const std::vector<RGB> values = solver.EvaluateProbes(probes);
  double peak = 0.0, worst = 0.0;
  for (const RGB& e : exact)
  {
    peak = std::max(peak, Luminance(e));
  }
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    worst = std::max(worst, std::fabs(Luminance(values[i]) - Luminance(exact[i])) / peak);
  }
  return worst;
}

template <typename Method, typename Options>
std::shared_ptr<Method> Solved(const Scene& scene, const Options& options, SolverStatistics& stats)
{
  auto solver = std::make_shared<Method>(std::make_shared<const Scene>(scene), options);
  stats = solver->Solve({});
  return solver;
}
} // namespace

int TestProgressiveGPUAccuracy(int, char*[])
{
  vtkFloatingPointExceptions::Disable();
  bool ok = true;

  // The closed cube, with the CPU test's elements (ClosedCube.UniformRadiosityIsEOverOneMinusRho).
  ProgressiveGPUOptions cubeOptions;
  cubeOptions.Tolerance = 1e-4;
  cubeOptions.MaxTimeSeconds = 120;
  cubeOptions.ShooterElementSize = 0.4;
  cubeOptions.InitialElementSize = 0.2;
  for (double rho : { 0.5, 0.9, 0.99, 0.999 })
  {
    SolverStatistics stats;
    auto gpu = Solved<ProgressiveGPUMethod>(MakeClosedCube(1.0, 2, rho, 1.0), cubeOptions, stats);
    const double error = MaxCellError(gpu->Surface(), 1.0 / (1.0 - rho));
    std::cout << "closed cube rho " << rho << ": " << stats.Iterations << " shots, " << stats.SolveSeconds
              << " s on " << gpu->Renderer() << ", max error " << error << "\n";
    ok &= Check(stats.Stop == StopReason::Converged, "closed cube converges");
    // Measured 1.5e-5, 2.9e-5, 2.3e-5, 2.5e-5 (rho 0.5, 0.9, 0.99, 0.999;
    // llvmpipe; elements split near each shooter and gather their history).
    ok &= Check(error < 1e-4, "closed cube within 1e-4");
  }
  // Scale: the same cube at 1e-4 m and 1e4 m gives the same answer.
  for (double size : { 1e-4, 1e4 })
  {
    SolverStatistics stats;
    auto gpu = Solved<ProgressiveGPUMethod>(MakeClosedCube(size, 2, 0.9, 1.0), cubeOptions, stats);
    const double error = MaxCellError(gpu->Surface(), 10.0);
    std::cout << "closed cube of edge " << size << " m, rho 0.9: max error " << error << "\n";
    // Measured 2.9e-5 at both scales, as at 1 m.
    ok &= Check(error < 1e-4, "closed cube within 1e-4 at any scale");
  }

  // The Cornell box: the GPU against the CPU solver, per input triangle.
  {
    const Scene box = MakeCornellBox();
    ProgressiveGPUOptions options;
    options.Tolerance = 1e-3;
    SolverStatistics gpuStats, cpuStats;
    auto gpu = Solved<ProgressiveGPUMethod>(box, options, gpuStats);
    auto cpu = Solved<ProgressiveMethod>(box, static_cast<const ProgressiveOptions&>(options), cpuStats);
    const std::vector<double> g = TriangleMeans(gpu->Surface(), box.Triangles.size());
    const std::vector<double> c = TriangleMeans(cpu->Surface(), box.Triangles.size());
    const double peak = *std::max_element(c.begin(), c.end());
    double worst = 0.0;
    for (std::size_t t = 0; t < g.size(); ++t)
    {
      worst = std::max(worst, std::fabs(g[t] - c[t]) / peak);
    }
    std::cout << "Cornell box: GPU " << gpuStats.Iterations << " shots " << gpuStats.SolveSeconds << " s, CPU "
              << cpuStats.Iterations << " shots " << cpuStats.SolveSeconds
              << " s; triangle means differ by at most " << worst << " of the peak\n";
    ok &= Check(gpuStats.Stop == StopReason::Converged, "Cornell box converges");
    // Measured 0.0116 of the peak (the issue asks for 3%); both split
    // their elements by the same gradient criterion (1640 splits on the GPU).
    std::cout << "Cornell box: " << gpuStats.Subdivisions << " splits on the GPU, " << cpuStats.Subdivisions
              << " on the CPU\n";
    ok &= Check(worst < 0.02, "Cornell box within 2% of the CPU solver");
    ok &= Check(gpuStats.Subdivisions > 0, "Cornell box: the GPU subdivides");
  }

  // The exact penumbra (a black scene: the direct light alone) and the
  // contact edge: the GPU's error beside the CPU's.
  {
    const Scene shadow = MakeShadowScene(4, 1.0);
    const std::vector<Probe> probes = PenumbraLineProbes();
    AnalyticReference ref;
    std::string why;
    ok &= Check(ComputeAnalyticReference(shadow, probes, ref, why), "penumbra reference: " + why);
    ProgressiveGPUOptions options;
    SolverStatistics stats;
    auto gpu = Solved<ProgressiveGPUMethod>(shadow, options, stats);
    auto cpu = Solved<ProgressiveMethod>(shadow, static_cast<const ProgressiveOptions&>(options), stats);
    const double gpuError = ProbeError(*gpu, probes, ref.Irradiance);
    const double cpuError = ProbeError(*cpu, probes, ref.Irradiance);
    std::cout << "penumbra: max error " << gpuError << " of the peak (CPU " << cpuError
              << "): the item buffer adds " << gpuError - cpuError << "\n";
    // Measured 0.0745 (CPU 0.0998): the 16 item buffers of the emitter's
    // parts sample its penumbra as the CPU's 16 rays do.
    ok &= Check(gpuError < 0.09, "penumbra within 0.09 of the peak");
  }
  {
    const Scene contact = MakeContactScene(4, 0.0, 10.0);
    std::vector<Probe> probes;
    std::vector<RGB> exact;
    for (double d : { 1e-2, 5e-2, 0.1, 0.25, 0.5 })
    {
      probes.push_back(Probe{ Vec3(d, 0.5, 0.0), Vec3(0, 0, 1) });
    }
    AnalyticReference ref;
    std::string why;
    ok &= Check(ComputeAnalyticReference(contact, probes, ref, why), "contact reference: " + why);
    ProgressiveGPUOptions options;
    SolverStatistics stats;
    auto gpu = Solved<ProgressiveGPUMethod>(contact, options, stats);
    auto cpu = Solved<ProgressiveMethod>(contact, static_cast<const ProgressiveOptions&>(options), stats);
    ProgressiveGPUOptions uniform = options;
    uniform.MaxSubdivisionLevels = 0;
    auto flat = Solved<ProgressiveGPUMethod>(contact, uniform, stats);
    const double gpuError = ProbeError(*gpu, probes, ref.Irradiance);
    const double cpuError = ProbeError(*cpu, probes, ref.Irradiance);
    const double flatError = ProbeError(*flat, probes, ref.Irradiance);
    std::cout << "contact edge: max error " << gpuError << " of the peak (CPU " << cpuError
              << "): the item buffer adds " << gpuError - cpuError << "; without subdivision " << flatError << "\n";
    // Measured 5.3e-4 (CPU 5.0e-4); without the adaptive subdivision
    // (section 4) 1.28e-3.
    ok &= Check(gpuError < 8e-4, "contact edge within 8e-4 of the peak");
    ok &= Check(gpuError < 0.6 * flatError, "contact edge: subdivision halves the error");
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
