// vtkRadiosityFilter inside a plain VTK pipeline: a scene made with VTK's own
// sources and filters, the solution coloured by VTK's standard mapper; its
// values against the definition B = E + rho H and against the path tracer
// on the same scene built by the core; and the documented error for bad input.
#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkCamera.h"
#include "vtkCell.h"
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

#include "Radiosity/Reference/PathTracer.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <algorithm>
#include <cmath>
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

/// The same three planes as a core scene, for the path tracer.
radiosity::Scene PipelineScene()
{
  using radiosity::Vec3;
  radiosity::Material floor, light, wall;
  floor.Reflectance = radiosity::RGB(0.7);
  light.Reflectance = radiosity::RGB(0.0);
  light.Emission = radiosity::RGB(100.0);
  wall.Reflectance = radiosity::RGB(0.5);
  radiosity::Scene s;
  radiosity::AppendQuad(s, Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), floor, 1, "floor");
  radiosity::AppendQuad(s, Vec3(0.4, 0.4, 0.6), Vec3(0.4, 0.6, 0.6), Vec3(0.6, 0.6, 0.6),
    Vec3(0.6, 0.4, 0.6), light, 1, "light");
  radiosity::AppendQuad(s, Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(0, 1, 1), Vec3(0, 0, 1), wall, 1, "wall");
  return s;
}

/// Checks the solution's cells: B = E + rho H per channel (the material from
/// the plane the cell lies in), and the irradiance of every 7th floor and
/// wall cell against the path tracer at its centroid. Returns false on failure.
bool CheckValues(vtkPolyData* out)
{
  vtkDataArray* irradiance = out->GetCellData()->GetArray("Irradiance");
  vtkDataArray* radiosityArray = out->GetCellData()->GetArray("Radiosity");
  if (!irradiance || !radiosityArray || irradiance->GetNumberOfComponents() != 3 ||
    radiosityArray->GetNumberOfComponents() != 3)
  {
    std::cerr << "no 3-component cell arrays Irradiance and Radiosity\n";
    return false;
  }
  std::vector<radiosity::Probe> probes;
  std::vector<double> solved;
  std::size_t floorCells = 0, wallCells = 0, lightCells = 0;
  double worstIdentity = 0.0;
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    double centre[3] = { 0, 0, 0 };
    vtkCell* cell = out->GetCell(c);
    const vtkIdType n = cell->GetNumberOfPoints();
    for (vtkIdType k = 0; k < n; ++k)
    {
      double x[3];
      cell->GetPoints()->GetPoint(k, x);
      for (int d = 0; d < 3; ++d)
      {
        centre[d] += x[d] / static_cast<double>(n);
      }
    }
    double rho = 0.0, emission = 0.0;
    radiosity::Vec3 normal(0.0);
    std::size_t* count = nullptr;
    if (std::fabs(centre[2] - 0.6) < 1e-6)
    {
      emission = 100.0;
      count = &lightCells;
    }
    else if (std::fabs(centre[2]) < 1e-6)
    {
      rho = 0.7;
      normal = radiosity::Vec3(0, 0, 1);
      count = &floorCells;
    }
    else if (std::fabs(centre[0]) < 1e-6)
    {
      rho = 0.5;
      normal = radiosity::Vec3(1, 0, 0);
      count = &wallCells;
    }
    else
    {
      std::cerr << "cell " << c << " lies on no plane of the scene\n";
      return false;
    }
    double h[3], b[3];
    irradiance->GetTuple(c, h);
    radiosityArray->GetTuple(c, b);
    for (int k = 0; k < 3; ++k)
    {
      const double expected = emission + rho * h[k];
      worstIdentity = std::max(worstIdentity, std::fabs(b[k] - expected) / std::max(expected, 1e-300));
    }
    const std::size_t index = (*count)++;
    if (rho > 0.0 && index % 7 == 0)
    {
      probes.push_back(radiosity::Probe{ radiosity::Vec3(centre[0], centre[1], centre[2]), normal });
      solved.push_back(radiosity::Luminance(radiosity::RGB(h[0], h[1], h[2])));
    }
  }
  // Measured: 0 (the arrays are written from one B per cell).
  if (!(worstIdentity < 1e-12) || floorCells == 0 || wallCells == 0 || lightCells == 0)
  {
    std::cerr << "B = E + rho H off by " << worstIdentity << " (relative); cells: " << floorCells
              << " floor, " << wallCells << " wall, " << lightCells << " light\n";
    return false;
  }
  // 16,384 paths per probe: relative standard error at most 0.032.
  const radiosity::Scene scene = PipelineScene();
  radiosity::PathTracerOptions options;
  options.SamplesPerProbe = 16384;
  const radiosity::PathTracer tracer(scene, options);
  const std::vector<radiosity::ReferenceValue> reference = tracer.Irradiance(probes);
  double sum = 0.0, worst = 0.0, worstSe = 0.0;
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    const double expected = radiosity::Luminance(reference[i].Value);
    const double error = std::fabs(solved[i] - expected) / expected;
    worstSe = std::max(worstSe, radiosity::Luminance(reference[i].StandardError) / expected);
    if (!std::isfinite(error))
    {
      std::cerr << "probe " << i << ": solved " << solved[i] << ", path traced " << expected << "\n";
      return false;
    }
    sum += error * error;
    worst = std::max(worst, error);
  }
  const double rms = std::sqrt(sum / static_cast<double>(probes.size()));
  std::cout << probes.size() << " cells against the path tracer: RMS relative error " << rms
            << ", max " << worst << " (largest relative SE " << worstSe << ")\n";
  // Measured over 189 cells: RMS 0.0175, max 0.066 (mostly the path
  // tracer's noise).
  if (!(rms < 0.035) || !(worst < 0.13))
  {
    std::cerr << "the solution departs from the path tracer\n";
    return false;
  }
  return true;
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
  radiosity->SetMethodToProgressive(); // its elements, as the baseline shows them
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
  if (!CheckValues(out))
  {
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
