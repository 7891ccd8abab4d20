#include "vtkShepardSplatMapper.h"

#include "vtkActor.h"
#include "vtkAlgorithmOutput.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellTypes.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLActor.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"
#include "vtkProperty.h"
#include "vtkRadiosityCellArrays.h"
#include "vtkRadiosityShaderVarying.h"
#include "vtkRadiosityTexelBuffer.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <array>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkShepardSplatMapper);

namespace
{
constexpr int FloatsPerCell = 12;
constexpr int FloatsPerPoint = 12;
constexpr int MaximumLevels = 64;

// Pass 2: one quad (two triangles, six vertices) per basis function, read
// from the level-sorted point texels at firstPoint + gl_VertexID / 6. The quad
// covers the projection of the support's bounding cube: the eight corners
// projected, or the whole viewport when a corner is behind the eye.
const char* const SplatVS = R"(//VTK::System::Dec
uniform samplerBuffer splatPoints;
uniform int firstPoint;
uniform mat4 MCDCMatrix;
flat out vec4 splatCentre;
flat out vec4 splatNormal;
flat out vec3 splatCoefficient;
void main()
{
  int point = firstPoint + gl_VertexID / 6;
  int corner = gl_VertexID - 6 * (gl_VertexID / 6);
  splatCentre = texelFetch(splatPoints, 3 * point);
  splatNormal = texelFetch(splatPoints, 3 * point + 1);
  splatCoefficient = texelFetch(splatPoints, 3 * point + 2).xyz;
  vec2 lo = vec2(1.0e30);
  vec2 hi = vec2(-1.0e30);
  bool behind = false;
  for (int i = 0; i < 8; ++i)
  {
    vec3 offset = vec3((i & 1) != 0 ? 1.0 : -1.0, (i & 2) != 0 ? 1.0 : -1.0,
      (i & 4) != 0 ? 1.0 : -1.0);
    vec4 c = MCDCMatrix * vec4(splatCentre.xyz + splatCentre.w * offset, 1.0);
    if (c.w <= 0.0)
    {
      behind = true;
    }
    else
    {
      lo = min(lo, c.xy / c.w);
      hi = max(hi, c.xy / c.w);
    }
  }
  if (behind)
  {
    lo = vec2(-1.0);
    hi = vec2(1.0);
  }
  lo = clamp(lo, vec2(-1.0), vec2(1.0));
  hi = clamp(hi, vec2(-1.0), vec2(1.0));
  const vec2 quad[6] = vec2[6](vec2(0.0, 0.0), vec2(1.0, 0.0), vec2(1.0, 1.0),
    vec2(0.0, 0.0), vec2(1.0, 1.0), vec2(0.0, 1.0));
  gl_Position = vec4(mix(lo, hi, quad[corner]), 0.0, 1.0);
}
)";

// Eqs. 12 and 13 at the G-buffer's point, accumulated as (w alpha, w).
const char* const SplatFS = R"(//VTK::System::Dec
//VTK::Output::Dec
uniform sampler2D gPosition;
uniform sampler2D gNormal;
flat in vec4 splatCentre;
flat in vec4 splatNormal;
flat in vec3 splatCoefficient;
void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 position = texelFetch(gPosition, pixel, 0);
  vec4 normal = texelFetch(gNormal, pixel, 0);
  if (position.w < 0.5 || (normal.w >= 0.0 && abs(normal.w - splatNormal.w) > 0.5))
  {
    discard;
  }
  float c = dot(normal.xyz, splatNormal.xyz);
  float r = length(position.xyz - splatCentre.xyz) / splatCentre.w;
  if (!(c > 0.0) || !(r < 1.0))
  {
    discard;
  }
  float w = ((2.0 * r - 3.0) * r * r + 1.0) * c;
  gl_FragData[0] = vec4(w * splatCoefficient, w);
}
)";

// Eq. 8: the level's normalised interpolation, added to the irradiance.
const char* const NormaliseFS = R"(//VTK::System::Dec
//VTK::Output::Dec
in vec2 texCoord;
uniform sampler2D levelSums;
void main()
{
  vec4 sums = texelFetch(levelSums, ivec2(texCoord * vec2(textureSize(levelSums, 0))), 0);
  if (!(sums.a > 0.0))
  {
    discard;
  }
  gl_FragData[0] = vec4(sums.rgb / sums.a, 1.0);
}
)";

