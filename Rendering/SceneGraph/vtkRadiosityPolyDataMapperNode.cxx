#include "vtkRadiosityPolyDataMapperNode.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRadiosityActorNode.h"
#include "vtkRadiosityRendererNode.h"
#include "vtkRadiosityTextureColour.h"
#include "vtkScalarsToColors.h"
#include "vtkTexture.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

vtkStandardNewMacro(vtkRadiosityPolyDataMapperNode);

namespace
{
// Both sides solved: every surface (the pass's TwoSided), or this actor's
// (TWO_SIDED set to 1 in its PropertyKeys: a glTF material's doubleSided).
bool IsTwoSided(vtkRadiosityRendererNode* renderer, vtkActor* actor)
{
  vtkInformation* keys = actor->GetPropertyKeys();
  return renderer->GetTwoSided() ||
    (keys && keys->Has(vtkRadiosityRendererNode::TWO_SIDED()) && keys->Get(vtkRadiosityRendererNode::TWO_SIDED()) != 0);
}

// Whether two arrays hold the same values bit for bit (name, type, shape).
bool SameArray(vtkDataArray* a, vtkDataArray* b)
{
  if (!a || !b)
  {
    return a == b;
  }
  const char* na = a->GetName();
  const char* nb = b->GetName();
  if (a->GetDataType() != b->GetDataType() || a->GetNumberOfComponents() != b->GetNumberOfComponents() ||
    a->GetNumberOfTuples() != b->GetNumberOfTuples() || (na == nullptr) != (nb == nullptr) ||
    (na && std::strcmp(na, nb) != 0))
  {
    return false;
  }
  const std::size_t bytes = static_cast<std::size_t>(a->GetNumberOfValues()) *
    static_cast<std::size_t>(a->GetDataTypeSize());
  return bytes == 0 || std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0), bytes) == 0;
}

// Whether two conversions gave the same scene: same objects, points,
// triangles and material arrays. A moved MTime that changes none of it
// (ParaView's first render sets mapper and lookup-table state once) is not
// a change to solve.
bool SameObjects(const std::vector<vtkRadiosityPolyDataMapperNode::Object>& a,
  const std::vector<vtkRadiosityPolyDataMapperNode::Object>& b)
{
  if (a.size() != b.size())
  {
    return false;
  }
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    vtkPolyData* pa = a[i].Data;
    vtkPolyData* pb = b[i].Data;
    if (a[i].Name != b[i].Name || !pa || !pb || !pa->GetPoints() || !pb->GetPoints() ||
      !SameArray(pa->GetPoints()->GetData(), pb->GetPoints()->GetData()) ||
      !SameArray(pa->GetPolys()->GetOffsetsArray(), pb->GetPolys()->GetOffsetsArray()) ||
      !SameArray(pa->GetPolys()->GetConnectivityArray(), pb->GetPolys()->GetConnectivityArray()))
    {
      return false;
    }
    vtkCellData* ca = pa->GetCellData();
    vtkCellData* cb = pb->GetCellData();
    if (ca->GetNumberOfArrays() != cb->GetNumberOfArrays())
    {
      return false;
    }
    for (int k = 0; k < ca->GetNumberOfArrays(); ++k)
    {
      if (!SameArray(ca->GetArray(k), cb->GetArray(k)))
      {
        return false;
      }
    }
  }
  return true;
}
}

vtkRadiosityPolyDataMapperNode::vtkRadiosityPolyDataMapperNode() = default;
vtkRadiosityPolyDataMapperNode::~vtkRadiosityPolyDataMapperNode() = default;

