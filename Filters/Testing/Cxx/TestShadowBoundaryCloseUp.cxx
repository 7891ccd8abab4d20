// A close-up of a penumbra: a square area light above a square blocker over a
// grey floor (radiosity::MakeShadowScene with a reflecting floor), solved by
// hierarchical radiosity and discontinuity meshed. One window, two halves with
// the same camera: left, the hierarchical solution's quadtree leaves drawn with
// Gouraud interpolation of the point Radiosity (vtkRadiosityView's Gouraud
// path); right, the discontinuity mesh drawn with its per-pixel quadratic
// interpolants. The two halves must differ visibly.
#include "FilterTestSupport.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRadiosityFilter.h"
#include "Radiosity/Hierarchical/HierarchicalMethod.h"
#include "vtkRadiositySceneConverter.h"
#include "vtkRadiosityView.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Reference/AnalyticReference.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>


namespace
{
/// The discontinuity mesh behind the filter's port 1 (its statistics).
const radiosity::DiscontinuityMesh& HierarchicalMesh(vtkRadiosityFilter* filter)
{
  return std::dynamic_pointer_cast<const radiosity::HierarchicalMethod>(filter->GetSolver())
    ->LastMesh();
}
}

int TestShadowBoundaryCloseUp(int argc, char* argv[])
{
  vtkFloatingPointExceptions::Disable();
  // Emitter [-0.25, 0.25]^2 at z = 1 facing down, blocker [-0.05, 0.35] x
  // [-0.2, 0.2] at z = 0.5, floor [-1, 1]^2: umbra x in [0.15, 0.45], penumbra
  // from x = -0.35. The floor reflects (object 0); the rest stays black, so the
  // floor sees the direct light only.
  vtkSmartPointer<vtkPolyData> scene =
    vtkRadiositySceneConverter::FromScene(radiosity::MakeShadowScene(4, 10.0));
  vtkDataArray* reflectance = scene->GetCellData()->GetArray("Reflectance");
  vtkDataArray* objects = scene->GetCellData()->GetArray("ObjectId");
  if (!reflectance || !objects)
  {
    std::cerr << "FromScene gave no Reflectance or ObjectId\n";
    return EXIT_FAILURE;
  }
  for (vtkIdType c = 0; c < scene->GetNumberOfCells(); ++c)
  {
    if (objects->GetComponent(c, 0) == 0)
    {
      reflectance->SetTuple3(c, 0.75, 0.7, 0.6);
    }
  }

  vtkNew<vtkRadiosityFilter> radiosity;
  radiosity->SetInputData(scene);
  radiosity->SetMethodToHierarchical();
  radiosity->Update();
  vtkPolyData* leaves = radiosity->GetOutput();
  vtkPolyData* meshed = radiosity->GetOutput(1); // the discontinuity mesh
  if (!radiosity->GetLastError().empty() ||
    meshed->GetNumberOfCells() <= leaves->GetNumberOfCells())
  {
    std::cerr << "solve or meshing failed: " << radiosity->GetLastError() << "\n";
    return EXIT_FAILURE;
  }
  std::cout << leaves->GetNumberOfCells() << " leaves, " << meshed->GetNumberOfCells()
            << " triangles, " << HierarchicalMesh(radiosity).LeavesMeshed << " leaves meshed, "
            << HierarchicalMesh(radiosity).SegmentsKept << " segments\n";

  // The floor sees the direct light only, so its exact irradiance is the
  // emitter's form factor clipped by the blocker (DirectIrradiance, the
  // closed form of the Reference folder). Across the penumbra and umbra
  // (y = -0.15, x from -0.45 to 0.55) the interpolants of the discontinuity
  // mesh follow it; the constant leaves (the left half) step.
  std::vector<radiosity::Probe> probes;
  std::vector<radiosity::RGB> exact;
  const std::vector<radiosity::Vec3> blocker = { { -0.05, -0.2, 0.5 }, { 0.35, -0.2, 0.5 },
    { 0.35, 0.2, 0.5 }, { -0.05, 0.2, 0.5 } };
  const radiosity::Scene& core = radiosity->GetScene();
  double peak = 0.0;
  for (int i = 0; i <= 100; ++i)
  {
    const radiosity::Probe probe{ { -0.45 + 0.01 * i, -0.15, 0.0 }, { 0.0, 0.0, 1.0 } };
    probes.push_back(probe);
    exact.push_back(radiosity::DirectIrradiance(core, probe.Position, probe.Normal, blocker));
    peak = std::max(peak, radiosity::Luminance(exact.back()));
  }
  const std::vector<radiosity::RGB> onMesh =
    radiosity::EvaluateInterpolants(HierarchicalMesh(radiosity), probes, 1e-6);
  const radiosity::ProbeEvaluator constantLeaves(*radiosity->GetSolution(), core);
  const std::vector<radiosity::RGB> onLeaves = constantLeaves.Evaluate(probes);
  double meshError = 0.0, leafError = 0.0;
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    const double h = radiosity::Luminance(exact[i]);
    const double m = std::fabs(radiosity::Luminance(onMesh[i]) - h) / peak;
    const double l = std::fabs(radiosity::Luminance(onLeaves[i]) - h) / peak;
    meshError = std::isfinite(m) ? std::max(meshError, m) : HUGE_VAL;
    leafError = std::isfinite(l) ? std::max(leafError, l) : HUGE_VAL;
  }
  std::cout << "across the shadow, largest error relative to the peak " << peak
            << ": interpolants " << meshError << ", constant leaves " << leafError << "\n";
  // Measured: interpolants 5.4e-4 of the peak, constant leaves 0.30.
  if (!(meshError < 1.5e-3) || !(leafError > 0.1))
  {
    std::cerr << "the interpolants do not follow the exact penumbra, or the leaves do\n";
    return EXIT_FAILURE;
  }

  // Straight down from just under the blocker (z = 0.45) at the umbra's
  // corner (0.15, -0.15): the umbra top right, the penumbrae of its -x and -y
  // edges across the rest (the floor from about (-0.38, -0.58) to (0.38, 0.18)).
  const double position[3] = { 0.0, -0.2, 0.45 };
  const double focal[3] = { 0.0, -0.2, 0.0 };
  const double up[3] = { 0.0, 1.0, 0.0 };
  const int width = 400, height = 400;
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRadiosityView> gouraud;
  gouraud->SetInputData(leaves);
  vtkNew<vtkRadiosityView> quadratic;
  quadratic->SetInputData(meshed);
  FilterTestSupport::SideBySide(window, gouraud, quadratic, width, height, position, focal, up, 80.0, 4.0);
  if (gouraud->UsesInterpolantMapper() || !quadratic->UsesInterpolantMapper())
  {
    std::cerr << "wrong display paths\n";
    return EXIT_FAILURE;
  }
  if (!gouraud->Render() || !quadratic->Render())
  {
    return EXIT_FAILURE;
  }

  // The halves differ: mean absolute difference of corresponding pixels.
  const FilterTestSupport::Halves halves = FilterTestSupport::CompareHalves(window, width, height);
  const double difference = halves.Difference, left = halves.LeftMean;
  std::cout << "mean pixel difference between the halves " << difference << ", left mean "
            << left << "\n";
  // Measured: a mean difference of 11.3 (of 255), left mean 117.
  if (left < 40.0 || difference < 4.0)
  {
    std::cerr << "the image is dark or the halves do not differ\n";
    return EXIT_FAILURE;
  }
  const int result = vtkRegressionTestImage(window);
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