// Pass 3: L = (Emission + Reflectance E) / pi * Exposure, with the surface's
// depth.
const char* const CompositeFS = R"(//VTK::System::Dec
//VTK::Output::Dec
in vec2 texCoord;
uniform sampler2D gReflectance;
uniform sampler2D gEmission;
uniform sampler2D gDepth;
uniform sampler2D irradiance;
uniform float radianceScale;
uniform float inverseGamma;
void main()
{
  ivec2 pixel = ivec2(texCoord * vec2(textureSize(gReflectance, 0)));
  vec4 reflectance = texelFetch(gReflectance, pixel, 0);
  if (reflectance.w < 0.5)
  {
    discard;
  }
  vec3 e = texelFetch(irradiance, pixel, 0).rgb;
  vec3 radiance = (texelFetch(gEmission, pixel, 0).rgb + reflectance.rgb * e) * radianceScale;
  gl_FragData[0] = vec4(pow(max(radiance, vec3(0.0)), vec3(inverseGamma)), 1.0);
  gl_FragDepth = texelFetch(gDepth, pixel, 0).r;
}
)";

std::string DescribeCell(vtkPolyData* input, vtkIdType cellId)
{
  std::ostringstream os;
  const char* type = vtkCellTypes::GetClassNameFromTypeId(input->GetCellType(cellId));
  os << "Input cell " << cellId << " is a " << (type ? type : "cell of unknown type")
     << ": vtkShepardSplatMapper draws polygons only (the surfaces the field lies on).";
  return os.str();
}

// The field array `name` with `components` components and a tuple per point,
// or null with `message` set.
vtkDataArray* FieldArray(vtkPolyData* field, const char* name, int components, std::string& message)
{
  vtkPointData* pd = field->GetPointData();
  vtkDataArray* array = pd->GetArray(name);
  std::ostringstream os;
  if (!array)
  {
    os << (pd->GetAbstractArray(name) ? "Field point array '" : "Field has no point array '") << name
       << (pd->GetAbstractArray(name) ? "' is not numeric." : "' (vtkMeshlessFieldFilter's output expected).");
  }
  else if (array->GetNumberOfComponents() != components)
  {
    os << "Field point array '" << name << "' has " << array->GetNumberOfComponents()
       << " components, " << components << " expected.";
  }
  else if (array->GetNumberOfTuples() < field->GetNumberOfPoints())
  {
    os << "Field point array '" << name << "' has " << array->GetNumberOfTuples()
       << " tuples for " << field->GetNumberOfPoints() << " points.";
  }
  else
  {
    return array;
  }
  message = os.str();
  return nullptr;
}
}

//------------------------------------------------------------------------------
struct vtkShepardSplatMapper::GraphicsResources
{
  vtkNew<vtkOpenGLFramebufferObject> Framebuffer;
  // The G-buffer (position and coverage, normal and group, reflectance and
  // coverage, emission), then the level's sums and the irradiance.
  vtkNew<vtkTextureObject> Position;
  vtkNew<vtkTextureObject> Normal;
  vtkNew<vtkTextureObject> Reflectance;
  vtkNew<vtkTextureObject> Emission;
  vtkNew<vtkTextureObject> LevelSums;
  vtkNew<vtkTextureObject> Irradiance;
  vtkNew<vtkTextureObject> Depth;
  vtkNew<vtkOpenGLVertexArrayObject> SplatArrays; // none: an empty VAO
  std::unique_ptr<vtkOpenGLQuadHelper> Normalise;
  std::unique_ptr<vtkOpenGLQuadHelper> Composite;
  int Width = 0;
  int Height = 0;

  std::array<vtkTextureObject*, 6> ColourTargets()
  {
    return { this->Position, this->Normal, this->Reflectance, this->Emission, this->LevelSums,
      this->Irradiance };
  }

