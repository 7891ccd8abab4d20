#include "vtkQuadraticInterpolantMapper.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLCellToVTKCellMap.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRadiosityCellArrays.h"
#include "vtkRadiosityShaderVarying.h"
#include "vtkRadiosityTexelBuffer.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"

#include <algorithm>
#include <sstream>

vtkStandardNewMacro(vtkQuadraticInterpolantMapper);

namespace
{
// Generic vertex attribute carrying the barycentrics (s,t), and the point
// array of the unshared-vertex copy it is read from.
const char* const BarycentricAttribute = "interpolantST";
const char* const BarycentricArray = "vtkQuadraticInterpolantST";

// Floats per triangle in the texture buffer: (A, 2B, 2C, D, 2E, F,
// Reflectance, Emission), each RGB; six RGBA texels.
constexpr int FloatsPerTriangle = 24;
constexpr int InterpolantComponents = 18;
}

//------------------------------------------------------------------------------
vtkQuadraticInterpolantMapper::vtkQuadraticInterpolantMapper()
  : vtkRadiosityCellTexelMapper("interpolantTexture", FloatsPerTriangle, "the quadratic interpolants")
{
  this->MapDataArrayToVertexAttribute(
    BarycentricAttribute, BarycentricArray, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
}

//------------------------------------------------------------------------------
vtkQuadraticInterpolantMapper::~vtkQuadraticInterpolantMapper() = default;

//------------------------------------------------------------------------------
bool vtkQuadraticInterpolantMapper::ValidateInput(vtkPolyData* input, std::string* message)
{
  vtkRadiosityCellArrays::Reason reason(message);
  std::string& why = reason.Text;
  if (input && input->GetNumberOfCells() == 0)
  {
    return true;
  }
  if (!vtkRadiosityCellArrays::CheckPolygons(input, true,
        ": vtkQuadraticInterpolantMapper draws triangles only (the cells the interpolants are "
        "defined on).",
        why))
  {
    return false;
  }
  const vtkIdType numberOfCells = input->GetNumberOfCells();

  const char* name = GetInterpolantArrayName();
  vtkCellData* cd = input->GetCellData();
  vtkDataArray* interpolant = cd->GetArray(name);
  std::ostringstream os;
  if (!interpolant)
  {
    if (cd->GetAbstractArray(name))
    {
      os << "Cell array '" << name << "' is not numeric.";
    }
    else if (input->GetPointData()->GetAbstractArray(name))
    {
      os << "'" << name << "' is a point array; a cell array of " << InterpolantComponents
         << " components (RGB x (A, 2B, 2C, D, 2E, F)) is expected.";
    }
    else
    {
      os << "No cell array '" << name << "' (" << InterpolantComponents
         << " components: RGB x (A, 2B, 2C, D, 2E, F)) on the input.";
    }
    why = os.str();
    return false;
  }
  if (interpolant->GetNumberOfComponents() != InterpolantComponents)
  {
    os << "Cell array '" << name << "' has " << interpolant->GetNumberOfComponents()
       << " components, " << InterpolantComponents << " (RGB x (A, 2B, 2C, D, 2E, F)) expected.";
    why = os.str();
    return false;
  }
  if (interpolant->GetNumberOfTuples() < numberOfCells)
  {
    os << "Cell array '" << name << "' has " << interpolant->GetNumberOfTuples() << " tuples for "
       << numberOfCells << " cells.";
    why = os.str();
    return false;
  }
  return vtkRadiosityCellArrays::CheckOptional(input, GetReflectanceArrayName(), 3, why) &&
    vtkRadiosityCellArrays::CheckOptional(input, GetEmissionArrayName(), 3, why);
}

//------------------------------------------------------------------------------
bool vtkQuadraticInterpolantMapper::UpdateTriangles(vtkPolyData* input)
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

  this->InputValid = ValidateInput(input, &this->InputError);
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
  vtkDataArray* interpolant = cd->GetArray(GetInterpolantArrayName());
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
  this->CellTexels.assign(static_cast<size_t>(n) * FloatsPerTriangle, 0.0f);

  static const float corners[3][2] = { { 0.0f, 0.0f }, { 1.0f, 0.0f }, { 0.0f, 1.0f } };
  vtkCellArray* polys = input->GetPolys();
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  double coefficients[InterpolantComponents];
  double rho[3] = { 0.5, 0.5, 0.5 };
  double e[3] = { 0.0, 0.0, 0.0 };
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

    // All cells are polys (ValidateInput), so poly i is cell i.
    interpolant->GetTuple(i, coefficients);
    if (reflectance)
    {
      reflectance->GetTuple(i, rho);
    }
    if (emission)
    {
      emission->GetTuple(i, e);
    }
    float* texel = this->CellTexels.data() + static_cast<size_t>(i) * FloatsPerTriangle;
    // Coefficient-major: texel[3k + c] is coefficient k of channel c, the
    // array's component 6c + k.
    for (int k = 0; k < 6; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        texel[3 * k + c] = static_cast<float>(coefficients[6 * c + k]);
      }
    }
    for (int c = 0; c < 3; ++c)
    {
      texel[18 + c] = static_cast<float>(rho[c]);
      texel[21 + c] = static_cast<float>(e[c]);
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
void vtkQuadraticInterpolantMapper::UpdateCameraShiftScale(vtkRenderer* ren, vtkActor* actor)
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
void vtkQuadraticInterpolantMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor)
{
  // The barycentrics: a vertex attribute passed on as a smooth varying (the
  // default, perspective-correct interpolation).
  vtkRadiosityAddVarying(shaders, "vec2", "interpolantST", "in vec2 interpolantST;\n",
    "interpolantST", std::string("uniform samplerBuffer interpolantTexture;\n") + RadianceUniforms());
  this->Superclass::ReplaceShaderValues(shaders, ren, actor);
}

