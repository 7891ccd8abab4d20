// vtkRadiosityFilter's Relighting mode (Lehtinen et al. 2007, section 6.5)
// through the pipeline: the first request solves and precomputes; a new
// vtkLight or a recoloured lamp is relit, not solved, and equals a fresh
// solve of the same input within 1% of the peak; a changed reflectance or
// setting invalidates the transfer with a warning naming the change; a
// limit on the gathers per relight defers receivers to the next requests,
// which end at a fresh solve's answer; a method without relighting says so.
// Face cluster relights a moved light and a recoloured lamp over its kept
// transfer couplings to a fresh solve's answer.
#include "vtkCellData.h"
#include "vtkCornellBoxSource.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRadiosityFilter.h"
#include "vtkStringArray.h"

#include "FilterTestSupport.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

using FilterTestSupport::Check;
using FilterTestSupport::RelativeDifference;

namespace
{
bool StartsWith(const std::string& text, const std::string& prefix)
{
  return text.compare(0, prefix.size(), prefix) == 0;
}

/// A fresh solve of `input` with `light` (may be null) by the same
/// method, for comparison.
double AgainstFreshSolve(vtkRadiosityFilter* relit, vtkPolyData* input, vtkLight* light)
{
  vtkNew<vtkRadiosityFilter> fresh;
  fresh->SetInputData(input);
  fresh->SetMethod(relit->GetMethod());
  fresh->SetPointLevels(relit->GetPointLevels());
  if (light)
  {
    fresh->AddLight(light);
  }
  fresh->Update();
  return RelativeDifference(relit->GetOutput(), fresh->GetOutput());
}

std::string FieldStatus(vtkPolyData* output)
{
  auto* a = vtkStringArray::SafeDownCast(output->GetFieldData()->GetAbstractArray("Relighting"));
  return a && a->GetNumberOfValues() == 1 ? a->GetValue(0) : std::string("(no Relighting array)");
}
}

