// Renders a synthetic radiosity solution with vtkRadiosityView and compares it
// with the baseline; checks that invalid input is refused with an error that
// names the array instead of crashing.

#include "vtkRadiosityView.h"

#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkSphereSource.h"
#include "vtkTestErrorObserver.h"
#include "vtkTestUtilities.h"

#include <cmath>
#include <iostream>
#include <string>

namespace
{
// A sphere lit from above: a small hot spot (up to 120 W/m^2, far above the
// displayable range once divided by pi) on top of a smooth gradient of a few
// W/m^2, warm on one side and cold on the other, so that the image shows both
// the HDR compression and the per-vertex interpolation.
vtkSmartPointer<vtkPolyData> MakeSolution()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(48);
  sphere->SetRadius(1.0);
  sphere->Update();
  vtkSmartPointer<vtkPolyData> pd = sphere->GetOutput();

  vtkNew<vtkDoubleArray> radiosity;
  radiosity->SetName("Radiosity");
  radiosity->SetNumberOfComponents(3);
  radiosity->SetNumberOfTuples(pd->GetNumberOfPoints());
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
  {
    double p[3];
    pd->GetPoint(i, p);
    const double d2 = (p[0] - 0.45) * (p[0] - 0.45) + (p[1] - 0.55) * (p[1] - 0.55) +
      (p[2] - 0.7) * (p[2] - 0.7);
    const double spot = 120.0 * std::exp(-d2 / 0.03);
    const double s = 0.5 * (p[0] + 1.0); // 0 .. 1 across the sphere
    const double base = 0.5 + 2.5 * 0.5 * (p[1] + 1.0);
    radiosity->SetTuple3(
      i, base * (0.3 + 0.9 * s) + spot, base * 0.7 + 0.8 * spot, base * (1.2 - 0.9 * s) + 0.5 * spot);
  }
  pd->GetPointData()->AddArray(radiosity);
  return pd;
}

// Expects Render() to fail with an error message containing `expected`.
bool ExpectRefused(vtkRadiosityView* view, const std::string& expected)
{
  vtkNew<vtkTest::ErrorObserver> observer;
  const unsigned long tag = view->AddObserver(vtkCommand::ErrorEvent, observer);
  const bool rendered = view->Render();
  view->RemoveObserver(tag);
  if (rendered)
  {
    std::cerr << "Render() accepted invalid input (expected: " << expected << ")\n";
    return false;
  }
  if (!observer->GetError() || observer->GetErrorMessage().find(expected) == std::string::npos)
  {
    std::cerr << "Expected an error containing '" << expected << "', got '"
              << observer->GetErrorMessage() << "'\n";
    return false;
  }
  return true;
}

bool TestInvalidInput()
{
  bool ok = true;
  vtkNew<vtkRadiosityView> view;
  ok &= ExpectRefused(view, "No input");

  vtkSmartPointer<vtkPolyData> pd = MakeSolution();
  view->SetInputData(pd);
  view->SetArrayName("Irradiance");
  ok &= ExpectRefused(view, "'Irradiance'");

  vtkNew<vtkFloatArray> scalar;
  scalar->SetName("Scalar");
  scalar->SetNumberOfTuples(pd->GetNumberOfPoints());
  scalar->FillValue(1.0f);
  pd->GetPointData()->AddArray(scalar);
  view->SetArrayName("Scalar");
  ok &= ExpectRefused(view, "'Scalar' has 1 components");

  // The view is still usable once the input is fixed.
  view->SetArrayName("Radiosity");
  view->SetSize(64, 48);
  if (!view->Render())
  {
    std::cerr << "Render() failed on valid input after invalid input\n";
    ok = false;
  }
  vtkNew<vtkTest::ErrorObserver> observer;
  view->AddObserver(vtkCommand::ErrorEvent, observer);
  if (view->WritePNG("") || !observer->GetError())
  {
    std::cerr << "WritePNG accepted an empty file name\n";
    ok = false;
  }
  return ok;
}
}

int TestRadiosityView(int argc, char* argv[])
{
  // Mesa's llvmpipe raises SIGFPE when VTK's driver enables FP exceptions.
  vtkFloatingPointExceptions::Disable();

  if (!TestInvalidInput())
  {
    return EXIT_FAILURE;
  }

  // Setters clamp.
  vtkNew<vtkRadiosityView> view;
  view->SetExposure(-1.0);
  view->SetToneMappingType(42);
  if (view->GetExposure() != 0.0 || view->GetToneMappingType() != vtkRadiosityView::GenericFilmic)
  {
    std::cerr << "Exposure or ToneMappingType not clamped\n";
    return EXIT_FAILURE;
  }
  view->SetToneMappingTypeToReinhard();
  view->SetExposure(1.0);

  view->SetInputData(MakeSolution());
  view->SetSize(300, 300);
  const double position[3] = { 1.2, 1.6, 3.6 };
  const double focal[3] = { 0.0, 0.0, 0.0 };
  const double up[3] = { 0.0, 1.0, 0.0 };
  view->SetCamera(position, focal, up, 30.0);
  if (!view->Render())
  {
    std::cerr << "Render() failed on valid input\n";
    return EXIT_FAILURE;
  }

  // Optionally keep the image for a look: -T <dir> is the test output dir.
  char* tempDir =
    vtkTestUtilities::GetArgOrEnvOrDefault("-T", argc, argv, "VTK_TEMP_DIR", "Testing/Temporary");
  const std::string png = std::string(tempDir) + "/TestRadiosityView-written.png";
  delete[] tempDir;
  if (!view->WritePNG(png.c_str()))
  {
    std::cerr << "WritePNG failed for " << png << "\n";
    return EXIT_FAILURE;
  }

  const int retVal = vtkRegressionTestImage(view->GetRenderWindow());
  return !retVal;
}
