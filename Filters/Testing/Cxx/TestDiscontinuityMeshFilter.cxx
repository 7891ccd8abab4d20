// vtkCornellBoxSource -> vtkRadiosityFilter (Hierarchical), port 1: the
// discontinuity mesh's arrays and their layout, the triangle counts with and
// without discontinuities, the interpolants against the point samples, an
// empty product for a progressive solve, and abort.
#include "vtkCallbackCommand.h"
#include "vtkExecutive.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkCornellBoxSource.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkStringArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRadiosityFilter.h"

#include "Radiosity/Hierarchical/HierarchicalMethod.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>

namespace
{
bool Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "FAILED: " << what << "\n";
  }
  return condition;
}

bool HasArray(vtkFieldData* data, const char* name, int components, vtkIdType tuples,
  const char* where, bool finite = true)
{
  vtkDataArray* a = data->GetArray(name);
  if (!a)
  {
    std::cerr << "FAILED: no " << where << " array " << name << "\n";
    return false;
  }
  bool ok = Check(a->GetNumberOfComponents() == components,
    std::string(where) + " " + name + " has " + std::to_string(a->GetNumberOfComponents()) +
      " components, expected " + std::to_string(components));
  ok &= Check(a->GetNumberOfTuples() == tuples, std::string(where) + " " + name + " tuple count");
  for (vtkIdType i = 0; ok && finite && i < a->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < components; ++c)
    {
      if (!std::isfinite(a->GetComponent(i, c)))
      {
        std::cerr << "FAILED: " << where << " " << name << " is not finite at " << i << "\n";
        return false;
      }
    }
  }
  return ok;
}

int progressEvents = 0;
void AbortOnFirstEvent(vtkObject* caller, unsigned long, void*, void*)
{
  if (++progressEvents == 1)
  {
    vtkAlgorithm::SafeDownCast(caller)->AbortExecuteOn();
  }
}
}

