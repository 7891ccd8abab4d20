// The pass's solution of PassTestScene against the path tracer: the scene
// the pass gathered (GetFilter()->GetScene(), world transforms, vtkProperty
// colours, the spot and the sun as the pass mapped them) is path traced at
// sensors on the floor, the walls, the box's top and its sunlit side, and
// the solution's irradiance there (the method's own representation,
// RadiositySolver::EvaluateProbes, as the command line's --probes) must be
// within a bound of the largest reference value, for progressive,
// hierarchical and meshless. UpdateSolution only: no window, no OpenGL.
//
// Measured (Release, 2 threads, 16384 paths per sensor: standard errors at
// most 1.8e-3 of the peak 4.13 W/m^2; 224 triangles, the spot and the sun):
// - progressive (default settings, 2.7 s): largest difference 0.0194 of
//   the peak (the floor under the spot, 0.3 m from the box, where the
//   solution is 2% darker); bound 0.02, the issue's;
// - hierarchical (default settings: discontinuity meshing on, the sensors
//   from the quadratic interpolants with the punctual lights exact at the
//   sensor, as the command line's --probes; 9.4 s): 0.0121 of the peak at
//   the same sensor (the back wall 0.0107); bound 0.015. Without the
//   discontinuity mesh the sensors come from the leaves' constants and
//   measured 0.0338 (the box's top 0.028, the floor in the sun 0.020);
// - meshless (default settings, 4.2 s; the punctual lights exact at the
//   sensors): 0.0082 of the peak at the same sensor; bound 0.012.
// Face cluster radiosity measured 0.031 there (and 0.014 on the back
// wall): not held to the 2% here until the face cluster issue's accuracy
// work (its coarse-input and scale findings) lands.
#include "PassTestScene.h"

#include "vtkFloatingPointExceptions.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiosityPass.h"

#include "Radiosity/Common/RadiositySolver.h"
#include "Radiosity/Reference/PathTracer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

using radiosity::Probe;
using radiosity::Vec3;

int TestRadiosityPassReference(int, char*[])
{
  vtkFloatingPointExceptions::Disable();
  vtkNew<vtkRenderer> renderer;
  PassTestScene::Build(renderer);

  // Sensors: on the floor (in the spot, in the sun, in the box's and the
  // sphere's shadows), on both walls, on the box's top and the sphere's top.
  const std::vector<Probe> probes = {
    { Vec3(0.2, 0.2, 0.0), Vec3(0, 0, 1) },    // floor under the spot
    { Vec3(1.2, -1.4, 0.0), Vec3(0, 0, 1) },   // floor in the sun
    { Vec3(-1.5, 1.5, 0.0), Vec3(0, 0, 1) },   // floor, back corner
    { Vec3(-0.5, 0.3, 0.0), Vec3(0, 0, 1) },   // floor behind the sphere
    { Vec3(0.0, 2.0, 1.2), Vec3(0, -1, 0) },   // back wall
    { Vec3(-2.0, 0.0, 1.2), Vec3(1, 0, 0) },   // left wall
    { Vec3(0.8, 0.5, 0.8), Vec3(0, 0, 1) },    // top of the box
    { Vec3(1.0, 0.1536, 0.4), Vec3(0.5, -0.866025, 0) }, // the box's sunlit side
  };
  // Largest |solution - reference| over the sensors, as a fraction of the
  // largest reference value: measured, and the bound just above it.
  const int methods[3] = { vtkRadiosityFilter::Progressive, vtkRadiosityFilter::Hierarchical,
    vtkRadiosityFilter::Meshless };
  const double bounds[3] = { 0.02, 0.015, 0.012 };
  bool ok = true;
  for (int m = 0; m < 3; ++m)
  {
    vtkNew<vtkRadiosityPass> pass;
    pass->SetMethod(methods[m]);
    pass->GetFilter()->SetNumberOfThreads(2);
    const auto start = std::chrono::steady_clock::now();
    if (!PassTestScene::Check(pass->UpdateSolution(renderer), "UpdateSolution failed"))
    {
      return EXIT_FAILURE;
    }
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const radiosity::Scene& scene = pass->GetFilter()->GetScene();
    // The method's own representation, as the command line's --probes reads it.
    const std::vector<radiosity::RGB> solved = pass->GetFilter()->GetSolver()->EvaluateProbes(probes);
    radiosity::PathTracerOptions options;
    options.Threads = 2;
    const radiosity::PathTracer tracer(scene, options);
    const std::vector<radiosity::ReferenceValue> truth = tracer.Irradiance(probes, 16384);
    double peak = 0.0, worst = 0.0, worstSe = 0.0;
    for (const radiosity::ReferenceValue& r : truth)
    {
      peak = std::max({ peak, r.Value.r, r.Value.g, r.Value.b });
    }
    std::cout << vtkRadiosityFilter::GetMethodName(methods[m]) << ": " << scene.Triangles.size()
              << " triangles, " << scene.Lighting.Lights.size() << " lights, solved in " << seconds
              << " s; peak reference irradiance " << peak << " W/m^2\n";
    for (std::size_t i = 0; i < probes.size(); ++i)
    {
      const double d = std::max({ std::fabs(solved[i].r - truth[i].Value.r),
        std::fabs(solved[i].g - truth[i].Value.g), std::fabs(solved[i].b - truth[i].Value.b) });
      worst = std::max(worst, d / peak);
      worstSe = std::max({ worstSe, truth[i].StandardError.r / peak,
        truth[i].StandardError.g / peak, truth[i].StandardError.b / peak });
      std::cout << "  sensor " << i << ": solution (" << solved[i].r << ", " << solved[i].g << ", "
                << solved[i].b << "), path traced (" << truth[i].Value.r << ", " << truth[i].Value.g
                << ", " << truth[i].Value.b << "), |difference| " << d / peak << " of the peak\n";
    }
    std::cout << "  largest difference " << worst << " of the peak (bound " << bounds[m]
              << "), largest standard error " << worstSe << "\n";
    ok &= PassTestScene::Check(worst <= bounds[m],
      std::string(vtkRadiosityFilter::GetMethodName(methods[m])) + ": " + std::to_string(worst) +
        " of the peak from the path tracer");
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
