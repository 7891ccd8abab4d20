// The meshless method through the VTK pipeline: vtkRadiosityFilter (Method
// Meshless), port 1 (the point hierarchy and coefficients, also in port 0's
// field data) -> vtkShepardFieldProbe (the field on another dataset), checked
// against the solver's own evaluation; and the error for a progressive
// solve's empty product.
#include "vtkCellArray.h"
#include "vtkCornellBoxSource.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkInformation.h"
#include "vtkRadiositySceneConverter.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRadiosityFilter.h"
#include "vtkShepardFieldProbe.h"

#include "Radiosity/Meshless/MeshlessRadiosity.h"

#include "FilterTestSupport.h"

#include <cmath>
#include <iostream>
#include <string>

using FilterTestSupport::Check;

int TestMeshlessFieldFilter(int, char*[])
{
  vtkFloatingPointExceptions::Disable();
  bool ok = true;
  vtkNew<vtkCornellBoxSource> box;
  vtkNew<vtkRadiosityFilter> radiosity;
  radiosity->SetInputConnection(box->GetOutputPort());
  radiosity->SetMethodToMeshless();
  radiosity->SetPointLevels(3);
  radiosity->Update();
  ok &= Check(radiosity->GetLastError().empty(), "meshless solve: " + radiosity->GetLastError());
  vtkPolyData* solved = radiosity->GetOutput();
  ok &= Check(solved->GetPointData()->GetArray("Irradiance") != nullptr, "surface Irradiance");
  const auto solution = radiosity->GetMeshlessSolution();
  ok &= Check(solution != nullptr, "GetMeshlessSolution");

  vtkPolyData* points = radiosity->GetOutput(1);
  // The same field in the surface's field data (what ParaView's splat
  // representation reads), sharing the arrays.
  auto attached = vtkRadiositySceneConverter::AttachedPointProduct(solved, "ShepardField");
  ok &= Check(attached && attached->GetNumberOfPoints() == points->GetNumberOfPoints() &&
      attached->GetPointData()->GetArray("Coefficient") &&
      attached->GetPointData()->GetArray("Coefficient")->GetVoidPointer(0) ==
        points->GetPointData()->GetArray("Coefficient")->GetVoidPointer(0),
    "the field in port 0's field data shares port 1's arrays");
  const vtkIdType n = points->GetNumberOfPoints();
  ok &= Check(n == static_cast<vtkIdType>(solution->Points().Points().size()), "one vertex per basis function");
  ok &= Check(points->GetNumberOfVerts() == n, "vertices");
  for (auto [name, components] : { std::pair<const char*, int>{ "Level", 1 }, { "Radius", 1 },
         { "Normal", 3 }, { "Group", 1 }, { "Coefficient", 3 }, { "DirectCoefficient", 3 },
         { "Irradiance", 3 }, { "Gathered", 1 } })
  {
    vtkDataArray* a = points->GetPointData()->GetArray(name);
    ok &= Check(a && a->GetNumberOfComponents() == components && a->GetNumberOfTuples() == n,
      std::string("field array ") + name);
  }
  if (!ok)
  {
    return EXIT_FAILURE;
  }
  double range[2];
  points->GetPointData()->GetArray("Level")->GetRange(range);
  ok &= Check(range[0] == 0 && range[1] == 2, "levels 0..2");

  // Probe the field on a point cloud with normals and object ids (the solver
  // assigns each probe to the nearest triangle's object) and compare.
  const radiosity::Scene& scene = solution->GetScene();
  vtkNew<vtkPoints> cloud;
  cloud->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> objects;
  objects->SetName("ObjectId");
  std::vector<radiosity::Probe> probes;
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    const radiosity::Vec3 c = scene.Centroid(t), nn = scene.Normal(t);
    cloud->InsertNextPoint(c.x, c.y, c.z);
    normals->InsertNextTuple3(nn.x, nn.y, nn.z);
    objects->InsertNextValue(scene.ObjectIds[t]);
    probes.push_back({ c, nn });
  }
  vtkNew<vtkPolyData> target;
  target->SetPoints(cloud);
  target->GetPointData()->AddArray(normals);
  target->GetPointData()->AddArray(objects);
  vtkNew<vtkShepardFieldProbe> probe;
  probe->SetInputData(target);
  probe->SetSourceConnection(radiosity->GetOutputPort(1));
  probe->GlobalWarningDisplayOff(); // no materials on the cloud: a warning, Irradiance only
  probe->Update();
  probe->GlobalWarningDisplayOn();
  vtkDataArray* probed = probe->GetOutput()->GetPointData()->GetArray("Irradiance");
  ok &= Check(probed != nullptr, "probe Irradiance");
  if (probed)
  {
    const std::vector<radiosity::RGB> expected = solution->Evaluate(probes);
    double worst = 0.0;
    for (std::size_t i = 0; i < probes.size(); ++i)
    {
      double h[3];
      probed->GetTuple(static_cast<vtkIdType>(i), h);
      for (int c = 0; c < 3; ++c)
      {
        worst = std::max(worst, std::fabs(h[c] - expected[i][c]) / (1e-12 + std::fabs(expected[i][c])));
      }
    }
    std::cout << "probe against the solver: largest relative difference " << worst << "\n";
    ok &= Check(worst < 1e-9, "probe equals the solver's evaluation");
  }
  // Onto the scene's own surface (materials present): Radiosity too.
  vtkNew<vtkShepardFieldProbe> onSurface;
  onSurface->SetInputConnection(box->GetOutputPort());
  onSurface->SetSourceConnection(radiosity->GetOutputPort(1));
  onSurface->Update();
  ok &= Check(onSurface->GetOutput()->GetPointData()->GetArray("Radiosity") != nullptr,
    "Radiosity on a surface with materials");

  // A progressive solution has no field (port 1 is empty): probing it is
  // an error naming what is expected, and an empty output.
  vtkNew<vtkRadiosityFilter> progressive;
  progressive->SetInputConnection(box->GetOutputPort());
  progressive->SetTolerance(1e-2);
  vtkNew<vtkShepardFieldProbe> none;
  none->SetInputData(target);
  none->SetSourceConnection(progressive->GetOutputPort(1));
  none->GlobalWarningDisplayOff();
  none->Update();
  none->GlobalWarningDisplayOn();
  ok &= Check(none->GetLastError().find("Method Meshless") != std::string::npos,
    "error without a field: " + none->GetLastError());
  ok &= Check(none->GetOutput()->GetNumberOfPoints() == 0, "empty output without a field");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
