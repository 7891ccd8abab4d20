#include "vtkRadiositySceneConverter.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkIntArray.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStringArray.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedShortArray.h"

#include <algorithm>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkRadiositySceneConverter);

namespace
{
using radiosity::RGB;

const char* const SourceCellArray = "vtkRadiositySourceCell";

/// Reads a 3-component material array (or its default); false on a wrong shape.
bool ReadColour(vtkCellData* cd, const char* name, vtkIdType cell, RGB& value, std::string& error)
{
  vtkDataArray* a = cd->GetArray(name);
  if (!a)
  {
    return true;
  }
  if (a->GetNumberOfComponents() != 3)
  {
    error = std::string("array ") + name + " has " + std::to_string(a->GetNumberOfComponents()) +
      " components, 3 (RGB) expected";
    return false;
  }
  for (int c = 0; c < 3; ++c)
  {
    value[c] = a->GetComponent(cell, c);
  }
  return true;
}

/// One dataset (one object) appended to the scene.
/// The global ids (VTK's GetGlobalIds) of `pd`'s points and of the cells
/// `object`'s triangles came from, appended to `ids`; false when `pd` lacks
/// either (then `ids` is of no use: the caller drops it).
bool AppendGlobalIds(vtkPolyData* pd, const radiosity::Scene& object, radiosity::PieceGlobalIds& ids)
{
  vtkDataArray* points = pd->GetPointData()->GetGlobalIds();
  vtkDataArray* cells = pd->GetCellData()->GetGlobalIds();
  if (!points || !cells || points->GetNumberOfTuples() != static_cast<vtkIdType>(object.Points.size()))
  {
    return false;
  }
  for (vtkIdType p = 0; p < points->GetNumberOfTuples(); ++p)
  {
    ids.Points.push_back(static_cast<long long>(points->GetComponent(p, 0)));
  }
  for (long long source : object.SourceCells)
  {
    if (source < 0 || source >= cells->GetNumberOfTuples())
    {
      return false;
    }
    ids.Triangles.push_back(static_cast<long long>(cells->GetComponent(source, 0)));
  }
  return true;
}

bool AppendDataSet(vtkDataSet* ds, const std::string& name, radiosity::Scene& scene,
  std::string& error, std::vector<std::string>& warnings, radiosity::PieceGlobalIds* ids,
  bool& idsComplete)
{
  vtkSmartPointer<vtkPolyData> pd = vtkPolyData::SafeDownCast(ds);
  if (!pd)
  {
    vtkNew<vtkDataSetSurfaceFilter> surface;
    surface->SetInputData(ds);
    surface->Update();
    pd = surface->GetOutput();
    warnings.push_back(name + ": " + ds->GetClassName() + " converted to its outer surface");
  }
  const vtkIdType nVerts = pd->GetNumberOfVerts(), nLines = pd->GetNumberOfLines(),
                  nStrips = pd->GetNumberOfStrips(), nPolys = pd->GetNumberOfPolys();
  if (nVerts + nLines + nStrips > 0)
  {
    std::ostringstream w;
    w << name << ": ignored " << nVerts << " vertex, " << nLines << " line and " << nStrips
      << " strip cells (only polygons are surfaces)";
    warnings.push_back(w.str());
  }
  if (nPolys == 0)
  {
    return true;
  }
  // Polygons only, with their original cell ids, then triangulated.
  vtkNew<vtkPolyData> polys;
  polys->SetPoints(pd->GetPoints());
  polys->SetPolys(pd->GetPolys());
  vtkCellData* in = pd->GetCellData();
  for (const char* array :
    { "Reflectance", "Emission", "Specular", "Shininess", "TwoSided", "ObjectId" })
  {
    if (vtkDataArray* a = in->GetArray(array))
    {
      if (a->GetNumberOfTuples() != pd->GetNumberOfCells())
      {
        error = name + ": array " + array + " has " + std::to_string(a->GetNumberOfTuples()) +
          " tuples for " + std::to_string(pd->GetNumberOfCells()) + " cells";
        return false;
      }
      vtkSmartPointer<vtkDataArray> slice;
      slice.TakeReference(a->NewInstance());
      slice->SetName(array);
      slice->SetNumberOfComponents(a->GetNumberOfComponents());
      slice->SetNumberOfTuples(nPolys);
      for (vtkIdType i = 0; i < nPolys; ++i)
      {
        slice->SetTuple(i, nVerts + nLines + i, a);
      }
      polys->GetCellData()->AddArray(slice);
    }
  }
  vtkNew<vtkIdTypeArray> sourceIds;
  sourceIds->SetName(SourceCellArray);
  sourceIds->SetNumberOfTuples(nPolys);
  for (vtkIdType i = 0; i < nPolys; ++i)
  {
    sourceIds->SetValue(i, nVerts + nLines + i);
  }
  polys->GetCellData()->AddArray(sourceIds);
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(polys);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  vtkPolyData* tris = triangulate->GetOutput();
  vtkCellData* cd = tris->GetCellData();

  if (!in->GetArray("Reflectance"))
  {
    warnings.push_back(name + ": no Reflectance array, using 0.5 grey");
  }
  if (vtkDataArray* s = cd->GetArray("Shininess"))
  {
    if (s->GetNumberOfComponents() != 1)
    {
      error = name + ": array Shininess has " + std::to_string(s->GetNumberOfComponents()) +
        " components, 1 expected";
      return false;
    }
  }
  vtkDataArray* twoSided = cd->GetArray("TwoSided");
  if (twoSided && twoSided->GetNumberOfComponents() != 1)
  {
    error = name + ": array TwoSided has " + std::to_string(twoSided->GetNumberOfComponents()) +
      " components, 1 expected";
    return false;
  }

  radiosity::Scene object;
  object.ObjectNames.push_back(name);
  const vtkIdType np = tris->GetNumberOfPoints();
  object.Points.resize(np);
  for (vtkIdType p = 0; p < np; ++p)
  {
    double x[3];
    tris->GetPoint(p, x);
    object.Points[p] = radiosity::Vec3(x[0], x[1], x[2]);
  }
  vtkDataArray* sourceCells = cd->GetArray(SourceCellArray);
  vtkCellArray* cells = tris->GetPolys();
  vtkIdType cellIndex = 0;
  vtkIdType npts;
  const vtkIdType* pts;
  for (cells->InitTraversal(); cells->GetNextCell(npts, pts); ++cellIndex)
  {
    if (npts != 3)
    {
      continue;
    }
    radiosity::Material m;
    std::string arrayError;
    if (!ReadColour(cd, "Reflectance", cellIndex, m.Reflectance, arrayError) ||
      !ReadColour(cd, "Emission", cellIndex, m.Emission, arrayError) ||
      !ReadColour(cd, "Specular", cellIndex, m.Specular, arrayError))
    {
      error = name + ": " + arrayError;
      return false;
    }
    if (vtkDataArray* s = cd->GetArray("Shininess"))
    {
      m.Shininess = s->GetComponent(cellIndex, 0);
    }
    const long long source = static_cast<long long>(sourceCells->GetComponent(cellIndex, 0));
    const radiosity::Triangle tri{ { static_cast<std::uint32_t>(pts[0]),
      static_cast<std::uint32_t>(pts[1]), static_cast<std::uint32_t>(pts[2]) } };
    const bool both = twoSided && twoSided->GetComponent(cellIndex, 0) != 0;
    for (int side = 0; side < (both ? 2 : 1); ++side)
    {
      radiosity::Triangle t = tri;
      if (side == 1)
      {
        std::swap(t.V[1], t.V[2]); // the back side, facing the other way
      }
      object.Triangles.push_back(t);
      object.Materials.push_back(m);
      object.ObjectIds.push_back(0);
      object.SourceCells.push_back(source);
    }
  }
  // A polydata carrying `ObjectId` (as vtkCornellBoxSource writes) holds
  // several objects: keep them apart, with their `ObjectNames` when given.
  vtkDataArray* objectIds = cd->GetArray("ObjectId");
  if (objectIds && objectIds->GetNumberOfComponents() == 1)
  {
    auto* names = vtkStringArray::SafeDownCast(pd->GetFieldData()->GetAbstractArray("ObjectNames"));
    int maxId = 0;
    std::vector<int> ids;
    ids.reserve(object.Triangles.size());
    vtkIdType cell = 0;
    for (cells->InitTraversal(); cells->GetNextCell(npts, pts); ++cell)
    {
      if (npts != 3)
      {
        continue;
      }
      const int id = std::max(0, static_cast<int>(objectIds->GetComponent(cell, 0)));
      const bool both = twoSided && twoSided->GetComponent(cell, 0) != 0;
      ids.insert(ids.end(), both ? 2 : 1, id);
      maxId = std::max(maxId, id);
    }
    object.ObjectNames.clear();
    for (int i = 0; i <= maxId; ++i)
    {
      object.ObjectNames.push_back(names && i < names->GetNumberOfValues()
          ? names->GetValue(i)
          : name + " object " + std::to_string(i));
    }
    object.ObjectIds = ids;
  }
  if (ids && idsComplete)
  {
    idsComplete = AppendGlobalIds(pd, object, *ids);
  }
  radiosity::AppendScene(scene, object);
  return true;
}
}

