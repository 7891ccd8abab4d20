// vtkRadiosityFilter honours AbortExecute from a progress observer: the solve
// stops early and says so; VTK's pipeline empties an aborted filter's output,
// and the solution so far stays available through GetSolution().
#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkCornellBoxSource.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRadiosityFilter.h"

#include "Radiosity/Common/SolutionMesh.h"

#include <iostream>

namespace
{
int progressEvents = 0;
void AbortOnSecondEvent(vtkObject* caller, unsigned long, void*, void*)
{
  if (++progressEvents == 2)
  {
    vtkAlgorithm::SafeDownCast(caller)->AbortExecuteOn();
  }
}
}

int TestRadiosityFilterAbort(int, char*[])
{
  // The test driver traps floating-point exceptions; Embree's BVH builder
  // relies on IEEE semantics (infinities in empty bounds).
  vtkFloatingPointExceptions::Disable();
  vtkNew<vtkCornellBoxSource> box;
  vtkNew<vtkRadiosityFilter> radiosity;
  radiosity->SetInputConnection(box->GetOutputPort());
  radiosity->SetTolerance(1e-9); // would run for a long time
  vtkNew<vtkCallbackCommand> observer;
  observer->SetCallback(AbortOnSecondEvent);
  radiosity->AddObserver(vtkCommand::ProgressEvent, observer);
  radiosity->GlobalWarningDisplayOff();
  radiosity->Update();
  radiosity->GlobalWarningDisplayOn();
  const radiosity::SolverStatistics& stats = radiosity->GetStatistics();
  if (stats.Stop != radiosity::StopReason::Aborted)
  {
    std::cerr << "expected an aborted solve, got " << radiosity::ToString(stats.Stop) << "\n";
    return EXIT_FAILURE;
  }
  if (progressEvents < 2 || !radiosity->GetSolution() ||
    radiosity->GetSolution()->Triangles.empty() || stats.History.Rows.empty())
  {
    std::cerr << "no partial solution after abort\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
