// vtkRadiosityFilter honours AbortExecute from a progress observer: the solve
// stops early and says so; VTK's pipeline empties an aborted filter's output,
// and the solution so far stays available through GetSolution(); for the
// progressive method, its GPU form and Auto's choice on the Cornell box.
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
#include <string>

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
  bool ok = true;
  // Progressive, on the CPU and the GPU, and Auto (the default: clustered
  // hierarchical radiosity here).
  for (int method : { int(vtkRadiosityFilter::Progressive), int(vtkRadiosityFilter::ProgressiveGPU),
         int(vtkRadiosityFilter::Auto) })
  {
    const std::string name = vtkRadiosityFilter::GetMethodName(method);
    progressEvents = 0;
    vtkNew<vtkRadiosityFilter> radiosity;
    radiosity->SetInputConnection(box->GetOutputPort());
    radiosity->SetMethod(method);
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
      std::cerr << name << ": expected an aborted solve, got " << radiosity::ToString(stats.Stop) << "\n";
      ok = false;
      continue;
    }
    // Hierarchical radiosity is stopped while it links (its second progress
    // event), before its first gathering sweep: elements, no history row yet.
    const bool sweeps = method != vtkRadiosityFilter::Auto;
    if (progressEvents < 2 || !radiosity->GetSolution() || radiosity->GetSolution()->Triangles.empty() ||
      (sweeps && stats.History.Rows.empty()) || (!sweeps && stats.Iterations != 0))
    {
      std::cerr << name << ": no partial solution after abort (" << progressEvents << " progress events, "
                << (radiosity->GetSolution() ? radiosity->GetSolution()->Triangles.size() : 0) << " triangles, "
                << stats.History.Rows.size() << " history rows)\n";
      ok = false;
    }
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
