#include "vtkRadiosityTriangleFieldMapper.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRadiosityCellArrays.h"
#include "vtkRadiosityShaderVarying.h"
#include "vtkShaderProgram.h"

#include <sstream>
#include <vector>

namespace
{
// Generic vertex attribute carrying the barycentrics (s,t), the point array
// of the unshared-vertex copy it is read from, and the texel sampler.
const char* const BarycentricAttribute = "fieldST";
const char* const BarycentricArray = "vtkRadiosityFieldST";
const char* const FieldSampler = "fieldTexture";

// The field's vectors, Reflectance and Emission (RGB each) in whole RGBA texels.
int FloatsPerTriangle(int vectors)
{
  return (3 * (vectors + 2) + 3) / 4 * 4;
}
}

//------------------------------------------------------------------------------
vtkRadiosityTriangleFieldMapper::vtkRadiosityTriangleFieldMapper(const char* arrayName,
  int vectors, const char* layout, const char* mapper, const char* what)
  : vtkRadiosityCellTexelMapper(FieldSampler, FloatsPerTriangle(vectors), what)
  , FieldArrayName(arrayName)
  , FieldVectors(vectors)
  , FieldLayout(layout)
  , MapperName(mapper)
{
  this->MapDataArrayToVertexAttribute(
    BarycentricAttribute, BarycentricArray, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
}

//------------------------------------------------------------------------------
vtkRadiosityTriangleFieldMapper::~vtkRadiosityTriangleFieldMapper() = default;

//------------------------------------------------------------------------------
bool vtkRadiosityTriangleFieldMapper::ValidateField(vtkPolyData* input, const char* name,
  int vectors, const char* layout, const char* mapper, std::string* message)
{
  vtkRadiosityCellArrays::Reason reason(message);
  std::string& why = reason.Text;
  if (input && input->GetNumberOfCells() == 0)
  {
    return true;
  }
  if (!vtkRadiosityCellArrays::CheckPolygons(input, true,
        std::string(": ") + mapper + " draws triangles only (the cells the field is defined on).",
        why))
  {
    return false;
  }
  const int components = 3 * vectors;
  vtkCellData* cd = input->GetCellData();
  vtkDataArray* field = cd->GetArray(name);
  std::ostringstream os;
  if (!field)
  {
    if (cd->GetAbstractArray(name))
    {
      os << "Cell array '" << name << "' is not numeric.";
    }
    else if (input->GetPointData()->GetAbstractArray(name))
    {
      os << "'" << name << "' is a point array; a cell array of " << components << " components ("
         << layout << ") is expected.";
    }
    else
    {
      os << "No cell array '" << name << "' (" << components << " components: " << layout
         << ") on the input.";
    }
    why = os.str();
    return false;
  }
  if (field->GetNumberOfComponents() != components)
  {
    os << "Cell array '" << name << "' has " << field->GetNumberOfComponents() << " components, "
       << components << " (" << layout << ") expected.";
    why = os.str();
    return false;
  }
  if (field->GetNumberOfTuples() < input->GetNumberOfCells())
  {
    os << "Cell array '" << name << "' has " << field->GetNumberOfTuples() << " tuples for "
       << input->GetNumberOfCells() << " cells.";
    why = os.str();
    return false;
  }
  return vtkRadiosityCellArrays::CheckOptional(input, GetReflectanceArrayName(), 3, why) &&
    vtkRadiosityCellArrays::CheckOptional(input, GetEmissionArrayName(), 3, why);
}

//------------------------------------------------------------------------------
bool vtkRadiosityTriangleFieldMapper::UpdateTriangles(vtkPolyData* input)
{
  if (input == this->TrianglesSource && input->GetMTime() == this->TrianglesSourceTime)
  {
    if (!this->InputValid)
    {
      vtkErrorMacro(<< this->InputError);
    }
    return this->InputValid;
  }
  this->TrianglesSource = input;
  this->TrianglesSourceTime = input->GetMTime();

  this->InputValid = ValidateField(input, this->FieldArrayName.c_str(), this->FieldVectors,
    this->FieldLayout.c_str(), this->MapperName.c_str(), &this->InputError);
  if (!this->InputValid)
  {
    vtkErrorMacro(<< this->InputError);
    this->Triangles->Initialize();
    this->CellTexels.clear();
    this->CellTexelsTime.Modified();
    return false;
  }

  const vtkIdType n = input->GetNumberOfPolys();
  vtkCellData* cd = input->GetCellData();
  vtkDataArray* field = cd->GetArray(this->FieldArrayName.c_str());
  vtkDataArray* reflectance = cd->GetArray(GetReflectanceArrayName());
  vtkDataArray* emission = cd->GetArray(GetEmissionArrayName());
  if (n > 0 && !reflectance && !this->WarnedNoReflectance)
  {
    vtkWarningMacro(<< "No cell array '" << GetReflectanceArrayName()
                    << "' on the input: drawing reflectance 0.5 grey.");
    this->WarnedNoReflectance = true;
  }
  if (n > 0 && !emission && !this->WarnedNoEmission)
  {
    vtkWarningMacro(<< "No cell array '" << GetEmissionArrayName()
                    << "' on the input: drawing no emission.");
    this->WarnedNoEmission = true;
  }

  // The unshared-vertex copy: triangle i owns points 3i, 3i+1, 3i+2 (its
  // cell's p0, p1, p2) with barycentrics (0,0), (1,0), (0,1).
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints() ? input->GetPoints()->GetDataType() : VTK_FLOAT);
  points->SetNumberOfPoints(3 * n);
  vtkNew<vtkFloatArray> st;
  st->SetName(BarycentricArray);
  st->SetNumberOfComponents(2);
  st->SetNumberOfTuples(3 * n);
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfTuples(n + 1);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfTuples(3 * n);
  const int floats = this->CellFloats;
  this->CellTexels.assign(static_cast<size_t>(n) * floats, 0.0f);

  static const float corners[3][2] = { { 0.0f, 0.0f }, { 1.0f, 0.0f }, { 0.0f, 1.0f } };
  vtkCellArray* polys = input->GetPolys();
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  std::vector<double> tuple(static_cast<size_t>(3 * this->FieldVectors));
  double rho[3] = { 0.5, 0.5, 0.5 };
  double e[3] = { 0.0, 0.0, 0.0 };
  const int materials = 3 * this->FieldVectors;
  for (vtkIdType i = 0; i < n; ++i)
  {
    polys->GetCellAtId(i, npts, pts);
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType id = 3 * i + k;
      points->SetPoint(id, input->GetPoint(pts[k]));
      st->SetTypedTuple(id, corners[k]);
      connectivity->SetValue(id, id);
    }
    offsets->SetValue(i, 3 * i);

    // All cells are polys (ValidateField), so poly i is cell i.
    field->GetTuple(i, tuple.data());
    if (reflectance)
    {
      reflectance->GetTuple(i, rho);
    }
    if (emission)
    {
      emission->GetTuple(i, e);
    }
    float* texel = this->CellTexels.data() + static_cast<size_t>(i) * floats;
    // Vector-major: texel[3k + c] is channel c of vector k.
    for (int k = 0; k < this->FieldVectors; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        texel[3 * k + c] = static_cast<float>(tuple[this->FieldComponent(k, c)]);
      }
    }
    for (int c = 0; c < 3; ++c)
    {
      texel[materials + c] = static_cast<float>(rho[c]);
      texel[materials + 3 + c] = static_cast<float>(e[c]);
    }
  }
  offsets->SetValue(n, 3 * n);

  vtkNew<vtkCellArray> triangles;
  triangles->SetData(offsets, connectivity);
  this->Triangles->Initialize();
  this->Triangles->SetPoints(points);
  this->Triangles->SetPolys(triangles);
  this->Triangles->GetPointData()->AddArray(st);
  this->CellTexelsTime.Modified();
  return true;
}