void vtkRadiositySceneConverter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

radiosity::Light vtkRadiositySceneConverter::ToLight(vtkLight* vtk, double lightScale)
{
  radiosity::Light light;
  double position[3], focal[3], colour[3];
  vtk->GetTransformedPosition(position);
  vtk->GetTransformedFocalPoint(focal);
  vtk->GetDiffuseColor(colour);
  const radiosity::Vec3 from(position[0], position[1], position[2]);
  const radiosity::Vec3 to(focal[0], focal[1], focal[2]);
  const double watts = lightScale * vtk->GetIntensity();
  light.Intensity = radiosity::RGB(watts * colour[0], watts * colour[1], watts * colour[2]);
  light.Position = from;
  light.Direction = to - from;
  if (!vtk->GetPositional())
  {
    light.Type = radiosity::LightType::Directional;
  }
  else if (vtk->GetConeAngle() < 90.0)
  {
    light.Type = radiosity::LightType::Spot;
    light.InnerConeAngle = 0.0;
    light.OuterConeAngle = vtk->GetConeAngle() * radiosity::Pi / 180.0;
  }
  else
  {
    light.Type = radiosity::LightType::Point;
  }
  return light;
}

bool vtkRadiositySceneConverter::ToScene(vtkDataObject* input, radiosity::Scene& scene,
  std::string& error, std::vector<std::string>& warnings, radiosity::PieceGlobalIds* ids)
{
  scene = radiosity::Scene();
  if (ids)
  {
    *ids = radiosity::PieceGlobalIds();
  }
  // Cleared by the first block without global ids: then no block has them.
  bool idsComplete = ids != nullptr;
  const auto finish = [&](bool ok)
  {
    if (ids && !idsComplete)
    {
      *ids = radiosity::PieceGlobalIds();
    }
    return ok;
  };
  if (!input)
  {
    error = "no input";
    return false;
  }
  if (auto* ds = vtkDataSet::SafeDownCast(input))
  {
    return finish(AppendDataSet(ds, "object 0", scene, error, warnings, ids, idsComplete));
  }
  auto* composite = vtkDataObjectTree::SafeDownCast(input);
  if (!composite)
  {
    error = std::string("unsupported input type ") + input->GetClassName();
    return finish(false);
  }
  vtkSmartPointer<vtkDataObjectTreeIterator> it;
  it.TakeReference(composite->NewTreeIterator());
  it->VisitOnlyLeavesOn();
  it->SkipEmptyNodesOn();
  int block = 0;
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem(), ++block)
  {
    std::string name = "block " + std::to_string(block);
    if (it->HasCurrentMetaData() && it->GetCurrentMetaData()->Has(vtkCompositeDataSet::NAME()))
    {
      name = it->GetCurrentMetaData()->Get(vtkCompositeDataSet::NAME());
    }
    auto* ds = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
    if (!ds)
    {
      warnings.push_back(name + ": not a dataset, ignored");
      continue;
    }
    if (!AppendDataSet(ds, name, scene, error, warnings, ids, idsComplete))
    {
      return finish(false);
    }
  }
  return finish(true);
}

