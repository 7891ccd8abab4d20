#include "vtkDiscontinuityMeshFilter.h"
#include "vtkRadiosityRequestGuard.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkHierarchicalRadiositySolution.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseKey.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiositySceneConverter.h"
#include "vtkVersion.h"

#include "Radiosity/Hierarchical/HierarchicalRadiosity.h"

#include <chrono>

vtkStandardNewMacro(vtkDiscontinuityMeshFilter);

vtkDiscontinuityMeshFilter::vtkDiscontinuityMeshFilter() = default;
vtkDiscontinuityMeshFilter::~vtkDiscontinuityMeshFilter() = default;

namespace
{
vtkSmartPointer<vtkDoubleArray> DoubleArray(const char* name, int components, vtkIdType tuples)
{
  return vtkRadiositySceneConverter::NewDoubleArray(name, components, tuples);
}

void SetColour(vtkDoubleArray* a, vtkIdType i, const radiosity::RGB& c)
{
  double* p = a->GetPointer(3 * i);
  p[0] = c.r;
  p[1] = c.g;
  p[2] = c.b;
}
}

int vtkDiscontinuityMeshFilter::Fail(const std::string& message)
{
  this->LastError = message;
  vtkErrorMacro(<< message);
  return 0;
}

int vtkDiscontinuityMeshFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return vtkRadiosityGuardedRequest(
    vtkPolyData::GetData(outputVector, 0),
    [&] { return this->ExecuteRequest(inputVector, outputVector); },
    [this](const std::string& message) { return this->Fail(message); });
}