//------------------------------------------------------------------------------
void vtkRadiosityTriangleFieldMapper::UpdateCameraShiftScale(vtkRenderer* ren, vtkActor* actor)
{
  // vtkOpenGLPolyDataMapper::RenderPiece calls this once per render, after it
  // has updated the input into CurrentInput and before RenderPieceStart: the
  // place to check the input and to switch to its unshared-vertex copy.
  this->DrawPiece = false;
  vtkPolyData* input = this->CurrentInput;
  if (!input || input->GetNumberOfCells() == 0)
  {
    return;
  }
  if (!this->UpdateTriangles(input) || this->Triangles->GetNumberOfCells() == 0)
  {
    return;
  }
  // The barycentric attribute is part of this mapper's contract: restore it
  // if RemoveAllVertexAttributeMappings removed it.
  if (this->ExtraAttributes.find(BarycentricAttribute) == this->ExtraAttributes.end())
  {
    this->MapDataArrayToVertexAttribute(
      BarycentricAttribute, BarycentricArray, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  }
  this->CurrentInput = this->Triangles;
  this->DrawnPolyData = this->Triangles;
  this->DrawPiece = true;
  this->Superclass::UpdateCameraShiftScale(ren, actor);
}

//------------------------------------------------------------------------------
void vtkRadiosityTriangleFieldMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor)
{
  // The barycentrics: a vertex attribute passed on as a smooth varying (the
  // default, perspective-correct interpolation).
  vtkRadiosityAddVarying(shaders, "vec2", BarycentricAttribute,
    std::string("in vec2 ") + BarycentricAttribute + ";\n", BarycentricAttribute,
    std::string("uniform samplerBuffer ") + FieldSampler + ";\n" + RadianceUniforms());
  this->Superclass::ReplaceShaderValues(shaders, ren, actor);
}