vtkSmartPointer<vtkDoubleArray> vtkRadiositySceneConverter::NewDoubleArray(
  const char* name, int components, vtkIdType tuples)
{
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  return a;
}

namespace
{
/// A one-component array of `n` tuples named `name`.
template <typename ArrayT>
vtkSmartPointer<ArrayT> NamedArray(const char* name, vtkIdType n)
{
  auto a = vtkSmartPointer<ArrayT>::New();
  a->SetName(name);
  a->SetNumberOfTuples(n);
  return a;
}

vtkSmartPointer<vtkDoubleArray> ColourArray(const char* name, vtkIdType n)
{
  return vtkRadiositySceneConverter::NewDoubleArray(name, 3, n);
}

void SetColour(vtkDoubleArray* a, vtkIdType i, const RGB& c)
{
  a->SetTypedTuple(i, &c[0]);
}

// Each element's own irradiance at its corners and centroid (12 floats,
// sample-major), what vtkIrradianceSamplesMapper draws per pixel and the
// probes interpolate (radiosity::InterpolateSamples). Float: the display
// reads floats, and the array is the largest of the output.
vtkSmartPointer<vtkFloatArray> SamplesArray(const std::vector<radiosity::ElementSamples>& samples)
{
  auto a = vtkSmartPointer<vtkFloatArray>::New();
  a->SetName("IrradianceSamples");
  a->SetNumberOfComponents(12);
  const char* const names[4] = { "0", "1", "2", "Centroid" };
  for (int k = 0; k < 4; ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      a->SetComponentName(3 * k + c, (std::string(names[k]) + "_" + "RGB"[c]).c_str());
    }
  }
  a->SetNumberOfTuples(static_cast<vtkIdType>(samples.size()));
  float* out = a->GetPointer(0);
  for (const radiosity::ElementSamples& s : samples)
  {
    for (int k = 0; k < 4; ++k)
    {
      const RGB& h = k < 3 ? s.Corner[k] : s.Centre;
      for (int c = 0; c < 3; ++c)
      {
        *out++ = static_cast<float>(h[c]);
      }
    }
  }
  return a;
}

