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
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
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
#include "Radiosity/Common/DirectLighting.h"
#include "Radiosity/Common/ErrorMetrics.h"
#include "Radiosity/Common/Lights.h"
#include "Radiosity/Scenes/OfficeScene.h"
#include "Radiosity/Reference/PathTracer.h"
#include "Radiosity/Scenes/SceneGenerators.h"
#include "Radiosity/Common/SystemInfo.h"
#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Common/RadianceImage.h"
#include "Radiosity/Common/SolutionMesh.h"

#include <CLI/CLI.hpp>

#include <csignal>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <sys/stat.h>

namespace solve
{
double Since(Clock::time_point t)
{
  return std::chrono::duration<double>(Clock::now() - t).count();
}

void RunPhases::End(const std::string& name)
{
  const auto now = Clock::now();
  const double seconds = std::chrono::duration<double>(now - this->Mark).count();
  this->Mark = now;
  for (auto& phase : this->Phases)
  {
    if (phase.first == name)
    {
      phase.second += seconds;
      return;
    }
  }
  this->Phases.emplace_back(name, seconds);
}

void RunPhases::EndFilter(const vtkRadiosityFilter& filter)
{
  const double block = Since(this->Mark);
  const std::pair<const char*, double> own[] = { { "preprocessing_s", filter.GetPreprocessSeconds() },
    { "solve_s", filter.GetSolveWallSeconds() }, { "output_evaluation_s", filter.GetOutputSeconds() },
    { "product_s", filter.GetProductSeconds() } };
  double measured = 0.0;
  for (const auto& phase : own)
  {
    this->Phases.emplace_back(phase.first, phase.second);
    measured += phase.second;
  }
  this->Phases.emplace_back("pipeline_s", std::max(0.0, block - measured));
  this->Mark += std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(block));
}

void RunPhases::Part(const std::string& name, const nlohmann::json& seconds, const std::string& of)
{
  this->Parts[name] = seconds;
  this->PartOf[name] = of;
}

nlohmann::json RunPhases::Json() const
{
  nlohmann::json time = this->Parts;
  nlohmann::json names = nlohmann::json::array();
  double sum = 0.0;
  for (const auto& phase : this->Phases)
  {
    time[phase.first] = phase.second;
    names.push_back(phase.first);
    sum += phase.second;
  }
  const double total = Since(this->Start);
  time["phases"] = names;
  time["part_of"] = this->PartOf;
  time["total_s"] = total;
  time["unaccounted_s"] = total - sum;
  return time;
}

vtkSmartPointer<vtkTable> HistoryTable(const ConvergenceHistory& history)
{
  auto table = vtkSmartPointer<vtkTable>::New();
  const auto names = ConvergenceHistory::ColumnNames();
  std::vector<vtkSmartPointer<vtkDoubleArray>> columns;
  for (const auto& name : names)
  {
    auto c = vtkSmartPointer<vtkDoubleArray>::New();
    c->SetName(name.c_str());
    c->SetNumberOfTuples(static_cast<vtkIdType>(history.Rows.size()));
    columns.push_back(c);
    table->AddColumn(c);
  }
  for (std::size_t i = 0; i < history.Rows.size(); ++i)
  {
    const ConvergenceRow& r = history.Rows[i];
    const double row[7] = { static_cast<double>(r.Iteration), r.TimeSeconds, r.UnshotPowerW,
      r.EnergyBalance, r.RmsError, r.MaxRelError, r.OvershootPowerW };
    for (std::size_t c = 0; c < columns.size(); ++c)
    {
      columns[c]->SetValue(static_cast<vtkIdType>(i), row[c]);
    }
  }
  return table;
}

void ThrowFilterError(const std::string& message)
{
  if (message.empty())
  {
    return;
  }
  const std::string bad = "bad input: ";
  if (message.compare(0, bad.size(), bad) == 0)
  {
    throw BadInput(message.substr(bad.size()));
  }
  throw std::runtime_error(message);
}

void Check(bool ok, const std::string& error)
{
  if (!ok)
  {
    throw std::runtime_error(error);
  }
}