  bool Allocate(vtkOpenGLRenderWindow* window, int width, int height)
  {
    if (width == this->Width && height == this->Height && this->Position->GetHandle() != 0 &&
      this->Position->GetContext() == window)
    {
      return true;
    }
    this->Width = this->Height = 0;
    for (vtkTextureObject* target : this->ColourTargets())
    {
      target->ReleaseGraphicsResources(window);
      target->SetContext(window);
      target->SetInternalFormat(GL_RGBA32F);
      target->SetFormat(GL_RGBA);
      target->SetDataType(GL_FLOAT);
      target->SetMinificationFilter(vtkTextureObject::Nearest);
      target->SetMagnificationFilter(vtkTextureObject::Nearest);
      target->SetWrapS(vtkTextureObject::ClampToEdge);
      target->SetWrapT(vtkTextureObject::ClampToEdge);
      if (!target->Allocate2D(width, height, 4, VTK_FLOAT))
      {
        return false;
      }
    }
    this->Depth->ReleaseGraphicsResources(window);
    this->Depth->SetContext(window);
    if (!this->Depth->AllocateDepth(width, height, vtkTextureObject::Float32))
    {
      return false;
    }
    this->Framebuffer->SetContext(window);
    this->Width = width;
    this->Height = height;
    return true;
  }

  void Release(vtkWindow* window)
  {
    for (vtkTextureObject* target : this->ColourTargets())
    {
      target->ReleaseGraphicsResources(window);
    }
    this->Depth->ReleaseGraphicsResources(window);
    this->Framebuffer->ReleaseGraphicsResources(window);
    this->SplatArrays->ReleaseGraphicsResources();
    for (auto* quad : { &this->Normalise, &this->Composite })
    {
      if (*quad)
      {
        (*quad)->ReleaseGraphicsResources(window);
        quad->reset();
      }
    }
    this->Width = this->Height = 0;
  }
};

//------------------------------------------------------------------------------
vtkShepardSplatMapper::vtkShepardSplatMapper()
  : CellBuffer(new vtkRadiosityTexelBuffer)
  , PointBuffer(new vtkRadiosityTexelBuffer)
  , Resources(new GraphicsResources)
{
  this->SetNumberOfInputPorts(2);
  this->ScalarVisibilityOff();
  // The G-buffer holds model coordinates, as the field does.
  this->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
}

//------------------------------------------------------------------------------
vtkShepardSplatMapper::~vtkShepardSplatMapper() = default;

//------------------------------------------------------------------------------
int vtkShepardSplatMapper::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    // Optional for the pipeline, so that its absence gets this mapper's error.
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

//------------------------------------------------------------------------------
void vtkShepardSplatMapper::SetFieldConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
void vtkShepardSplatMapper::SetFieldData(vtkPolyData* field)
{
  this->SetInputDataInternal(1, field);
}

//------------------------------------------------------------------------------
vtkPolyData* vtkShepardSplatMapper::GetField()
{
  if (this->GetNumberOfInputConnections(1) < 1)
  {
    return nullptr;
  }
  return vtkPolyData::SafeDownCast(this->GetInputDataObject(1, 0));
}

//------------------------------------------------------------------------------
int vtkShepardSplatMapper::GetNumberOfLevels() const
{
  return this->LevelOffsets.empty() ? 0 : static_cast<int>(this->LevelOffsets.size()) - 1;
}

//------------------------------------------------------------------------------
bool vtkShepardSplatMapper::ValidateSurface(vtkPolyData* surface, std::string* message)
{
  std::string dummy;
  std::string& why = message ? *message : dummy;
  why.clear();
  if (!surface)
  {
    why = "No input polydata.";
    return false;
  }
  if (surface->GetNumberOfVerts() > 0 || surface->GetNumberOfLines() > 0)
  {
    why = DescribeCell(surface, 0);
    return false;
  }
  if (surface->GetNumberOfStrips() > 0)
  {
    why = DescribeCell(surface, surface->GetNumberOfPolys());
    return false;
  }
  return vtkRadiosityCellArrays::CheckOptional(surface, "Reflectance", 3, why) &&
    vtkRadiosityCellArrays::CheckOptional(surface, "Emission", 3, why) &&
    vtkRadiosityCellArrays::CheckOptional(surface, "ObjectId", 1, why);
}