vtkSmartPointer<vtkPoints> ToPoints(const std::vector<radiosity::Vec3>& pts)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(pts.size()));
  for (std::size_t i = 0; i < pts.size(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), pts[i].x, pts[i].y, pts[i].z);
  }
  return points;
}

vtkSmartPointer<vtkCellArray> ToTriangles(const std::vector<radiosity::Triangle>& tris)
{
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->AllocateExact(static_cast<vtkIdType>(tris.size()), 3 * static_cast<vtkIdType>(tris.size()));
  for (const auto& t : tris)
  {
    const vtkIdType ids[3] = { t.V[0], t.V[1], t.V[2] };
    cells->InsertNextCell(3, ids);
  }
  return cells;
}

vtkSmartPointer<vtkStringArray> ObjectNames(const radiosity::Scene& scene)
{
  auto names = vtkSmartPointer<vtkStringArray>::New();
  names->SetName("ObjectNames");
  for (const auto& n : scene.ObjectNames)
  {
    names->InsertNextValue(n);
  }
  return names;
}
}

vtkSmartPointer<vtkPolyData> vtkRadiositySceneConverter::FromScene(const radiosity::Scene& scene)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(ToPoints(scene.Points));
  pd->SetPolys(ToTriangles(scene.Triangles));
  const auto n = static_cast<vtkIdType>(scene.Triangles.size());
  auto reflectance = ColourArray("Reflectance", n);
  auto emission = ColourArray("Emission", n);
  auto specular = ColourArray("Specular", n);
  auto shininess = NamedArray<vtkDoubleArray>("Shininess", n);
  auto objects = NamedArray<vtkIntArray>("ObjectId", n);
  for (vtkIdType t = 0; t < n; ++t)
  {
    const radiosity::Material& m = scene.Materials[t];
    SetColour(reflectance, t, m.Reflectance);
    SetColour(emission, t, m.Emission);
    SetColour(specular, t, m.Specular);
    shininess->SetValue(t, m.Shininess);
    objects->SetValue(t, scene.ObjectIds[t]);
  }
  vtkCellData* cd = pd->GetCellData();
  cd->AddArray(reflectance);
  cd->AddArray(emission);
  cd->AddArray(specular);
  cd->AddArray(shininess);
  cd->AddArray(objects);
  pd->GetFieldData()->AddArray(ObjectNames(scene));
  return pd;
}