namespace
{
std::string Triple(const double v[3])
{
  std::ostringstream s;
  s << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
  return s.str();
}

bool Finite3(const double v[3])
{
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

/// A 3-component double cell array named `name` with `n` tuples.
vtkSmartPointer<vtkDoubleArray> CellColours(const char* name, vtkIdType n)
{
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(3);
  a->SetNumberOfTuples(n);
  return a;
}
}

vtkActor* vtkRadiosityPolyDataMapperNode::GetActor()
{
  vtkViewNode* parent = this->GetParent();
  return parent ? vtkActor::SafeDownCast(parent->GetRenderable()) : nullptr;
}

vtkRadiosityRendererNode* vtkRadiosityPolyDataMapperNode::GetRendererNode()
{
  return vtkRadiosityRendererNode::SafeDownCast(
    this->GetFirstAncestorOfType("vtkRadiosityRendererNode"));
}

vtkMTimeType vtkRadiosityPolyDataMapperNode::GetSceneMTime()
{
  vtkMTimeType time = 0;
  if (vtkActor* actor = this->GetActor())
  {
    // vtkActor's MTime covers its property, textures and user transform or
    // matrix; an assembly's matrix above a part is its node's.
    time = actor->GetMTime();
  }
  if (auto* actorNode = vtkRadiosityActorNode::SafeDownCast(this->GetParent()))
  {
    time = std::max(time, actorNode->GetAssemblyMTime());
  }
  if (auto* mapper = vtkMapper::SafeDownCast(this->GetRenderable()))
  {
    time = std::max(time, mapper->GetMTime()); // the lookup table's too
    if (vtkDataObject* input = mapper->GetInputDataObject(0, 0))
    {
      time = std::max(time, input->GetMTime());
    }
  }
  return time;
}

void vtkRadiosityPolyDataMapperNode::Synchronize(bool prepass)
{
  if (!prepass)
  {
    return;
  }
  vtkActor* actor = this->GetActor();
  auto* actorNode = vtkRadiosityActorNode::SafeDownCast(this->GetParent());
  auto* mapper = vtkMapper::SafeDownCast(this->GetRenderable());
  vtkRadiosityRendererNode* rendererNode = this->GetRendererNode();
  if (!actor || !actorNode || !mapper || !rendererNode)
  {
    this->Objects.clear();
    this->Error.clear();
    return;
  }
  const bool solvable = actorNode->GetSolvable();
  const int twoSided = IsTwoSided(rendererNode, actor) ? 1 : 0;
  if (solvable)
  {
    // The input as the mapper would draw it (a pipeline runs here, not at
    // the render: the mapper itself never renders a solved actor).
    mapper->Update();
  }
  if (solvable == this->ConvertedSolvable && this->GetSceneMTime() <= this->ConvertedMTime &&
    this->ConvertedMaxReflectance == rendererNode->GetMaxReflectance() &&
    this->ConvertedLightScale == rendererNode->GetLightScale() &&
    this->ConvertedTwoSided == twoSided)
  {
    return;
  }
  std::vector<Object> previous;
  previous.swap(this->Objects);
  const std::string previousError = this->Error;
  const bool converted = this->ConversionTime.GetMTime() > 0;
  this->Error.clear();
  this->Warnings.clear();
  this->ClampedColours = 0;
  if (solvable && !this->Convert(actor, mapper, actorNode->GetLabel()))
  {
    this->Objects.clear();
  }
  if (this->ClampedColours > 0)
  {
    this->Warnings.push_back(actorNode->GetLabel() + ": display colours at or above MaxReflectance " +
      std::to_string(rendererNode->GetMaxReflectance()) + " clamped to it (" +
      std::to_string(this->ClampedColours) + " objects)");
  }
  // After the conversion: creating the default lookup table or setting its
  // range moves the mapper's MTime once, and that is not a change to solve.
  this->ConvertedMTime = this->GetSceneMTime();
  if (!converted || this->Error != previousError || !SameObjects(previous, this->Objects))
  {
    this->ConversionTime.Modified();
  }
  this->ConvertedSolvable = solvable;
  this->ConvertedMaxReflectance = rendererNode->GetMaxReflectance();
  this->ConvertedLightScale = rendererNode->GetLightScale();
  this->ConvertedTwoSided = twoSided;
}

bool vtkRadiosityPolyDataMapperNode::Convert(
  vtkActor* actor, vtkMapper* mapper, const std::string& label)
{
  vtkDataObject* input = mapper->GetInputDataObject(0, 0);
  auto* poly = vtkPolyData::SafeDownCast(input);
  if (!poly)
  {
    if (input)
    {
      this->Warnings.push_back(label + ": input " + input->GetClassName() +
        " is not polydata: left out of the solve");
    }
    return true;
  }
  return this->ConvertPolyData(poly, actor, mapper, nullptr, label);
}

bool vtkRadiosityPolyDataMapperNode::ConvertPolyData(vtkPolyData* input, vtkActor* actor,
  vtkMapper* mapper, const double* blockColor, const std::string& name)
{
  if (input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    if (input->GetNumberOfCells() > 0)
    {
      this->Warnings.push_back(name + ": no polygons (only vertices or lines): left out of the solve");
    }
    return true;
  }
  vtkRadiosityRendererNode* rendererNode = this->GetRendererNode();
  const double maxReflectance = rendererNode->GetMaxReflectance();
  vtkProperty* property = actor->GetProperty();
  const bool pbr = property->GetInterpolation() == VTK_PBR;

  // The material of the property.
  double base[3];
  property->GetDiffuseColor(base);
  if (blockColor)
  {
    std::copy(blockColor, blockColor + 3, base);
  }
  const double factor = pbr ? 1.0 - property->GetMetallic() : property->GetDiffuse();
  if (!Finite3(base) || !std::isfinite(factor) || factor < 0.0 || base[0] < 0.0 ||
    base[1] < 0.0 || base[2] < 0.0)
  {
    this->Error = name + ": property " + (blockColor ? "block colour " : "DiffuseColor ") +
      Triple(base) + (pbr ? " x (1 - Metallic " : " x Diffuse (") +
      std::to_string(pbr ? property->GetMetallic() : property->GetDiffuse()) +
      ") is not a colour (non-finite or negative)";
    return false;
  }
  double emissive[3] = { 0.0, 0.0, 0.0 };
  if (pbr)
  {
    property->GetEmissiveFactor(emissive);
    if (!Finite3(emissive) || emissive[0] < 0.0 || emissive[1] < 0.0 || emissive[2] < 0.0)
    {
      this->Error = name + ": property EmissiveFactor " + Triple(emissive) +
        " is not a colour (non-finite or negative)";
      return false;
    }
    for (double& e : emissive)
    {
      e *= rendererNode->GetLightScale();
    }
  }
  double specular[3] = { 0.0, 0.0, 0.0 };
  const bool glossy = !pbr && property->GetSpecular() > 0.0;
  if (glossy)
  {
    property->GetSpecularColor(specular);
    for (double& s : specular)
    {
      s *= property->GetSpecular();
    }
  }

  // Triangles only.
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(input);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  vtkPolyData* tris = triangulate->GetOutput();
  const vtkIdType nc = tris->GetNumberOfCells();
  if (nc == 0)
  {
    return true;
  }

  // Mapped scalar colours, as the mapper would draw them.
  vtkSmartPointer<vtkUnsignedCharArray> colours;
  int cellFlag = -1;
  if (mapper->GetScalarVisibility())
  {
    vtkAbstractArray* scalars = vtkAbstractMapper::GetAbstractScalars(tris, mapper->GetScalarMode(),
      mapper->GetArrayAccessMode(), mapper->GetArrayId(), mapper->GetArrayName(), cellFlag);
    if (scalars && (cellFlag == 0 || cellFlag == 1))
    {
      vtkScalarsToColors* lut = mapper->GetLookupTable();
      if (!mapper->GetUseLookupTableScalarRange())
      {
        lut->SetRange(mapper->GetScalarRange());
      }
      lut->Build();
      colours.TakeReference(
        lut->MapScalars(scalars, mapper->GetColorMode(), mapper->GetArrayComponent()));
    }
  }

  // Colour textures (the base colour's and, for PBR, the emission's), each
  // triangle taking the texture's mean over its texture coordinates.
  vtkRadiosityTextureColour* textures[2] = { nullptr, nullptr };
  vtkNew<vtkRadiosityTextureColour> baseTexture, emissiveTexture;
  vtkDataArray* tcoords = tris->GetPointData()->GetTCoords();
  {
    vtkTexture* given[2] = { pbr ? property->GetTexture("albedoTex") : actor->GetTexture(),
      pbr ? property->GetTexture("emissiveTex") : nullptr };
    vtkRadiosityTextureColour* samplers[2] = { baseTexture, emissiveTexture };
    const char* what[2] = { pbr ? "base colour texture" : "texture", "emissive texture" };
    for (int k = 0; k < 2; ++k)
    {
      if (!given[k])
      {
        continue;
      }
      std::string why;
      if (!tcoords || tcoords->GetNumberOfComponents() < 2)
      {
        this->Warnings.push_back(name + ": a " + what[k] +
          " but no texture coordinates: the colour factor alone is solved");
      }
      else if (!samplers[k]->SetTexture(given[k], why))
      {
        this->Warnings.push_back(name + ": " + what[k] + " not used (" + why + ")");
      }
      else
      {
        textures[k] = samplers[k];
      }
    }
  }
  const auto textureMean = [&](vtkRadiosityTextureColour* texture, const vtkIdType tri[3], double rgb[3])
  {
    double uv[3][2];
    for (int v = 0; v < 3; ++v)
    {
      uv[v][0] = tcoords->GetComponent(tri[v], 0);
      uv[v][1] = tcoords->GetComponent(tri[v], 1);
    }
    texture->TriangleMean(uv, rgb);
  };

  // World coordinates (a part of an assembly by its path's matrix).
  auto* actorNode = vtkRadiosityActorNode::SafeDownCast(this->GetParent());
  vtkMatrix4x4* matrix = actorNode ? actorNode->GetWorldMatrix() : actor->GetMatrix();
  const bool mirrored = matrix->Determinant() < 0.0;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(tris->GetNumberOfPoints());
  for (vtkIdType i = 0; i < tris->GetNumberOfPoints(); ++i)
  {
    double p[4] = { 0.0, 0.0, 0.0, 1.0 };
    tris->GetPoint(i, p);
    double w[4];
    matrix->MultiplyPoint(p, w);
    if (!(std::isfinite(w[0]) && std::isfinite(w[1]) && std::isfinite(w[2]) && w[3] != 0.0))
    {
      this->Error = name + ": point " + std::to_string(i) + " " + Triple(p) +
        " is not finite in world coordinates (the actor's matrix applied)";
      return false;
    }
    points->SetPoint(i, w[0] / w[3], w[1] / w[3], w[2] / w[3]);
  }

  // Only the back side is seen: solve that one (the triangles reversed).
  const bool twoSided = IsTwoSided(rendererNode, actor);
  const bool backOnly =
    !twoSided && property->GetFrontfaceCulling() && !property->GetBackfaceCulling();
  const bool reverse = mirrored != backOnly;

  vtkNew<vtkCellArray> cells;
  auto reflectance = CellColours("Reflectance", nc);
  auto emission = CellColours("Emission", nc);
  vtkDataArray* inputEmission = tris->GetCellData()->GetArray("Emission");
  if (inputEmission && inputEmission->GetNumberOfComponents() != 3)
  {
    this->Error = name + ": cell array Emission has " +
      std::to_string(inputEmission->GetNumberOfComponents()) + " components, 3 expected";
    return false;
  }
  bool clamped = false;
  vtkIdType t = 0;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < nc; ++c)
  {
    tris->GetCellPoints(c, ids);
    if (ids->GetNumberOfIds() != 3)
    {
      continue;
    }
    vtkIdType tri[3] = { ids->GetId(0), ids->GetId(1), ids->GetId(2) };
    if (reverse)
    {
      std::swap(tri[1], tri[2]);
    }
    cells->InsertNextCell(3, tri);
    double rho[3] = { base[0], base[1], base[2] };
    if (colours && cellFlag == 1)
    {
      const unsigned char* rgba = colours->GetPointer(4 * c);
      for (int k = 0; k < 3; ++k)
      {
        rho[k] = rgba[k] / 255.0;
      }
    }
    else if (colours && cellFlag == 0)
    {
      // Point colours, averaged per triangle.
      for (int k = 0; k < 3; ++k)
      {
        rho[k] = 0.0;
        for (vtkIdType v : tri)
        {
          rho[k] += colours->GetValue(4 * v + k) / (3.0 * 255.0);
        }
      }
    }
    if (textures[0])
    {
      double texel[3];
      textureMean(textures[0], tri, texel);
      for (int k = 0; k < 3; ++k)
      {
        rho[k] *= texel[k];
      }
    }
    for (double& r : rho)
    {
      r *= factor;
      if (r >= maxReflectance)
      {
        r = maxReflectance;
        clamped = true;
      }
    }
    reflectance->SetTuple(t, rho);
    double e[3] = { emissive[0], emissive[1], emissive[2] };
    if (textures[1])
    {
      double texel[3];
      textureMean(textures[1], tri, texel);
      for (int k = 0; k < 3; ++k)
      {
        e[k] *= texel[k];
      }
    }
    if (inputEmission)
    {
      for (int k = 0; k < 3; ++k)
      {
        e[k] += inputEmission->GetComponent(c, k);
      }
    }
    emission->SetTuple(t, e);
    ++t;
  }
  reflectance->SetNumberOfTuples(t);
  emission->SetNumberOfTuples(t);
  this->ClampedColours += clamped ? 1 : 0;

