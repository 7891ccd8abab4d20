// Face cluster radiosity lit by a point light (HardShadowScene.h: a red
// one-sided plate above a grey floor of 64 x 64 squares, 8,192 triangles): the output
// shows the light's exact irradiance at every vertex, hard shadow included,
// while the solution stays coarse (a leaf cluster is opened for the light
// only where what it reflects needs it). Before, each vertex showed its
// leaf's fit of the light (on 128 triangles the sun's shadow was 0.5 of the
// peak off at a vertex), and every leaf cluster was opened down to its
// triangles for the lights. The image: the floor and the plate from above
// a corner, drawn per pixel from the vertex irradiance vectors
// (vtkVectorIrradianceMapper).
#include "FilterTestSupport.h"
#include "HardShadowScene.h"
#include "vtkDataArray.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiositySceneConverter.h"
#include "vtkRadiosityView.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

#include "Radiosity/FaceCluster/FaceClusterRadiosity.h"

#include <algorithm>
#include <cmath>
#include <iostream>

using FilterTestSupport::Check;

namespace
{
const radiosity::RGB PlateTop(0.7, 0.35, 0.2);
}

int TestFaceClusterPointLight(int argc, char* argv[])
{
  vtkFloatingPointExceptions::Disable();
  bool ok = true;
  const radiosity::Scene geometry = HardShadowScene::Make(64, &PlateTop);
  vtkSmartPointer<vtkPolyData> scene = vtkRadiositySceneConverter::FromScene(geometry);
  vtkNew<vtkRadiosityFilter> radiosity;
  radiosity->SetInputData(scene);
  radiosity->SetMethodToFaceCluster();
  radiosity->SetSceneLights(HardShadowScene::Lamp());
  radiosity->Update();
  ok &= Check(radiosity->GetLastError().empty(), "solve: " + radiosity->GetLastError());
  vtkPolyData* out = radiosity->GetOutput();
  vtkDataArray* irradiance = out->GetPointData()->GetArray("Irradiance");
  vtkDataArray* vectors = out->GetPointData()->GetArray("IrradianceVector");
  ok &= Check(irradiance && vectors && irradiance->GetNumberOfTuples() == out->GetNumberOfPoints(),
    "Irradiance and IrradianceVector per point");
  if (!ok)
  {
    return EXIT_FAILURE;
  }
  // Every floor vertex (z = 0) but those within 1e-6 of a shadow edge (where
  // a vertex takes one side's limit), against the closed form.
  double peak = 0.0, worst = 0.0, worstVector = 0.0;
  vtkIdType counted = 0, shadowed = 0;
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    double x[3];
    out->GetPoint(p, x);
    double edge = 0.0;
    const double exact = HardShadowScene::Exact(radiosity::Vec3(x[0], x[1], x[2]), &edge);
    peak = std::max(peak, exact);
    if (x[2] != 0.0 || edge < 1e-6)
    {
      continue;
    }
    ++counted;
    shadowed += exact == 0.0 ? 1 : 0;
    // Red channel: the floor's vector's normal part is the irradiance.
    worst = std::max(worst, std::abs(irradiance->GetComponent(p, 0) - exact));
    worstVector = std::max(worstVector, std::abs(vectors->GetComponent(p, 2) - exact));
  }
  const std::size_t leaves = radiosity->GetFaceClusterSolution()->Statistics().LeafElements;
  // The same scene with a floor of 4 x 4 squares: the tolerance, not the
  // input, sets the solution's size.
  vtkNew<vtkRadiosityFilter> coarse;
  coarse->SetInputData(vtkRadiositySceneConverter::FromScene(HardShadowScene::Make(4, &PlateTop)));
  coarse->SetMethodToFaceCluster();
  coarse->SetSceneLights(HardShadowScene::Lamp());
  coarse->Update();
  ok &= Check(coarse->GetLastError().empty(), "coarse solve: " + coarse->GetLastError());
  const std::size_t coarseLeaves = coarse->GetFaceClusterSolution()->Statistics().LeafElements;
  std::cout << geometry.Triangles.size() << " triangles, " << leaves << " leaf elements (" << coarseLeaves
            << " on a floor of 32 triangles); " << counted
            << " floor vertices (" << shadowed << " in the shadow): largest error of the peak " << worst / peak
            << ", of the vectors' normal part " << worstVector / peak << "\n";
  // Measured: 4.1e-16 of the peak for both (bound 1e-12); 6,665 leaf
  // elements, 6,322 on the coarse floor (bound 1.25 times: the tolerance
  // refines both below their triangles where the light's gradient is
  // reflected).
  ok &= Check(counted > 4000 && shadowed > 100, "the floor's vertices, some in the shadow");
  ok &= Check(worst < 1e-12 * peak && worstVector < 1e-12 * peak, "the exact light at every floor vertex");
  ok &= Check(leaves <= 1.25 * static_cast<double>(coarseLeaves), "no more leaves than on a coarse floor");

  vtkNew<vtkRadiosityView> view;
  view->SetInputData(out);
  view->SetSize(400, 400);
  const double position[3] = { 0.6, -3.0, 2.4 }, focal[3] = { -0.1, 0.0, 0.15 }, up[3] = { 0.0, 0.0, 1.0 };
  view->SetCamera(position, focal, up, 50.0);
  ok &= Check(view->UsesVectorIrradianceMapper(), "the view shades the irradiance vectors");
  ok &= Check(view->Render(), "render");
  if (!ok)
  {
    return EXIT_FAILURE;
  }
  const int result = vtkRegressionTestImage(view->GetRenderWindow());
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
