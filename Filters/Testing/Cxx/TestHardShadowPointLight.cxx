// A point light's hard shadow (SPEC "Lights and sky"): a black square plate
// above a grey floor lit by one point light, no emitting triangle. One
// window, two halves with the same camera (just under the plate's height,
// looking straight down at a corner of the shadow): left, the progressive
// solution (its elements split along the shadow edge by the gradient
// criterion, Gouraud-shaded); right, hierarchical radiosity with
// discontinuity meshing (the shadow's boundary inserted into the leaves'
// triangulations, D0, drawn with the per-pixel quadratic interpolants).
// Across the edge the interpolants follow the exact step; the elements blur it.
#include "FilterTestSupport.h"
#include "HardShadowScene.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRadiosityFilter.h"
#include "Radiosity/Hierarchical/HierarchicalMethod.h"
#include "vtkRadiositySceneConverter.h"
#include "vtkRadiosityView.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

int TestHardShadowPointLight(int argc, char* argv[])
{
  vtkFloatingPointExceptions::Disable();
  vtkSmartPointer<vtkPolyData> scene = vtkRadiositySceneConverter::FromScene(HardShadowScene::Make(4));
  const radiosity::LightSet lights = HardShadowScene::Lamp();

  vtkNew<vtkRadiosityFilter> progressive;
  progressive->SetInputData(scene);
  progressive->SetMethodToProgressive();
  progressive->SetSceneLights(lights);
  progressive->Update();
  vtkNew<vtkRadiosityFilter> hierarchical;
  hierarchical->SetInputData(scene);
  hierarchical->SetMethodToHierarchical();
  hierarchical->SetSceneLights(lights);
  hierarchical->Update();
  vtkPolyData* elements = progressive->GetOutput();
  vtkPolyData* meshed = hierarchical->GetOutput(1); // the discontinuity mesh
  if (!progressive->GetLastError().empty() || !hierarchical->GetLastError().empty() ||
    meshed->GetNumberOfCells() == 0)
  {
    std::cerr << "solve failed: " << progressive->GetLastError() << hierarchical->GetLastError() << "\n";
    return EXIT_FAILURE;
  }
  const radiosity::DiscontinuityMesh& dm =
    std::dynamic_pointer_cast<const radiosity::HierarchicalMethod>(hierarchical->GetSolver())->LastMesh();

  // Along y = 0 across both shadow edges (x = -0.75 and 0.45), probes 1e-3
  // or more from the edges.
  std::vector<radiosity::Probe> probes;
  double peak = 0.0;
  for (int i = 0; i <= 300; ++i)
  {
    const double x = -1.5 + 0.01 * i;
    if (std::fabs(x + 0.75) < 1e-3 || std::fabs(x - 0.45) < 1e-3)
    {
      continue;
    }
    probes.push_back({ { x, 0.0, 0.0 }, { 0.0, 0.0, 1.0 } });
    peak = std::max(peak, HardShadowScene::Exact(probes.back().Position));
  }
  const std::vector<radiosity::RGB> onMesh = radiosity::EvaluateInterpolants(dm, probes, 1e-6);
  // The elements as drawn (Gouraud), not the sensors' exact punctual light.
  radiosity::ProbeEvaluator onElements(*progressive->GetSolution(), progressive->GetScene());
  onElements.SetExactPunctualLight(false);
  const std::vector<radiosity::RGB> fromElements = onElements.Evaluate(probes);
  double meshError = 0.0, elementError = 0.0;
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    const double h = HardShadowScene::Exact(probes[i].Position);
    const double m = std::fabs(onMesh[i].x - h) / peak, e = std::fabs(fromElements[i].x - h) / peak;
    meshError = std::isfinite(m) ? std::max(meshError, m) : HUGE_VAL;
    elementError = std::isfinite(e) ? std::max(elementError, e) : HUGE_VAL;
  }
  std::cout << elements->GetNumberOfCells() << " progressive elements, " << meshed->GetNumberOfCells()
            << " interpolant triangles; across the shadow edges, largest error of the peak: interpolants "
            << meshError << ", progressive elements " << elementError << "\n";
  // Measured: interpolants 3.7e-5 of the peak (3,877 triangles), progressive 0.64 (2,082 elements).
  if (!(meshError < 2e-4) || !(elementError > 0.3))
  {
    std::cerr << "the interpolants do not follow the exact hard shadow, or the elements do\n";
    return EXIT_FAILURE;
  }

  // Straight down from just under the plate at the shadow's corner (-0.75, -0.65).
  const double position[3] = { -0.75, -0.65, 0.45 };
  const double focal[3] = { -0.75, -0.65, 0.0 };
  const double up[3] = { 0.0, 1.0, 0.0 };
  const int width = 400, height = 400;
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRadiosityView> gouraud;
  gouraud->SetInputData(elements);
  // The per-vertex path: the elements' own samples (the default for this
  // output) draw the shadow closer to the interpolants (the halves differ by
  // 1.5 instead of 10.0 of 255).
  gouraud->InterpolantRenderingOff();
  vtkNew<vtkRadiosityView> quadratic;
  quadratic->SetInputData(meshed);
  FilterTestSupport::SideBySide(window, gouraud, quadratic, width, height, position, focal, up, 80.0, 1.5);
  if (gouraud->UsesInterpolantMapper() || !quadratic->UsesInterpolantMapper())
  {
    std::cerr << "wrong display paths\n";
    return EXIT_FAILURE;
  }
  if (!gouraud->Render() || !quadratic->Render())
  {
    return EXIT_FAILURE;
  }
  const FilterTestSupport::Halves halves = FilterTestSupport::CompareHalves(window, width, height);
  std::cout << "mean pixel difference between the halves " << halves.Difference << ", left mean "
            << halves.LeftMean << "\n";
  if (halves.LeftMean < 30.0 || halves.Difference < 2.0)
  {
    std::cerr << "the image is dark or the halves do not differ\n";
    return EXIT_FAILURE;
  }
  const int result = vtkRegressionTestImage(window);
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