/// Sensors for the demo's error curve: the centre of every input triangle of
/// the Cornell box but the light's, facing the way the triangle does.
void MarkTwoSided(vtkDataObject* input)
{
  const auto mark = [](vtkDataObject* leaf) {
    auto* pd = vtkPolyData::SafeDownCast(leaf);
    if (!pd)
    {
      std::cerr << "warning: --two-sided: a " << (leaf ? leaf->GetClassName() : "null")
                << " block is solved on one side (only polydata takes the TwoSided array)\n";
      return;
    }
    vtkNew<vtkIntArray> sides;
    sides->SetName("TwoSided");
    sides->SetNumberOfTuples(pd->GetNumberOfCells());
    sides->FillValue(1);
    pd->GetCellData()->AddArray(sides);
  };
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      mark(it->GetCurrentDataObject());
    }
    return;
  }
  mark(input);
}

std::vector<Probe> CornellDemoProbes()
{
  const Scene box = MakeCornellBox();
  std::vector<Probe> probes;
  for (std::size_t t = 0; t < box.Triangles.size(); ++t)
  {
    if (MaxComponent(box.Materials[t].Emission) == 0.0)
    {
      probes.push_back(Probe{ box.Centroid(t), box.Normal(t) });
    }
  }
  return probes;
}

void WriteVtp(vtkPolyData* data, const std::string& file)
{
  std::string error;
  Check(cli::WriteThroughTemporary(file, ".vtp",
          [data](const std::string& temporary) {
            vtkNew<vtkXMLPolyDataWriter> writer;
            writer->SetFileName(temporary.c_str());
            writer->SetInputData(data);
            writer->SetDataModeToAppended();
            return writer->Write() == 1;
          },
          error),
    error);
}

namespace
{
// VTK's X window aborts the process when it cannot open its display ("bad X
// server connection": no DISPLAY, or an Xvfb resetting as its last client
// left). Everything else is written by then (the picture is drawn last):
// the abort becomes an error that says so, exit status 1.
extern "C" void RenderAborted(int)
{
  static const char message[] =
    "error: the picture could not be drawn (VTK aborted: no display?); the solution, the sensors' values "
    "and the report asked for are written\n";
  const ssize_t ignored = write(2, message, sizeof message - 1);
  (void)ignored;
  _exit(1);
}

struct AbortIsARenderError
{
  AbortIsARenderError() { this->Previous = std::signal(SIGABRT, RenderAborted); }
  ~AbortIsARenderError() { std::signal(SIGABRT, this->Previous); }
  void (*Previous)(int) = nullptr;
};
}

/// --image through vtkRadiosityView (which draws the quadratic interpolants
/// per pixel when the polydata has them, and splats `shepardField` per pixel
/// when given) and --exr by ray casting `radiance` from the same camera;
/// --reference-exr path traces that view.
void RenderOutputs(const SolveArguments& args, vtkPolyData* solved,
  const std::function<const SolutionMesh*()>& radiance, const Scene& scene,
  vtkPolyData* shepardField, const cli::ViewCamera* camera)
{
  if (args.Image.empty() && args.Exr.empty())
  {
    return;
  }
  std::string error;
  const AbortIsARenderError guard;
  cli::ViewCamera asked; // --view, before a file's own camera
  if (!args.View.empty())
  {
    for (int k = 0; k < 3; ++k)
    {
      asked.Position[k] = args.View[k];
      asked.FocalPoint[k] = args.View[3 + k];
      asked.ViewUp[k] = args.View.size() >= 9 ? args.View[6 + k] : (k == 2 ? 1.0 : 0.0);
    }
    asked.ViewAngle = args.View.size() == 10 ? args.View[9] : 30.0;
    camera = &asked;
  }
  vtkNew<vtkRadiosityView> view;
  view->SetInputData(solved);
  view->SetShepardField(shepardField);
  view->SetSize(args.Width, args.Height);
  if (camera)
  {
    view->SetCamera(camera->Position, camera->FocalPoint, camera->ViewUp, camera->ViewAngle);
  }
  else if (args.Scene == "cornell")
  {
    double position[3], focal[3], up[3], angle;
    vtkCornellBoxSource::GetCamera(position, focal, up, angle);
    view->SetCamera(position, focal, up, angle);
  }
  Check(view->Render(), "cannot render the solution");
  if (!args.Image.empty())
  {
    Check(cli::WriteThroughTemporary(args.Image, ".png",
            [&view](const std::string& temporary) { return view->WritePNG(temporary.c_str()); }, error),
      error);
  }
  if (!args.Exr.empty())
  {
    // Same camera as the PNG, linear radiance by ray casting the solution.
    vtkCamera* camera = view->GetRenderer()->GetActiveCamera();
    PinholeCamera pinhole;
    double v[3];
    camera->GetPosition(v);
    pinhole.Position = Vec3(v[0], v[1], v[2]);
    camera->GetFocalPoint(v);
    pinhole.FocalPoint = Vec3(v[0], v[1], v[2]);
    camera->GetViewUp(v);
    pinhole.ViewUp = Vec3(v[0], v[1], v[2]);
    pinhole.ViewAngleDegrees = camera->GetViewAngle();
    const RadianceImage image = RenderRadiance(*radiance(), pinhole, args.Width, args.Height);
    Check(cli::WriteExrHalf(args.Exr, image, error), error);
    if (!args.ReferenceExr.empty())
    {
      // The path-traced reference of the same view, pixel for pixel.
      PathTracerOptions options;
      const PathTracer tracer(scene, options);
      const RadianceImage truth =
        tracer.Render(pinhole, args.Width, args.Height, args.ReferencePixelSamples);
      Check(cli::WriteExrHalf(args.ReferenceExr, truth, error), error);
    }
  }
}

