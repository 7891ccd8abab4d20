// Every method through the one core interface (Common/RadiositySolver.h) on
// every analytic light case (Scenes/LightScenes.h: point, spot and sun over
// planes, a point light in a sphere, skies over a plane and beside a wall),
// the probes evaluated from the method's own representation as the CLI's
// --probe-output does (RadiositySolver::EvaluateProbes: the hierarchical
// method's quadratic interpolants, the meshless Shepard field, the face
// cluster bases, progressive refinement's elements; the punctual lights'
// direct light exact at each sensor), the error the project's metric
// (ErrorMetrics.h: |value - exact| / peak exact over every probe) against
// ComputeAnalyticReference (checked against hand-derived forms in
// Reference/TestAnalyticLights.cxx and by the path tracer in
// Reference/TestPathTracerLights.cxx). Default settings, but a tolerance of
// 1e-4 for progressive refinement and hierarchical radiosity.
//
// Bounds: the issue asks 2% of the peak for every case and 1e-4 where the
// answer is the punctual lights' direct light alone (LightCase::DirectPunctual).
// Measured (progressive, hierarchical, meshless, face cluster):
//   direct-only cases: 9e-8, 1.5e-15, 1.5e-15, 1.5e-15 (bound 1e-6: the
//     representation's own fit of the punctual light cancels to rounding;
//     before the exact light at the sensor, 7.4e-3, 8.1e-2, 0.16, 0.45);
//   point light in a sphere: 4.6e-4, 4.4e-4, 1.2e-3, 7.4e-4;
//   uniform sky beside a wall: 1.8e-2, 2.1e-3, 6.1e-3, 2.2e-3;
//   CIE overcast sky over a plane: 1.6e-6 for all (the sky quadrature);
// the cases with interreflection or a sky held to the 2%.
#include "Radiosity/Common/ErrorMetrics.h"
#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Common/RadiositySolver.h"
#include "Radiosity/FaceCluster/FaceClusterMethod.h"
#include "Radiosity/Hierarchical/HierarchicalMethod.h"
#include "Radiosity/Meshless/MeshlessMethod.h"
#include "Radiosity/Progressive/ProgressiveMethod.h"
#include "Radiosity/Reference/AnalyticReference.h"
#include "Radiosity/Scenes/LightScenes.h"

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <iostream>
#include <memory>
#include <string>

namespace
{
using namespace radiosity;

using MakeMethod = std::function<std::unique_ptr<RadiositySolver>(std::shared_ptr<const Scene>)>;

constexpr double AllCasesBound = 0.02;
constexpr double DirectPunctualBound = 1e-6;

/// Solves every light case with `make`'s method; checks and prints the errors.
void CheckEveryCase(const char* method, const MakeMethod& make)
{
  for (const LightCase& c : AnalyticLightCases(1.0))
  {
    AnalyticReference exact;
    std::string why;
    ASSERT_TRUE(ComputeAnalyticReference(c.Geometry, c.Probes, exact, why)) << c.Name << ": " << why;
    auto scene = std::make_shared<const Scene>(c.Geometry);
    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<RadiositySolver> solver = make(scene);
    const SolverStatistics stats = solver->Solve({});
    EXPECT_NE(stats.Stop, StopReason::Aborted) << method << ", " << c.Name;
    const SolutionMesh surface = solver->Surface();
    std::size_t gathered = 0;
    const std::vector<RGB> values = solver->EvaluateProbes(c.Probes, &gathered);
    const ErrorFigures e = RelativeErrors(values, exact.Irradiance);
    const double bound = c.DirectPunctual ? DirectPunctualBound : AllCasesBound;
    std::cout << "  " << method << ", " << c.Name << ": max " << e.Max << " RMS " << e.Rms
              << " of the peak " << e.Peak << " (bound " << bound << "; "
              << surface.Triangles.size() << " elements, " << gathered
              << " probes gathered; "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
              << " s)\n";
    EXPECT_EQ(e.NotFinite, 0u) << method << ", " << c.Name;
    EXPECT_LT(e.Max, bound) << method << ", " << c.Name;
    if (!(e.Max < bound))
    {
      for (std::size_t i = 0; i < values.size(); ++i)
      {
        const Vec3& x = c.Probes[i].Position;
        std::cout << "    probe " << i << " (" << x.x << ", " << x.y << ", " << x.z << "): "
                  << values[i].r << " exact " << exact.Irradiance[i].r << "\n";
      }
    }
  }
}
}

TEST(LightCases, Progressive)
{
  CheckEveryCase("progressive",
    [](std::shared_ptr<const Scene> scene)
    {
      ProgressiveOptions options;
      options.Tolerance = 1e-4;
      return std::make_unique<ProgressiveMethod>(scene, options);
    });
}

TEST(LightCases, Hierarchical)
{
  CheckEveryCase("hierarchical",
    [](std::shared_ptr<const Scene> scene)
    {
      HierarchicalOptions options;
      options.Tolerance = 1e-4;
      return std::make_unique<HierarchicalMethod>(scene, options, DiscontinuityMeshOptions());
    });
}

TEST(LightCases, Meshless)
{
  CheckEveryCase("meshless",
    [](std::shared_ptr<const Scene> scene)
    {
      MeshlessOptions options;
      return std::make_unique<MeshlessMethod>(scene, options);
    });
}

TEST(LightCases, FaceCluster)
{
  CheckEveryCase("facecluster",
    [](std::shared_ptr<const Scene> scene)
    { return std::make_unique<FaceClusterMethod>(scene, FaceClusterSettings()); });
}