//------------------------------------------------------------------------------
bool vtkShepardSplatMapper::ValidateField(vtkPolyData* field, std::string* message)
{
  std::string dummy;
  std::string& why = message ? *message : dummy;
  why.clear();
  if (!field)
  {
    why = "No field: connect vtkMeshlessFieldFilter's output with SetFieldConnection.";
    return false;
  }
  vtkDataArray* level = FieldArray(field, "Level", 1, why);
  vtkDataArray* radius = level ? FieldArray(field, "Radius", 1, why) : nullptr;
  vtkDataArray* normal = radius ? FieldArray(field, "Normal", 3, why) : nullptr;
  vtkDataArray* group = normal ? FieldArray(field, "Group", 1, why) : nullptr;
  vtkDataArray* coefficient = group ? FieldArray(field, "Coefficient", 3, why) : nullptr;
  if (!coefficient)
  {
    return false;
  }
  std::ostringstream os;
  for (vtkIdType i = 0; i < field->GetNumberOfPoints(); ++i)
  {
    const double l = level->GetComponent(i, 0);
    const double r = radius->GetComponent(i, 0);
    const double* alpha = coefficient->GetTuple3(i);
    if (!(l >= 0 && l < MaximumLevels && l == std::floor(l)))
    {
      os << "Field point " << i << " has Level " << l << ", an integer in [0, " << MaximumLevels
         << ") expected.";
    }
    else if (!(r > 0 && std::isfinite(r)))
    {
      os << "Field point " << i << " has Radius " << r << ", a finite positive value expected.";
    }
    else if (!(std::isfinite(alpha[0]) && std::isfinite(alpha[1]) && std::isfinite(alpha[2])))
    {
      os << "Field point " << i << " has a Coefficient that is not finite (" << alpha[0] << ", "
         << alpha[1] << ", " << alpha[2] << ").";
    }
    else
    {
      continue;
    }
    why = os.str();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkShepardSplatMapper::UpdateField()
{
  if (this->GetNumberOfInputConnections(1) > 0 && !this->Static)
  {
    this->GetExecutive()->GetInputExecutive(1, 0)->Update();
  }
  vtkPolyData* field = this->GetField();
  if (field && field == this->PointTexelsSource && field->GetMTime() == this->PointTexelsSourceTime)
  {
    return this->FieldError.empty();
  }
  this->PointTexelsSource = field;
  this->PointTexelsSourceTime = field ? field->GetMTime() : 0;
  this->LevelOffsets.clear();
  this->PointTexels.clear();
  if (!ValidateField(field, &this->FieldError))
  {
    vtkErrorMacro(<< this->FieldError);
    return false;
  }

  // Counting sort by level, so that a level is one contiguous draw.
  const vtkIdType n = field->GetNumberOfPoints();
  vtkPointData* pd = field->GetPointData();
  vtkDataArray* level = pd->GetArray("Level");
  vtkDataArray* radius = pd->GetArray("Radius");
  vtkDataArray* normal = pd->GetArray("Normal");
  vtkDataArray* group = pd->GetArray("Group");
  vtkDataArray* coefficient = pd->GetArray("Coefficient");
  int levels = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    levels = std::max(levels, static_cast<int>(level->GetComponent(i, 0)) + 1);
  }
  this->LevelOffsets.assign(levels + 1, 0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    ++this->LevelOffsets[static_cast<int>(level->GetComponent(i, 0)) + 1];
  }
  for (int l = 0; l < levels; ++l)
  {
    this->LevelOffsets[l + 1] += this->LevelOffsets[l];
  }
  std::vector<size_t> next(this->LevelOffsets.begin(), this->LevelOffsets.end() - 1);
  this->PointTexels.assign(static_cast<size_t>(n) * FloatsPerPoint, 0.0f);
  for (vtkIdType i = 0; i < n; ++i)
  {
    float* texel =
      this->PointTexels.data() + next[static_cast<int>(level->GetComponent(i, 0))]++ * FloatsPerPoint;
    double x[3], nj[3], alpha[3];
    field->GetPoint(i, x);
    normal->GetTuple(i, nj);
    coefficient->GetTuple(i, alpha);
    for (int c = 0; c < 3; ++c)
    {
      texel[c] = static_cast<float>(x[c]);
      texel[4 + c] = static_cast<float>(nj[c]);
      texel[8 + c] = static_cast<float>(alpha[c]);
    }
    texel[3] = static_cast<float>(radius->GetComponent(i, 0));
    texel[7] = static_cast<float>(group->GetComponent(i, 0));
  }
  this->PointTexelsTime.Modified();
  return true;
}

//------------------------------------------------------------------------------
void vtkShepardSplatMapper::UpdateCameraShiftScale(vtkRenderer* ren, vtkActor* actor)
{
  this->DrawPiece = false;
  vtkPolyData* input = this->CurrentInput;
  if (!input || input->GetNumberOfCells() == 0)
  {
    return;
  }
  if (input != this->CellTexelsSource || input->GetMTime() != this->CellTexelsSourceTime)
  {
    this->CellTexelsSource = input;
    this->CellTexelsSourceTime = input->GetMTime();
    this->SurfaceValid = ValidateSurface(input, &this->SurfaceError);
    if (!this->SurfaceValid)
    {
      vtkErrorMacro(<< this->SurfaceError);
      return;
    }
    vtkCellData* cd = input->GetCellData();
    vtkDataArray* reflectance = cd->GetArray("Reflectance");
    vtkDataArray* emission = cd->GetArray("Emission");
    vtkDataArray* objects = cd->GetArray("ObjectId");
    if (!reflectance && !this->WarnedNoReflectance)
    {
      vtkWarningMacro(<< "Input has no cell array 'Reflectance': drawn with reflectance 0.5.");
      this->WarnedNoReflectance = true;
    }
    const vtkIdType n = input->GetNumberOfCells();
    this->CellTexels.assign(static_cast<size_t>(n) * FloatsPerCell, 0.0f);
    vtkCellArray* polys = input->GetPolys();
    const vtkIdType* pts = nullptr;
    vtkIdType npts = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      // All cells are polys (ValidateSurface), so poly i is cell i.
      polys->GetCellAtId(i, npts, pts);
      double normal[3] = { 0.0, 0.0, 0.0 };
      vtkPolygon::ComputeNormal(input->GetPoints(), static_cast<int>(npts), pts, normal);
      float* texel = this->CellTexels.data() + static_cast<size_t>(i) * FloatsPerCell;
      for (int c = 0; c < 3; ++c)
      {
        texel[c] = static_cast<float>(reflectance ? reflectance->GetComponent(i, c) : 0.5);
        texel[4 + c] = static_cast<float>(emission ? emission->GetComponent(i, c) : 0.0);
        texel[8 + c] = static_cast<float>(normal[c]);
      }
      // Group -1: no ObjectId, every field point applies.
      texel[3] = objects ? static_cast<float>(objects->GetComponent(i, 0)) : -1.0f;
    }
    this->CellTexelsTime.Modified();
  }
  if (!this->SurfaceValid)
  {
    return;
  }
  this->DrawPiece = true;
  this->Superclass::UpdateCameraShiftScale(ren, actor);
}