int TestRadiosityFilterRelighting(int, char*[])
{
  vtkFloatingPointExceptions::Disable();
  bool ok = true;
  vtkNew<vtkCornellBoxSource> box;
  box->Update();
  vtkNew<vtkPolyData> scene;
  scene->DeepCopy(box->GetOutput());

  vtkNew<vtkRadiosityFilter> radiosity;
  radiosity->SetInputData(scene);
  radiosity->SetMethodToMeshless();
  radiosity->SetPointLevels(3);
  radiosity->RelightingOn();
  // A point light in the left half of the box besides the lamp.
  vtkNew<vtkLight> bulb;
  bulb->SetPositional(true);
  bulb->SetConeAngle(180.0);
  double bounds[6];
  scene->GetBounds(bounds);
  const double size[3] = { bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] };
  bulb->SetPosition(bounds[0] + 0.25 * size[0], bounds[2] + 0.5 * size[1], bounds[4] + 0.5 * size[2]);
  bulb->SetIntensity(0.5);
  radiosity->AddLight(bulb);
  radiosity->Update();
  ok &= Check(radiosity->GetLastError().empty(), "solve: " + radiosity->GetLastError());
  std::cout << "first request: " << radiosity->GetRelightingStatus() << "\n";
  ok &= Check(StartsWith(radiosity->GetRelightingStatus(), "precomputed: "), "the first request precomputes");
  ok &= Check(radiosity->GetRelightingPrecomputeSeconds() > 0, "the precomputation is timed");
  ok &= Check(FieldStatus(radiosity->GetOutput()) == radiosity->GetRelightingStatus(), "the status in the field data");

  // The bulb moved by a tenth of the box and tinted: relit, and a fresh solve's answer.
  bulb->SetPosition(bounds[0] + 0.35 * size[0], bounds[2] + 0.45 * size[1], bounds[4] + 0.5 * size[2]);
  bulb->SetDiffuseColor(1.0, 0.8, 0.6);
  radiosity->Update();
  std::cout << "point light moved: " << radiosity->GetRelightingStatus() << "\n";
  ok &= Check(StartsWith(radiosity->GetRelightingStatus(), "relit: "), "a moved light is relit");
  const double withBulb = AgainstFreshSolve(radiosity, scene, bulb);
  std::cout << "  against a fresh solve: " << withBulb << " of the peak\n";
  // Measured 1.8e-9 (the moved bulb's oracle stays within the transfer's
  // rows); the bound is 1%.
  ok &= Check(withBulb < 0.01, "the relit moved light equals a fresh solve within 1%");

  // The lamp recoloured (a change of the input's Emission): relit too.
  vtkDataArray* emission = scene->GetCellData()->GetArray("Emission");
  ok &= Check(emission != nullptr, "the box has an Emission array");
  for (vtkIdType c = 0; emission && c < emission->GetNumberOfTuples(); ++c)
  {
    emission->SetTuple3(c, 0.5 * emission->GetComponent(c, 0), emission->GetComponent(c, 1),
      2.0 * emission->GetComponent(c, 2));
  }
  scene->Modified();
  radiosity->Update();
  std::cout << "lamp recoloured: " << radiosity->GetRelightingStatus() << "\n";
  ok &= Check(StartsWith(radiosity->GetRelightingStatus(), "relit: "), "a recoloured lamp is relit");
  const double recoloured = AgainstFreshSolve(radiosity, scene, bulb);
  std::cout << "  against a fresh solve: " << recoloured << " of the peak\n";
  ok &= Check(recoloured < 0.01, "the recoloured lamp equals a fresh solve within 1%");

  // A limit on the gathers per relight (MaxRelightGatherTime): the bulb
  // moved into a corner wants receivers the transfer lacks; at a microsecond
  // a relight most of them wait, and requesting the same lighting again
  // gathers on until none is left, then a fresh solve's answer.
  radiosity->SetMaxRelightGatherTime(1e-6);
  bulb->SetPosition(bounds[0] + 0.9 * size[0], bounds[2] + 0.1 * size[1], bounds[4] + 0.9 * size[2]);
  radiosity->Update();
  const std::string deferredFirst = radiosity->GetRelightingStatus();
  std::cout << "bulb in a corner, 1 us of gathers: " << deferredFirst << "\n";
  ok &= Check(StartsWith(deferredFirst, "relit: ") && deferredFirst.find(" deferred ") != std::string::npos,
    "a relight past its gather time defers receivers and says so");
  const double firstError = AgainstFreshSolve(radiosity, scene, bulb);
  int requests = 1;
  while (radiosity->GetRelightingStatus().find(" deferred ") != std::string::npos && requests < 200)
  {
    radiosity->Modified(); // the same lighting requested again
    radiosity->Update();
    ++requests;
  }
  const double lastError = AgainstFreshSolve(radiosity, scene, bulb);
  std::cout << "  against a fresh solve: " << firstError << " of the peak at the first request, "
            << lastError << " after " << requests << " (" << radiosity->GetRelightingStatus() << ")\n";
  ok &= Check(StartsWith(radiosity->GetRelightingStatus(), "relit: ") &&
      radiosity->GetRelightingStatus().find(" deferred ") == std::string::npos,
    "the same lighting requested again gathers the deferred receivers");
  // Measured: 8.7e-2 of the peak at the first request (8 receivers added,
  // 92 deferred), 5.4e-9 after 13 requests.
  ok &= Check(lastError < 0.01, "then equals a fresh solve within 1%");
  ok &= Check(firstError > 100.0 * lastError, "the first request, its receivers deferred, was farther off");
  radiosity->SetMaxRelightGatherTime(0.0);

  // A reflectance changed: the transfer no longer applies; solved again.
  vtkDataArray* reflectance = scene->GetCellData()->GetArray("Reflectance");
  ok &= Check(reflectance != nullptr, "the box has a Reflectance array");
  if (reflectance)
  {
    reflectance->SetTuple3(0, 0.2, 0.3, 0.4);
  }
  scene->Modified();
  radiosity->Update();
  std::cout << "reflectance changed: " << radiosity->GetRelightingStatus() << "\n";
  ok &= Check(StartsWith(radiosity->GetRelightingStatus(), "invalidated: ") &&
      radiosity->GetRelightingStatus().find("reflectance of triangle 0") != std::string::npos &&
      radiosity->GetRelightingStatus().find("; precomputed: ") != std::string::npos,
    "a changed reflectance invalidates the transfer, naming the triangle, and it is precomputed again");
  const auto& warnings = radiosity->GetWarnings();
  ok &= Check(std::any_of(warnings.begin(), warnings.end(),
                [](const std::string& w) { return StartsWith(w, "relighting invalidated: "); }),
    "and warns");
  ok &= Check(AgainstFreshSolve(radiosity, scene, bulb) < 1e-12, "the new solve is a fresh solve's");
  radiosity->Update(); // nothing changed: the pipeline does not execute
  bulb->SetIntensity(0.25);
  radiosity->Update();
  ok &= Check(StartsWith(radiosity->GetRelightingStatus(), "relit: "), "precomputed again: relit");

  // A setting the transfer depends on.
  radiosity->SetGatherRays(128);
  radiosity->Update();
  std::cout << "setting changed: " << radiosity->GetRelightingStatus() << "\n";
  ok &= Check(StartsWith(radiosity->GetRelightingStatus(),
                "invalidated: the method's settings changed since the precomputation; precomputed: "),
    "a changed setting invalidates the transfer");

  // Off, and a method without relighting.
  radiosity->RelightingOff();
  radiosity->Update();
  ok &= Check(radiosity->GetRelightingStatus() == "off", "off");
  vtkNew<vtkRadiosityFilter> progressive;
  progressive->SetInputData(scene);
  progressive->SetMethodToProgressive();
  progressive->RelightingOn();
  progressive->SetMaxIterations(50);
  progressive->Update();
  std::cout << "progressive: " << progressive->GetRelightingStatus() << "\n";
  ok &= Check(StartsWith(progressive->GetRelightingStatus(), "unavailable: method progressive"),
    "progressive says it has no relighting");

  // Face cluster: a moved light and a recoloured lamp relit over the
  // solve's kept transfer couplings, each a fresh solve's answer to the
  // bit; a changed reflectance solves again.
  vtkNew<vtkPolyData> room;
  room->DeepCopy(box->GetOutput());
  vtkNew<vtkRadiosityFilter> clusters;
  clusters->SetInputData(room);
  clusters->SetMethodToFaceCluster();
  clusters->RelightingOn();
  bulb->SetPosition(bounds[0] + 0.25 * size[0], bounds[2] + 0.5 * size[1], bounds[4] + 0.5 * size[2]);
  bulb->SetIntensity(0.5);
  clusters->AddLight(bulb);
  clusters->Update();
  std::cout << "face cluster, first request: " << clusters->GetRelightingStatus() << "\n";
  ok &= Check(StartsWith(clusters->GetRelightingStatus(), "precomputed: ") &&
      clusters->GetRelightingStatus().find(" transfer couplings kept") != std::string::npos,
    "face cluster: the first request keeps its transfer couplings");
  bulb->SetPosition(bounds[0] + 0.7 * size[0], bounds[2] + 0.4 * size[1], bounds[4] + 0.4 * size[2]);
  bulb->SetDiffuseColor(0.6, 0.8, 1.0);
  clusters->Update();
  std::cout << "face cluster, point light moved: " << clusters->GetRelightingStatus() << "\n";
  ok &= Check(StartsWith(clusters->GetRelightingStatus(), "relit: "), "face cluster: a moved light is relit");
  const double clustersMoved = AgainstFreshSolve(clusters, room, bulb);
  std::cout << "  against a fresh solve: " << clustersMoved << " of the peak\n";
  // Measured 0: the same oracle over the same couplings.
  ok &= Check(clustersMoved <= 1e-12, "face cluster: the relit moved light is a fresh solve's");
  vtkDataArray* lamp = room->GetCellData()->GetArray("Emission");
  for (vtkIdType c = 0; lamp && c < lamp->GetNumberOfTuples(); ++c)
  {
    lamp->SetTuple3(c, 2.0 * lamp->GetComponent(c, 0), lamp->GetComponent(c, 1), lamp->GetComponent(c, 2));
  }
  room->Modified();
  clusters->Update();
  std::cout << "face cluster, lamp recoloured: " << clusters->GetRelightingStatus() << "\n";
  ok &= Check(StartsWith(clusters->GetRelightingStatus(), "relit: "), "face cluster: a recoloured lamp is relit");
  const double clustersLamp = AgainstFreshSolve(clusters, room, bulb);
  std::cout << "  against a fresh solve: " << clustersLamp << " of the peak\n";
  ok &= Check(clustersLamp <= 1e-12, "face cluster: the recoloured lamp relit is a fresh solve's");
  vtkDataArray* paint = room->GetCellData()->GetArray("Reflectance");
  if (paint)
  {
    paint->SetTuple3(3, 0.2, 0.3, 0.4);
  }
  room->Modified();
  clusters->Update();
  std::cout << "face cluster, reflectance changed: " << clusters->GetRelightingStatus() << "\n";
  ok &= Check(StartsWith(clusters->GetRelightingStatus(), "invalidated: face cluster relighting: ") &&
      clusters->GetRelightingStatus().find("reflectance of triangle 3") != std::string::npos &&
      clusters->GetRelightingStatus().find("; precomputed: ") != std::string::npos,
    "face cluster: a changed reflectance invalidates, naming the triangle, and is solved and kept again");
  ok &= Check(AgainstFreshSolve(clusters, room, bulb) <= 1e-12, "face cluster: then a fresh solve's answer");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
