#include "vtkShepardFieldProbe.h"
#include "vtkRadiosityRequestGuard.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStaticPointLocator.h"

#include "Radiosity/Meshless/ShepardField.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkShepardFieldProbe);

vtkShepardFieldProbe::vtkShepardFieldProbe()
{
  this->SetNumberOfInputPorts(2);
}

vtkShepardFieldProbe::~vtkShepardFieldProbe() = default;

int vtkShepardFieldProbe::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkDataSet" : "vtkPolyData");
  return 1;
}

int vtkShepardFieldProbe::Fail(const std::string& message)
{
  this->LastError = message;
  vtkErrorMacro(<< message);
  return 0;
}

namespace
{
/// One level of the field: its points in a locator, and the largest radius.
struct FieldLevel
{
  std::vector<radiosity::MeshlessPoint> Points;
  std::vector<radiosity::RGB> Alpha;
  vtkSmartPointer<vtkStaticPointLocator> Locator;
  double MaxRadius = 0.0;
};

vtkDataArray* Array(vtkFieldData* data, const char* name, int components)
{
  vtkDataArray* a = data->GetArray(name);
  return a && a->GetNumberOfComponents() == components ? a : nullptr;
}
}

int vtkShepardFieldProbe::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return vtkRadiosityGuardedRequest(
    vtkDataSet::GetData(outputVector, 0),
    [&] { return this->ExecuteRequest(inputVector, outputVector); },
    [this](const std::string& message) { return this->Fail(message); });
}

