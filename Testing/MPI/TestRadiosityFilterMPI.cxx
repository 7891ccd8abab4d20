// vtkRadiosityFilter on MPI ranks (run under mpirun with 1, 2 or 4
// processes): light does not stop at a piece's boundary. The Cornell box is
// split over the ranks three ways, and each rank's output must equal the
// one-process solve of the whole box on that rank's elements, cells and
// points, to 1e-12 of the peak, for every method:
//  1. interleaved pieces (triangle t on rank t % n, no rank holds a whole
//     wall) carrying only the points they use, with VTK's global point and
//     cell ids (what a redistribution leaves);
//  2. consecutive ranges of cells over all the points, without ids (the
//     points welded by position; the box's unwelded corners stay unwelded
//     because every rank holds every point);
//  3. the whole box on rank 0 and empty pieces on the others (a source that
//     does not split: ParaView's Cornell Box): no error and no warning
//     anywhere.
// Then a NaN reflectance on the last rank fails the request on every rank
// with the same message, naming that rank.
#include "vtkCellData.h"
#include "vtkCornellBoxSource.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkMPIController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiosityRankExchange.h"

#include "Radiosity/Common/WorkShare.h"
#include "Radiosity/Reference/PathTracer.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

namespace
{
int Rank = 0, Ranks = 1;

bool Check(bool ok, const std::string& what)
{
  std::printf("[rank %d] %s: %s\n", Rank, ok ? "ok" : "FAILED", what.c_str());
  return ok;
}

/// The cells `keep` of `box`: over all its points, or over the points they
/// use (`compact`, with global ids when `ids`).
vtkSmartPointer<vtkPolyData> Piece(vtkPolyData* box, const std::vector<vtkIdType>& keep, bool compact, bool ids)
{
  auto piece = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  std::map<vtkIdType, vtkIdType> used;
  if (!compact)
  {
    points->DeepCopy(box->GetPoints());
    for (vtkIdType p = 0; p < box->GetNumberOfPoints(); ++p)
    {
      used[p] = p;
    }
  }
  vtkNew<vtkCellArray> polys;
  piece->SetPoints(points);
  piece->SetPolys(polys);
  piece->GetCellData()->CopyAllocate(box->GetCellData(), static_cast<vtkIdType>(keep.size()));
  vtkIdType out = 0;
  for (vtkIdType c : keep)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    box->GetCellPoints(c, npts, pts);
    std::vector<vtkIdType> ptIds;
    for (vtkIdType k = 0; k < npts; ++k)
    {
      const auto found = used.emplace(pts[k], points->GetNumberOfPoints());
      if (found.second)
      {
        points->InsertNextPoint(box->GetPoint(pts[k]));
      }
      ptIds.push_back(found.first->second);
    }
    polys->InsertNextCell(npts, ptIds.data());
    piece->GetCellData()->CopyData(box->GetCellData(), c, out++);
  }
  piece->GetFieldData()->ShallowCopy(box->GetFieldData());
  if (ids)
  {
    vtkNew<vtkIdTypeArray> pointIds, cellIds;
    pointIds->SetName("GlobalPointIds");
    cellIds->SetName("GlobalCellIds");
    pointIds->SetNumberOfTuples(points->GetNumberOfPoints());
    for (const auto& u : used)
    {
      pointIds->SetValue(u.second, u.first);
    }
    for (vtkIdType c : keep)
    {
      cellIds->InsertNextValue(c);
    }
    piece->GetPointData()->SetGlobalIds(pointIds);
    piece->GetCellData()->SetGlobalIds(cellIds);
  }
  return piece;
}

vtkSmartPointer<vtkRadiosityFilter> Solver(int method, vtkMultiProcessController* controller)
{
  auto f = vtkSmartPointer<vtkRadiosityFilter>::New();
  f->SetController(controller);
  f->SetMethod(method);
  f->SetNumberOfThreads(1); // several ranks share this machine's cores
  f->SetTolerance(1e-2);
  f->SetMaxIterations(method == vtkRadiosityFilter::Progressive ? 300 : 200000);
  f->SetPointLevels(3);
  f->SetGatherRays(64);
  return f;
}

