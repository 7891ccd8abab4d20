// Lights and sky (issue 17): error against run time for each method on the
// analytic light cases (Scenes/LightScenes.h, exact answers from
// Reference/AnalyticLights.h) and on the daylit office (Scenes/OfficeScene.h,
// against a path tracer of 2^21 paths per sensor), each method at two or
// three settings, and the path tracer itself at about the method's time
// (its error against the same reference). Error: the project's metric,
// max |value - reference| / peak reference over the probes. Writes
// <dir>/lights.md and <dir>/lights-error-vs-time.csv.
//   bench_lights <dir> [--quick]
#include "BenchArguments.h"

#include "Radiosity/Common/ErrorMetrics.h"
#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Common/Stopwatch.h"
#include "Radiosity/FaceCluster/FaceClusterMethod.h"
#include "Radiosity/Hierarchical/HierarchicalMethod.h"
#include "Radiosity/Meshless/MeshlessMethod.h"
#include "Radiosity/Progressive/ProgressiveMethod.h"
#include "Radiosity/Reference/AnalyticReference.h"
#include "Radiosity/Reference/PathTracer.h"
#include "Radiosity/Scenes/LightScenes.h"
#include "Radiosity/Scenes/OfficeScene.h"

#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace radiosity;

namespace
{
struct Setting
{
  std::string Method, Label;
  std::function<std::unique_ptr<RadiositySolver>(std::shared_ptr<const Scene>)> Make;
};

std::vector<Setting> Settings(bool quick)
{
  std::vector<Setting> out;
  for (double size : quick ? std::vector<double>{ 1.0 / 16 } : std::vector<double>{ 1.0 / 8, 1.0 / 16, 1.0 / 32 })
  {
    out.push_back({ "progressive", "element " + std::to_string(size).substr(0, 6),
      [size](std::shared_ptr<const Scene> s) {
        ProgressiveOptions o;
        o.InitialElementSize = size;
        return std::make_unique<ProgressiveMethod>(s, o);
      } });
  }
  for (double tolerance : quick ? std::vector<double>{ 0.05 } : std::vector<double>{ 0.2, 0.05 })
  {
    out.push_back({ "hierarchical", "link tolerance " + std::to_string(tolerance).substr(0, 4),
      [tolerance](std::shared_ptr<const Scene> s) {
        HierarchicalOptions o;
        o.RelativeLinkTolerance = tolerance;
        return std::make_unique<HierarchicalMethod>(s, o, DiscontinuityMeshOptions());
      } });
  }
  for (int levels : quick ? std::vector<int>{ 3 } : std::vector<int>{ 3, 5 })
  {
    out.push_back({ "meshless", std::to_string(levels) + " levels",
      [levels](std::shared_ptr<const Scene> s) {
        MeshlessOptions o;
        o.Placement.Levels = levels;
        return std::make_unique<MeshlessMethod>(s, o);
      } });
  }
  for (int bisections : quick ? std::vector<int>{ 10 } : std::vector<int>{ 4, 10 })
  {
    out.push_back({ "facecluster", std::to_string(bisections) + " light bisections",
      [bisections](std::shared_ptr<const Scene> s) {
        FaceClusterSettings o;
        o.MaxLightBisections = bisections;
        return std::make_unique<FaceClusterMethod>(s, o);
      } });
  }
  return out;
}

struct Case
{
  std::string Name;
  std::shared_ptr<const Scene> Geometry;
  std::vector<Probe> Probes;
  std::vector<RGB> Reference;
  std::string ReferenceKind;
};
}

