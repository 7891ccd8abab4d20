#include "SolveCommon.h"


#include "Bench.h"
#include "ExrWriter.h"
#include "InterpolantSolution.h"
#include "ProbeIO.h"
#include "ProgressBar.h"
#include "Report.h"
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
#include "Radiosity/Hierarchical/HierarchicalMethod.h"
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
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <sys/stat.h>

namespace solve
{
void ConfigureHierarchical(const SolveArguments& args, vtkRadiosityFilter* filter)
{
  if (!(args.LinkTolerance > 0.0))
  {
    throw BadInput("--link-tolerance must be positive");
  }
  int clustering = vtkRadiosityFilter::ClusteringAuto;
  if (args.Clustering == "on")
  {
    clustering = vtkRadiosityFilter::ClusteringOn;
  }
  else if (args.Clustering == "off")
  {
    clustering = vtkRadiosityFilter::ClusteringOff;
  }
  else if (args.Clustering != "auto")
  {
    throw BadInput("--clustering " + args.Clustering + ": expected auto, on or off");
  }
  filter->SetLinkTolerance(args.LinkTolerance);
  filter->SetMinElementSize(args.MinElementSize);
  filter->SetMaxRefinementRounds(args.MaxRefinementRounds);
  filter->SetClustering(clustering);
  filter->SetDiscontinuityMeshing(!args.NoDiscontinuityMeshing);
  filter->SetMaxDiscontinuitiesPerLeaf(args.DiscontinuitiesPerLeaf);
  filter->SetMinDiscontinuityWeight(args.MinDiscontinuityWeight);
}

/// Hardt & Teller's hierarchical radiosity with discontinuity meshing
/// (SPEC), through vtkRadiosityFilter: port 0 the constant leaves, port 1
/// the discontinuity mesh.
int FinishHierarchicalSolve(const SolveArguments& args, const std::vector<Probe>& probes,
  const std::vector<RGB>& reference, const std::string& referenceKind, SolveTarget& target,
  cli::ProgressBar& bar, RunPhases& phases)
{
  vtkRadiosityFilter* filter = target.Filter();
  const std::vector<std::string>& warnings = filter->GetWarnings();
  const SceneCleanupReport& cleanup = filter->GetCleanupReport();
  const Scene& scene = filter->GetScene();
  const SolverStatistics& stats = filter->GetStatistics();

  auto method = std::dynamic_pointer_cast<const HierarchicalMethod>(filter->GetSolver());
  if (!method)
  {
    throw std::runtime_error("the hierarchical solve produced no solution");
  }
  const bool meshing = !args.NoDiscontinuityMeshing && stats.Stop != StopReason::Aborted &&
    filter->GetOutput(1)->GetNumberOfCells() > 0;
  bar.Finish(std::string("stopped: ") + ToString(stats.Stop));
  // The filter reported the leaves that could not be triangulated among its warnings.
  const DiscontinuityMesh& mesh = method->LastMesh();
  const SolutionMesh& leaves = *filter->GetSolution();
  vtkPolyData* solved = meshing ? filter->GetOutput(1) : filter->GetOutput();
  const HierarchicalRadiosity& solver = *filter->GetHierarchicalSolution();
  const HierarchicalOptions& options = solver.Options();
  std::string error;

  // The discontinuity mesh is the method's product.
  phases.Part("meshing_s", meshing ? nlohmann::json(mesh.Seconds) : nlohmann::json(), "product_s");
  if (!args.Output.empty())
  {
    WriteVtp(solved, args.Output);
    phases.End("write_s");
  }
  // Probes: from the interpolants (meshing) or the constant leaves; a probe
  // on no surface is gathered from the leaves' radiosity; the punctual
  // lights exact at each sensor (HierarchicalMethod::EvaluateProbes).
  std::size_t gathered = 0, onMesh = 0;
  std::vector<RGB> probeValues;
  if (!args.ProbeOutput.empty() || !reference.empty())
  {
    probeValues = method->EvaluateProbes(probes, &gathered);
    if (meshing)
    {
      for (const RGB& v : EvaluateInterpolants(mesh, probes, 1e-6 * solver.Analysis().Diagonal))
      {
        onMesh += std::isfinite(Luminance(v)) ? 1 : 0;
      }
    }
  }
  phases.End("probes_s");
  WriteProbesAndHistory(
    args, probes, probeValues, stats.History, ", hierarchical radiosity", scene);
  phases.End("write_s");

  // The report is written before the picture is drawn (and again after it,
  // with the render's time): a render that fails loses none of the rest.
  const auto writeReport = [&]() {
    if (args.Report.empty())
    {
      return;
    }
    nlohmann::json report;
    report["method"] = "hierarchical";
    report["method_choice"] = MethodChoiceReport(args.Method, filter);
    report["parameters"] = { { "tolerance", options.Tolerance },
      { "max_iterations", options.MaxIterations }, { "max_time_s", options.MaxTimeSeconds },
      { "threads", options.Threads }, { "link_tolerance", options.RelativeLinkTolerance },
      { "link_tolerance_W_m2", solver.GetLinkTolerance() },
      { "min_element_size", options.MinElementSize },
      { "max_refinement_rounds", options.MaxRefinementRounds },
      { "clustering", args.Clustering }, { "clustered", solver.Clustered() },
      { "max_blockers_per_link", options.MaxBlockersPerLink },
      { "discontinuity_meshing", meshing },
      { "discontinuities", filter->GetDiscontinuityMeshing() },
      { "discontinuities_per_leaf", filter->GetMaxDiscontinuitiesPerLeaf() },
      { "min_discontinuity_weight", filter->GetMinDiscontinuityWeight() },
      { "conforming_boundaries", filter->GetConformingBoundaries() } };
    report["parameters"]["memory_budget_bytes"] = ResolveMemoryBudget(args.MaxMemory * 1e9);
    report["scene"] = { { "source", args.Scene }, { "triangles", scene.Triangles.size() },
      { "objects", scene.ObjectNames.size() }, { "emitters", scene.NumberOfEmitters() },
      { "lights", scene.Lighting.Lights.size() }, { "sky", scene.Lighting.SkyLight.Enabled() },
      { "emitted_power_W", stats.EmittedPowerW }, { "warnings", warnings },
      { "left_out",
        { { "degenerate_triangles_dropped", cleanup.DegenerateTrianglesDropped },
          { "solve_skipped_no_emitters", stats.Stop == StopReason::NoEmitters } } } };
    report["solution"] = { { "stop", ToString(stats.Stop) }, { "iterations", stats.Iterations },
      { "leaves", stats.Elements }, { "nodes", solver.Mesh().Elements().size() },
      { "links", stats.Links }, { "cluster_links", stats.ClusterLinks },
      { "partial_links", stats.PartialLinks },
      { "hidden_links", stats.HiddenLinks }, { "links_with_blockers_cut", stats.LinksWithBlockersCut },
      { "rays", stats.RaysCast },
      { "relative_unshot_power",
        stats.EmittedPowerW > 0 ? stats.UnshotPowerW / stats.EmittedPowerW : 0.0 },
      { "absorbed_power_W", stats.AbsorbedPowerW }, { "escaped_power_W", stats.EscapedPowerW },
      { "probes", probes.size() }, { "probes_on_the_mesh", onMesh },
      { "probes_gathered_off_surface", gathered } };
    if (meshing)
    {
      report["discontinuity_mesh"] = { { "leaves_meshed", mesh.LeavesMeshed },
        { "segments_found", mesh.SegmentsFound }, { "segments_kept", mesh.SegmentsKept },
        { "leaves_triangulation_failed", mesh.LeavesTriangulationFailed },
        { "leaves_past_time_limit", mesh.LeavesPastTimeLimit },
        { "leaves_sampled_past_time_limit", mesh.LeavesSampledPastTimeLimit },
        { "point_samples", mesh.PointSamples }, { "points", mesh.Points.size() },
        { "triangles", mesh.Triangles.size() }, { "interpolants", mesh.Interpolants.size() },
        { "seconds", mesh.Seconds }, { "discontinuities_s", mesh.DiscontinuitySeconds },
        { "point_samples_s", mesh.SampleSeconds } };
    }
    else
    {
      report["discontinuity_mesh"] = nullptr;
    }
    report["lights"] = LightsReport(scene);
    report["scene"]["import"] = target.ImportReport();
    if (reference.empty())
    {
      report["error"] = nullptr; // no reference known
    }
    else
    {
      const ConvergenceRow& last = stats.History.Rows.back();
      nlohmann::json e = ErrorHead(referenceKind, probes.size(), stats.ErrorProbesTracked);
      // The representation the user sees: the interpolants with meshing
      // (probes on the mesh), the constant leaves without.
      // Every probe, relative to the peak reference (a probe off the mesh is
      // an infinite error, null).
      double seenRms = last.RmsError, seenMax = last.MaxRelError;
      if (meshing)
      {
        const ErrorFigures interpolants = RelativeErrors(
          EvaluateInterpolants(mesh, probes, 1e-6 * solver.Analysis().Diagonal), reference);
        seenRms = interpolants.Rms;
        seenMax = interpolants.Max;
      }
      e["evaluated_from"] = meshing ? "quadratic interpolants" : "constant leaves";
      e["rms_relative_error"] = Finite(seenRms);
      e["max_relative_error"] = Finite(seenMax);
      e["leaves_rms_relative_error"] = Finite(last.RmsError);
      e["leaves_max_relative_error"] = Finite(last.MaxRelError);
      AddProbeOutputErrors(e, RelativeErrors(probeValues, reference));
      report["error"] = e;
    }
    ReportRunAndHistory(report, phases, stats);
    Check(cli::WriteFileAtomically(args.Report, report.dump(2) + "\n", error), error);
  };
  writeReport();
  if (!args.Image.empty() || !args.Exr.empty())
  {
    SolutionMesh interpolants; // for --exr only
    RenderOutputs(args, solved,
      [&]() -> const SolutionMesh* {
        if (!meshing)
        {
          return &leaves;
        }
        interpolants = cli::InterpolantSolution(mesh, scene);
        return &interpolants;
      },
      scene, nullptr, target.Camera());
    phases.End("render_s");
    writeReport();
  }
  std::cerr << "solved " << args.Scene << " (" << EmitterSummary(scene) << "): " << stats.Elements
            << " leaves, " << stats.Links
            << " links (" << stats.PartialLinks << " partial), " << stats.Iterations
            << " sweeps, " << stats.SolveSeconds << " s";
  if (meshing)
  {
    std::cerr << "; discontinuity mesh: " << mesh.Triangles.size() << " triangles, "
              << mesh.LeavesMeshed << " leaves meshed, " << mesh.Seconds << " s";
  }
  std::cerr << "\n";
  return 0;
}

} // namespace solve
