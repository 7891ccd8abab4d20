// vtkRadiosityPass on MPI ranks (mpirun with 1, 2 or 4 processes, under an
// X server): as in a ParaView render view on several ranks, every rank's
// renderer holds all of PassTestScene's actors and lights, and each actor's
// data is on one rank (actor i on rank i % n, empty elsewhere).
// - The solution equals the one-process solve of all the actors (in the
//   order the ranks give them) to 1e-12 of the peak, cells and vertices;
//   the ranks' own elements add up to it.
// - All actors on rank 0 and empty renderers elsewhere: the same, no error.
// - A redraw solves nothing on any rank; one rank's actor changed (the
//   box's colour, on its rank only): every rank solves once, together.
#include "PassTestScene.h"

#include "vtkAutoInit.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkMPIController.h"
#include "vtkProperty.h"
#include "vtkRadiosityFilter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

VTK_MODULE_INIT(vtkRenderingOpenGL2);

namespace
{
int Rank = 0, Ranks = 1;

bool Check(bool ok, const std::string& what)
{
  std::printf("[rank %d] %s: %s\n", Rank, ok ? "ok" : "FAILED", what.c_str());
  return ok;
}

struct View
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRadiosityPass> Pass;
  PassTestScene::Scene Scene;
};

/// PassTestScene's five actors in the order a gathered scene has them
/// (rank by rank); rank >= 0: the actors of other ranks hold empty data.
void Build(View& view, vtkMultiProcessController* controller, const std::vector<int>& owner, int rank)
{
  vtkNew<vtkPolyData> empty;
  view.Window->SetOffScreenRendering(1);
  view.Window->SetSize(200, 150);
  view.Window->AddRenderer(view.Renderer);
  view.Scene = PassTestScene::Build(view.Renderer);
  vtkActor* actors[5] = { view.Scene.Floor, view.Scene.BackWall, view.Scene.LeftWall, view.Scene.Box,
    view.Scene.Ball };
  view.Renderer->RemoveAllViewProps();
  for (int r = 0; r < Ranks; ++r)
  {
    for (int i = 0; i < 5; ++i)
    {
      if (owner[i] == r)
      {
        view.Renderer->AddActor(actors[i]);
        if (rank >= 0 && rank != r)
        {
          vtkPolyDataMapper::SafeDownCast(actors[i]->GetMapper())->SetInputData(empty);
        }
      }
    }
  }
  view.Pass->GetFilter()->SetController(controller);
  view.Pass->GetFilter()->SetMethod(vtkRadiosityFilter::Progressive);
  view.Pass->GetFilter()->SetTolerance(0.02);
  view.Pass->GetFilter()->SetNumberOfThreads(1);
  view.Renderer->SetPass(view.Pass);
}

/// Worst difference between two whole solutions, relative to the peak.
double WorstDifference(const radiosity::SolutionMesh* a, const radiosity::SolutionMesh* b)
{
  if (!a || !b || a->Triangles.size() != b->Triangles.size() || a->Points.size() != b->Points.size())
  {
    return -1.0;
  }
  double peak = 0.0, worst = 0.0;
  for (std::size_t i = 0; i < b->PointIrradiance.size(); ++i)
  {
    peak = std::max({ peak, b->PointIrradiance[i].x, b->PointIrradiance[i].y, b->PointIrradiance[i].z });
    const radiosity::RGB d = a->PointIrradiance[i] - b->PointIrradiance[i];
    worst = std::max({ worst, std::abs(d.x), std::abs(d.y), std::abs(d.z) });
  }
  for (std::size_t i = 0; i < b->CellIrradiance.size(); ++i)
  {
    const radiosity::RGB d = a->CellIrradiance[i] - b->CellIrradiance[i];
    worst = std::max({ worst, std::abs(d.x), std::abs(d.y), std::abs(d.z) });
  }
  return peak > 0.0 ? worst / peak : -1.0;
}
}

int main(int argc, char* argv[])
{
  vtkFloatingPointExceptions::Disable();
  vtkNew<vtkMPIController> controller;
  controller->Initialize(&argc, &argv);
  vtkMultiProcessController::SetGlobalController(controller);
  Rank = controller->GetLocalProcessId();
  Ranks = controller->GetNumberOfProcesses();
  bool ok = true;

  for (bool allOnRankZero : { false, true })
  {
    std::vector<int> owner(5);
    for (int i = 0; i < 5; ++i)
    {
      owner[i] = allOnRankZero ? 0 : i % Ranks;
    }
    const std::string what = allOnRankZero ? "all actors on rank 0" : "actor i on rank i % n";
    View whole, mine;
    Build(whole, nullptr, owner, -1);
    Build(mine, controller, owner, Rank);
    whole.Window->Render();
    mine.Window->Render();
    const double worst =
      WorstDifference(mine.Pass->GetFilter()->GetSolution(), whole.Pass->GetFilter()->GetSolution());
    const vtkIdType own = mine.Pass->GetFilter()->GetOutput()->GetNumberOfCells();
    long long sum = 0, local = own;
    controller->AllReduce(&local, &sum, 1, vtkCommunicator::SUM_OP);
    std::printf("[rank %d] %s: %lld own elements of %zu, worst difference %.3g of the peak\n", Rank,
      what.c_str(), static_cast<long long>(own),
      whole.Pass->GetFilter()->GetSolution() ? whole.Pass->GetFilter()->GetSolution()->Triangles.size() : 0,
      worst);
    ok &= Check(mine.Pass->GetFilter()->GetLastError().empty(), what + ": no error");
    ok &= Check(worst >= 0.0 && worst <= 1e-12, what + ": the one-process solution to 1e-12");
    ok &= Check(whole.Pass->GetFilter()->GetSolution() &&
        sum == static_cast<long long>(whole.Pass->GetFilter()->GetSolution()->Triangles.size()),
      what + ": the ranks' own elements add up to the whole");
    if (allOnRankZero)
    {
      continue;
    }
    int expected = mine.Pass->GetNumberOfSolves();
    mine.Window->Render();
    ok &= Check(mine.Pass->GetNumberOfSolves() == expected, what + ": a redraw solves nothing");
    // The box is actor 3, on rank 3 % n only.
    if (Rank == owner[3])
    {
      mine.Scene.Box->GetProperty()->SetColor(0.2, 0.8, 0.4);
    }
    mine.Window->Render();
    ok &= Check(mine.Pass->GetNumberOfSolves() == expected + 1,
      what + ": the box's colour on rank " + std::to_string(owner[3]) + " only: one solve on every rank");
  }

  const int failed = ok ? 0 : 1;
  int anyFailed = 0;
  controller->AllReduce(&failed, &anyFailed, 1, vtkCommunicator::MAX_OP);
  controller->Finalize();
  return anyFailed;
}
