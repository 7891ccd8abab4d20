// vtkradiosity: the command-line program of SPEC.md.
//   vtkradiosity solve SCENE [options]   solve, write the result, image, probes, report
//   vtkradiosity demo [--output-dir DIR] the built-in Cornell box, everything into DIR (out/)
// Exit status: 0 success, 2 bad input (nothing written), 1 internal failure.
#include "Bench.h"
#include "SolveCommon.h"
#include "ExrWriter.h"
#include "InterpolantSolution.h"
#include "ProbeIO.h"
#include "ProgressBar.h"
#include "Report.h"
#include "ImportedScene.h"
#include "SceneLoader.h"
#include "SolveTarget.h"

#include "vtkCamera.h"
#include "vtkCornellBoxSource.h"
#include "vtkDoubleArray.h"
#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRadiosityConvergenceChart.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiositySceneConverter.h"
#include "vtkRadiosityView.h"
#include "vtkRenderer.h"
#include "vtkTable.h"
#include "vtkXMLPolyDataWriter.h"

#include "Radiosity/Reference/AnalyticReference.h"
#include "Radiosity/Hierarchical/DiscontinuityMesher.h"
#include "Radiosity/Hierarchical/HierarchicalRadiosity.h"
#include "Radiosity/FaceCluster/FaceClusterRadiosity.h"
#include "Radiosity/Meshless/MeshlessRadiosity.h"
#include "Radiosity/Common/ErrorMetrics.h"
#include "Radiosity/Common/MemoryBudget.h"
#include "Radiosity/Reference/PathTracer.h"
#include "Radiosity/Scenes/SceneGenerators.h"
#include "Radiosity/Common/SystemInfo.h"
#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Common/RadianceImage.h"
#include "Radiosity/Common/SolutionMesh.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <new>
#include <stdexcept>
#include <sys/stat.h>

