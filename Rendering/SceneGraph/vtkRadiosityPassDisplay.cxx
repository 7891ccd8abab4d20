#include "vtkRadiosityPassDisplay.h"

#include "vtkActor.h"
#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkIrradianceSamplesMapper.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkQuadraticInterpolantMapper.h"
#include "vtkShaderProperty.h"
#include "vtkShepardSplatMapper.h"
#include "vtkStringArray.h"
#include "vtkUniforms.h"
#include "vtkVectorIrradianceMapper.h"

vtkStandardNewMacro(vtkRadiosityPassDisplay);

namespace
{
const char* const PathNames[6] = { "none", "interpolants", "splats", "vector irradiance",
  "irradiance samples", "radiosity per vertex" };
}

vtkRadiosityPassDisplay::vtkRadiosityPassDisplay()
  : InterpolantMapper(vtkSmartPointer<vtkQuadraticInterpolantMapper>::New())
  , SplatMapper(vtkSmartPointer<vtkShepardSplatMapper>::New())
  , VectorMapper(vtkSmartPointer<vtkVectorIrradianceMapper>::New())
  , SamplesMapper(vtkSmartPointer<vtkIrradianceSamplesMapper>::New())
  , VertexMapper(vtkSmartPointer<vtkOpenGLPolyDataMapper>::New())
{
  vtkMapper* mappers[6] = { nullptr, this->InterpolantMapper, this->SplatMapper,
    this->VectorMapper, this->SamplesMapper, this->VertexMapper };
  for (int i = Interpolants; i <= Vertices; ++i)
  {
    this->Actors[i] = vtkSmartPointer<vtkActor>::New();
    this->Actors[i]->SetMapper(mappers[i]);
    this->Actors[i]->GetProperty()->LightingOff();
    this->Actors[i]->GetProperty()->BackfaceCullingOn();
  }
  // The radiosity per vertex reaches the shaders as a float attribute (not
  // scalars: no lookup table, no clamping) and is written as the project's
  // mappers write radiance (vtkRadiosityCellTexelMapper::RadianceDisplayFunction).
  this->VertexMapper->ScalarVisibilityOff();
  vtkShaderProperty* sp = this->Actors[Vertices]->GetShaderProperty();
  sp->AddVertexShaderReplacement("//VTK::Normal::Dec", true,
    "//VTK::Normal::Dec\n"
    "in vec3 radiosityMC;\n"
    "out vec3 radianceVSOutput;\n",
    false);
  sp->AddVertexShaderReplacement("//VTK::Normal::Impl", true,
    "//VTK::Normal::Impl\n"
    "  radianceVSOutput = radiosityMC * radianceScale;\n",
    false);
  sp->AddFragmentShaderReplacement("//VTK::Normal::Dec", true,
    std::string("//VTK::Normal::Dec\n"
                "in vec3 radianceVSOutput;\n") +
      vtkRadiosityCellTexelMapper::RadianceDisplayFunction(),
    false);
  sp->AddFragmentShaderReplacement("//VTK::Light::Impl", true,
    "//VTK::Light::Impl\n"
    "  gl_FragData[0] = vec4(radianceDisplay(radianceVSOutput), 1.0);\n",
    false);
  sp->GetFragmentCustomUniforms()->SetUniformf("inverseGamma", static_cast<float>(1.0 / 2.2));
}

vtkRadiosityPassDisplay::~vtkRadiosityPassDisplay() = default;

