// What the solve paths of the vtkradiosity program share: its arguments,
// bad-input errors, and the writers of outputs, images and histories.
#ifndef vtkradiosity_SolveCommon_h
#define vtkradiosity_SolveCommon_h

#include "ProgressBar.h"

#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"

#include "Radiosity/Common/ConvergenceHistory.h"
#include "Radiosity/Common/ErrorMetrics.h"
#include "Radiosity/Hierarchical/DiscontinuityMesher.h"
#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Common/Scene.h"
#include "Radiosity/Common/SolutionMesh.h"
#include "Radiosity/Common/SolverTypes.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

class vtkDataObject;
class vtkRadiosityFilter;

namespace radiosity
{
namespace cli
{
struct ViewCamera;
}
}

namespace solve
{
using Clock = std::chrono::steady_clock;
using namespace radiosity;

/// Bad input: exit status 2, message on stderr, nothing written.
struct BadInput : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct SolveArguments
{
  std::string Scene;
  std::string Method = "auto";
  double Tolerance = 1e-3;
  long long MaxIterations = 200000;
  double MaxTime = 0.0;
  int Threads = 0;
  double MaxReflectance = 0.95; ///< .mtl Kd clamped to it (SPEC, Scenes), in (0, 1)
  bool TwoSided = false; ///< --two-sided: every surface solved on both sides
  std::string ReferenceOutput; ///< --reference-output: the computed reference at the probes (CSV)
  /// --view px,py,pz,fx,fy,fz[,ux,uy,uz[,angle]]: the camera of --image and
  /// --exr (position, focal point, view up, vertical angle in degrees),
  /// before a file's own; read into View (empty: none).
  std::string ViewText;
  std::vector<double> View;
  double MaxMemory = 0.0; ///< GB; 0: 75% of physical memory
  std::string Output, Image, Exr, Probes, ProbeOutput, Report, HistoryCsv, HistoryPng;
  std::string Reference;
  std::string Lights; ///< --lights LIGHTS.json (SPEC "Lights and sky")
  std::size_t ReferenceSamples = 16384;
  std::string ReferenceExr;
  std::size_t ReferencePixelSamples = 64;
  bool DemoProbes = false; ///< the demo's fixed sensors with a path-traced reference
  int Width = 800, Height = 800;
  bool NoOvershooting = false;
  double ElementSize = 1.0 / 16.0;
  double ShooterSize = 0.25;
  int HemicubeResolution = 256; ///< progressive-gpu: item buffer pixels per face edge
  // --method hierarchical
  double LinkTolerance = 0.05;   ///< relative to the scene's mean irradiance
  double MinElementSize = 1.0 / 64.0;
  int MaxRefinementRounds = 4;
  std::string Clustering = "auto"; ///< hierarchical: auto|on|off
  bool NoDiscontinuityMeshing = false;
  int DiscontinuitiesPerLeaf = 10;
  double MinDiscontinuityWeight = 0.05; ///< relative to the brightest emitter (none: the brightest radiosity)
  // --method meshless
  double PointRadius = 0.1; ///< coarsest Poisson-disk radius, fraction of the diagonal
  int PointLevels = 5;
  int GatherRays = 256;
  double VariationThreshold = 0.01;
  // --method facecluster
  std::string IrradianceBasis = "linear";
  std::string RadiosityBasis = "constant";
  double TransferTolerance = 1e-5; ///< relative to the emitted power
  int MaxBisections = 5;
  bool NoExactEmitters = false;
};

double Since(Clock::time_point t);

/// The report's time section (SPEC: time per phase): the run's phases one
/// after another, each named and timed where it ends, so that they add up
/// to the run's wall time; parts of a phase (the face cluster hierarchy in
/// the preprocessing, the meshless bounces in the solve, ...) beside them.
class RunPhases
{
public:
  explicit RunPhases(Clock::time_point start)
    : Start(start)
    , Mark(start)
  {
  }
  /// Ends the phase that ran since the last end as `name` (added to it
  /// when it ran before: the writes).
  void End(const std::string& name);
  /// Ends the phase since the last end as the filter's phases (its
  /// preprocessing, solve, output evaluation and product) and the rest of
  /// it as pipeline_s: the VTK pipeline's own work around them and, for an
  /// imported scene, vtkRadiosityPass gathering the renderer's scene.
  void EndFilter(const vtkRadiosityFilter& filter);
  /// `name` (seconds, or null) as a part of the phase `of`, not a phase.
  void Part(const std::string& name, const nlohmann::json& seconds, const std::string& of);
  /// Every phase and part; "phases": the phases' names in run order;
  /// "part_of": each part's phase; "total_s": the run's wall time so far;
  /// "unaccounted_s": total_s less the phases (the time since the last end).
  nlohmann::json Json() const;

private:
  Clock::time_point Start, Mark;
  std::vector<std::pair<std::string, double>> Phases;
  nlohmann::json Parts = nlohmann::json::object(), PartOf = nlohmann::json::object();
};
vtkSmartPointer<vtkTable> HistoryTable(const ConvergenceHistory& history);
void Check(bool ok, const std::string& error);
/// A filter's LastError as an exception: "bad input: ..." as BadInput (exit
/// status 2), anything else (an internal error, out of memory) as
/// std::runtime_error (exit status 1); nothing when empty.
void ThrowFilterError(const std::string& message);
std::vector<Probe> CornellDemoProbes();
/// --two-sided on a loaded scene: SPEC's TwoSided cell array, 1 on every
/// cell of every polydata in `input` (a leaf of another type is converted
/// to its outer surface by the filter and keeps its one side: a warning).
void MarkTwoSided(vtkDataObject* input);
void WriteVtp(vtkPolyData* data, const std::string& file);
/// `camera`: the view of --image and --exr (an imported file's camera);
/// null: the Cornell box's for `cornell`, else framing the scene.
/// `radiance` gives the solution that --exr ray casts (asked only then).
void RenderOutputs(const SolveArguments& args, vtkPolyData* solved,
  const std::function<const SolutionMesh*()>& radiance, const Scene& scene,
  vtkPolyData* shepardField = nullptr, const cli::ViewCamera* camera = nullptr);
void WriteHistoryPlot(const ConvergenceHistory& history, const std::string& file,
  const std::string& title);
nlohmann::json Finite(double v);
class SolveTarget;
/// Sets the settings every method shares (tolerance, limits, threads, the
/// error reference) on the target's filter, solves with the progress bar,
/// refuses bad input (BadInput; for an imported scene the message starts
/// with the file) and prints the warnings; the caller sets the method's own.
/// `lights` (--lights, read by ReadLights) go to the filter's SetSceneLights.
/// An imported scene is known only once gathered: its --reference analytic
/// or pathtraced is computed after the solve from the scene solved (into
/// `reference` and `referenceKind`; the history then has no error columns).
/// `phases`: the filter's phases ended (EndFilter), then reference_s.
void RunRadiosityFilter(SolveTarget& target, const SolveArguments& args,
  const std::vector<Probe>& probes, std::vector<RGB>& reference, std::string& referenceKind,
  const LightSet& lights, cli::ProgressBar& bar, RunPhases& phases);
/// --reference analytic or pathtraced at `probes` for `scene` (its lights
/// included); BadInput when the scene has no closed form.
void ComputeReference(const SolveArguments& args, const Scene& scene, const std::vector<Probe>& probes,
  std::vector<RGB>& reference, std::string& referenceKind);
/// --lights: the file read and checked (before anything is solved or
/// written); a bad file or light is BadInput naming the file, the light's
/// index and the field. Empty without --lights.
LightSet ReadLights(const SolveArguments& args);
/// --probe-output, --history and --history-plot (`method` ends the plot
/// title). With a sky in `scene`, the probe output has the column DF.
void WriteProbesAndHistory(const SolveArguments& args, const std::vector<Probe>& probes,
  const std::vector<RGB>& values, const ConvergenceHistory& history, const std::string& method,
  const Scene& scene);
/// The report's "lights" section (SPEC "Lights and sky"): every punctual
/// light (type, position and/or direction, intensity RGB, emitted power for
/// point and spot, the power the scene's front faces receive from it,
/// DirectLighting::ReceivedPower), the sky (model, up, radiance, received
/// power) and E_unobstructed (RGB and luminance; null without a sky).
nlohmann::json LightsReport(const Scene& scene);
/// The console line about emitters: "N emitting triangles, M lights[, a sky]".
std::string EmitterSummary(const Scene& scene);
/// The report's run figures every method shares: time per phase (report_s
/// ended here: call it last, before the report is written) and in all,
/// peak memory, the convergence history.
void ReportRunAndHistory(nlohmann::json& report, RunPhases& phases, const SolverStatistics& stats);
/// The head of the report's error section: the reference and the probes.
nlohmann::json ErrorHead(const std::string& referenceKind, std::size_t probes, std::size_t onSurface);
/// The error figures of the probe output (every probe, ErrorMetrics.h): peak-
/// and per-probe relative RMS and maximum, probes counted and not finite.
void AddProbeOutputErrors(nlohmann::json& e, const ErrorFigures& all);

/// The hierarchical options of `args` (--link-tolerance, --clustering,
/// discontinuity meshing) on `filter`, for --method hierarchical and auto;
/// a bad one is BadInput, before anything is solved.
void ConfigureHierarchical(const SolveArguments& args, vtkRadiosityFilter* filter);
/// The rest of `solve` once the filter solved with the hierarchical method
/// (--method hierarchical, or auto's choice): outputs, probes, report.
int FinishHierarchicalSolve(const SolveArguments& args, const std::vector<Probe>& probes,
  const std::vector<RGB>& reference, const std::string& referenceKind, SolveTarget& target,
  cli::ProgressBar& bar, RunPhases& phases);
/// The report's "method_choice": the method asked for (--method), the one
/// solved with and, for auto, why (vtkRadiosityFilter::GetMethodChoice;
/// null otherwise).
nlohmann::json MethodChoiceReport(const std::string& requested, const vtkRadiosityFilter* filter);
} // namespace solve

#endif