/// Worst difference between `piece` (this rank's output) and the whole
/// solve's elements of the same ElementId, cells and corners, relative to
/// the whole solve's peak; -1 when an element is missing.
double WorstDifference(vtkPolyData* piece, vtkPolyData* whole)
{
  std::map<vtkIdType, vtkIdType> cellOf;
  vtkDataArray* wholeIds = whole->GetCellData()->GetArray("ElementId");
  for (vtkIdType c = 0; c < whole->GetNumberOfCells(); ++c)
  {
    cellOf[static_cast<vtkIdType>(wholeIds->GetComponent(c, 0))] = c;
  }
  double peak = 0.0, worst = 0.0;
  for (const char* name : { "Irradiance", "Radiosity" })
  {
    vtkDataArray* a = whole->GetPointData()->GetArray(name);
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        peak = std::max(peak, std::abs(a->GetComponent(i, k)));
      }
    }
  }
  vtkDataArray* ids = piece->GetCellData()->GetArray("ElementId");
  if (!ids)
  {
    return piece->GetNumberOfCells() == 0 ? 0.0 : -1.0;
  }
  for (vtkIdType c = 0; c < piece->GetNumberOfCells(); ++c)
  {
    const auto found = cellOf.find(static_cast<vtkIdType>(ids->GetComponent(c, 0)));
    if (found == cellOf.end())
    {
      return -1.0;
    }
    const vtkIdType w = found->second;
    for (const char* name : { "Irradiance", "Radiosity" })
    {
      vtkDataArray* mine = piece->GetCellData()->GetArray(name);
      vtkDataArray* theirs = whole->GetCellData()->GetArray(name);
      for (int k = 0; k < 3; ++k)
      {
        worst = std::max(worst, std::abs(mine->GetComponent(c, k) - theirs->GetComponent(w, k)));
      }
      vtkDataArray* minePoints = piece->GetPointData()->GetArray(name);
      vtkDataArray* theirPoints = whole->GetPointData()->GetArray(name);
      for (int corner = 0; corner < 3; ++corner)
      {
        const vtkIdType p = piece->GetCell(c)->GetPointId(corner);
        const vtkIdType q = whole->GetCell(w)->GetPointId(corner);
        for (int k = 0; k < 3; ++k)
        {
          worst = std::max(worst, std::abs(minePoints->GetComponent(p, k) - theirPoints->GetComponent(q, k)));
        }
      }
    }
  }
  return peak > 0.0 ? worst / peak : -1.0;
}

long long SumOverRanks(vtkMultiProcessController* controller, long long value)
{
  long long total = 0;
  controller->AllReduce(&value, &total, 1, vtkCommunicator::SUM_OP);
  return total;
}
}

