#include "vtkVectorIrradianceMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"
#include "vtkProperty.h"
#include "vtkRadiosityCellArrays.h"
#include "vtkRadiosityShaderVarying.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"

#include <sstream>

vtkStandardNewMacro(vtkVectorIrradianceMapper);

namespace
{
constexpr int FloatsPerCell = 12;
// Generic vertex attributes and the point arrays of the copy they come from.
const char* const Attributes[4][2] = { { "irradianceR", "vtkVectorIrradianceR" },
  { "irradianceG", "vtkVectorIrradianceG" }, { "irradianceB", "vtkVectorIrradianceB" },
  { "surfaceNormal", "vtkVectorIrradianceNormal" } };
}

//------------------------------------------------------------------------------
vtkVectorIrradianceMapper::vtkVectorIrradianceMapper()
  : vtkRadiosityCellTexelMapper("vectorCellTexels", FloatsPerCell, "the materials")
{
  // The view direction is formed in model coordinates.
  this->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
  for (const auto& a : Attributes)
  {
    this->MapDataArrayToVertexAttribute(a[0], a[1], vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  }
}

//------------------------------------------------------------------------------
vtkVectorIrradianceMapper::~vtkVectorIrradianceMapper() = default;

//------------------------------------------------------------------------------
bool vtkVectorIrradianceMapper::ValidateInput(vtkPolyData* input, std::string* message)
{
  vtkRadiosityCellArrays::Reason reason(message);
  std::string& why = reason.Text;
  if (!vtkRadiosityCellArrays::CheckPolygons(
        input, false, ": vtkVectorIrradianceMapper draws polygons only.", why))
  {
    return false;
  }
  vtkPointData* pd = input->GetPointData();
  vtkDataArray* vectors = pd->GetArray("IrradianceVector");
  std::ostringstream os;
  if (!vectors)
  {
    os << (pd->GetAbstractArray("IrradianceVector") ? "Point array 'IrradianceVector' is not numeric."
                                                    : "No point array 'IrradianceVector' (9 components: the "
                                                      "R, G and B irradiance vectors).");
  }
  else if (vectors->GetNumberOfComponents() != 9)
  {
    os << "Point array 'IrradianceVector' has " << vectors->GetNumberOfComponents()
       << " components, 9 (R, G, B vectors) expected.";
  }
  else if (vectors->GetNumberOfTuples() < input->GetNumberOfPoints())
  {
    os << "Point array 'IrradianceVector' has " << vectors->GetNumberOfTuples() << " tuples for "
       << input->GetNumberOfPoints() << " points.";
  }
  else if (vtkDataArray* normals = pd->GetArray("Normals"))
  {
    if (normals->GetNumberOfComponents() != 3)
    {
      os << "Point array 'Normals' has " << normals->GetNumberOfComponents() << " components, 3 expected.";
    }
  }
  if (!os.str().empty())
  {
    why = os.str();
    return false;
  }
  return vtkRadiosityCellArrays::CheckOptional(input, "Reflectance", 3, why) &&
    vtkRadiosityCellArrays::CheckOptional(input, "Emission", 3, why) &&
    vtkRadiosityCellArrays::CheckOptional(input, "Specular", 3, why) &&
    vtkRadiosityCellArrays::CheckOptional(input, "Shininess", 1, why);
}

//------------------------------------------------------------------------------
bool vtkVectorIrradianceMapper::UpdateCopy(vtkPolyData* input)
{
  if (input == this->CopySource && input->GetMTime() == this->CopySourceTime)
  {
    return this->InputValid;
  }
  this->CopySource = input;
  this->CopySourceTime = input->GetMTime();
  this->InputValid = ValidateInput(input, &this->InputError);
  if (!this->InputValid)
  {
    vtkErrorMacro(<< this->InputError);
    return false;
  }
  const vtkIdType np = input->GetNumberOfPoints();
  this->Copy->Initialize();
  this->Copy->SetPoints(input->GetPoints());
  this->Copy->SetPolys(input->GetPolys());
  vtkDataArray* vectors = input->GetPointData()->GetArray("IrradianceVector");
  for (int c = 0; c < 3; ++c)
  {
    vtkNew<vtkFloatArray> channel;
    channel->SetName(Attributes[c][1]);
    channel->SetNumberOfComponents(3);
    channel->SetNumberOfTuples(np);
    for (vtkIdType p = 0; p < np; ++p)
    {
      for (int d = 0; d < 3; ++d)
      {
        channel->SetTypedComponent(p, d, static_cast<float>(vectors->GetComponent(p, 3 * c + d)));
      }
    }
    this->Copy->GetPointData()->AddArray(channel);
  }
  // Normals: the input's, or the area-weighted mean of the polygons'.
  vtkNew<vtkFloatArray> normals;
  normals->SetName(Attributes[3][1]);
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(np);
  normals->Fill(0.0);
  const vtkIdType nc = input->GetNumberOfCells();
  this->CellTexels.assign(static_cast<std::size_t>(nc) * FloatsPerCell, 0.0f);
  vtkDataArray* given = input->GetPointData()->GetArray("Normals");
  vtkCellData* cd = input->GetCellData();
  vtkDataArray* reflectance = cd->GetArray("Reflectance");
  vtkDataArray* specular = cd->GetArray("Specular");
  vtkDataArray* shininess = cd->GetArray("Shininess");
  vtkDataArray* emission = cd->GetArray("Emission");
  this->Glossy = false;
  vtkCellArray* polys = input->GetPolys();
  const vtkIdType* pts = nullptr;
  vtkIdType npts = 0;
  for (vtkIdType i = 0; i < nc; ++i)
  {
    polys->GetCellAtId(i, npts, pts);
    if (!given)
    {
      double n[3];
      vtkPolygon::ComputeNormal(input->GetPoints(), static_cast<int>(npts), pts, n);
      const double area = vtkPolygon::ComputeArea(input->GetPoints(), npts, pts, n);
      for (vtkIdType k = 0; k < npts; ++k)
      {
        for (int d = 0; d < 3; ++d)
        {
          normals->SetTypedComponent(pts[k], d,
            normals->GetTypedComponent(pts[k], d) + static_cast<float>(area * n[d]));
        }
      }
    }
    float* t = this->CellTexels.data() + static_cast<std::size_t>(i) * FloatsPerCell;
    for (int c = 0; c < 3; ++c)
    {
      t[c] = static_cast<float>(reflectance ? reflectance->GetComponent(i, c) : 0.5);
      t[4 + c] = static_cast<float>(specular ? specular->GetComponent(i, c) : 0.0);
      t[8 + c] = static_cast<float>(emission ? emission->GetComponent(i, c) : 0.0);
      this->Glossy = this->Glossy || t[4 + c] > 0.0f;
    }
    t[3] = static_cast<float>(shininess ? shininess->GetComponent(i, 0) : 0.0);
  }
  for (vtkIdType p = 0; p < np; ++p)
  {
    double n[3];
    for (int d = 0; d < 3; ++d)
    {
      n[d] = given ? given->GetComponent(p, d) : normals->GetTypedComponent(p, d);
    }
    vtkMath::Normalize(n);
    for (int d = 0; d < 3; ++d)
    {
      normals->SetTypedComponent(p, d, static_cast<float>(n[d]));
    }
  }
  this->Copy->GetPointData()->AddArray(normals);
  this->CellTexelsTime.Modified();
  return true;
}

//------------------------------------------------------------------------------
void vtkVectorIrradianceMapper::UpdateCameraShiftScale(vtkRenderer* ren, vtkActor* actor)
{
  this->DrawPiece = false;
  vtkPolyData* input = this->CurrentInput;
  if (!input || input->GetNumberOfCells() == 0 || !this->UpdateCopy(input))
  {
    return;
  }
  for (const auto& a : Attributes)
  {
    if (this->ExtraAttributes.find(a[0]) == this->ExtraAttributes.end())
    {
      this->MapDataArrayToVertexAttribute(a[0], a[1], vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
    }
  }
  this->CurrentInput = this->Copy;
  this->DrawnPolyData = this->Copy;
  this->DrawPiece = true;
  this->Superclass::UpdateCameraShiftScale(ren, actor);
}

//------------------------------------------------------------------------------
bool vtkVectorIrradianceMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  return this->Glossy != this->ShaderGlossy || this->Superclass::GetNeedToRebuildShaders(cellBO, ren, actor);
}

//------------------------------------------------------------------------------
void vtkVectorIrradianceMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor)
{
  vtkRadiosityAddVarying(shaders, "vec3", "irradianceR", "in vec3 irradianceR;\n", "irradianceR", "");
  vtkRadiosityAddVarying(shaders, "vec3", "irradianceG", "in vec3 irradianceG;\n", "irradianceG", "");
  vtkRadiosityAddVarying(shaders, "vec3", "irradianceB", "in vec3 irradianceB;\n", "irradianceB", "");
  vtkRadiosityAddVarying(shaders, "vec3", "surfaceNormal", "in vec3 surfaceNormal;\n", "surfaceNormal", "");
  vtkRadiosityAddVarying(shaders, "vec3", "surfacePosition", ModelPositionDeclarations(), ModelPosition(),
    std::string("uniform samplerBuffer vectorCellTexels;\n"
                "uniform vec3 eyePositionMC;\n") +
      RadianceUniforms());
  this->Superclass::ReplaceShaderValues(shaders, ren, actor);
}