namespace
{
using namespace solve;

std::string StripPrefix(const std::string& text, const std::string& prefix)
{
  return text.compare(0, prefix.size(), prefix) == 0 ? text.substr(prefix.size()) : text;
}

int RunSolve(SolveArguments args) // a copy: --view is read into args.View
{
  RunPhases phases(Clock::now());
  if (args.Method != "auto" && args.Method != "progressive" && args.Method != "hierarchical" &&
    args.Method != "meshless" && args.Method != "facecluster" && args.Method != "progressive-gpu")
  {
    throw BadInput("--method " + args.Method +
      ": not available in this version (available: progressive, hierarchical, meshless, "
      "facecluster, progressive-gpu, auto)");
  }
  bool meshless = args.Method == "meshless"; // or auto's choice, once solved
  bool faceCluster = args.Method == "facecluster";
  auto basis = [](const std::string& option, const std::string& name) {
    for (int b = vtkRadiosityFilter::ConstantBasis; b <= vtkRadiosityFilter::CubicBasis; ++b)
    {
      if (name == vtkRadiosityFilter::GetBasisName(b))
      {
        return b;
      }
    }
    throw BadInput(option + " " + name + ": not a basis (constant, linear, bilinear, quadratic, cubic)");
  };
  const int irradianceBasis = basis("--irradiance-basis", args.IrradianceBasis);
  const int radiosityBasis = basis("--radiosity-basis", args.RadiosityBasis);
  if (radiosityBasis > irradianceBasis)
  {
    throw BadInput("--radiosity-basis " + args.RadiosityBasis + " is larger than --irradiance-basis " +
      args.IrradianceBasis + " (the radiosity basis is a subset of the irradiance one)");
  }
  if (!args.ReferenceExr.empty() && args.Exr.empty())
  {
    throw BadInput("--reference-exr needs --exr (the same view, path traced)");
  }
  if (!args.ProbeOutput.empty() && args.Probes.empty())
  {
    throw BadInput("--probe-output needs --probes");
  }
  if (!args.ViewText.empty())
  {
    // px,py,pz,fx,fy,fz[,ux,uy,uz[,angle]]: finite, the focal point away
    // from the position, an up not along the view, an angle in (0, 180).
    std::stringstream text(args.ViewText);
    std::string field;
    while (std::getline(text, field, ','))
    {
      char* end = nullptr;
      const double v = std::strtod(field.c_str(), &end);
      if (field.empty() || end == field.c_str() || *end != '\0' || !std::isfinite(v))
      {
        throw BadInput("--view '" + args.ViewText + "': '" + field + "' is not a finite number");
      }
      args.View.push_back(v);
    }
    const std::size_t n = args.View.size();
    if (n != 6 && n != 9 && n != 10)
    {
      throw BadInput("--view '" + args.ViewText + "': " + std::to_string(n) +
        " numbers; expected px,py,pz,fx,fy,fz[,ux,uy,uz[,angle]]");
    }
    const Vec3 position(args.View[0], args.View[1], args.View[2]), focal(args.View[3], args.View[4], args.View[5]);
    const Vec3 up = n >= 9 ? Vec3(args.View[6], args.View[7], args.View[8]) : Vec3(0.0, 0.0, 1.0);
    const Vec3 look = focal - position;
    if (!(glm::length(look) > 0.0) || !(glm::length(glm::cross(look, up)) > 1e-9 * glm::length(look) * glm::length(up)))
    {
      throw BadInput("--view '" + args.ViewText + "': the focal point must differ from the position and the view up "
                     "must not lie along the view");
    }
    if (n == 10 && !(args.View[9] > 0.0 && args.View[9] < 180.0))
    {
      throw BadInput("--view '" + args.ViewText + "': the view angle must be in (0, 180) degrees");
    }
  }
  std::string noWindow;
  if ((!args.Image.empty() || !args.Exr.empty() || !args.HistoryPng.empty()) &&
    !vtkRadiosityView::CanOpenWindow(noWindow))
  {
    // Before the solve, not after it: the images need a window.
    throw BadInput(std::string(!args.Image.empty() ? "--image" : !args.Exr.empty() ? "--exr" : "--history-plot") +
      ": " + noWindow);
  }
  // Everything that can be refused is read and checked before anything is written.
  std::vector<Probe> probes;
  std::string error;
  if (args.DemoProbes)
  {
    probes = CornellDemoProbes();
  }
  if (!args.Probes.empty() && !cli::ReadProbes(args.Probes, probes, error))
  {
    throw BadInput(error);
  }
  if (!args.Reference.empty() && probes.empty() && !args.DemoProbes)
  {
    throw BadInput("--reference needs --probes (the points where the error is measured)");
  }
  // --lights: read and checked before the scene is loaded or anything solved.
  const LightSet lights = ReadLights(args);
  std::vector<std::string> loadWarnings, loadNotes;
  // An importer format goes into a renderer and is solved through
  // vtkRadiosityPass (ImportedScene.h, SolveTarget.h); the rest is loaded.
  cli::ImportedScene imported;
  vtkSmartPointer<vtkDataObject> input;
  if (cli::IsImporterFile(args.Scene))
  {
    if (!cli::ImportScene(args.Scene, imported, error, loadWarnings, loadNotes))
    {
      throw BadInput(error);
    }
  }
  else
  {
    cli::LoadOptions loadOptions;
    loadOptions.MaxReflectance = args.MaxReflectance;
    input = cli::LoadScene(args.Scene, error, loadWarnings, loadNotes, loadOptions);
    if (!input)
    {
      throw BadInput(error);
    }
  }
  for (const auto& n : loadNotes)
  {
    std::cerr << n << "\n";
  }
  for (const auto& w : loadWarnings)
  {
    std::cerr << "warning: " << w << "\n";
  }
  phases.End("load_s");
  if (args.TwoSided && input)
  {
    MarkTwoSided(input); // SPEC's TwoSided cell array on every surface
  }
  SolveTarget target = input ? SolveTarget(input) : SolveTarget(imported, args.MaxReflectance);
  if (args.TwoSided && !input)
  {
    target.SetTwoSided(); // vtkRadiosityPass::TwoSided
  }

  // The reference: a file of values at the probes, or a closed form the scene
  // has (an imported scene's once the pass has gathered it, RunRadiosityFilter).
  std::vector<RGB> reference;
  std::string referenceKind;
  if ((args.Reference == "analytic" || args.Reference == "pathtraced") && input)
  {
    // The scene as the core sees it, for the references (the filter converts its own).
    std::vector<std::string> ignored;
    std::string why;
    Scene scene;
    if (!vtkRadiositySceneConverter::ToScene(input, scene, why, ignored))
    {
      throw BadInput(why);
    }
    try
    {
      ValidateScene(scene);
    }
    catch (const SceneError& e)
    {
      throw BadInput(e.what());
    }
    DropDegenerateTriangles(scene);
    scene.Lighting = lights;
    ComputeReference(args, scene, probes, reference, referenceKind);
  }
  else if (!args.Reference.empty() && args.Reference != "analytic" && args.Reference != "pathtraced")
  {
    if (!cli::ReadProbeValues(args.Reference, probes, reference, error))
    {
      throw BadInput(error);
    }
    referenceKind = "file: " + args.Reference;
  }
  if (!reference.empty())
  {
    phases.End("reference_s");
  }

  vtkRadiosityFilter* filter = target.Filter();
  const bool autoMethod = args.Method == "auto";
  if (autoMethod || args.Method == "hierarchical")
  {
    ConfigureHierarchical(args, filter); // checked before anything is solved
  }
  target.SetMethod(autoMethod                   ? vtkRadiosityFilter::Auto
      : args.Method == "hierarchical" ? vtkRadiosityFilter::Hierarchical
      : meshless                      ? vtkRadiosityFilter::Meshless
      : faceCluster                   ? vtkRadiosityFilter::FaceCluster
      : args.Method == "progressive-gpu" ? vtkRadiosityFilter::ProgressiveGPU
                                      : vtkRadiosityFilter::Progressive);
  filter->SetHemicubeResolution(args.HemicubeResolution);
  filter->SetIrradianceBasis(irradianceBasis);
  filter->SetRadiosityBasis(radiosityBasis);
  filter->SetTransferTolerance(args.TransferTolerance);
  filter->SetMaxBisections(args.MaxBisections);
  filter->SetExactEmitters(!args.NoExactEmitters);
  filter->SetPointRadius(args.PointRadius);
  filter->SetPointLevels(args.PointLevels);
  filter->SetGatherRays(args.GatherRays);
  filter->SetVariationThreshold(args.VariationThreshold);
  filter->SetOvershooting(!args.NoOvershooting);
  filter->SetInitialElementSize(args.ElementSize);
  filter->SetShooterElementSize(args.ShooterSize);
  if (!target.IsImported() && !autoMethod && args.Method != "hierarchical")
  {
    // Only what the options ask for: the surface for --output, --image and
    // --exr (its view frames the surface; the probes evaluate their own),
    // the meshless field for its splats in --image. (Hierarchical, and auto
    // until it has chosen, keep both: port 1 is the discontinuity mesh.)
    // The pass draws what its filter outputs: all of it.
    filter->SetSurfaceOutput(!args.Output.empty() || !args.Image.empty() || !args.Exr.empty());
    filter->SetProductOutput(meshless && !args.Image.empty());
  }
  cli::ProgressBar bar;
  RunRadiosityFilter(target, args, probes, reference, referenceKind, lights, bar, phases);
  if (autoMethod)
  {
    std::cerr << "method auto: " << vtkRadiosityFilter::GetMethodName(filter->GetResolvedMethod()) << " ("
              << filter->GetMethodChoice() << ")\n";
  }
  if (filter->GetResolvedMethod() == vtkRadiosityFilter::Hierarchical)
  {
    return FinishHierarchicalSolve(args, probes, reference, referenceKind, target, bar, phases);
  }
  meshless = filter->GetResolvedMethod() == vtkRadiosityFilter::Meshless;
  faceCluster = filter->GetResolvedMethod() == vtkRadiosityFilter::FaceCluster;
  const SolverStatistics& stats = filter->GetStatistics();
  bar.Finish(std::string("stopped: ") + ToString(stats.Stop));

  vtkPolyData* solved = filter->GetOutput();

  if (!args.Output.empty())
  {
    WriteVtp(solved, args.Output);
    phases.End("write_s");
  }
  std::size_t gathered = 0;
  std::vector<RGB> probeValues;
  if ((!args.ProbeOutput.empty() || !reference.empty()) && filter->GetSolver())
  {
    // SPEC: each method's probes from its own representation (the meshless
    // Shepard field, the face cluster bases, the elements), the punctual
    // lights exact at each sensor (RadiositySolver::EvaluateProbes).
    probeValues = filter->GetSolver()->EvaluateProbes(probes, &gathered);
  }
  phases.End("probes_s");
  WriteProbesAndHistory(args, probes, probeValues, stats.History,
    meshless ? ", meshless radiosity" : faceCluster ? ", face cluster radiosity"
      : filter->GetResolvedMethod() == vtkRadiosityFilter::ProgressiveGPU ? ", progressive refinement on the GPU"
                                                                           : ", progressive refinement",
    filter->GetScene());
  phases.End("write_s");

  // The report is written before the picture is drawn (and again after it,
  // with the render's time): a render that fails loses none of the rest.
  const auto writeReport = [&]() {
    if (args.Report.empty())
    {
      return;
    }
    const Scene& scene = filter->GetScene();
    // The power balance: the method's own, else from its surface solution
    // (face clusters and meshless keep none while they solve), where
    // escaped = emitted - absorbed (SPEC).
    std::pair<double, double> balance(stats.AbsorbedPowerW, stats.EscapedPowerW);
    if (!(stats.AbsorbedPowerW > 0.0) && stats.EmittedPowerW > 0.0 && filter->GetSolution())
    {
      balance.first = AbsorbedPower(*filter->GetSolution(), scene);
      balance.second = stats.EmittedPowerW - balance.first;
    }
    nlohmann::json report;
    report["method"] = vtkRadiosityFilter::GetMethodName(filter->GetResolvedMethod());
    report["method_choice"] = MethodChoiceReport(args.Method, filter);
    report["parameters"] = { { "tolerance", filter->GetTolerance() },
      { "max_iterations", filter->GetMaxIterations() }, { "max_time_s", filter->GetMaxTime() },
      { "threads", filter->GetNumberOfThreads() }, { "overshooting", filter->GetOvershooting() },
      { "shooter_element_size", filter->GetShooterElementSize() },
      { "initial_element_size", filter->GetInitialElementSize() },
      { "max_subdivision_levels", filter->GetMaxSubdivisionLevels() },
      { "subdivision_threshold", filter->GetSubdivisionThreshold() },
      { "form_factor_tolerance", filter->GetFormFactorTolerance() },
      { "visibility_samples", filter->GetVisibilitySamples() },
      { "indirect_visibility_samples", filter->GetIndirectVisibilitySamples() },
      { "hemicube_resolution", filter->GetHemicubeResolution() } };
    report["scene"] = { { "source", args.Scene }, { "triangles", scene.Triangles.size() },
      { "objects", scene.ObjectNames.size() }, { "emitters", scene.NumberOfEmitters() },
      { "lights", scene.Lighting.Lights.size() }, { "sky", scene.Lighting.SkyLight.Enabled() },
      { "emitted_power_W", stats.EmittedPowerW }, { "warnings", filter->GetWarnings() },
      { "left_out",
        { { "degenerate_triangles_dropped", filter->GetCleanupReport().DegenerateTrianglesDropped },
          { "triangles_that_cannot_occlude", scene.Triangles.size() - stats.Occluders },
          { "element_pairs_facing_away", stats.PairsFacingAway },
          { "element_pairs_needing_no_ray", stats.PairsUnoccludable },
          { "solve_skipped_no_emitters", stats.Stop == StopReason::NoEmitters } } } };
    report["solution"] = { { "stop", ToString(stats.Stop) }, { "iterations", stats.Iterations },
      { "elements", stats.Elements }, { "subdivisions", stats.Subdivisions },
      { "rays", stats.RaysCast },
      { "rays_per_second", stats.SolveSeconds > 0 ? stats.RaysCast / stats.SolveSeconds : 0.0 },
      { "form_factors", { { "analytic", stats.AnalyticFormFactors }, { "disc", stats.DiscFormFactors } } },
      { "relative_unshot_power",
        stats.EmittedPowerW > 0 ? stats.UnshotPowerW / stats.EmittedPowerW : 0.0 },
      { "absorbed_power_W", balance.first }, { "escaped_power_W", balance.second },
      { "probes", probes.size() }, { "probes_gathered_off_surface", gathered } };
    report["parameters"]["memory_budget_bytes"] = ResolveMemoryBudget(args.MaxMemory * 1e9);
    if (meshless)
    {
      // The columns of Lehtinen et al.'s Table 1.
      const MeshlessStatistics& t = filter->GetMeshlessSolution()->Statistics();
      report["parameters"]["point_radius"] = args.PointRadius;
      report["parameters"]["point_levels"] = args.PointLevels;
      report["parameters"]["gather_rays"] = args.GatherRays;
      report["parameters"]["variation_threshold"] = args.VariationThreshold;
      report["parameters"]["solid_angle_threshold_sr"] = filter->GetSolidAngleThreshold();
      report["meshless"] = { { "samples_generated", t.SamplesGenerated },
        { "samples_gathered_to", t.SamplesGatheredTo }, { "gather_operations", t.GatherOperations },
        { "visibility_rays", t.VisibilityRays }, { "hierarchy_levels", t.Levels },
        { "samples_at_coarsest_level", t.CoarsestSamples }, { "memory_bytes", t.MemoryBytes } };
      phases.Part("point_placement_s", t.PlacementSeconds, "solve_s");
      phases.Part("direct_light_s", t.DirectSeconds, "solve_s");
      phases.Part("bounces_s", t.BounceSeconds, "solve_s");
    }
    if (faceCluster)
    {
      const FaceClusterStatistics& f = filter->GetFaceClusterSolution()->Statistics();
      report["parameters"]["irradiance_basis"] = args.IrradianceBasis;
      report["parameters"]["radiosity_basis"] = args.RadiosityBasis;
      report["parameters"]["transfer_tolerance"] = args.TransferTolerance;
      report["parameters"]["max_bisections"] = args.MaxBisections;
      report["parameters"]["exact_emitters"] = !args.NoExactEmitters;
      report["facecluster"] = { { "clusters", filter->GetFaceClusterSolution()->Hierarchy().NumberOfClusters() },
        { "elements", f.Elements }, { "leaf_elements", f.LeafElements }, { "transfers", f.Transfers },
        { "refinements", f.Refinements }, { "solution_memory_bytes", f.SolutionBytes },
        { "exact_emitter_triangles", f.ExactEmitterTriangles },
        { "hierarchy_memory_bytes", filter->GetFaceClusterSolution()->Hierarchy().MemoryBytes() } };
      // The filter builds the hierarchy and times it (FaceClusterRadiosity's
      // own HierarchySeconds starts after FaceClusterMethod has built it).
      phases.Part("hierarchy_s", std::max(f.HierarchySeconds, filter->GetHierarchySeconds()), "preprocessing_s");
    }
    report["lights"] = LightsReport(scene);
    report["scene"]["import"] = target.ImportReport();
    if (reference.empty())
    {
      report["error"] = nullptr; // no reference known
    }
    else
    {
      // The solver's last history row: every probe, relative to the peak
      // reference (a probe the solver does not follow is an infinite error, null).
      const ConvergenceRow& last = stats.History.Rows.back();
      nlohmann::json e = ErrorHead(referenceKind, probes.size(), stats.ErrorProbesTracked);
      e["rms_relative_error"] = std::isfinite(last.RmsError) ? nlohmann::json(last.RmsError) : nlohmann::json();
      e["max_relative_error"] = std::isfinite(last.MaxRelError) ? nlohmann::json(last.MaxRelError) : nlohmann::json();
      if (!probeValues.empty())
      {
        // Every probe, off-surface ones (gathered) included.
        AddProbeOutputErrors(e, RelativeErrors(probeValues, reference));
      }
      report["error"] = e;
    }
    ReportRunAndHistory(report, phases, stats);
    Check(cli::WriteFileAtomically(args.Report, report.dump(2) + "\n", error), error);
  };
  writeReport();
  if (!args.Image.empty() || !args.Exr.empty())
  {
    // The meshless field is drawn per pixel by splatting its basis functions.
    RenderOutputs(args, solved, [filter] { return filter->GetSolution(); }, filter->GetScene(),
      meshless && !args.Image.empty() ? filter->GetOutput(1) : nullptr, target.Camera());
    phases.End("render_s");
    writeReport();
  }
  std::cerr << "solved " << args.Scene << " (" << EmitterSummary(filter->GetScene()) << "): "
            << stats.Elements << " elements, " << stats.Iterations << " iterations, "
            << stats.SolveSeconds << " s\n";
  return 0;
}
}