int vtkDiscontinuityMeshFilter::ExecuteRequest(vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  using Clock = std::chrono::steady_clock;
  this->LastError.clear();
  this->Mesh = radiosity::DiscontinuityMesh();
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();

  auto* carrier = input
    ? vtkHierarchicalRadiositySolution::SafeDownCast(
        input->GetInformation()->Get(vtkRadiosityFilter::HIERARCHICAL_SOLUTION()))
    : nullptr;
  std::shared_ptr<const radiosity::HierarchicalRadiosity> solution =
    carrier ? carrier->GetSolution() : nullptr;
  // ParaView hands over a copy without the information: the solver that
  // produced the input then answers.
  if (!solution && this->GetNumberOfInputConnections(0) > 0)
  {
    if (auto* solver = vtkRadiosityFilter::FindUpstream(this->GetInputAlgorithm(0, 0)))
    {
      solution = solver->GetHierarchicalSolution();
    }
  }
  if (!solution)
  {
    return this->Fail("the input carries no hierarchical radiosity solution: run "
                      "vtkRadiosityFilter with Method Hierarchical upstream");
  }

  radiosity::DiscontinuityMeshOptions options;
  options.Discontinuities = this->Discontinuities;
  options.MaxPerLeaf = this->MaxDiscontinuitiesPerLeaf;
  options.MinWeight = this->MinDiscontinuityWeight;
  options.Threads = this->NumberOfThreads;
  options.Conforming = this->ConformingBoundaries;
  auto last = Clock::now() - std::chrono::seconds(1);
  bool aborted = false;
  this->Mesh = radiosity::BuildDiscontinuityMesh(*solution, options,
    [this, &last, &aborted](const radiosity::ProgressStatus& status)
    {
      const auto now = Clock::now();
      if (std::chrono::duration<double>(now - last).count() > 0.05)
      {
        last = now;
        this->UpdateProgress(status.Fraction);
      }
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 0)
      aborted = this->CheckAbort();
#else
      aborted = this->GetAbortExecute();
#endif
      return !aborted;
    });
  this->UpdateProgress(1.0);
  const radiosity::DiscontinuityMesh& mesh = this->Mesh;
  const radiosity::Scene& scene = solution->GetScene();

  const auto np = static_cast<vtkIdType>(mesh.Points.size());
  const auto nc = static_cast<vtkIdType>(mesh.Triangles.size());
  if (aborted || mesh.Interpolants.size() != mesh.Triangles.size() ||
    mesh.PointIrradiance.size() != mesh.Points.size())
  {
    // Aborted part-way: nothing consistent to write.
    vtkWarningMacro(<< "discontinuity meshing aborted");
    return 1;
  }
  if (mesh.LeavesTriangulationFailed > 0)
  {
    vtkWarningMacro(<< mesh.LeavesTriangulationFailed
                    << " leaves could not be triangulated with their discontinuities (CGAL refused "
                       "the constraints) and are meshed as the leaf alone");
  }

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(np);
  for (vtkIdType p = 0; p < np; ++p)
  {
    const radiosity::Vec3& x = mesh.Points[p];
    points->SetPoint(p, x.x, x.y, x.z);
  }
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(3 * nc);
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(nc + 1);
  for (vtkIdType t = 0; t < nc; ++t)
  {
    offsets->SetValue(t, 3 * t);
    for (int k = 0; k < 3; ++k)
    {
      connectivity->SetValue(3 * t + k, mesh.Triangles[t].V[k]);
    }
  }
  offsets->SetValue(nc, 3 * nc);
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);

  auto interpolant = DoubleArray("QuadraticInterpolant", 18, nc);
  auto cellIrradiance = DoubleArray("Irradiance", 3, nc);
  auto cellRadiosity = DoubleArray("Radiosity", 3, nc);
  auto reflectance = DoubleArray("Reflectance", 3, nc);
  auto emission = DoubleArray("Emission", 3, nc);
  vtkNew<vtkIdTypeArray> elementId;
  elementId->SetName("ElementId");
  elementId->SetNumberOfValues(nc);
  vtkNew<vtkIntArray> level;
  level->SetName("Level");
  level->SetNumberOfValues(nc);
  vtkNew<vtkIntArray> objects;
  objects->SetName("ObjectId");
  objects->SetNumberOfValues(nc);
  auto pointIrradiance = DoubleArray("Irradiance", 3, np);
  auto pointRadiosity = DoubleArray("Radiosity", 3, np);
  pointRadiosity->FillValue(0.0);
  for (vtkIdType p = 0; p < np; ++p)
  {
    SetColour(pointIrradiance, p, mesh.PointIrradiance[p]);
  }
  for (vtkIdType t = 0; t < nc; ++t)
  {
    const radiosity::QuadraticInterpolant& q = mesh.Interpolants[t];
    double* k = interpolant->GetPointer(18 * t);
    for (int c = 0; c < 3; ++c)
    {
      for (int j = 0; j < 6; ++j)
      {
        k[6 * c + j] = q.Coefficients[j][c];
      }
    }
    const radiosity::Material& m = scene.Materials[mesh.SourceTriangle[t]];
    const radiosity::RGB h = q.Mean();
    SetColour(cellIrradiance, t, h);
    SetColour(cellRadiosity, t, m.Emission + m.Reflectance * h);
    SetColour(reflectance, t, m.Reflectance);
    SetColour(emission, t, m.Emission);
    elementId->SetValue(t, mesh.Leaf[t]);
    level->SetValue(t, mesh.Level[t]);
    objects->SetValue(t, scene.ObjectIds[mesh.SourceTriangle[t]]);
    // Points are not shared between leaves, so every triangle using a point
    // has the same material.
    for (std::uint32_t p : mesh.Triangles[t].V)
    {
      SetColour(pointRadiosity, p, m.Emission + m.Reflectance * mesh.PointIrradiance[p]);
    }
  }

  output->SetPoints(points);
  output->SetPolys(polys);
  vtkCellData* cd = output->GetCellData();
  cd->AddArray(interpolant);
  cd->AddArray(cellIrradiance);
  cd->AddArray(cellRadiosity);
  cd->AddArray(reflectance);
  cd->AddArray(emission);
  cd->AddArray(elementId);
  cd->AddArray(level);
  cd->AddArray(objects);
  output->GetPointData()->AddArray(pointIrradiance);
  output->GetPointData()->AddArray(pointRadiosity);
  output->GetPointData()->SetActiveScalars("Radiosity");
  for (const char* name : { "ConvergenceHistory", "ObjectNames" })
  {
    if (vtkAbstractArray* a = input->GetFieldData()->GetAbstractArray(name))
    {
      output->GetFieldData()->AddArray(a);
    }
  }
  return 1;
}

void vtkDiscontinuityMeshFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Discontinuities: " << (this->Discontinuities ? "On" : "Off") << "\n";
  os << indent << "MaxDiscontinuitiesPerLeaf: " << this->MaxDiscontinuitiesPerLeaf << "\n";
  os << indent << "MinDiscontinuityWeight: " << this->MinDiscontinuityWeight << "\n";
  os << indent << "ConformingBoundaries: " << (this->ConformingBoundaries ? "On" : "Off") << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "Triangles: " << this->Mesh.Triangles.size() << "\n";
  os << indent << "LeavesMeshed: " << this->Mesh.LeavesMeshed << "\n";
  os << indent << "SegmentsFound: " << this->Mesh.SegmentsFound << "\n";
  os << indent << "SegmentsKept: " << this->Mesh.SegmentsKept << "\n";
  os << indent << "PointSamples: " << this->Mesh.PointSamples << "\n";
  os << indent << "Seconds: " << this->Mesh.Seconds << "\n";
  os << indent << "LastError: " << this->LastError << "\n";
}