int main(int argc, char* argv[])
{
  vtkNew<vtkMPIController> controller;
  controller->Initialize(&argc, &argv);
  vtkMultiProcessController::SetGlobalController(controller);
  Rank = controller->GetLocalProcessId();
  Ranks = controller->GetNumberOfProcesses();

  vtkNew<vtkCornellBoxSource> source;
  source->Update();
  vtkPolyData* box = source->GetOutput();
  const vtkIdType n = box->GetNumberOfCells();
  bool ok = true;

  const int methods[] = { vtkRadiosityFilter::Progressive, vtkRadiosityFilter::Hierarchical,
    vtkRadiosityFilter::Meshless, vtkRadiosityFilter::FaceCluster };
  for (int method : methods)
  {
    const std::string name = vtkRadiosityFilter::GetMethodName(method);
    // The whole box on this rank alone.
    auto whole = Solver(method, nullptr);
    whole->SetInputData(box);
    whole->Update();
    vtkPolyData* reference = whole->GetOutput();
    ok &= Check(reference->GetNumberOfCells() > 0, name + ": one-process solve");

    struct Split
    {
      const char* What;
      bool Compact, Ids, Interleaved, AllOnRankZero;
    };
    std::vector<Split> splits = { { "interleaved, compact, global ids", true, true, true, false } };
    if (method == vtkRadiosityFilter::Progressive)
    {
      splits.push_back({ "consecutive ranges, all points, no ids", false, false, false, false });
      splits.push_back({ "all on rank 0, empty elsewhere", false, false, false, true });
    }
    for (const Split& split : splits)
    {
      std::vector<vtkIdType> keep;
      for (vtkIdType c = 0; c < n; ++c)
      {
        const int owner = split.AllOnRankZero ? 0
          : split.Interleaved                 ? static_cast<int>(c % Ranks)
                                              : static_cast<int>(c * Ranks / n);
        if (owner == Rank)
        {
          keep.push_back(c);
        }
      }
      auto piece = Piece(box, keep, split.Compact, split.Ids);
      auto distributed = Solver(method, controller);
      distributed->SetInputData(piece);
      distributed->Update();
      vtkPolyData* output = distributed->GetOutput();
      const std::string what = name + " (" + split.What + ")";
      const double worst = WorstDifference(output, reference);
      std::printf("[rank %d] %s: %lld cells of %lld, worst difference %.3g of the peak\n", Rank,
        what.c_str(), static_cast<long long>(output->GetNumberOfCells()),
        static_cast<long long>(reference->GetNumberOfCells()), worst);
      ok &= Check(distributed->GetLastError().empty(), what + ": no error (" + distributed->GetLastError() + ")");
      ok &= Check(distributed->GetWarnings().empty(), what + ": no warning");
      ok &= Check(worst >= 0.0 && worst <= 1e-12, what + ": equals the one-process solve to 1e-12");
      ok &= Check(SumOverRanks(controller, output->GetNumberOfCells()) == reference->GetNumberOfCells(),
        what + ": the ranks' cells add up to the whole solve's");
      if (split.AllOnRankZero && Rank > 0)
      {
        ok &= Check(output->GetNumberOfCells() == 0, what + ": an empty piece gives an empty output");
      }
      if (Ranks > 1)
      {
        auto* triangles = vtkIdTypeArray::SafeDownCast(output->GetFieldData()->GetArray("RankTriangles"));
        ok &= Check(triangles && triangles->GetNumberOfTuples() == Ranks, what + ": RankTriangles");
        // The work split: every rank computed its share of the split loops
        // (contiguous shares differ by one item per loop at most).
        const std::vector<vtkIdType>& items = distributed->GetRankWorkItems();
        const std::vector<vtkIdType>& bytes = distributed->GetRankSolveBytesReceived();
        ok &= Check(items.size() == static_cast<std::size_t>(Ranks) && bytes.size() == items.size(),
          what + ": RankWorkItems and RankSolveBytesReceived, one per rank");
        vtkIdType least = items.empty() ? 0 : items[0], most = least, total = 0;
        for (std::size_t r = 0; r < items.size(); ++r)
        {
          least = std::min(least, items[r]);
          most = std::max(most, items[r]);
          total += items[r];
          std::printf("[rank %d] %s: rank %zu computed %lld items, received %lld bytes\n", Rank, what.c_str(),
            r, static_cast<long long>(items[r]), static_cast<long long>(bytes[r]));
        }
        // Measured, the larger shares rotating over the ranks (WorkShare):
        // at most 0.01% of the mean share apart for progressive, 0.1%
        // hierarchical and meshless, 1.5% face cluster (198 to 201 items on
        // 4 ranks: many small refinement rounds); bound 3%.
        ok &= Check(least > 0 && static_cast<double>(most - least) <= 0.03 * total / Ranks,
          what + ": every rank computed its share, within 3% of the mean");
        ok &= Check(bytes[0] > 0, what + ": the shares were exchanged");
      }
    }
  }

  // Face cluster radiosity with a point light above the boxes: the lights'
  // fits at the leaves, their punctual part included, are computed in
  // shares and exchanged (ResolveLights); the output shows the light's
  // exact value at every point.
  {
    radiosity::LightSet lights;
    radiosity::Light bulb;
    bulb.Position = radiosity::Vec3(350.0, 450.0, 250.0);
    bulb.Intensity = radiosity::RGB(2e5);
    lights.Lights.push_back(bulb);
    auto whole = Solver(vtkRadiosityFilter::FaceCluster, nullptr);
    whole->SetInputData(box);
    whole->SetSceneLights(lights);
    whole->Update();
    std::vector<vtkIdType> keep;
    for (vtkIdType c = Rank; c < n; c += Ranks)
    {
      keep.push_back(c);
    }
    auto distributed = Solver(vtkRadiosityFilter::FaceCluster, controller);
    distributed->SetInputData(Piece(box, keep, true, true));
    distributed->SetSceneLights(lights);
    distributed->Update();
    const double worst = WorstDifference(distributed->GetOutput(), whole->GetOutput());
    std::printf("[rank %d] facecluster with a point light: worst difference %.3g of the peak\n", Rank, worst);
    ok &= Check(whole->GetLastError().empty() && distributed->GetLastError().empty(),
      "facecluster with a point light: no error");
    ok &= Check(worst >= 0.0 && worst <= 1e-12, "facecluster with a point light: equals the one-process solve");
  }

  // Bad input on the last rank fails the request on every rank.
  {
    std::vector<vtkIdType> keep;
    for (vtkIdType c = Rank; c < n; c += Ranks)
    {
      keep.push_back(c);
    }
    auto piece = Piece(box, keep, true, false);
    if (Rank == Ranks - 1)
    {
      piece->GetCellData()->GetArray("Reflectance")->SetComponent(0, 1, std::nan(""));
    }
    auto f = Solver(vtkRadiosityFilter::Progressive, controller);
    f->SetInputData(piece);
    f->Update();
    const std::string error = f->GetLastError();
    std::printf("[rank %d] bad input: %s\n", Rank, error.c_str());
    ok &= Check(error.find("nan") != std::string::npos && error.find("Reflectance") != std::string::npos,
      "a NaN reflectance on the last rank is refused by name");
    if (Ranks > 1)
    {
      ok &= Check(error.find("(rank " + std::to_string(Ranks - 1) + " of " + std::to_string(Ranks) + ")") !=
          std::string::npos,
        "the message names the rank");
    }
    ok &= Check(f->GetOutput()->GetNumberOfCells() == 0, "nothing is output");
  }

  // One rank with a memory limit too small for the solve (ranks on machines
  // of different memory): every rank refuses alike, none waits for the
  // others in the solve's exchanges.
  {
    std::vector<vtkIdType> keep;
    for (vtkIdType c = Rank; c < n; c += Ranks)
    {
      keep.push_back(c);
    }
    auto f = Solver(vtkRadiosityFilter::Meshless, controller);
    f->SetInputData(Piece(box, keep, true, true));
    if (Rank == 0)
    {
      f->SetMaxMemory(1e-6); // 1 kB
    }
    f->Update();
    const std::string error = f->GetLastError();
    std::printf("[rank %d] small memory on rank 0: %s\n", Rank, error.c_str());
    ok &= Check(error.find("memory") != std::string::npos || error.find("budget") != std::string::npos,
      "rank 0's memory limit refuses the solve on every rank");
    ok &= Check(f->GetOutput()->GetNumberOfCells() == 0, "nothing is output");
  }

  // A time limit on rank 0 only: every rank stops at the same iteration
  // (the ranks' clocks are agreed), none waits for the others.
  for (int method : methods)
  {
    std::vector<vtkIdType> keep;
    for (vtkIdType c = Rank; c < n; c += Ranks)
    {
      keep.push_back(c);
    }
    auto f = Solver(method, controller);
    f->SetInputData(Piece(box, keep, true, true));
    f->SetTolerance(1e-6);
    if (Rank == 0)
    {
      f->SetMaxTime(1e-3);
    }
    f->Update();
    const radiosity::SolverStatistics& stats = f->GetStatistics();
    const long long iterations = stats.Iterations;
    const std::string what = std::string(vtkRadiosityFilter::GetMethodName(method)) + " with a time limit on rank 0";
    std::printf("[rank %d] %s: stopped by %s after %lld iterations\n", Rank, what.c_str(),
      radiosity::ToString(stats.Stop), iterations);
    ok &= Check(f->GetLastError().empty(), what + ": no error (" + f->GetLastError() + ")");
    ok &= Check(stats.Stop == radiosity::StopReason::TimeLimit, what + ": every rank stops by the time limit");
    ok &= Check(SumOverRanks(controller, iterations) == iterations * Ranks, what + ": at the same iteration");
  }

  // The path tracer's paths split over the ranks (the references' method):
  // a few sensors with many samples (the chunks split) and many sensors (the
  // sensors split) give one process's estimates to the bit.
  {
    const radiosity::Scene scene = radiosity::MakeCornellBox();
    for (std::size_t sensors : { std::size_t(8), std::size_t(300) })
    {
      std::vector<radiosity::Probe> probes;
      for (std::size_t i = 0; i < sensors; ++i)
      {
        radiosity::Probe p;
        p.Position = radiosity::Vec3(0.05 + 0.45 * (i + 0.5) / sensors, 0.001, 0.28);
        p.Normal = radiosity::Vec3(0.0, 1.0, 0.0);
        probes.push_back(p);
      }
      radiosity::PathTracerOptions options;
      options.Threads = 1;
      const std::size_t samples = sensors > 100 ? 64 : 4096;
      const radiosity::PathTracer alone(scene, options);
      options.Share = vtkRadiosityRankExchange::MakeWorkShare(controller);
      const radiosity::PathTracer split(scene, options);
      const std::vector<radiosity::ReferenceValue> one = alone.Irradiance(probes, samples, 0);
      const std::vector<radiosity::ReferenceValue> many = split.Irradiance(probes, samples, 0);
      double worst = 0.0, peak = 0.0;
      for (std::size_t i = 0; i < probes.size(); ++i)
      {
        worst = std::max(worst, radiosity::MaxComponent(glm::abs(one[i].Value - many[i].Value)));
        peak = std::max(peak, radiosity::MaxComponent(one[i].Value));
      }
      const radiosity::WorkShareStatistics& stats = options.Share->Statistics();
      const std::string what = "path tracer, " + std::to_string(sensors) + " sensors";
      std::printf("[rank %d] %s: this rank %zu of %zu items, worst difference %.3g (peak %.4g)\n", Rank,
        what.c_str(), stats.Items, stats.TotalItems, worst, peak);
      ok &= Check(peak > 0.0 && worst == 0.0, what + ": the ranks' estimates equal one process's to the bit");
      ok &= Check(stats.Items > 0 && stats.Items * static_cast<std::size_t>(Ranks) <= stats.TotalItems + Ranks,
        what + ": this rank traced its share");
    }
  }

  const int failed = ok ? 0 : 1;
  int anyFailed = 0;
  controller->AllReduce(&failed, &anyFailed, 1, vtkCommunicator::MAX_OP);
  controller->Finalize();
  return anyFailed;
}
