// vtkRadiosityFilter's default LightScale (pi, derived in its header): a
// directional vtkLight of Intensity 1 falling straight on a white surface
// looks as bright drawn by VTK's OpenGL shading (left viewport: a white
// vtkProperty, Diffuse 1, no ambient or specular) as solved and drawn per
// pixel by the project's mapper (right viewport: the hierarchical
// solution's quadratic interpolants, vtkQuadraticInterpolantMapper, no tone
// mapping pass). Reflectance 0.999 stands for white (a Reflectance of 1 is
// refused): the mapper then writes (0.999 x pi x 1 / pi)^(1/2.2), 254.9 of
// 255. Twice the LightScale would saturate, half of it gives 0.5^(1/2.2)
// of the peak, glTF's 186 of 255: both are checked, so the test tells the
// scale, not only that something was drawn.
#include "FilterTestSupport.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkQuadraticInterpolantMapper.h"
#include "vtkRadiosityFilter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <iostream>
#include <string>

using FilterTestSupport::Check;

namespace
{
constexpr int Size = 64;

/// A 1 m square at z = 0 facing +z, two triangles, with `reflectance`.
vtkSmartPointer<vtkPolyData> Square(double reflectance)
{
  auto square = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(-0.5, -0.5, 0.0);
  points->InsertNextPoint(0.5, -0.5, 0.0);
  points->InsertNextPoint(0.5, 0.5, 0.0);
  points->InsertNextPoint(-0.5, 0.5, 0.0);
  vtkNew<vtkCellArray> cells;
  const vtkIdType a[3] = { 0, 1, 2 }, b[3] = { 0, 2, 3 };
  cells->InsertNextCell(3, a);
  cells->InsertNextCell(3, b);
  square->SetPoints(points);
  square->SetPolys(cells);
  vtkNew<vtkDoubleArray> rho;
  rho->SetName("Reflectance");
  rho->SetNumberOfComponents(3);
  rho->InsertNextTuple3(reflectance, reflectance, reflectance);
  rho->InsertNextTuple3(reflectance, reflectance, reflectance);
  square->GetCellData()->AddArray(rho);
  return square;
}

/// The mean red value of the centre 16 x 16 pixels of viewport `x0`.
double CentreValue(vtkRenderWindow* window, int x0)
{
  vtkNew<vtkUnsignedCharArray> pixels;
  const int c = Size / 2;
  window->GetRGBACharPixelData(x0 + c - 8, c - 8, x0 + c + 7, c + 7, 1, pixels);
  double sum = 0.0;
  for (vtkIdType i = 0; i < 256; ++i)
  {
    sum += pixels->GetValue(4 * i);
  }
  return sum / 256.0;
}

void LookDown(vtkRenderer* renderer)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetPosition(0.0, 0.0, 2.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetParallelScale(0.3); // the square fills the viewport
  camera->SetClippingRange(0.5, 4.0);
}
}

int TestLightScaleBrightness(int, char*[])
{
  vtkFloatingPointExceptions::Disable(); // Embree's BVH build trips them (DESIGN.md)
  bool ok = true;
  // The sun: non-positional, straight down, Intensity 1, white.
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(0.0, 0.0, 1.0);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  sun->SetIntensity(1.0);
  sun->SetColor(1.0, 1.0, 1.0);

  vtkNew<vtkRadiosityFilter> radiosity;
  radiosity->SetInputData(Square(0.999));
  radiosity->SetMethodToHierarchical();
  radiosity->AddLight(sun);
  radiosity->Update();
  vtkPolyData* meshed = radiosity->GetOutput(1);
  if (!Check(radiosity->GetLastError().empty() && meshed->GetNumberOfCells() > 0,
        "the sunlit square did not solve: " + radiosity->GetLastError()))
  {
    return EXIT_FAILURE;
  }

  vtkNew<vtkRenderWindow> window;
  window->SetSize(2 * Size, Size);
  window->SetMultiSamples(0);
  // Left: VTK's own shading of a white surface under the same light.
  vtkNew<vtkRenderer> vtkSide;
  vtkSide->SetViewport(0.0, 0.0, 0.5, 1.0);
  vtkSide->AutomaticLightCreationOff();
  vtkSide->AddLight(sun);
  vtkNew<vtkPolyDataMapper> plain;
  plain->SetInputData(Square(0.999));
  plain->ScalarVisibilityOff();
  vtkNew<vtkActor> white;
  white->SetMapper(plain);
  white->GetProperty()->SetColor(1.0, 1.0, 1.0);
  white->GetProperty()->SetAmbient(0.0);
  white->GetProperty()->SetDiffuse(1.0);
  white->GetProperty()->SetSpecular(0.0);
  vtkSide->AddActor(white);
  LookDown(vtkSide);
  // Right: the solution per pixel.
  vtkNew<vtkRenderer> ourSide;
  ourSide->SetViewport(0.5, 0.0, 1.0, 1.0);
  vtkNew<vtkQuadraticInterpolantMapper> interpolants;
  interpolants->SetInputData(meshed);
  vtkNew<vtkActor> solved;
  solved->SetMapper(interpolants);
  ourSide->AddActor(solved);
  LookDown(ourSide);
  window->AddRenderer(vtkSide);
  window->AddRenderer(ourSide);
  window->Render();
  const double vtkValue = CentreValue(window, 0);
  const double ourValue = CentreValue(window, Size);
  std::cout << "centre of the sunlit white square: VTK " << vtkValue << ", radiosity " << ourValue
            << " (of 255; expected 255 and 255 x 0.999^(1/2.2) = 254.9)\n";
  // Rounding alone: 8-bit values of 255 and 254.9.
  ok &= Check(std::fabs(vtkValue - 255.0) <= 1.0, "VTK's shading is not white: " + std::to_string(vtkValue));
  ok &= Check(std::fabs(ourValue - vtkValue) <= 1.5,
    "LightScale pi: radiosity " + std::to_string(ourValue) + " against VTK " + std::to_string(vtkValue));

  // Half the scale: L = 0.4995, drawn 0.4995^(1/2.2) x 255 = 186.3.
  radiosity->SetLightScale(radiosity->GetLightScale() / 2.0);
  radiosity->Update();
  interpolants->SetInputData(radiosity->GetOutput(1));
  window->Render();
  const double half = CentreValue(window, Size);
  std::cout << "LightScale pi / 2: radiosity " << half << " (expected 186.3)\n";
  ok &= Check(std::fabs(half - 255.0 * std::pow(0.4995, 1.0 / 2.2)) <= 1.5,
    "LightScale pi / 2 drew " + std::to_string(half));
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