//------------------------------------------------------------------------------
void vtkShepardSplatMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* actor)
{
  this->CellTexelsReady = false;
  if (!this->DrawPiece)
  {
    return;
  }
  this->Superclass::RenderPieceStart(ren, actor);
  const int representation = actor->GetProperty()->GetRepresentation();
  std::string error;
  this->CellTexelsReady = this->CellBuffer->IsCurrent(this->CellTexelsTime, representation) ||
    this->CellBuffer->UploadPerPrimitive(static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow()),
      this->CellCellMap, this->CurrentInput, representation, this->CellTexels, FloatsPerCell,
      "the surface's materials", error);
  if (!this->CellTexelsReady)
  {
    vtkErrorMacro(<< error);
    return;
  }
  this->CellBuffer->Activate();
}

//------------------------------------------------------------------------------
void vtkShepardSplatMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* actor)
{
  if (this->DrawPiece && this->CellTexelsReady)
  {
    this->Superclass::RenderPieceDraw(ren, actor);
  }
}

//------------------------------------------------------------------------------
void vtkShepardSplatMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* actor)
{
  if (!this->DrawPiece)
  {
    return;
  }
  if (this->CellTexelsReady)
  {
    this->CellBuffer->Deactivate();
  }
  this->Superclass::RenderPieceFinish(ren, actor);
}

