#include "vtkMeshlessFieldFilter.h"
#include "vtkRadiosityRequestGuard.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMeshlessRadiositySolution.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiositySceneConverter.h"
#include "vtkUnsignedCharArray.h"

#include "Radiosity/Meshless/MeshlessRadiosity.h"

vtkStandardNewMacro(vtkMeshlessFieldFilter);

vtkMeshlessFieldFilter::vtkMeshlessFieldFilter() = default;
vtkMeshlessFieldFilter::~vtkMeshlessFieldFilter() = default;

namespace
{
vtkSmartPointer<vtkDoubleArray> Named(const char* name, int components, vtkIdType tuples)
{
  return vtkRadiositySceneConverter::NewDoubleArray(name, components, tuples);
}
}

int vtkMeshlessFieldFilter::Fail(const std::string& message)
{
  this->LastError = message;
  vtkErrorMacro(<< message);
  return 0;
}

int vtkMeshlessFieldFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return vtkRadiosityGuardedRequest(
    vtkPolyData::GetData(outputVector, 0),
    [&] { return this->ExecuteRequest(inputVector, outputVector); },
    [this](const std::string& message) { return this->Fail(message); });
}

int vtkMeshlessFieldFilter::ExecuteRequest(vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->LastError.clear();
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  auto* carrier = input
    ? vtkMeshlessRadiositySolution::SafeDownCast(
        input->GetInformation()->Get(vtkRadiosityFilter::MESHLESS_SOLUTION()))
    : nullptr;
  std::shared_ptr<const radiosity::MeshlessRadiosity> held = carrier ? carrier->GetSolution() : nullptr;
  // ParaView hands over a copy without the information: the solver that
  // produced the input then answers.
  if (!held && this->GetNumberOfInputConnections(0) > 0)
  {
    if (auto* solver = vtkRadiosityFilter::FindUpstream(this->GetInputAlgorithm(0, 0)))
    {
      held = solver->GetMeshlessSolution();
    }
  }
  if (!held)
  {
    return this->Fail("the input carries no meshless radiosity solution: run vtkRadiosityFilter "
                      "with Method Meshless upstream");
  }
  const radiosity::MeshlessRadiosity& solution = *held;
  const auto& points = solution.Points().Points();
  const auto n = static_cast<vtkIdType>(points.size());
  const std::vector<radiosity::RGB>& b = solution.Irradiance().Coefficients();
  const std::vector<radiosity::RGB>& e = solution.DirectIrradiance().Coefficients();

  vtkNew<vtkPoints> coordinates;
  coordinates->SetDataTypeToDouble();
  coordinates->SetNumberOfPoints(n);
  vtkNew<vtkCellArray> verts;
  vtkNew<vtkIntArray> level, group;
  level->SetName("Level");
  level->SetNumberOfTuples(n);
  group->SetName("Group");
  group->SetNumberOfTuples(n);
  auto radius = Named("Radius", 1, n);
  auto normal = Named("Normal", 3, n);
  auto coefficient = Named("Coefficient", 3, n);
  auto direct = Named("DirectCoefficient", 3, n);
  auto irradiance = Named("Irradiance", 3, n);
  vtkNew<vtkUnsignedCharArray> gathered;
  gathered->SetName("Gathered");
  gathered->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const radiosity::MeshlessPoint& p = points[static_cast<std::size_t>(i)];
    coordinates->SetPoint(i, p.Position.x, p.Position.y, p.Position.z);
    verts->InsertNextCell(1, &i);
    level->SetValue(i, p.Level);
    group->SetValue(i, static_cast<int>(p.Group));
    radius->SetValue(i, p.Radius);
    normal->SetTuple3(i, p.Normal.x, p.Normal.y, p.Normal.z);
    const radiosity::RGB& c = b[static_cast<std::size_t>(i)];
    coefficient->SetTuple3(i, c.x, c.y, c.z);
    const radiosity::RGB& d = e[static_cast<std::size_t>(i)];
    direct->SetTuple3(i, d.x, d.y, d.z);
    const radiosity::RGB h = solution.Irradiance().Evaluate(p.Position, p.Normal, p.Group);
    irradiance->SetTuple3(i, h.x, h.y, h.z);
    gathered->SetValue(i, solution.WasGatheredTo(static_cast<std::size_t>(i)) ? 1 : 0);
    if (i % 4096 == 0)
    {
      this->UpdateProgress(static_cast<double>(i) / static_cast<double>(n));
    }
  }
  output->SetPoints(coordinates);
  output->SetVerts(verts);
  vtkPointData* pd = output->GetPointData();
  pd->AddArray(level);
  pd->AddArray(radius);
  pd->AddArray(normal);
  pd->AddArray(group);
  pd->AddArray(coefficient);
  pd->AddArray(direct);
  pd->AddArray(irradiance);
  pd->AddArray(gathered);
  pd->SetActiveScalars("Irradiance");
  return 1;
}

void vtkMeshlessFieldFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LastError: " << (this->LastError.empty() ? "(none)" : this->LastError) << "\n";
}