//------------------------------------------------------------------------------
void vtkVectorIrradianceMapper::ReplaceShaderLight(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor)
{
  if (this->DrawingVertices)
  {
    this->Superclass::ReplaceShaderLight(shaders, ren, actor);
    return;
  }
  this->ShaderGlossy = this->Glossy;
  std::string FSSource = shaders[vtkShader::Fragment]->GetSource();
  std::string impl =
    // Three texels per primitive: (Reflectance, Shininess), (Specular, 0),
    // (Emission, 0).
    "  int vectorCell = " + this->CellTexelIndex() + ";\n"
    "  vec4 diffuseShininess = texelFetchBuffer(vectorCellTexels, vectorCell);\n"
    "  vec4 specularColour = texelFetchBuffer(vectorCellTexels, vectorCell + 1);\n"
    "  vec4 emitted = texelFetchBuffer(vectorCellTexels, vectorCell + 2);\n"
    "  vec3 n = normalize(surfaceNormalVSOutput);\n"
    "  vec3 E[3] = vec3[3](irradianceRVSOutput, irradianceGVSOutput, irradianceBVSOutput);\n"
    // Radiosity-like: pi L, which EncodedRadiance scales by Exposure / pi.
    "  vec3 radiosity = emitted.rgb;\n";
  if (this->Glossy)
  {
    impl += "  vec3 toEye = normalize(eyePositionMC - surfacePositionVSOutput);\n"
            "  vec3 mirror = reflect(-toEye, n);\n"
            "  float q = diffuseShininess.w;\n";
  }
  impl += "  for (int c = 0; c < 3; ++c)\n"
          "  {\n"
          "    float brdfTimesPi = diffuseShininess[c];\n";
  if (this->Glossy)
  {
    // Lewis's modified Phong lobe about the dominant direction (eq. 10).
    impl += "    float strength = length(E[c]);\n"
            "    if (strength > 0.0)\n"
            "    {\n"
            "      float s = max(dot(mirror, E[c] / strength), 0.0);\n"
            "      brdfTimesPi += specularColour[c] * (q + 2.0) / 2.0 * pow(s, q);\n"
            "    }\n";
  }
  impl += "    radiosity[c] += max(dot(n, E[c]), 0.0) * brdfTimesPi;\n"
          "  }\n"
          "  gl_FragData[0] = vec4(" + EncodedRadiance("radiosity") + ", opacity);\n";
  vtkShaderProgram::Substitute(FSSource, "//VTK::Light::Impl", impl);
  shaders[vtkShader::Fragment]->SetSource(FSSource);
}

//------------------------------------------------------------------------------
void vtkVectorIrradianceMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, actor);
  vtkShaderProgram* program = cellBO.Program;
  if (program->IsUniformUsed("eyePositionMC"))
  {
    // The eye in model coordinates: the camera position through the inverse
    // of the actor's matrix.
    double eye[4] = { 0, 0, 0, 1 };
    ren->GetActiveCamera()->GetPosition(eye);
    vtkNew<vtkMatrix4x4> inverse;
    vtkMatrix4x4::Invert(actor->GetMatrix(), inverse);
    double mc[4];
    inverse->MultiplyPoint(eye, mc);
    const float position[3] = { static_cast<float>(mc[0] / mc[3]), static_cast<float>(mc[1] / mc[3]),
      static_cast<float>(mc[2] / mc[3]) };
    program->SetUniform3f("eyePositionMC", position);
  }
}

//------------------------------------------------------------------------------
void vtkVectorIrradianceMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Glossy: " << (this->Glossy ? "true" : "false") << "\n";
  os << indent << "InputValid: " << (this->InputValid ? "true" : "false") << "\n";
  if (!this->InputValid && !this->InputError.empty())
  {
    os << indent << "InputError: " << this->InputError << "\n";
  }
}