vtkSmartPointer<vtkPolyData> vtkRadiositySceneConverter::FromSolution(
  const radiosity::SolutionMesh& solution, const radiosity::Scene& scene)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(ToPoints(solution.Points));
  pd->SetPolys(ToTriangles(solution.Triangles));
  const auto nc = static_cast<vtkIdType>(solution.Triangles.size());
  const auto np = static_cast<vtkIdType>(solution.Points.size());
  auto cellIrradiance = ColourArray("Irradiance", nc);
  auto cellRadiosity = ColourArray("Radiosity", nc);
  auto reflectance = ColourArray("Reflectance", nc);
  auto emission = ColourArray("Emission", nc);
  auto elementId = NamedArray<vtkIdTypeArray>("ElementId", nc);
  auto level = NamedArray<vtkIntArray>("Level", nc);
  auto objects = NamedArray<vtkIntArray>("ObjectId", nc);
  for (vtkIdType t = 0; t < nc; ++t)
  {
    const radiosity::Material& m = scene.Materials[solution.SourceTriangle[t]];
    SetColour(cellIrradiance, t, solution.CellIrradiance[t]);
    SetColour(cellRadiosity, t, solution.CellRadiosity[t]);
    SetColour(reflectance, t, m.Reflectance);
    SetColour(emission, t, m.Emission);
    elementId->SetValue(t, solution.ElementId[t]);
    level->SetValue(t, solution.Level[t]);
    objects->SetValue(t, scene.ObjectIds[solution.SourceTriangle[t]]);
  }
  vtkCellData* cd = pd->GetCellData();
  for (vtkDataArray* a : std::initializer_list<vtkDataArray*>{ cellIrradiance, cellRadiosity,
         reflectance, emission, elementId, level, objects })
  {
    cd->AddArray(a);
  }
  if (solution.Samples.size() == solution.Triangles.size() && nc > 0)
  {
    cd->AddArray(SamplesArray(solution.Samples));
  }
  auto pointIrradiance = ColourArray("Irradiance", np);
  auto pointRadiosity = ColourArray("Radiosity", np);
  for (vtkIdType p = 0; p < np; ++p)
  {
    SetColour(pointIrradiance, p, solution.PointIrradiance[p]);
    SetColour(pointRadiosity, p, solution.PointRadiosity[p]);
  }
  pd->GetPointData()->AddArray(pointIrradiance);
  pd->GetPointData()->AddArray(pointRadiosity);
  pd->GetPointData()->SetActiveScalars("Radiosity");
  pd->GetFieldData()->AddArray(ObjectNames(scene));
  return pd;
}