  auto object = vtkSmartPointer<vtkPolyData>::New();
  object->SetPoints(points);
  object->SetPolys(cells);
  vtkCellData* cd = object->GetCellData();
  cd->AddArray(reflectance);
  cd->AddArray(emission);
  if (glossy)
  {
    auto s = CellColours("Specular", t);
    vtkNew<vtkDoubleArray> shininess;
    shininess->SetName("Shininess");
    shininess->SetNumberOfTuples(t);
    for (vtkIdType i = 0; i < t; ++i)
    {
      s->SetTuple(i, specular);
      shininess->SetValue(i, property->GetSpecularPower());
    }
    cd->AddArray(s);
    cd->AddArray(shininess);
  }
  if (twoSided)
  {
    vtkNew<vtkIntArray> sides;
    sides->SetName("TwoSided");
    sides->SetNumberOfTuples(t);
    sides->FillValue(1);
    cd->AddArray(sides);
  }
  this->Objects.push_back({ object, name });
  return true;
}

void vtkRadiosityPolyDataMapperNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Objects: " << this->Objects.size() << "\n";
  for (const Object& o : this->Objects)
  {
    os << indent.GetNextIndent() << o.Name << ": " << o.Data->GetNumberOfCells() << " triangles\n";
  }
  os << indent << "Error: " << (this->Error.empty() ? "(none)" : this->Error) << "\n";
  os << indent << "Warnings: " << this->Warnings.size() << "\n";
  os << indent << "ConvertedMTime: " << this->ConvertedMTime << "\n";
  os << indent << "ConvertedSolvable: " << (this->ConvertedSolvable ? "true" : "false") << "\n";
  os << indent << "ConvertedMaxReflectance: " << this->ConvertedMaxReflectance << "\n";
  os << indent << "ConvertedLightScale: " << this->ConvertedLightScale << "\n";
  os << indent << "ConvertedTwoSided: " << this->ConvertedTwoSided << "\n";
}