int main(int argc, char* argv[])
{
  CLI::App app{ "vtkradiosity: global illumination by radiosity (see SPEC.md)" };
  app.require_subcommand(1);
  SolveArguments solve;
  CLI::App* solveCommand = app.add_subcommand("solve", "solve a scene");
  solveCommand->add_option("SCENE", solve.Scene, "scene file or a built-in scene: 'cornell', 'office' (lit by a lamp and the sky), ...")->required();
  solveCommand->add_option("--method", solve.Method, "progressive|hierarchical|meshless|facecluster|progressive-gpu|auto");
  solveCommand->add_option("--tolerance", solve.Tolerance, "relative unshot power to stop at")
    ->check(CLI::Range(1e-12, 1.0));
  solveCommand->add_option("--max-iterations", solve.MaxIterations)->check(CLI::NonNegativeNumber);
  solveCommand->add_option("--max-time", solve.MaxTime, "seconds")->check(CLI::NonNegativeNumber);
  solveCommand->add_option("--threads", solve.Threads)->check(CLI::Range(0, 4096));
  solveCommand->add_flag("--two-sided", solve.TwoSided,
    "solve every surface on both sides (SPEC TwoSided; default: the side its normal points to, and a glTF "
    "material's doubleSided)");
  solveCommand->add_option("--max-reflectance", solve.MaxReflectance,
    "display colours (.mtl Kd) at or above it are clamped to it (default 0.95)")
    ->check([](const std::string& v) {
      char* end = nullptr;
      const double x = std::strtod(v.c_str(), &end);
      return *end == '\0' && x > 0 && x < 1 ? std::string() : "must be in (0, 1), not " + v;
    });
  solveCommand->add_option("--max-memory", solve.MaxMemory,
    "memory budget of the solve in GB; a solve estimated or growing past it is refused "
    "(default 0: 75% of physical memory)")
    ->check(CLI::Range(0.0, 1e9));
  solveCommand->add_option("--output", solve.Output, "result polydata (.vtp)");
  solveCommand->add_option("--image", solve.Image, "tone-mapped PNG");
  solveCommand->add_option("--exr", solve.Exr, "linear radiance OpenEXR (half float)");
  solveCommand->add_option("--probes", solve.Probes, "sensor CSV x,y,z,nx,ny,nz");
  solveCommand->add_option("--probe-output", solve.ProbeOutput, "irradiance at the sensors");
  solveCommand->add_option("--report", solve.Report, "JSON report");
  solveCommand->add_option("--history", solve.HistoryCsv, "convergence history CSV");
  solveCommand->add_option("--history-plot", solve.HistoryPng, "convergence plot PNG");
  solveCommand->add_option("--size", solve.Width, "image width and height in pixels")
    ->check(CLI::Range(16, 8192));
  solveCommand->add_flag("--no-overshooting", solve.NoOvershooting);
  solveCommand->add_option("--point-radius", solve.PointRadius,
    "meshless: coarsest Poisson-disk radius, fraction of the scene diagonal (default 0.1)")
    ->check(CLI::Range(1e-6, 1.0));
  solveCommand->add_option("--point-levels", solve.PointLevels,
    "meshless: levels of the point hierarchy (default 5)")
    ->check(CLI::Range(1, 12));
  solveCommand->add_option("--gather-rays", solve.GatherRays,
    "meshless: hemisphere rays per gather (default 256)")
    ->check(CLI::Range(1, 65536));
  solveCommand->add_option("--variation-threshold", solve.VariationThreshold,
    "meshless: receiver refinement threshold relative to the largest direct irradiance (default 0.01)")
    ->check(CLI::Range(0.0, 1e6));
  solveCommand->add_option("--irradiance-basis", solve.IrradianceBasis,
    "facecluster: constant|linear|bilinear|quadratic|cubic (default linear)");
  solveCommand->add_option("--radiosity-basis", solve.RadiosityBasis,
    "facecluster: a basis no larger than the irradiance one (default constant)");
  solveCommand->add_option("--transfer-tolerance", solve.TransferTolerance,
    "facecluster: transfer error accepted, relative to the emitted power (default 1e-5)")
    ->check(CLI::Range(1e-12, 1.0));
  solveCommand->add_option("--max-bisections", solve.MaxBisections,
    "facecluster: halvings of an input triangle allowed below the hierarchy's leaves (default 5; 0: the paper's leaves)")
    ->check(CLI::Range(0, 16));
  solveCommand->add_flag("--no-exact-emitters", solve.NoExactEmitters,
    "facecluster: show the emitters' direct light by the solution's fit, not exactly (default: exactly where "
    "there are at most 1024 emitting triangles, in lamps whose count times the input triangles is at most 262,144)");
  solveCommand->add_option("--link-tolerance", solve.LinkTolerance,
    "hierarchical: link refinement threshold on B F, relative to the scene's mean irradiance "
    "(default 0.05)")
    ->check(CLI::NonNegativeNumber);
  solveCommand->add_option("--min-element-size", solve.MinElementSize,
    "hierarchical: smallest quadtree node edge, fraction of the scene diagonal (default 1/64)")
    ->check(CLI::Range(1e-6, 1.0));
  solveCommand->add_option("--max-refinement-rounds", solve.MaxRefinementRounds,
    "hierarchical: BF refinement passes after the first solve (default 4)")
    ->check(CLI::Range(0, 100));
  solveCommand->add_option("--clustering", solve.Clustering,
    "hierarchical: links from the face cluster hierarchy, auto|on|off (default auto: above 2048 "
    "triangles)");
  solveCommand->add_flag("--no-discontinuity-meshing", solve.NoDiscontinuityMeshing,
    "hierarchical: output and probes from the constant quadtree leaves");
  solveCommand->add_option("--discontinuities-per-leaf", solve.DiscontinuitiesPerLeaf,
    "hierarchical: the k strongest discontinuities meshed per leaf (default 10)")
    ->check(CLI::Range(0, 10000));
  solveCommand->add_option("--min-discontinuity-weight", solve.MinDiscontinuityWeight,
    "hierarchical: w_min, relative to the brightest emitter's exitance, or where none emits the brightest radiosity (default 0.05)")
    ->check(CLI::NonNegativeNumber);
  solveCommand->add_option("--reference-exr", solve.ReferenceExr,
    "path-traced OpenEXR of the --exr view (linear radiance, the reference per pixel)");
  solveCommand->add_option("--reference-pixel-samples", solve.ReferencePixelSamples,
    "paths per pixel for --reference-exr (default 64)")
    ->check(CLI::Range(std::size_t(1), std::size_t(1) << 20));
  solveCommand->add_option("--element-size", solve.ElementSize,
    "initial receiving element edge, fraction of the scene diagonal (default 1/16)")
    ->check(CLI::Range(1e-4, 1.0));
  solveCommand->add_option("--hemicube-resolution", solve.HemicubeResolution,
    "progressive-gpu: pixels along a hemicube face's edge (default 256)")
    ->check(CLI::Range(16, 4096));
  solveCommand->add_option("--shooter-size", solve.ShooterSize,
    "shooting element edge, fraction of the scene diagonal (default 0.25)")
    ->check(CLI::Range(1e-4, 1.0));
  solveCommand->add_option("--reference", solve.Reference,
    "analytic (scenes with a closed form), pathtraced, or a CSV x,y,z,E_r,E_g,E_b at the probes");
  solveCommand->add_option("--view", solve.ViewText,
    "the camera of --image and --exr: px,py,pz,fx,fy,fz[,ux,uy,uz[,angle]] (position, focal point, view up "
    "(default 0,0,1), vertical angle in degrees (default 30)); before a file's own");
  solveCommand->add_option("--reference-output", solve.ReferenceOutput,
    "write the analytic or path-traced reference at the probes (CSV x,y,z,E_r,E_g,E_b, path traced with its "
    "relative standard error SE, for --reference FILE)");
  solveCommand->add_option("--lights", solve.Lights,
    "LIGHTS.json: point, spot and directional lights and a sky (KHR_lights_punctual's fields, "
    "SPEC 'Lights and sky')");
  solveCommand->add_option("--reference-samples", solve.ReferenceSamples,
    "paths per probe for --reference pathtraced (default 16384)")
    ->check(CLI::Range(std::size_t(16), std::size_t(1) << 30));

  std::string outputDir = "out";
  CLI::App* demo = app.add_subcommand("demo", "solve, render and report the built-in Cornell box");
  demo->add_option("--output-dir", outputDir, "where the files go (default out/)");

  std::string benchDir = "bench/results/error-vs-time";
  bool quick = false;
  CLI::App* bench = app.add_subcommand("bench", "error against run time on the standard scenes");
  bench->add_option("--output-dir", benchDir, "where the CSVs, plots and table go");
  bench->add_flag("--quick", quick, "two settings per scene (under 2 minutes, for CI)");

  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::ParseError& e)
  {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try
  {
    if (*bench)
    {
      std::string noWindow;
      if (!vtkRadiosityView::CanOpenWindow(noWindow))
      {
        throw BadInput("bench writes its error-against-time plots: " + noWindow);
      }
      return cli::RunBench(benchDir, quick);
    }
    if (*demo)
    {
      std::string error;
      Check(cli::MakeDirectories(outputDir, error), error);
      SolveArguments d;
      d.Scene = "cornell";
      // The demo shows progressive refinement converging (unshot power,
      // overshooting, energy balance: README), not auto's choice.
      d.Method = "progressive";
      d.Output = outputDir + "/cornell.vtp";
      d.Image = outputDir + "/cornell.png";
      d.Exr = outputDir + "/cornell.exr";
      d.Report = outputDir + "/report.json";
      d.HistoryCsv = outputDir + "/convergence.csv";
      d.HistoryPng = outputDir + "/convergence.png";
      d.Reference = "pathtraced";
      d.DemoProbes = true;
      const int status = RunSolve(d);
      if (status == 0)
      {
        std::cout << "wrote " << d.Output << ", " << d.Image << ", " << d.Exr << ", " << d.Report
                  << ", " << d.HistoryCsv << ", " << d.HistoryPng << "\n";
      }
      return status;
    }
    solve.Height = solve.Width;
    return RunSolve(solve);
  }
  catch (const BadInput& e)
  {
    // SPEC: one line, "error: bad input: FILE: what, where, the value".
    std::cerr << "error: bad input: " << StripPrefix(e.what(), "bad input: ") << "\n";
    return 2;
  }
  catch (const std::bad_alloc&)
  {
    std::cerr << "internal error: out of memory (lower the settings, or --max-memory so that the "
                 "estimate refuses the solve before it starts)\n";
    return 1;
  }
  catch (const std::exception& e)
  {
    std::cerr << "internal error: " << StripPrefix(e.what(), "internal error: ") << "\n";
    return 1;
  }
}