bool vtkRadiosityPassDisplay::SetSolution(
  vtkPolyData* surface, vtkPolyData* product, vtkPolyData* materials, std::string& error)
{
  this->Active = None;
  error.clear();
  if (!surface || surface->GetNumberOfCells() == 0)
  {
    error = "the solution has no cells";
    return false;
  }
  std::string kind;
  if (product)
  {
    if (auto* kinds = vtkStringArray::SafeDownCast(
          product->GetFieldData()->GetAbstractArray("ProductKind")))
    {
      kind = kinds->GetNumberOfValues() > 0 ? kinds->GetValue(0) : "";
    }
  }
  if (product && product->GetNumberOfCells() > 0 &&
    product->GetCellData()->GetAbstractArray(vtkQuadraticInterpolantMapper::GetInterpolantArrayName()))
  {
    if (!vtkQuadraticInterpolantMapper::ValidateInput(product, &error))
    {
      return false;
    }
    this->InterpolantMapper->SetInputData(product);
    this->Active = Interpolants;
  }
  else if (product && kind == "ShepardField" && product->GetNumberOfPoints() > 0)
  {
    if (!vtkShepardSplatMapper::ValidateSurface(surface, &error) ||
      !vtkShepardSplatMapper::ValidateField(product, &error))
    {
      return false;
    }
    this->SplatMapper->SetInputData(surface);
    this->SplatMapper->SetFieldData(product);
    this->Active = Splats;
  }
  else if (surface->GetPointData()->GetAbstractArray("IrradianceVector"))
  {
    // The solution's cells are the input triangles: the glossy materials ride along.
    vtkNew<vtkPolyData> shaded;
    shaded->ShallowCopy(surface);
    if (materials && materials->GetNumberOfCells() == surface->GetNumberOfCells())
    {
      for (const char* name : { "Specular", "Shininess" })
      {
        if (vtkDataArray* a = materials->GetCellData()->GetArray(name))
        {
          shaded->GetCellData()->AddArray(a);
        }
      }
    }
    if (!vtkVectorIrradianceMapper::ValidateInput(shaded, &error))
    {
      return false;
    }
    this->VectorMapper->SetInputData(shaded);
    this->Active = Vectors;
  }
  else if (surface->GetCellData()->GetAbstractArray(vtkIrradianceSamplesMapper::GetSamplesArrayName()))
  {
    if (!vtkIrradianceSamplesMapper::ValidateInput(surface, &error))
    {
      return false;
    }
    this->SamplesMapper->SetInputData(surface);
    this->Active = Samples;
  }
  else
  {
    vtkDataArray* radiosity = surface->GetPointData()->GetArray("Radiosity");
    if (!radiosity || radiosity->GetNumberOfComponents() != 3)
    {
      error = "the solution has no point array Radiosity with 3 components";
      return false;
    }
    this->VertexMapper->SetInputData(surface);
    this->VertexMapper->RemoveAllVertexAttributeMappings();
    this->VertexMapper->MapDataArrayToVertexAttribute(
      "radiosityMC", "Radiosity", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
    this->Active = Vertices;
  }
  this->Update();
  return true;
}

void vtkRadiosityPassDisplay::Clear()
{
  this->Active = None;
}

vtkActor* vtkRadiosityPassDisplay::GetActor()
{
  return this->Active == None ? nullptr : this->Actors[this->Active].GetPointer();
}

const char* vtkRadiosityPassDisplay::GetPathName() const
{
  return PathNames[this->Active];
}

void vtkRadiosityPassDisplay::Update()
{
  for (vtkRadiosityCellTexelMapper* m : { static_cast<vtkRadiosityCellTexelMapper*>(
                                            this->InterpolantMapper),
         static_cast<vtkRadiosityCellTexelMapper*>(this->SplatMapper),
         static_cast<vtkRadiosityCellTexelMapper*>(this->VectorMapper),
         static_cast<vtkRadiosityCellTexelMapper*>(this->SamplesMapper) })
  {
    m->SetExposure(this->Exposure);
    m->SetToneMapping(this->ToneMapping);
  }
  vtkShaderProperty* sp = this->Actors[Vertices]->GetShaderProperty();
  sp->GetVertexCustomUniforms()->SetUniformf(
    "radianceScale", static_cast<float>(this->Exposure / vtkMath::Pi()));
  sp->GetFragmentCustomUniforms()->SetUniformi("toneOperator", this->ToneMapping);
}

void vtkRadiosityPassDisplay::ReleaseGraphicsResources(vtkWindow* window)
{
  for (int i = Interpolants; i <= Vertices; ++i)
  {
    this->Actors[i]->ReleaseGraphicsResources(window);
  }
}

vtkShepardSplatMapper* vtkRadiosityPassDisplay::GetSplatMapper()
{
  return this->SplatMapper;
}

void vtkRadiosityPassDisplay::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Path: " << this->GetPathName() << "\n";
  os << indent << "SplatMapper Evaluation: "
     << (this->SplatMapper->GetEvaluation() == vtkShepardSplatMapper::SPLATS ? "SPLATS" : "SURFACE_TEXELS")
     << ", TexelSpacing " << this->SplatMapper->GetTexelSpacing() << "\n";
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "ToneMapping: " << this->ToneMapping << "\n";
}