//------------------------------------------------------------------------------
void vtkRadiosityTriangleFieldMapper::ReplaceShaderLight(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor)
{
  if (this->DrawingVertices)
  {
    // Vertices drawn by VertexVisibility keep VTK's shading.
    this->Superclass::ReplaceShaderLight(shaders, ren, actor);
    return;
  }

  // The texels of the current primitive as floats f0, f1, ..., then the
  // field's vectors and the materials as vec3.
  std::ostringstream impl;
  impl << "  int fieldTexel = " << this->CellTexelIndex() << ";\n";
  const int texels = this->CellFloats / 4;
  for (int q = 0; q < texels; ++q)
  {
    impl << "  vec4 fieldQ" << q << " = texelFetchBuffer(" << FieldSampler << ", fieldTexel + " << q
         << ");\n";
  }
  auto component = [](int f) {
    static const char* const xyzw = "xyzw";
    return "fieldQ" + std::to_string(f / 4) + "." + xyzw[f % 4];
  };
  auto vector = [&component](int first) {
    return "vec3(" + component(first) + ", " + component(first + 1) + ", " + component(first + 2) +
      ")";
  };
  for (int k = 0; k < this->FieldVectors; ++k)
  {
    impl << "  vec3 field" << k << " = " << vector(3 * k) << ";\n";
  }
  impl << "  vec3 reflectance = " << vector(3 * this->FieldVectors) << ";\n"
       << "  vec3 emission = " << vector(3 * this->FieldVectors + 3) << ";\n"
       << "  float s = " << BarycentricAttribute << "VSOutput.x;\n"
       << "  float t = " << BarycentricAttribute << "VSOutput.y;\n"
       << this->FieldIrradianceGLSL()
       << "  vec3 encoded = " << EncodedRadiance("emission + reflectance*irradiance") << ";\n";
  if (this->DrawingEdges(ren, actor))
  {
    // emix: the superclass's edge coverage (//VTK::Edges::Impl).
    impl << "  encoded = mix(encoded, edgeColor, emix);\n";
  }
  impl << "  gl_FragData[0] = vec4(encoded, opacity);\n";
  std::string FSSource = shaders[vtkShader::Fragment]->GetSource();
  vtkShaderProgram::Substitute(FSSource, "//VTK::Light::Impl", impl.str());
  shaders[vtkShader::Fragment]->SetSource(FSSource);
}

//------------------------------------------------------------------------------
void vtkRadiosityTriangleFieldMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FieldArrayName: " << this->FieldArrayName << " (" << 3 * this->FieldVectors
     << " components: " << this->FieldLayout << ")\n";
  os << indent << "ReflectanceArrayName: " << GetReflectanceArrayName() << "\n";
  os << indent << "EmissionArrayName: " << GetEmissionArrayName() << "\n";
  os << indent << "InputValid: " << (this->InputValid ? "true" : "false") << "\n";
  if (!this->InputValid && !this->InputError.empty())
  {
    os << indent << "InputError: " << this->InputError << "\n";
  }
  os << indent << "Triangles (unshared-vertex copy): " << this->Triangles->GetNumberOfCells()
     << " triangles, " << this->Triangles->GetNumberOfPoints() << " points\n";
  os << indent << "WarnedNoReflectance: " << (this->WarnedNoReflectance ? "true" : "false") << "\n";
  os << indent << "WarnedNoEmission: " << (this->WarnedNoEmission ? "true" : "false") << "\n";
}