int vtkShepardFieldProbe::ExecuteRequest(vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->LastError.clear();
  vtkDataSet* input = vtkDataSet::GetData(inputVector[0], 0);
  vtkPolyData* field = vtkPolyData::GetData(inputVector[1], 0);
  vtkDataSet* output = vtkDataSet::GetData(outputVector, 0);
  if (!input || !field)
  {
    return this->Fail("a dataset (input 0) and a field (input 1: the Shepard field, port 1 of vtkRadiosityFilter with Method Meshless) are needed");
  }
  vtkPointData* fd = field->GetPointData();
  vtkDataArray* level = Array(fd, "Level", 1);
  vtkDataArray* radius = Array(fd, "Radius", 1);
  vtkDataArray* normal = Array(fd, "Normal", 3);
  vtkDataArray* group = Array(fd, "Group", 1);
  vtkDataArray* coefficient = Array(fd, "Coefficient", 3);
  for (auto [a, name] : { std::pair<vtkDataArray*, const char*>{ level, "Level (1 component)" },
         { radius, "Radius (1 component)" }, { normal, "Normal (3 components)" },
         { group, "Group (1 component)" }, { coefficient, "Coefficient (3 components)" } })
  {
    if (!a)
    {
      return this->Fail(std::string("the field has no point array ") + name +
        " (expected port 1 of vtkRadiosityFilter with Method Meshless)");
    }
  }
  // Levels, each with a locator over its points.
  std::map<int, FieldLevel> levels;
  for (vtkIdType i = 0; i < field->GetNumberOfPoints(); ++i)
  {
    // The field is data (a file, another filter): check what becomes an
    // index or a radius before it is one (a NaN cast to an integer is undefined).
    const double lv = level->GetTuple1(i), gv = group->GetTuple1(i), rv = radius->GetTuple1(i);
    double x[3], n[3], c[3];
    field->GetPoint(i, x);
    normal->GetTuple(i, n);
    coefficient->GetTuple(i, c);
    auto finite = [](const double* v, int k) { return std::all_of(v, v + k, [](double a) { return std::isfinite(a); }); };
    if (!(lv >= 0 && lv <= 64 && lv == std::floor(lv)) || !(gv >= 0 && gv <= 2147483647.0 && gv == std::floor(gv)) ||
      !(rv > 0 && std::isfinite(rv)) || !finite(x, 3) || !finite(n, 3) || !finite(c, 3))
    {
      std::ostringstream why;
      why << "the field's point " << i << " is not a meshless basis function: Level " << lv
          << " (an integer in [0, 64]), Group " << gv << " (a non-negative integer), Radius " << rv
          << " (positive), position, Normal and Coefficient finite";
      return this->Fail(why.str());
    }
    FieldLevel& l = levels[static_cast<int>(lv)];
    radiosity::MeshlessPoint p;
    p.Position = radiosity::Vec3(x[0], x[1], x[2]);
    p.Normal = radiosity::Vec3(n[0], n[1], n[2]);
    p.Radius = rv;
    p.Group = static_cast<std::uint32_t>(gv);
    l.Points.push_back(p);
    l.Alpha.emplace_back(c[0], c[1], c[2]);
    l.MaxRadius = std::max(l.MaxRadius, p.Radius);
  }
  std::vector<FieldLevel*> ordered;
  for (auto& [index, l] : levels)
  {
    if (this->MaxLevel >= 0 && index > this->MaxLevel)
    {
      continue;
    }
    vtkNew<vtkPoints> pts;
    pts->SetDataTypeToDouble();
    for (const radiosity::MeshlessPoint& p : l.Points)
    {
      pts->InsertNextPoint(p.Position.x, p.Position.y, p.Position.z);
    }
    vtkNew<vtkPolyData> cloud;
    cloud->SetPoints(pts);
    l.Locator = vtkSmartPointer<vtkStaticPointLocator>::New();
    l.Locator->SetDataSet(cloud);
    l.Locator->BuildLocator();
    ordered.push_back(&l);
  }

  // Normals of the probed points.
  vtkSmartPointer<vtkDataArray> normals = Array(input->GetPointData(), "Normals", 3);
  if (!normals)
  {
    auto* poly = vtkPolyData::SafeDownCast(input);
    if (!poly)
    {
      return this->Fail("the probed dataset has no point array Normals (3 components) and is not polydata");
    }
    vtkNew<vtkPolyDataNormals> compute;
    compute->SetInputData(poly);
    compute->SplittingOff();
    compute->ConsistencyOff();
    compute->AutoOrientNormalsOff();
    compute->ComputePointNormalsOn();
    compute->ComputeCellNormalsOff();
    compute->Update();
    normals = compute->GetOutput()->GetPointData()->GetNormals();
  }
  if (!normals || normals->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    return this->Fail("could not compute the point normals of the probed dataset");
  }
  // Per point: a cell using it, for the group and the materials.
  vtkDataArray* pointObjectId = Array(input->GetPointData(), "ObjectId", 1);
  vtkDataArray* objectId = Array(input->GetCellData(), "ObjectId", 1);
  vtkDataArray* rho = Array(input->GetCellData(), "Reflectance", 3);
  vtkDataArray* emission = Array(input->GetCellData(), "Emission", 3);
  const vtkIdType n = input->GetNumberOfPoints();
  std::vector<vtkIdType> owner(static_cast<std::size_t>(n), -1);
  if (objectId || (rho && emission))
  {
    vtkNew<vtkIdList> cells;
    for (vtkIdType i = 0; i < n; ++i)
    {
      input->GetPointCells(i, cells);
      owner[static_cast<std::size_t>(i)] = cells->GetNumberOfIds() > 0 ? cells->GetId(0) : -1;
    }
  }

  auto irradiance = vtkSmartPointer<vtkDoubleArray>::New();
  irradiance->SetName("Irradiance");
  irradiance->SetNumberOfComponents(3);
  irradiance->SetNumberOfTuples(n);
  vtkSMPTools::For(0, n, [&](vtkIdType begin, vtkIdType end) {
    vtkNew<vtkIdList> near;
    for (vtkIdType i = begin; i < end; ++i)
    {
      double x[3], nn[3];
      input->GetPoint(i, x);
      normals->GetTuple(i, nn);
      const radiosity::Vec3 p(x[0], x[1], x[2]);
      radiosity::Vec3 nv(nn[0], nn[1], nn[2]);
      const double len = glm::length(nv);
      nv = len > 0 ? nv / len : nv;
      // The group: the owning cell's object, else the nearest facing field point's.
      std::int64_t g = -1;
      const vtkIdType cell = owner[static_cast<std::size_t>(i)];
      if (pointObjectId)
      {
        g = static_cast<std::int64_t>(pointObjectId->GetTuple1(i));
      }
      else if (objectId && cell >= 0)
      {
        g = static_cast<std::int64_t>(objectId->GetTuple1(cell));
      }
      radiosity::RGB h(0.0);
      for (FieldLevel* l : ordered)
      {
        l->Locator->FindPointsWithinRadius(l->MaxRadius, x, near);
        if (g < 0)
        {
          double best = 1e300;
          for (vtkIdType k = 0; k < near->GetNumberOfIds(); ++k)
          {
            const radiosity::MeshlessPoint& q = l->Points[static_cast<std::size_t>(near->GetId(k))];
            const double d = glm::length(q.Position - p);
            if (glm::dot(q.Normal, nv) > 0 && d < best)
            {
              best = d;
              g = q.Group;
            }
          }
        }
        double wsum = 0.0;
        radiosity::RGB sum(0.0);
        for (vtkIdType k = 0; k < near->GetNumberOfIds(); ++k)
        {
          const auto j = static_cast<std::size_t>(near->GetId(k));
          const radiosity::MeshlessPoint& q = l->Points[j];
          if (static_cast<std::int64_t>(q.Group) != g)
          {
            continue;
          }
          const double w = radiosity::ShepardWeight(q, p, nv);
          wsum += w;
          sum += w * l->Alpha[j];
        }
        if (wsum > 0)
        {
          h += sum / wsum;
        }
      }
      irradiance->SetTuple3(i, h.x, h.y, h.z);
    }
  });

  output->ShallowCopy(input);
  output->GetPointData()->AddArray(irradiance);
  if (rho && emission)
  {
    auto radiosityArray = vtkSmartPointer<vtkDoubleArray>::New();
    radiosityArray->SetName("Radiosity");
    radiosityArray->SetNumberOfComponents(3);
    radiosityArray->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      const vtkIdType cell = owner[static_cast<std::size_t>(i)];
      double h[3], r[3] = { 0, 0, 0 }, e[3] = { 0, 0, 0 };
      irradiance->GetTuple(i, h);
      if (cell >= 0)
      {
        rho->GetTuple(cell, r);
        emission->GetTuple(cell, e);
      }
      radiosityArray->SetTuple3(i, e[0] + r[0] * h[0], e[1] + r[1] * h[1], e[2] + r[2] * h[2]);
    }
    output->GetPointData()->AddArray(radiosityArray);
  }
  else
  {
    vtkWarningMacro(<< "the probed dataset has no cell arrays Reflectance and Emission: "
                       "only Irradiance is written");
  }
  return 1;
}

void vtkShepardFieldProbe::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Source: "
     << (this->GetNumberOfInputConnections(1) > 0 ? this->GetInputDataObject(1, 0) : nullptr)
     << "\n";
  os << indent << "MaxLevel: " << this->MaxLevel << "\n";
  os << indent << "LastError: " << (this->LastError.empty() ? "(none)" : this->LastError) << "\n";
}