int TestDiscontinuityMeshFilter(int, char*[])
{
  // Embree's BVH builder relies on IEEE semantics (infinities in empty bounds).
  vtkFloatingPointExceptions::Disable();
  bool ok = true;

  vtkNew<vtkCornellBoxSource> box;
  vtkNew<vtkRadiosityFilter> radiosity;
  radiosity->SetInputConnection(box->GetOutputPort());
  radiosity->SetMethodToHierarchical();
  ok &= Check(std::string(vtkRadiosityFilter::GetMethodName(radiosity->GetMethod())) ==
      "hierarchical",
    "method name");
  radiosity->SetTolerance(1e-2);
  radiosity->SetLinkTolerance(0.1);
  radiosity->SetMinElementSize(1.0 / 32.0);
  radiosity->SetMaxRefinementRounds(2);
  radiosity->Update();
  vtkPolyData* solved = radiosity->GetOutput();
  if (!Check(radiosity->GetLastError().empty() && solved->GetNumberOfCells() > 0,
        "hierarchical solve: " + radiosity->GetLastError()))
  {
    return EXIT_FAILURE;
  }
  auto solution = radiosity->GetHierarchicalSolution();
  ok &= Check(solution != nullptr, "GetHierarchicalSolution after a hierarchical solve");
  ok &= Check(radiosity->GetSolution() != nullptr, "GetSolution after a hierarchical solve");
  auto method = std::dynamic_pointer_cast<const radiosity::HierarchicalMethod>(radiosity->GetSolver());
  ok &= Check(method != nullptr && &method->GetInstance() == solution.get(),
    "GetSolver is the hierarchical method holding GetHierarchicalSolution");
  if (!method)
  {
    return EXIT_FAILURE;
  }
  ok &= Check(solved->GetFieldData()->GetArray("ConvergenceHistory") != nullptr,
    "hierarchical ConvergenceHistory");
  const auto leaves = static_cast<vtkIdType>(solution->Mesh().NumberOfLeaves());
  ok &= Check(solved->GetNumberOfCells() == leaves, "one output cell per quadtree leaf");

  vtkPolyData* meshed = radiosity->GetOutput(1);
  auto* kind = vtkStringArray::SafeDownCast(meshed->GetFieldData()->GetAbstractArray("ProductKind"));
  ok &= Check(kind && kind->GetValue(0) == "DiscontinuityMesh", "port 1 is the discontinuity mesh");
  auto Mesh = [&radiosity]() -> const radiosity::DiscontinuityMesh&
  {
    return std::dynamic_pointer_cast<const radiosity::HierarchicalMethod>(radiosity->GetSolver())->LastMesh();
  };
  const vtkIdType nc = meshed->GetNumberOfCells();
  const vtkIdType np = meshed->GetNumberOfPoints();
  std::cout << "leaves " << leaves << ", triangles " << nc << ", points " << np
            << ", leaves meshed " << Mesh().LeavesMeshed << ", segments "
            << Mesh().SegmentsKept << " of " << Mesh().SegmentsFound << ", "
            << Mesh().PointSamples << " samples, " << Mesh().Seconds << " s\n";
  ok &= Check(nc > solved->GetNumberOfCells(), "more triangles than leaves with discontinuities");
  ok &= Check(Mesh().LeavesMeshed > 0 && Mesh().SegmentsKept > 0,
    "some leaves meshed");
  ok &= Check(static_cast<vtkIdType>(Mesh().Triangles.size()) == nc, "GetMesh matches");
  vtkCellData* cd = meshed->GetCellData();
  vtkPointData* pd = meshed->GetPointData();
  ok &= HasArray(cd, "QuadraticInterpolant", 18, nc, "cell");
  for (const char* name : { "Irradiance", "Radiosity", "Reflectance", "Emission" })
  {
    ok &= HasArray(cd, name, 3, nc, "cell");
  }
  ok &= HasArray(cd, "ElementId", 1, nc, "cell");
  ok &= HasArray(cd, "Level", 1, nc, "cell");
  ok &= HasArray(pd, "Irradiance", 3, np, "point");
  ok &= HasArray(pd, "Radiosity", 3, np, "point");
  ok &= HasArray(meshed->GetFieldData(), "ConvergenceHistory",
    solved->GetFieldData()->GetArray("ConvergenceHistory")->GetNumberOfComponents(),
    solved->GetFieldData()->GetArray("ConvergenceHistory")->GetNumberOfTuples(), "field",
    false); // the error columns are NaN without a reference
  if (!ok)
  {
    return EXIT_FAILURE;
  }

  // The interpolants reproduce the point samples at their corners, and the
  // radiosity is E + rho H.
  vtkDataArray* q = cd->GetArray("QuadraticInterpolant");
  vtkDataArray* rho = cd->GetArray("Reflectance");
  vtkDataArray* emission = cd->GetArray("Emission");
  vtkDataArray* pointH = pd->GetArray("Irradiance");
  vtkDataArray* pointB = pd->GetArray("Radiosity");
  vtkDataArray* cellH = cd->GetArray("Irradiance");
  double worst = 0.0, worstB = 0.0, worstMean = 0.0, peak = 0.0;
  vtkNew<vtkIdList> ids;
  for (vtkIdType t = 0; t < nc; ++t)
  {
    meshed->GetCellPoints(t, ids);
    if (!Check(ids->GetNumberOfIds() == 3, "cell " + std::to_string(t) + " is a triangle"))
    {
      return EXIT_FAILURE;
    }
    const double st[3][2] = { { 0, 0 }, { 1, 0 }, { 0, 1 } };
    for (int c = 0; c < 3; ++c)
    {
      double k[6], scale = 0.0;
      for (int j = 0; j < 6; ++j)
      {
        k[j] = q->GetComponent(t, 6 * c + j);
        scale = std::max(scale, std::fabs(k[j]));
      }
      for (int v = 0; v < 3; ++v)
      {
        const double s = st[v][0], u = st[v][1];
        const double r = s * (k[0] * s + k[1] * u + k[2]) + u * (k[3] * u + k[4]) + k[5];
        const double h = pointH->GetComponent(ids->GetId(v), c);
        peak = std::max(peak, std::fabs(h));
        if (scale > 0.0)
        {
          worst = std::max(worst, std::fabs(r - h) / scale);
        }
        const double b = emission->GetComponent(t, c) + rho->GetComponent(t, c) * h;
        worstB = std::max(worstB,
          std::fabs(pointB->GetComponent(ids->GetId(v), c) - b) / std::max(1.0, std::fabs(b)));
      }
      // The cell irradiance is the area mean: the mean of the edge midpoints.
      auto eval = [&k](double s, double u)
      { return s * (k[0] * s + k[1] * u + k[2]) + u * (k[3] * u + k[4]) + k[5]; };
      const double mean = (eval(0.5, 0.0) + eval(0.5, 0.5) + eval(0.0, 0.5)) / 3.0;
      if (scale > 0.0)
      {
        worstMean = std::max(worstMean, std::fabs(mean - cellH->GetComponent(t, c)) / scale);
      }
    }
  }
  std::cout << "interpolant at corners vs point Irradiance: " << worst
            << " relative; point Radiosity " << worstB << "; cell mean " << worstMean
            << "; peak irradiance " << peak << "\n";
  ok &= Check(worst <= 1e-9, "interpolants reproduce the point Irradiance at the corners");
  ok &= Check(worstB <= 1e-12, "point Radiosity is E + rho H");
  ok &= Check(worstMean <= 1e-12, "cell Irradiance is the interpolant's mean");
  ok &= Check(peak > 0.0, "the solution is lit");

  // PrintSelf names the new settings.
  {
    std::ostringstream printed;
    radiosity->Print(printed);
    for (const char* word : { "LinkTolerance", "MinElementSize", "MaxRefinementRounds",
           "MaxDiscontinuitiesPerLeaf", "MinDiscontinuityWeight", "ConformingBoundaries",
           "DiscontinuityMeshing", "Solver: hierarchical" })
    {
      ok &= Check(printed.str().find(word) != std::string::npos, std::string("PrintSelf: ") + word);
    }
  }

  // Without discontinuities, and with k = 0: one triangle per leaf (in the
  // paper's hybrid mesh; the conforming one also splits leaves that have
  // vertices of finer neighbours on their edges).
  radiosity->ConformingBoundariesOff();
  radiosity->DiscontinuityMeshingOff();
  radiosity->Update();
  ok &= Check(radiosity->GetOutput(1)->GetNumberOfCells() == leaves,
    "Discontinuities off: " + std::to_string(radiosity->GetOutput(1)->GetNumberOfCells()) +
      " triangles for " + std::to_string(leaves) + " leaves");
  ok &= Check(Mesh().SegmentsKept == 0, "Discontinuities off keeps no segment");
  radiosity->DiscontinuityMeshingOn();
  radiosity->SetMaxDiscontinuitiesPerLeaf(0);
  radiosity->Update();
  ok &= Check(radiosity->GetOutput(1)->GetNumberOfCells() == leaves,
    "MaxDiscontinuitiesPerLeaf 0: " + std::to_string(radiosity->GetOutput(1)->GetNumberOfCells()) +
      " triangles for " + std::to_string(leaves) + " leaves");
  radiosity->SetMaxDiscontinuitiesPerLeaf(10);
  radiosity->ConformingBoundariesOn();
  radiosity->Update();
  ok &= Check(radiosity->GetOutput(1)->GetNumberOfCells() == nc, "MaxDiscontinuitiesPerLeaf back to 10");
  ok &= Check(Mesh().LeavesConformed > 0, "conforming boundaries split some leaves");

  // Abort from a progress observer: an empty product.
  {
    vtkNew<vtkRadiosityFilter> aborted;
    aborted->SetInputConnection(box->GetOutputPort());
    aborted->SetMethodToHierarchical();
    aborted->SetTolerance(1e-2);
    aborted->SetLinkTolerance(0.1);
    vtkNew<vtkCallbackCommand> observer;
    observer->SetCallback(AbortOnFirstEvent);
    aborted->AddObserver(vtkCommand::ProgressEvent, observer);
    aborted->GlobalWarningDisplayOff();
    aborted->Update();
    aborted->GlobalWarningDisplayOn();
    ok &= Check(progressEvents >= 1, "progress events while solving");
    ok &= Check(aborted->GetOutput(1)->GetNumberOfCells() == 0, "aborted: empty product");
  }

  // A progressive solution has no discontinuity mesh: port 1 is empty.
  radiosity->SetMethodToProgressive();
  radiosity->Update();
  ok &= Check(radiosity->GetLastError().empty(), "progressive: " + radiosity->GetLastError());
  ok &= Check(radiosity->GetHierarchicalSolution() == nullptr,
    "no hierarchical solution for Progressive");
  ok &= Check(radiosity->GetOutput(1)->GetNumberOfCells() == 0 &&
      radiosity->GetOutput(1)->GetNumberOfPoints() == 0,
    "empty product for Progressive");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