//------------------------------------------------------------------------------
void vtkShepardSplatMapper::RenderPiece(vtkRenderer* ren, vtkActor* actor)
{
  if (ren->GetSelector())
  {
    this->Superclass::RenderPiece(ren, actor);
    return;
  }
  if (!this->UpdateField())
  {
    return;
  }
  auto* window = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();
  int viewport[4];
  state->vtkglGetIntegerv(GL_VIEWPORT, viewport);
  if (viewport[2] <= 0 || viewport[3] <= 0)
  {
    return;
  }
  GraphicsResources& r = *this->Resources;
  if (!r.Allocate(window, viewport[2], viewport[3]))
  {
    vtkErrorMacro(<< "Cannot allocate the G-buffer (" << viewport[2] << " x " << viewport[3]
                  << " RGBA32F targets).");
    return;
  }

  bool drawn = false;
  state->PushFramebufferBindings();
  r.Framebuffer->Bind();
  {
    vtkOpenGLState::ScopedglViewport viewportSaver(state);
    vtkOpenGLState::ScopedglClearColor clearSaver(state);
    vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
    vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(state);
    vtkOpenGLState::ScopedglEnableDisable scissorSaver(state, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);

    // Pass 1: the G-buffer.
    r.Framebuffer->AddColorAttachment(0, r.Position);
    r.Framebuffer->AddColorAttachment(1, r.Normal);
    r.Framebuffer->AddColorAttachment(2, r.Reflectance);
    r.Framebuffer->AddColorAttachment(3, r.Emission);
    r.Framebuffer->AddDepthAttachment(r.Depth);
    r.Framebuffer->ActivateDrawBuffers(4);
    state->vtkglViewport(0, 0, r.Width, r.Height);
    state->vtkglDisable(GL_SCISSOR_TEST);
    state->vtkglDisable(GL_BLEND);
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    state->vtkglClearDepth(1.0);
    state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    this->Superclass::RenderPiece(ren, actor);
    drawn = this->DrawPiece && this->CellTexelsReady;
    r.Framebuffer->RemoveColorAttachments(4);
    r.Framebuffer->RemoveDepthAttachment();

    // Pass 2: the splats.
    drawn = drawn && this->Splat(ren, actor);
  }
  state->PopFramebufferBindings();

  // Pass 3: into the renderer's framebuffer.
  if (drawn)
  {
    this->Composite(ren);
  }
  vtkOpenGLCheckErrorMacro("failed after splatting the Shepard field");
}