int main(int argc, char* argv[])
{
  BenchArguments args;
  if (!args.Parse(argc, argv))
  {
    return 2;
  }
  std::vector<Case> cases;
  for (const LightCase& c : AnalyticLightCases(1.0))
  {
    AnalyticReference exact;
    std::string why;
    if (!ComputeAnalyticReference(c.Geometry, c.Probes, exact, why))
    {
      std::cerr << c.Name << ": no closed form (" << why << ")\n";
      return 1;
    }
    cases.push_back({ c.Name, std::make_shared<const Scene>(c.Geometry), c.Probes, exact.Irradiance, "exact" });
  }
  {
    auto office = std::make_shared<const Scene>(MakeOfficeScene(false, true));
    std::vector<Probe> probes;
    const std::vector<Probe> grid = OfficeSensorGrid();
    for (std::size_t i = 0; i < grid.size(); i += 3)
    {
      probes.push_back(grid[i]);
    }
    PathTracerOptions o;
    o.SamplesPerProbe = args.Quick ? (1u << 17) : (1u << 21);
    std::vector<RGB> reference;
    for (const ReferenceValue& v : PathTracer(*office, o).Irradiance(probes))
    {
      reference.push_back(v.Value);
    }
    cases.push_back({ "office daylight (CIE overcast)", office, probes, reference,
      "path tracer, " + std::to_string(o.SamplesPerProbe) + " paths" });
  }

  std::ofstream csv(args.Directory + "/lights-error-vs-time.csv");
  csv << "case,method,setting,seconds,max_error_of_peak,rms_error_of_peak\n";
  std::ostringstream md;
  args.WriteHeading(md, "Lights and sky: error against run time");
  md << "Each method at its settings on every light case; the path tracer (MIS, next-event "
        "estimation of every light, the sky on escaping paths) given about the same time per "
        "case as the method's fastest setting. Error: max |value - reference| / peak reference "
        "over the probes (probes read from each method's own representation, the punctual lights exact at "
        "each sensor: RadiositySolver::EvaluateProbes, as `--probe-output` does).\n\n"
        "| case | reference | method | setting | time (s) | max error | RMS error |\n"
        "|---|---|---|---|---|---|---|\n";
  for (const Case& c : cases)
  {
    double fastest = 1e300;
    for (const Setting& s : Settings(args.Quick))
    {
      const Stopwatch clock;
      std::unique_ptr<RadiositySolver> solver = s.Make(c.Geometry);
      solver->Solve({});
      const std::vector<RGB> values = solver->EvaluateProbes(c.Probes);
      const double seconds = clock.Seconds();
      fastest = std::min(fastest, seconds);
      const ErrorFigures e = RelativeErrors(values, c.Reference);
      char row[512];
      std::snprintf(row, sizeof row, "| %s | %s | %s | %s | %.3f | %.3g | %.3g |\n", c.Name.c_str(),
        c.ReferenceKind.c_str(), s.Method.c_str(), s.Label.c_str(), seconds, e.Max, e.Rms);
      md << row;
      std::cout << row << std::flush;
      csv << '"' << c.Name << "\"," << s.Method << ",\"" << s.Label << "\"," << seconds << "," << e.Max << ","
          << e.Rms << "\n";
    }
    // The path tracer at about the fastest setting's time: paths per probe
    // from a short calibration run.
    PathTracerOptions o;
    o.Seed = 11;
    const std::size_t calibration = 1024;
    const Stopwatch probe;
    PathTracer tracer(*c.Geometry, o);
    tracer.Irradiance(c.Probes, calibration, 1);
    const double perPath = std::max(probe.Seconds(), 1e-6) / calibration;
    const std::size_t paths = std::max<std::size_t>(64, static_cast<std::size_t>(fastest / perPath));
    const Stopwatch clock;
    std::vector<RGB> values;
    for (const ReferenceValue& v : tracer.Irradiance(c.Probes, paths, 2))
    {
      values.push_back(v.Value);
    }
    const double seconds = clock.Seconds();
    const ErrorFigures e = RelativeErrors(values, c.Reference);
    char row[512];
    std::snprintf(row, sizeof row, "| %s | %s | path tracer | %zu paths per probe | %.3f | %.3g | %.3g |\n",
      c.Name.c_str(), c.ReferenceKind.c_str(), paths, seconds, e.Max, e.Rms);
    md << row;
    std::cout << row << std::flush;
    csv << '"' << c.Name << "\",pathtracer,\"" << paths << " paths\"," << seconds << "," << e.Max << "," << e.Rms
        << "\n";
  }
  std::ofstream(args.Directory + "/lights.md") << md.str();
  return 0;
}