vtkSmartPointer<vtkDoubleArray> vtkRadiositySceneConverter::FromHistory(
  const radiosity::ConvergenceHistory& history)
{
  const auto names = radiosity::ConvergenceHistory::ColumnNames();
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName("ConvergenceHistory");
  a->SetNumberOfComponents(static_cast<int>(names.size()));
  for (std::size_t c = 0; c < names.size(); ++c)
  {
    a->SetComponentName(static_cast<vtkIdType>(c), names[c].c_str());
  }
  a->SetNumberOfTuples(static_cast<vtkIdType>(history.Rows.size()));
  for (std::size_t i = 0; i < history.Rows.size(); ++i)
  {
    const radiosity::ConvergenceRow& r = history.Rows[i];
    const double row[7] = { static_cast<double>(r.Iteration), r.TimeSeconds, r.UnshotPowerW,
      r.EnergyBalance, r.RmsError, r.MaxRelError, r.OvershootPowerW };
    a->SetTypedTuple(static_cast<vtkIdType>(i), row);
  }
  // The magnitude range over the finite components: VTK's own (asked for by
  // ParaView's data information) is NaN where a tuple holds a NaN (the error
  // columns without a reference), and vtkDataWriter then skips the key but
  // not its count, so the binary stream ParaView sends between ranks (pvbatch
  // Fetch, client-server delivery) cannot be read back ("Unrecognized
  // keyword"). Set here, after the last change of the values, VTK keeps it.
  double range[2] = { 0.0, 0.0 };
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    double sum = 0.0;
    for (int c = 0; c < a->GetNumberOfComponents(); ++c)
    {
      const double v = a->GetComponent(i, c);
      sum += std::isfinite(v) ? v * v : 0.0;
    }
    const double norm = std::sqrt(sum);
    range[0] = i == 0 ? norm : std::min(range[0], norm);
    range[1] = i == 0 ? norm : std::max(range[1], norm);
  }
  a->GetInformation()->Set(vtkDataArray::L2_NORM_RANGE(), range, 2);
  a->GetInformation()->Set(vtkDataArray::L2_NORM_FINITE_RANGE(), range, 2);
  return a;
}

namespace
{
/// A new array sharing `a`'s values (no copy) under another name.
vtkSmartPointer<vtkDataArray> SharedAs(vtkDataArray* a, const std::string& name)
{
  vtkSmartPointer<vtkDataArray> shared;
  shared.TakeReference(a->NewInstance());
  shared->ShallowCopy(a);
  shared->SetName(name.c_str());
  return shared;
}

vtkSmartPointer<vtkCellArray> VertexCells(vtkIdType n)
{
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfValues(n + 1);
  connectivity->SetNumberOfValues(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    offsets->SetValue(i, i);
    connectivity->SetValue(i, i);
  }
  offsets->SetValue(n, n);
  auto verts = vtkSmartPointer<vtkCellArray>::New();
  verts->SetData(offsets, connectivity);
  return verts;
}
}

vtkSmartPointer<vtkDataArray> vtkRadiositySceneConverter::FromProductArray(
  const radiosity::ProductArray& array)
{
  using Type = radiosity::ProductArray::ValueType;
  vtkSmartPointer<vtkDataArray> out;
  switch (array.Type)
  {
    case Type::Int:
      out = vtkSmartPointer<vtkIntArray>::New();
      break;
    case Type::IdType:
      out = vtkSmartPointer<vtkIdTypeArray>::New();
      break;
    case Type::UnsignedChar:
      out = vtkSmartPointer<vtkUnsignedCharArray>::New();
      break;
    case Type::Double:
    default:
      out = vtkSmartPointer<vtkDoubleArray>::New();
      break;
  }
  out->SetName(array.Name.c_str());
  out->SetNumberOfComponents(array.Components);
  const auto tuples = static_cast<vtkIdType>(array.Tuples());
  out->SetNumberOfTuples(tuples);
  if (auto* doubles = vtkDoubleArray::SafeDownCast(out))
  {
    std::copy(array.Values.begin(), array.Values.end(), doubles->GetPointer(0));
  }
  else
  {
    // Sized above: distinct tuples are written from distinct threads.
    const int components = array.Components;
    vtkSMPTools::For(0, tuples,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          for (int c = 0; c < components; ++c)
          {
            out->SetComponent(i, c, array.Values[static_cast<std::size_t>(i * components + c)]);
          }
        }
      });
  }
  return out;
}