//------------------------------------------------------------------------------
bool vtkShepardSplatMapper::Splat(vtkRenderer* ren, vtkActor* actor)
{
  auto* window = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();
  GraphicsResources& r = *this->Resources;

  r.Framebuffer->AddColorAttachment(0, r.Irradiance);
  r.Framebuffer->ActivateDrawBuffers(1);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  if (this->PointTexels.empty())
  {
    r.Framebuffer->RemoveColorAttachments(1);
    return true; // no basis functions: zero irradiance
  }
  std::string error;
  if (!this->PointBuffer->IsCurrent(this->PointTexelsTime, -1) &&
    !this->PointBuffer->Upload(window, this->PointTexels, "the Shepard field's points", error))
  {
    vtkErrorMacro(<< error);
    r.Framebuffer->RemoveColorAttachments(1);
    return false;
  }

  // Model to clip coordinates, as vtkOpenGLPolyDataMapper forms MCDCMatrix.
  vtkMatrix4x4* wcvc = nullptr;
  vtkMatrix4x4* vcdc = nullptr;
  vtkMatrix4x4* wcdc = nullptr;
  vtkMatrix3x3* normals = nullptr;
  static_cast<vtkOpenGLCamera*>(ren->GetActiveCamera())
    ->GetKeyMatrices(ren, wcvc, normals, vcdc, wcdc);
  vtkNew<vtkMatrix4x4> mcdc;
  mcdc->DeepCopy(wcdc);
  if (!actor->GetIsIdentity())
  {
    vtkMatrix4x4* mcwc = nullptr;
    vtkMatrix3x3* actorNormals = nullptr;
    static_cast<vtkOpenGLActor*>(actor)->GetKeyMatrices(mcwc, actorNormals);
    vtkMatrix4x4::Multiply4x4(mcwc, wcdc, mcdc);
  }

  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  state->vtkglBlendEquation(GL_FUNC_ADD);
  r.Position->Activate();
  r.Normal->Activate();
  this->PointBuffer->Activate();
  bool ok = true;
  vtkOpenGLShaderCache* cache = window->GetShaderCache();
  for (int level = 0; ok && level + 1 < static_cast<int>(this->LevelOffsets.size()); ++level)
  {
    const size_t first = this->LevelOffsets[level];
    const size_t count = this->LevelOffsets[level + 1] - first;
    if (count == 0)
    {
      continue;
    }
    r.Framebuffer->AddColorAttachment(0, r.LevelSums);
    state->vtkglClear(GL_COLOR_BUFFER_BIT);
    vtkShaderProgram* splat = cache->ReadyShaderProgram(SplatVS, SplatFS, "");
    if (!splat || !splat->GetCompiled())
    {
      vtkErrorMacro(<< "Cannot build the splat shader program.");
      ok = false;
      break;
    }
    splat->SetUniformi("splatPoints", this->PointBuffer->GetTextureUnit());
    splat->SetUniformi("gPosition", r.Position->GetTextureUnit());
    splat->SetUniformi("gNormal", r.Normal->GetTextureUnit());
    splat->SetUniformi("firstPoint", static_cast<int>(first));
    splat->SetUniformMatrix("MCDCMatrix", mcdc);
    r.SplatArrays->Bind();
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(6 * count));
    r.SplatArrays->Release();

    r.Framebuffer->AddColorAttachment(0, r.Irradiance);
    if (!r.Normalise)
    {
      r.Normalise.reset(new vtkOpenGLQuadHelper(window, nullptr, NormaliseFS, ""));
    }
    else
    {
      cache->ReadyShaderProgram(r.Normalise->Program);
    }
    if (!r.Normalise->Program || !r.Normalise->Program->GetCompiled())
    {
      vtkErrorMacro(<< "Cannot build the normalisation shader program.");
      ok = false;
      break;
    }
    r.LevelSums->Activate();
    r.Normalise->Program->SetUniformi("levelSums", r.LevelSums->GetTextureUnit());
    r.Normalise->Render();
    r.LevelSums->Deactivate();
  }
  this->PointBuffer->Deactivate();
  r.Normal->Deactivate();
  r.Position->Deactivate();
  r.Framebuffer->RemoveColorAttachments(1);
  return ok;
}

//------------------------------------------------------------------------------
bool vtkShepardSplatMapper::Composite(vtkRenderer* ren)
{
  auto* window = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();
  GraphicsResources& r = *this->Resources;
  if (!r.Composite)
  {
    r.Composite.reset(new vtkOpenGLQuadHelper(window, nullptr, CompositeFS, ""));
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(r.Composite->Program);
  }
  vtkShaderProgram* program = r.Composite->Program;
  if (!program || !program->GetCompiled())
  {
    vtkErrorMacro(<< "Cannot build the composite shader program.");
    return false;
  }
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(state);
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LEQUAL);
  state->vtkglDepthMask(GL_TRUE);

  vtkTextureObject* inputs[4] = { r.Reflectance, r.Emission, r.Depth, r.Irradiance };
  const char* names[4] = { "gReflectance", "gEmission", "gDepth", "irradiance" };
  for (int i = 0; i < 4; ++i)
  {
    inputs[i]->Activate();
    program->SetUniformi(names[i], inputs[i]->GetTextureUnit());
  }
  // Lambertian surfaces: L = B / pi.
  program->SetUniformf("radianceScale", static_cast<float>(this->Exposure / vtkMath::Pi()));
  program->SetUniformf("inverseGamma", static_cast<float>(1.0 / this->Gamma));
  r.Composite->Render();
  for (vtkTextureObject* input : inputs)
  {
    input->Deactivate();
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkShepardSplatMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor)
{
  // The model-coordinate position of the fragment, for the G-buffer.
  vtkRadiosityAddVarying(shaders, "vec3", "splatPositionMC", "", "vertexMC.xyz",
    "uniform samplerBuffer splatCellTexels;\n");
  this->Superclass::ReplaceShaderValues(shaders, ren, actor);
}

