// vtkRadiosityFilter on MPI ranks (issue 19): the 1.5M-triangle bunny room
// cut into slabs along x (a partitioned reader's pieces, with VTK's global
// ids), gathered and solved with the work split between the ranks.
//   mpirun -np N bench_mpi <bunny index.js> [--method meshless|progressive|hierarchical|facecluster]
//          [--triangles T] [--threads K]
// Rank 0 prints one markdown row: ranks, threads per rank (0: all cores),
// method, triangles; the request's wall time, of it the scene's gather with
// the solver's set-up, the solve and the output (each the slowest rank's);
// each rank's share of the split loops and the MB it received (scene,
// solve); the largest per-rank peak memory; the peak irradiance (the same
// on every rank count).
#include "vtkRadiosityFilter.h"
#include "vtkRadiositySceneConverter.h"

#include "Radiosity/Common/ScenePieces.h"
#include "Radiosity/Common/SolverTypes.h"
#include "Radiosity/Common/SystemInfo.h"
#include "Radiosity/Scenes/BunnyScene.h"

#include "vtkCellData.h"
#include "vtkIdTypeArray.h"
#include "vtkMPIController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

using namespace radiosity;

namespace
{
/// Rank `rank`'s slab of `scene`: the triangles in order of their
/// centroids' x, cut into `ranks` equal runs (the spatial pieces a parallel
/// reader or a redistribution leaves), over the points they use, with the
/// scene's point and triangle indices as VTK's global ids.
vtkSmartPointer<vtkPolyData> PieceOf(const Scene& scene, int rank, int ranks)
{
  const std::size_t n = scene.Triangles.size();
  std::vector<std::size_t> order(n);
  for (std::size_t t = 0; t < n; ++t)
  {
    order[t] = t;
  }
  std::stable_sort(order.begin(), order.end(), [&scene](std::size_t a, std::size_t b) {
    return scene.Centroid(a).x < scene.Centroid(b).x;
  });
  std::vector<std::size_t> mine(order.begin() + static_cast<std::ptrdiff_t>(n * rank / ranks),
    order.begin() + static_cast<std::ptrdiff_t>(n * (rank + 1) / ranks));
  std::sort(mine.begin(), mine.end());
  std::vector<std::uint32_t> pointSource;
  const Scene piece = SceneOfTriangles(scene, mine, &pointSource);
  const std::vector<long long> pointIds(pointSource.begin(), pointSource.end()),
    cellIds(piece.SourceCells.begin(), piece.SourceCells.end());
  vtkSmartPointer<vtkPolyData> pd = vtkRadiositySceneConverter::FromScene(piece);
  for (auto* ids : { &pointIds, &cellIds })
  {
    vtkNew<vtkIdTypeArray> a;
    a->SetName(ids == &pointIds ? "GlobalPointIds" : "GlobalCellIds");
    a->SetNumberOfTuples(static_cast<vtkIdType>(ids->size()));
    for (std::size_t i = 0; i < ids->size(); ++i)
    {
      a->SetValue(static_cast<vtkIdType>(i), static_cast<vtkIdType>((*ids)[i]));
    }
    if (ids == &pointIds)
    {
      pd->GetPointData()->SetGlobalIds(a);
    }
    else
    {
      pd->GetCellData()->SetGlobalIds(a);
    }
  }
  return pd;
}

double MaxOver(vtkMPIController* c, double v)
{
  double out = v;
  c->AllReduce(&v, &out, 1, vtkCommunicator::MAX_OP);
  return out;
}
}

int main(int argc, char* argv[])
{
  vtkNew<vtkMPIController> controller;
  controller->Initialize(&argc, &argv);
  vtkMultiProcessController::SetGlobalController(controller);
  const int rank = controller->GetLocalProcessId(), ranks = controller->GetNumberOfProcesses();
  std::string bunnyJs, method = "meshless";
  std::size_t triangles = 1500000;
  int threads = 0;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--method" && i + 1 < argc)
    {
      method = argv[++i];
    }
    else if (a == "--triangles" && i + 1 < argc)
    {
      triangles = static_cast<std::size_t>(std::stoull(argv[++i]));
    }
    else if (a == "--threads" && i + 1 < argc)
    {
      threads = std::stoi(argv[++i]);
    }
    else
    {
      bunnyJs = a;
    }
  }
  if (bunnyJs.empty())
  {
    if (rank == 0)
    {
      std::fprintf(stderr, "usage: mpirun -np N %s <bunny index.js> [--method M] [--triangles T] [--threads K]\n", argv[0]);
    }
    controller->Finalize();
    return 2;
  }
  const Scene room = MakeBunnyRoomWithTriangles(ReadNpmBunny(bunnyJs), triangles);
  const std::size_t n = room.Triangles.size();
  vtkSmartPointer<vtkPolyData> piece = PieceOf(room, rank, ranks);

  vtkNew<vtkRadiosityFilter> filter;
  filter->SetController(controller);
  filter->SetInputData(piece);
  filter->SetNumberOfThreads(threads);
  filter->SetMethod(method == "progressive" ? vtkRadiosityFilter::Progressive
      : method == "hierarchical"            ? vtkRadiosityFilter::Hierarchical
      : method == "facecluster"             ? vtkRadiosityFilter::FaceCluster
                                            : vtkRadiosityFilter::Meshless);
  controller->Barrier();
  const auto start = std::chrono::steady_clock::now();
  filter->Update();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const SolverStatistics& stats = filter->GetStatistics();
  const double wall = MaxOver(controller, seconds);
  const double preprocess = MaxOver(controller, filter->GetPreprocessSeconds());
  const double solve = MaxOver(controller, stats.SolveSeconds);
  const double output = MaxOver(controller, seconds - filter->GetPreprocessSeconds() - stats.SolveSeconds);
  const double memory = MaxOver(controller, PeakMemoryBytes());
  double peak = 0.0;
  if (vtkDataArray* e = filter->GetOutput()->GetCellData()->GetArray("Irradiance"))
  {
    for (vtkIdType c = 0; c < e->GetNumberOfTuples(); ++c)
    {
      peak = std::max(peak, e->GetComponent(c, 1));
    }
  }
  peak = MaxOver(controller, peak);
  if (rank == 0)
  {
    const auto list = [](const std::vector<vtkIdType>& v, double scale) {
      std::ostringstream s;
      for (std::size_t i = 0; i < v.size(); ++i)
      {
        s << (i ? " / " : "") << static_cast<double>(v[i]) * scale;
      }
      return v.empty() ? std::string("-") : s.str();
    };
    std::printf("| %d | %d | %s | %zu | %.1f | %.1f | %.1f | %.1f | %s | %s | %s | %.0f | %.6g | %s |\n", ranks,
      threads, method.c_str(), n, wall, preprocess, solve, output, list(filter->GetRankWorkItems(), 1.0).c_str(),
      list(filter->GetRankBytesReceived(), 1e-6).c_str(), list(filter->GetRankSolveBytesReceived(), 1e-6).c_str(),
      memory / 1e6, peak, filter->GetLastError().empty() ? "ok" : filter->GetLastError().c_str());
  }
  controller->Finalize();
  return filter->GetLastError().empty() ? 0 : 1;
}