void WriteHistoryPlot(const ConvergenceHistory& history, const std::string& file,
  const std::string& title)
{
  vtkNew<vtkRadiosityConvergenceChart> chart;
  chart->SetInputData(HistoryTable(history));
  chart->SetTitle(title.c_str());
  chart->RemoveAllColumns();
  chart->AddColumn("unshot_power_W", "unshot power (W)");
  chart->AddColumn("overshoot_power_W", "power shot in advance by overshooting (W)");
  chart->AddColumn("energy_balance", "|energy balance| (relative)");
  chart->AddColumn("rms_error", "RMS relative irradiance error at the probes");
  chart->AddColumn("max_rel_error", "max relative irradiance error");
  std::string error;
  Check(cli::WriteThroughTemporary(file, ".png",
          [&chart](const std::string& temporary) { return chart->WritePNG(temporary.c_str(), 900, 500); },
          error),
    error);
}

nlohmann::json Finite(double v)
{
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

/// The discontinuity mesh as polydata: the SPEC output arrays (cell values
/// the interpolants' means, point values the accurate samples) and the cell
/// array QuadraticInterpolant (18 components, channel-major: 6c + k is
/// coefficient k of channel c, in the triangle's point order).
LightSet ReadLights(const SolveArguments& args)
{
  if (args.Lights.empty())
  {
    // The built-in office brings its own lamp and sky; --lights replaces them.
    return args.Scene == "office" ? MakeOfficeScene().Lighting : LightSet();
  }
  try
  {
    return ReadLightsFile(args.Lights);
  }
  catch (const SceneError& e)
  {
    throw BadInput(e.what());
  }
  catch (const nlohmann::json::exception& e)
  {
    // nlohmann's refusals outside its parse errors (a number overflowing a
    // double, 1e999) are bad input too, not an internal failure.
    throw BadInput(args.Lights + ": not a valid lights file: " + e.what());
  }
}

namespace
{
nlohmann::json Triple(const Vec3& v)
{
  return nlohmann::json::array({ v.x, v.y, v.z });
}
}

nlohmann::json LightsReport(const Scene& scene)
{
  const LightSet& set = scene.Lighting;
  nlohmann::json report;
  report["count"] = set.Lights.size();
  std::vector<RGB> received;
  if (!set.Empty() && !scene.Triangles.empty())
  {
    received = DirectLighting(scene).ReceivedPower();
  }
  const auto receivedAt = [&received](std::size_t i) {
    return i < received.size() ? Triple(received[i]) : nlohmann::json();
  };
  nlohmann::json lights = nlohmann::json::array();
  for (std::size_t i = 0; i < set.Lights.size(); ++i)
  {
    const Light& l = set.Lights[i];
    nlohmann::json entry;
    entry["index"] = i;
    entry["type"] = LightTypeName(l.Type);
    if (!l.Name.empty())
    {
      entry["name"] = l.Name;
    }
    if (l.Type != LightType::Directional)
    {
      entry["position"] = Triple(l.Position);
    }
    if (l.Type != LightType::Point)
    {
      entry["direction"] = Triple(l.Direction);
    }
    entry["intensity"] = Triple(l.Intensity);
    entry["intensity_unit"] = l.Type == LightType::Directional ? "W/m^2" : "W/sr";
    if (l.Type == LightType::Spot)
    {
      entry["inner_cone_angle"] = l.InnerConeAngle;
      entry["outer_cone_angle"] = l.OuterConeAngle;
    }
    entry["emitted_power_W"] =
      l.Type == LightType::Directional ? nlohmann::json() : Triple(EmittedPower(l));
    entry["received_power_W"] = receivedAt(i);
    lights.push_back(entry);
  }
  report["lights"] = lights;
  if (set.SkyLight.Enabled())
  {
    const RGB e = UnobstructedHorizontalIrradiance(set.SkyLight);
    report["sky"] = { { "model", SkyModelName(set.SkyLight.Model) }, { "up", Triple(set.SkyLight.Up) },
      { "radiance", Triple(set.SkyLight.Radiance) },
      { "radiance_is", set.SkyLight.Model == SkyModel::Uniform ? "uniform" : "zenith" },
      { "received_power_W", receivedAt(set.Lights.size()) } };
    report["E_unobstructed"] = { { "rgb", Triple(e) }, { "luminance", Luminance(e) },
      { "unit", "W/m^2" } };
  }
  else
  {
    report["sky"] = nullptr;
    report["E_unobstructed"] = nullptr;
  }
  return report;
}

std::string EmitterSummary(const Scene& scene)
{
  std::string text = std::to_string(scene.NumberOfEmitters()) + " emitting triangles, " +
    std::to_string(scene.Lighting.Lights.size()) + " lights";
  if (scene.Lighting.SkyLight.Enabled())
  {
    text += std::string(", a ") + SkyModelName(scene.Lighting.SkyLight.Model) + " sky";
  }
  return text;
}

void ComputeReference(const SolveArguments& args, const Scene& scene, const std::vector<Probe>& probes,
  std::vector<RGB>& reference, std::string& referenceKind)
{
  std::string error;
  reference.clear();
  std::vector<double> standardErrors; // path traced: each value's, relative
  if (args.Reference == "analytic")
  {
    AnalyticReference analytic;
    if (!ComputeAnalyticReference(scene, probes, analytic, error))
    {
      throw BadInput("--reference analytic: " + error);
    }
    reference = analytic.Irradiance;
    referenceKind = "analytic: " + analytic.Kind;
  }
  else if (args.Reference == "pathtraced")
  {
    PathTracerOptions options;
    options.SamplesPerProbe = args.ReferenceSamples;
    const PathTracer tracer(scene, options);
    double worst = 0.0;
    for (const ReferenceValue& v : tracer.Irradiance(probes))
    {
      reference.push_back(v.Value);
      const double relative = Luminance(v.Value) > 0 ? Luminance(v.StandardError) / Luminance(v.Value) : 0.0;
      standardErrors.push_back(relative);
      worst = std::max(worst, relative);
    }
    char kind[160];
    std::snprintf(kind, sizeof kind,
      "path traced: %zu paths per probe, largest relative standard error %.2e",
      args.ReferenceSamples, worst);
    referenceKind = kind;
  }
  if (!args.ReferenceOutput.empty() && !reference.empty())
  {
    // Kept for later runs' --reference FILE: a converged path-traced
    // reference costs more than the solves it measures.
    Check(cli::WriteProbeValues(args.ReferenceOutput, probes, reference, error, nullptr,
            standardErrors.empty() ? nullptr : &standardErrors),
      error);
  }
}

void RunRadiosityFilter(SolveTarget& target, const SolveArguments& args,
  const std::vector<Probe>& probes, std::vector<RGB>& reference, std::string& referenceKind,
  const LightSet& lights, cli::ProgressBar& bar, RunPhases& phases)
{
  vtkRadiosityFilter* filter = target.Filter();
  filter->SetSceneLights(target.SceneLights(lights));
  filter->SetTolerance(args.Tolerance);
  filter->SetMaxIterations(args.MaxIterations);
  filter->SetMaxTime(args.MaxTime);
  filter->SetNumberOfThreads(args.Threads);
  filter->SetMaxMemory(args.MaxMemory);
  filter->SetErrorReference(reference.empty() ? std::vector<Probe>() : probes, reference);
  filter->GlobalWarningDisplayOff(); // messages go through our own stderr lines
  filter->SetStatusCallback([&bar](const ProgressStatus& status) { return bar.Update(status); });
  target.Update();
  phases.EndFilter(*filter);
  filter->GlobalWarningDisplayOn();
  try
  {
    ThrowFilterError(filter->GetLastError());
  }
  catch (const BadInput& e)
  {
    // The pass names the actor, the array or the light; the file is ours to name.
    if (target.IsImported())
    {
      throw BadInput(args.Scene + ": " + e.what());
    }
    throw;
  }
  if (target.IsImported() && reference.empty() &&
    (args.Reference == "analytic" || args.Reference == "pathtraced"))
  {
    ComputeReference(args, filter->GetScene(), probes, reference, referenceKind);
    phases.End("reference_s");
  }
  for (const auto& w : target.PassWarnings())
  {
    std::cerr << "warning: " << w << "\n";
  }
  for (const auto& w : filter->GetWarnings())
  {
    std::cerr << "warning: " << w << "\n";
  }
  const SolverStatistics& stats = filter->GetStatistics();
  ProgressStatus done;
  done.Phase = "solved";
  done.Iteration = stats.Iterations;
  done.Residual = stats.EmittedPowerW > 0 ? stats.UnshotPowerW / stats.EmittedPowerW : 0.0;
  done.Fraction = 1.0;
  bar.Update(done);
}

void WriteProbesAndHistory(const SolveArguments& args, const std::vector<Probe>& probes,
  const std::vector<RGB>& values, const ConvergenceHistory& history, const std::string& method,
  const Scene& scene)
{
  std::string error;
  if (!args.ProbeOutput.empty())
  {
    // With a sky, the daylight factor column DF (SPEC "Lights and sky").
    const RGB sky = UnobstructedHorizontalIrradiance(scene.Lighting.SkyLight);
    Check(cli::WriteProbeValues(args.ProbeOutput, probes, values, error,
            scene.Lighting.SkyLight.Enabled() ? &sky : nullptr),
      error);
  }
  if (!args.HistoryCsv.empty())
  {
    Check(cli::WriteFileAtomically(args.HistoryCsv, cli::HistoryCsv(history), error), error);
  }
  if (!args.HistoryPng.empty())
  {
    WriteHistoryPlot(history, args.HistoryPng, "Convergence: " + args.Scene + method);
  }
}

void ReportRunAndHistory(nlohmann::json& report, RunPhases& phases, const SolverStatistics& stats)
{
  report["peak_memory_bytes"] = PeakMemoryBytes();
  report["convergence_history"] = cli::HistoryJson(stats.History);
  phases.End("report_s");
  report["time"] = phases.Json();
}

nlohmann::json ErrorHead(const std::string& referenceKind, std::size_t probes, std::size_t onSurface)
{
  nlohmann::json e;
  e["reference"] = referenceKind;
  e["probes"] = probes;
  e["probes_on_a_surface"] = onSurface;
  return e;
}

void AddProbeOutputErrors(nlohmann::json& e, const ErrorFigures& all)
{
  // The probe output (every probe): the error relative to the peak reference
  // irradiance, then each probe's error relative to its own reference.
  e["probe_output_rms_relative_error"] = Finite(all.Rms);
  e["probe_output_max_relative_error"] = Finite(all.Max);
  e["probe_output_rms_per_probe_relative_error"] = Finite(all.RmsRelative);
  e["probe_output_max_per_probe_relative_error"] = Finite(all.MaxRelative);
  e["probe_output_probes_counted"] = all.Counted;
  e["probe_output_probes_not_finite"] = all.NotFinite;
  e["peak_reference_irradiance"] = Finite(all.Peak);
}

nlohmann::json MethodChoiceReport(const std::string& requested, const vtkRadiosityFilter* filter)
{
  const std::string& why = filter->GetMethodChoice();
  return { { "requested", requested },
    { "chosen", vtkRadiosityFilter::GetMethodName(filter->GetResolvedMethod()) },
    { "why", why.empty() ? nlohmann::json() : nlohmann::json(why) } };
}
} // namespace solve
