// The filters' boundary (vtkRadiosityRequestGuard.h): a failed request
// returns 0 (VTK's convention), reports its message through vtkErrorMacro and
// LastError, leaves an empty output and throws nothing, whether the core
// refused the input, a solve would not fit in its memory budget, or a
// downstream filter's field is not what it claims; the next valid request on
// the same filter then solves.
#include "FilterTestSupport.h"

#include "vtkCellData.h"
#include "vtkCornellBoxSource.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRadiosityFilter.h"
#include "vtkShepardFieldProbe.h"
#include "vtkTestErrorObserver.h"

#include <cmath>
#include <string>

using FilterTestSupport::Check;

namespace
{
double PeakIrradiance(vtkPolyData* data)
{
  vtkDataArray* h = data->GetCellData()->GetArray("Irradiance");
  double peak = -1.0;
  for (vtkIdType i = 0; h && i < h->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v = h->GetComponent(i, c);
      peak = std::isfinite(v) ? std::max(peak, v) : std::nan("");
    }
  }
  return peak;
}

bool Contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}
}

int TestRadiosityFilterFailures(int, char*[])
{
  vtkFloatingPointExceptions::Disable(); // Embree's BVH build trips them (DESIGN.md)
  bool ok = true;
  vtkNew<vtkCornellBoxSource> box;
  box->Update();
  vtkNew<vtkRadiosityFilter> filter;
  vtkNew<vtkTest::ErrorObserver> errors;
  filter->AddObserver(vtkCommand::ErrorEvent, errors);
  filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  filter->SetInputConnection(box->GetOutputPort());
  filter->SetMaxTime(20);

  // A valid solve first, so that a failure must empty a full output.
  filter->SetMethodToProgressive();
  ok &= Check(filter->GetExecutive()->Update() == 1, "progressive solve of the Cornell box failed");
  const double first = PeakIrradiance(filter->GetOutput());
  ok &= Check(first > 1.0, "progressive peak irradiance " + std::to_string(first));

  // Over the memory budget, every method: the estimate (or the guard on what
  // grows) refuses before anything large is made. Face cluster's refusal is
  // a SceneError thrown from its constructor: before the guard it left
  // RequestData and ended the process.
  filter->SetMaxMemory(1e-6); // 1 kB
  for (int method : { vtkRadiosityFilter::Progressive, vtkRadiosityFilter::Hierarchical,
         vtkRadiosityFilter::Meshless, vtkRadiosityFilter::FaceCluster })
  {
    filter->SetMethod(method);
    errors->Clear();
    const int status = filter->GetExecutive()->Update();
    const std::string name = vtkRadiosityFilter::GetMethodName(method);
    ok &= Check(status == 0, name + ": a solve over its memory budget returned " + std::to_string(status));
    ok &= Check(Contains(filter->GetLastError(), "bad input: ") &&
        Contains(filter->GetLastError(), "memory budget") && Contains(filter->GetLastError(), "--max-memory"),
      name + ": message '" + filter->GetLastError() + "'");
    ok &= Check(errors->GetError(), name + ": no ErrorEvent");
    ok &= Check(filter->GetOutput()->GetNumberOfCells() == 0,
      name + ": the refused solve left " + std::to_string(filter->GetOutput()->GetNumberOfCells()) + " cells");
  }

  // Bad input: a negative Emission names the array and the value.
  filter->SetMaxMemory(0.0);
  vtkNew<vtkPolyData> negative;
  negative->DeepCopy(box->GetOutput());
  vtkDataArray* emission = negative->GetCellData()->GetArray("Emission");
  emission->SetComponent(3, 1, -2.5);
  filter->SetInputData(negative);
  filter->SetMethodToHierarchical();
  ok &= Check(filter->GetExecutive()->Update() == 0, "negative emission was not refused");
  ok &= Check(Contains(filter->GetLastError(), "Emission") && Contains(filter->GetLastError(), "-2.5"),
    "bad input message '" + filter->GetLastError() + "'");
  ok &= Check(filter->GetOutput()->GetNumberOfCells() == 0, "bad input left an output");

  // The same filter, valid input again: it solves.
  filter->SetInputConnection(box->GetOutputPort());
  ok &= Check(filter->GetExecutive()->Update() == 1, "the solve after the failures failed: " + filter->GetLastError());
  ok &= Check(filter->GetLastError().empty(), "LastError kept: " + filter->GetLastError());
  const double again = PeakIrradiance(filter->GetOutput());
  // The same answer as a filter that never failed (the solve is deterministic
  // up to the order of parallel sums).
  vtkNew<vtkRadiosityFilter> fresh;
  fresh->SetInputConnection(box->GetOutputPort());
  fresh->SetMaxTime(20);
  fresh->SetMethod(filter->GetMethod());
  fresh->Update();
  const double expected = PeakIrradiance(fresh->GetOutput());
  ok &= Check(again > 1.0 && std::fabs(again - expected) <= 1e-9 * expected,
    "peak irradiance after the failures " + std::to_string(again) + ", a fresh filter's " +
      std::to_string(expected));

  // vtkShepardFieldProbe: a field whose Level is NaN is refused by name (the
  // cast of a NaN to an integer was undefined behaviour).
  vtkNew<vtkPolyData> field;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.1, 0.2, 0.3);
  field->SetPoints(points);
  for (const char* name : { "Level", "Radius", "Group" })
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->InsertNextValue(std::string(name) == "Level" ? std::nan("") : 1.0);
    field->GetPointData()->AddArray(a);
  }
  for (const char* name : { "Normal", "Coefficient" })
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(3);
    a->InsertNextTuple3(0, 0, 1);
    field->GetPointData()->AddArray(a);
  }
  vtkNew<vtkShepardFieldProbe> probe;
  probe->AddObserver(vtkCommand::ErrorEvent, errors);
  probe->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  probe->SetInputConnection(box->GetOutputPort());
  probe->SetSourceData(field);
  ok &= Check(probe->GetExecutive()->Update() == 0, "a NaN Level was not refused");
  ok &= Check(Contains(probe->GetLastError(), "point 0") && Contains(probe->GetLastError(), "Level nan"),
    "Shepard probe message '" + probe->GetLastError() + "'");
  if (!ok)
  {
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
