// vtkRadiosityFilter inside a plain VTK pipeline: a scene made with VTK's own
// sources and filters, the solution coloured by VTK's standard mapper; and
// the documented error for bad input.
#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRadiosityFilter.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <iostream>

namespace
{
/// A plane with uniform material arrays added as cell data.
vtkSmartPointer<vtkPolyData> Plane(const double o[3], const double p1[3], const double p2[3],
  int res, double reflectance, double emission)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(o[0], o[1], o[2]);
  plane->SetPoint1(p1[0], p1[1], p1[2]);
  plane->SetPoint2(p2[0], p2[1], p2[2]);
  plane->SetResolution(res, res);
  plane->Update();
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->ShallowCopy(plane->GetOutput());
  pd->GetPointData()->Initialize();
  const vtkIdType n = pd->GetNumberOfCells();
  for (const char* name : { "Reflectance", "Emission" })
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(3);
    a->SetNumberOfTuples(n);
    a->Fill(std::string(name) == "Reflectance" ? reflectance : emission);
    pd->GetCellData()->AddArray(a);
  }
  return pd;
}
}

int TestRadiosityFilterPipeline(int argc, char* argv[])
{
  vtkFloatingPointExceptions::Disable();
  // Floor (normal +z), a small emitter above it facing down, a wall (normal +x).
  const double f0[3] = { 0, 0, 0 }, f1[3] = { 1, 0, 0 }, f2[3] = { 0, 1, 0 };
  const double l0[3] = { 0.4, 0.4, 0.6 }, l1[3] = { 0.4, 0.6, 0.6 }, l2[3] = { 0.6, 0.4, 0.6 };
  const double w0[3] = { 0, 0, 0 }, w1[3] = { 0, 1, 0 }, w2[3] = { 0, 0, 1 };
  vtkNew<vtkAppendPolyData> scene;
  scene->AddInputData(Plane(f0, f1, f2, 4, 0.7, 0.0));
  scene->AddInputData(Plane(l0, l1, l2, 1, 0.0, 100.0));
  scene->AddInputData(Plane(w0, w1, w2, 4, 0.5, 0.0));

  vtkNew<vtkRadiosityFilter> radiosity;
  radiosity->SetInputConnection(scene->GetOutputPort());
  radiosity->Update();
  vtkPolyData* out = radiosity->GetOutput();
  for (const char* name : { "Irradiance", "Radiosity" })
  {
    if (!out->GetPointData()->GetArray(name) || !out->GetCellData()->GetArray(name))
    {
      std::cerr << "missing output array " << name << "\n";
      return EXIT_FAILURE;
    }
  }
  if (!out->GetCellData()->GetArray("ElementId") || !out->GetCellData()->GetArray("Level"))
  {
    std::cerr << "missing ElementId or Level\n";
    return EXIT_FAILURE;
  }

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(radiosity->GetOutputPort());
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("Irradiance");
  mapper->ColorByArrayComponent("Irradiance", 0);
  // Blue (dark) to red (bright) over the floor's range of irradiance.
  vtkNew<vtkLookupTable> colours;
  colours->SetHueRange(0.667, 0.0);
  colours->Build();
  mapper->SetLookupTable(colours);
  mapper->SetScalarRange(0.0, 4.0);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->GetActiveCamera()->SetPosition(2.2, 1.8, 1.6);
  renderer->GetActiveCamera()->SetFocalPoint(0.3, 0.4, 0.2);
  renderer->GetActiveCamera()->SetViewUp(0, 0, 1);
  renderer->ResetCameraClippingRange();
  vtkNew<vtkRenderWindow> window;
  window->SetSize(300, 300);
  window->AddRenderer(renderer);
  window->Render();
  const int result = vtkRegressionTestImage(window);
  if (result == vtkRegressionTester::FAILED)
  {
    return EXIT_FAILURE;
  }

  // Bad input: a reflectance of 1.2 is refused with the array named, and the
  // output is empty.
  vtkNew<vtkAppendPolyData> bad;
  bad->AddInputData(Plane(f0, f1, f2, 1, 1.2, 0.0));
  bad->AddInputData(Plane(l0, l1, l2, 1, 0.0, 100.0));
  vtkNew<vtkRadiosityFilter> refused;
  refused->SetInputConnection(bad->GetOutputPort());
  refused->GlobalWarningDisplayOff();
  refused->Update();
  refused->GlobalWarningDisplayOn();
  if (refused->GetLastError().find("Reflectance") == std::string::npos ||
    refused->GetOutput()->GetNumberOfCells() != 0)
  {
    std::cerr << "bad input not refused: '" << refused->GetLastError() << "'\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