//------------------------------------------------------------------------------
void vtkQuadraticInterpolantMapper::ReplaceShaderLight(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor)
{
  if (this->DrawingVertices)
  {
    // Vertices drawn by VertexVisibility keep VTK's shading.
    this->Superclass::ReplaceShaderLight(shaders, ren, actor);
    return;
  }

  std::string FSSource = shaders[vtkShader::Fragment]->GetSource();
  std::string impl =
    // Six texels per OpenGL primitive (see the class description).
    "  int interpolantTexel = " + this->CellTexelIndex() + ";\n"
    "  vec4 q0 = texelFetchBuffer(interpolantTexture, interpolantTexel);\n"
    "  vec4 q1 = texelFetchBuffer(interpolantTexture, interpolantTexel + 1);\n"
    "  vec4 q2 = texelFetchBuffer(interpolantTexture, interpolantTexel + 2);\n"
    "  vec4 q3 = texelFetchBuffer(interpolantTexture, interpolantTexel + 3);\n"
    "  vec4 q4 = texelFetchBuffer(interpolantTexture, interpolantTexel + 4);\n"
    "  vec4 q5 = texelFetchBuffer(interpolantTexture, interpolantTexel + 5);\n"
    "  vec3 coefA = q0.xyz;\n"
    "  vec3 coef2B = vec3(q0.w, q1.xy);\n"
    "  vec3 coef2C = vec3(q1.zw, q2.x);\n"
    "  vec3 coefD = q2.yzw;\n"
    "  vec3 coef2E = q3.xyz;\n"
    "  vec3 coefF = vec3(q3.w, q4.xy);\n"
    "  vec3 reflectance = vec3(q4.zw, q5.x);\n"
    "  vec3 emission = q5.yzw;\n"
    "  float s = interpolantSTVSOutput.x;\n"
    "  float t = interpolantSTVSOutput.y;\n"
    // Hardt & Teller eq. 1: eight multiplies and five adds per channel.
    "  vec3 irradiance = coefA*s*s + coef2B*s*t + coef2C*s + coefD*t*t + coef2E*t + coefF;\n"
    "  vec3 encoded = " + EncodedRadiance("emission + reflectance*irradiance") + ";\n";
  if (this->DrawingEdges(ren, actor))
  {
    // emix: the superclass's edge coverage (//VTK::Edges::Impl).
    impl += "  encoded = mix(encoded, edgeColor, emix);\n";
  }
  impl += "  gl_FragData[0] = vec4(encoded, opacity);\n";
  vtkShaderProgram::Substitute(FSSource, "//VTK::Light::Impl", impl);
  shaders[vtkShader::Fragment]->SetSource(FSSource);
}

//------------------------------------------------------------------------------
//------------------------------------------------------------------------------
void vtkQuadraticInterpolantMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "InterpolantArrayName: " << GetInterpolantArrayName() << "\n";
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
