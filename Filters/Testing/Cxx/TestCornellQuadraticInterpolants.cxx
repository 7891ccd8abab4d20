// The Cornell box solved by hierarchical radiosity, discontinuity meshed
// (port 1 of vtkRadiosityFilter) and drawn by vtkRadiosityView through its
// per-pixel quadratic interpolant path, against a baseline image.
#include "vtkCellData.h"
#include "vtkCornellBoxSource.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRadiosityFilter.h"
#include "Radiosity/Hierarchical/HierarchicalMethod.h"
#include "vtkRadiosityView.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

#include <iostream>


namespace
{
/// The discontinuity mesh behind the filter's port 1 (its statistics).
const radiosity::DiscontinuityMesh& HierarchicalMesh(vtkRadiosityFilter* filter)
{
  return std::dynamic_pointer_cast<const radiosity::HierarchicalMethod>(filter->GetSolver())
    ->LastMesh();
}
}

int TestCornellQuadraticInterpolants(int argc, char* argv[])
{
  vtkFloatingPointExceptions::Disable();
  vtkNew<vtkCornellBoxSource> box;
  vtkNew<vtkRadiosityFilter> radiosity;
  radiosity->SetInputConnection(box->GetOutputPort());
  radiosity->SetMethodToHierarchical();
  radiosity->SetTolerance(1e-3);
  radiosity->Update();
  vtkPolyData* meshed = radiosity->GetOutput(1); // the discontinuity mesh
  if (!radiosity->GetLastError().empty() ||
    meshed->GetNumberOfCells() == 0 || !meshed->GetCellData()->GetArray("QuadraticInterpolant"))
  {
    std::cerr << "solve or meshing failed: " << radiosity->GetLastError() << "\n";
    return EXIT_FAILURE;
  }
  std::cout << radiosity->GetOutput()->GetNumberOfCells() << " leaves, "
            << meshed->GetNumberOfCells() << " triangles, " << HierarchicalMesh(radiosity).LeavesMeshed
            << " leaves meshed\n";

  double position[3], focal[3], up[3], angle;
  vtkCornellBoxSource::GetCamera(position, focal, up, angle);
  vtkNew<vtkRadiosityView> view;
  view->SetInputData(meshed);
  view->SetSize(400, 400);
  view->SetCamera(position, focal, up, angle);
  view->SetExposure(1.0);
  if (!view->UsesInterpolantMapper())
  {
    std::cerr << "the view does not take the interpolant path\n";
    return EXIT_FAILURE;
  }
  if (!view->Render())
  {
    return EXIT_FAILURE;
  }
  const int result = vtkRegressionTestImage(view->GetRenderWindow());
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
