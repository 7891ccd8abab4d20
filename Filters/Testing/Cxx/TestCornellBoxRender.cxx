// The Cornell box solved by vtkRadiosityFilter and drawn by vtkRadiosityView
// (HDR radiance through vtkToneMappingPass), against a baseline image.
#include "vtkCornellBoxSource.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiosityView.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

#include <iostream>

int TestCornellBoxRender(int argc, char* argv[])
{
  vtkFloatingPointExceptions::Disable();
  vtkNew<vtkCornellBoxSource> box;
  vtkNew<vtkRadiosityFilter> radiosity;
  radiosity->SetInputConnection(box->GetOutputPort());
  radiosity->SetTolerance(1e-2);
  radiosity->Update();
  vtkPolyData* solved = radiosity->GetOutput();
  if (!radiosity->GetLastError().empty() || solved->GetNumberOfCells() == 0)
  {
    std::cerr << "solve failed: " << radiosity->GetLastError() << "\n";
    return EXIT_FAILURE;
  }
  auto* history =
    vtkDoubleArray::SafeDownCast(solved->GetFieldData()->GetArray("ConvergenceHistory"));
  if (!history || history->GetNumberOfTuples() < 2 ||
    history->GetValue((history->GetNumberOfTuples() - 1) * 7 + 2) >
      1e-2 * radiosity->GetStatistics().EmittedPowerW)
  {
    std::cerr << "missing or unconverged ConvergenceHistory\n";
    return EXIT_FAILURE;
  }

  double position[3], focal[3], up[3], angle;
  vtkCornellBoxSource::GetCamera(position, focal, up, angle);
  vtkNew<vtkRadiosityView> view;
  view->SetInputData(solved);
  view->SetSize(400, 400);
  view->SetCamera(position, focal, up, angle);
  view->SetExposure(1.0);
  if (!view->Render())
  {
    return EXIT_FAILURE;
  }
  const int result = vtkRegressionTestImage(view->GetRenderWindow());
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