//------------------------------------------------------------------------------
void vtkShepardSplatMapper::ReplaceShaderLight(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor)
{
  if (this->DrawingVertices)
  {
    this->Superclass::ReplaceShaderLight(shaders, ren, actor);
    return;
  }
  std::string FSSource = shaders[vtkShader::Fragment]->GetSource();
  vtkShaderProgram::Substitute(FSSource, "//VTK::Light::Impl",
    // Three texels per OpenGL primitive: (Reflectance, group), (Emission, 0),
    // (normal, 0).
    "  int splatCell = 3 * (gl_PrimitiveID + PrimitiveIDOffset);\n"
    "  vec4 cell0 = texelFetchBuffer(splatCellTexels, splatCell);\n"
    "  vec4 cell1 = texelFetchBuffer(splatCellTexels, splatCell + 1);\n"
    "  vec4 cell2 = texelFetchBuffer(splatCellTexels, splatCell + 2);\n"
    // Alpha 1 in target 0: VTK's shader discards fragments of alpha 0.
    "  gl_FragData[0] = vec4(splatPositionMCVSOutput, 1.0);\n"
    "  gl_FragData[1] = vec4(cell2.xyz, cell0.w);\n"
    "  gl_FragData[2] = vec4(cell0.xyz, 1.0);\n"
    "  gl_FragData[3] = vec4(cell1.xyz, 1.0);\n");
  shaders[vtkShader::Fragment]->SetSource(FSSource);
}

//------------------------------------------------------------------------------
void vtkShepardSplatMapper::ReplaceShaderTCoord(
  std::map<vtkShader::Type, vtkShader*>, vtkRenderer*, vtkActor*)
{
}

//------------------------------------------------------------------------------
void vtkShepardSplatMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, actor);
  if (this->CellTexelsReady && cellBO.Program->IsUniformUsed("splatCellTexels"))
  {
    cellBO.Program->SetUniformi("splatCellTexels", this->CellBuffer->GetTextureUnit());
  }
}

//------------------------------------------------------------------------------
void vtkShepardSplatMapper::SetLightingShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  if (this->DrawingVertices)
  {
    this->Superclass::SetLightingShaderParameters(cellBO, ren, actor);
  }
}

//------------------------------------------------------------------------------
void vtkShepardSplatMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  this->CellBuffer->ReleaseGraphicsResources(win);
  this->PointBuffer->ReleaseGraphicsResources(win);
  this->Resources->Release(win);
  this->CellTexelsReady = false;
  this->Superclass::ReleaseGraphicsResources(win);
}

//------------------------------------------------------------------------------
void vtkShepardSplatMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "Gamma: " << this->Gamma << "\n";
  os << indent << "Field: " << this->GetField() << "\n";
  os << indent << "NumberOfLevels: " << this->GetNumberOfLevels() << "\n";
  os << indent << "FieldPoints: " << this->PointTexels.size() / FloatsPerPoint << "\n";
  if (!this->FieldError.empty())
  {
    os << indent << "FieldError: " << this->FieldError << "\n";
  }
  os << indent << "SurfaceValid: " << (this->SurfaceValid ? "true" : "false") << "\n";
  if (!this->SurfaceValid && !this->SurfaceError.empty())
  {
    os << indent << "SurfaceError: " << this->SurfaceError << "\n";
  }
  os << indent << "SurfaceCells: " << this->CellTexels.size() / FloatsPerCell << "\n";
  os << indent << "G-buffer: " << this->Resources->Width << " x " << this->Resources->Height
     << "\n";
  os << indent << "CellBuffer:\n";
  this->CellBuffer->PrintSelf(os, indent.GetNextIndent());
  os << indent << "PointBuffer:\n";
  this->PointBuffer->PrintSelf(os, indent.GetNextIndent());
  os << indent << "WarnedNoReflectance: " << (this->WarnedNoReflectance ? "true" : "false")
     << "\n";
}