vtkSmartPointer<vtkPolyData> vtkRadiositySceneConverter::FromProduct(
  const radiosity::SolverProduct& product)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  if (product.Kind.empty() || !product.Complete)
  {
    return pd;
  }
  pd->SetPoints(ToPoints(product.Points));
  if (!product.Triangles.empty())
  {
    pd->SetPolys(ToTriangles(product.Triangles));
  }
  else
  {
    pd->SetVerts(VertexCells(static_cast<vtkIdType>(product.Points.size())));
  }
  for (const radiosity::ProductArray& a : product.PointArrays)
  {
    pd->GetPointData()->AddArray(FromProductArray(a));
  }
  for (const radiosity::ProductArray& a : product.CellArrays)
  {
    pd->GetCellData()->AddArray(FromProductArray(a));
  }
  // What the viewer colours by: the radiosity where the product has it (the
  // discontinuity mesh), else the irradiance (the Shepard field).
  for (const char* name : { "Radiosity", "Irradiance" })
  {
    if (pd->GetPointData()->GetArray(name))
    {
      pd->GetPointData()->SetActiveScalars(name);
      break;
    }
  }
  vtkNew<vtkStringArray> kind;
  kind->SetName("ProductKind");
  kind->InsertNextValue(product.Kind);
  pd->GetFieldData()->AddArray(kind);
  return pd;
}

void vtkRadiositySceneConverter::AttachPointProduct(vtkPolyData* product, vtkPolyData* surface)
{
  auto* kinds = vtkStringArray::SafeDownCast(product->GetFieldData()->GetAbstractArray("ProductKind"));
  if (!kinds || kinds->GetNumberOfValues() < 1 || !product->GetPoints())
  {
    return;
  }
  const std::string kind = kinds->GetValue(0);
  vtkFieldData* fd = surface->GetFieldData();
  fd->AddArray(SharedAs(product->GetPoints()->GetData(), kind + ".Points"));
  vtkPointData* pd = product->GetPointData();
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i)
  {
    if (vtkDataArray* a = pd->GetArray(i))
    {
      fd->AddArray(SharedAs(a, kind + "." + a->GetName()));
    }
  }
}

vtkSmartPointer<vtkPolyData> vtkRadiositySceneConverter::AttachedPointProduct(
  vtkPolyData* surface, const std::string& kind)
{
  vtkFieldData* fd = surface ? surface->GetFieldData() : nullptr;
  vtkDataArray* coordinates = fd ? fd->GetArray((kind + ".Points").c_str()) : nullptr;
  if (!coordinates || coordinates->GetNumberOfComponents() != 3)
  {
    return nullptr;
  }
  auto product = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetData(SharedAs(coordinates, "Points"));
  product->SetPoints(points);
  const vtkIdType n = coordinates->GetNumberOfTuples();
  product->SetVerts(VertexCells(n));
  const std::string prefix = kind + ".";
  for (int i = 0; i < fd->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* a = fd->GetArray(i);
    const std::string name = a && a->GetName() ? a->GetName() : "";
    if (a && a != coordinates && name.compare(0, prefix.size(), prefix) == 0 && a->GetNumberOfTuples() == n)
    {
      product->GetPointData()->AddArray(SharedAs(a, name.substr(prefix.size())));
    }
  }
  return product;
}
