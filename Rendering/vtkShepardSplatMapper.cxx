#include "vtkShepardSplatMapper.h"

#include "vtkActor.h"
#include "vtkAlgorithmOutput.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
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
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
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
#include "vtkShepardSplatNodes.h"
#include "vtkShepardSplatPasses.h"
#include "vtkShepardSplatSurfaceTexels.h"
#include "vtk_glew.h"

#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkShepardSplatMapper);

namespace
{
// (Reflectance, group), (Emission, 0), (normal, 0), then the node grid's
// frame of vtkShepardSplatSurfaceTexels (SURFACE_TEXELS).
constexpr int FloatsPerCell = 24;
constexpr int FrameOffset = 12;
constexpr int FloatsPerPoint = 12;
constexpr int MaximumLevels = 64;


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
       << (pd->GetAbstractArray(name) ? "' is not numeric." : "' (port 1 of vtkRadiosityFilter with Method Meshless expected).");
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
vtkShepardSplatMapper::vtkShepardSplatMapper()
  : vtkRadiosityCellTexelMapper("splatCellTexels", FloatsPerCell, "the surface's materials")
  , NodeBuffer(new vtkRadiosityTexelBuffer)
  , PointBuffer(new vtkRadiosityTexelBuffer)
  , Passes(new vtkShepardSplatPasses)
  , CullingNodes(new vtkShepardSplatNodes)
  , BoxBuffer(new vtkRadiosityTexelBuffer)
{
  this->SetNumberOfInputPorts(2);
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
vtkIdType vtkShepardSplatMapper::GetNumberOfCullingNodes() const
{
  return static_cast<vtkIdType>(this->CullingNodes->GetNodes().size());
}

//------------------------------------------------------------------------------
bool vtkShepardSplatMapper::ValidateSurface(vtkPolyData* surface, std::string* message)
{
  vtkRadiosityCellArrays::Reason reason(message);
  std::string& why = reason.Text;
  return vtkRadiosityCellArrays::CheckPolygons(surface, false,
           ": vtkShepardSplatMapper draws polygons only (the surfaces the field lies on).", why) &&
    vtkRadiosityCellArrays::CheckOptional(surface, "Reflectance", 3, why) &&
    vtkRadiosityCellArrays::CheckOptional(surface, "Emission", 3, why) &&
    vtkRadiosityCellArrays::CheckOptional(surface, "ObjectId", 1, why);
}

//------------------------------------------------------------------------------
bool vtkShepardSplatMapper::ValidateField(vtkPolyData* field, std::string* message)
{
  vtkRadiosityCellArrays::Reason reason(message);
  std::string& why = reason.Text;
  if (!field)
  {
    why = "No field: connect port 1 of vtkRadiosityFilter (Method Meshless) with SetFieldConnection.";
    return false;
  }
  if (field->GetNumberOfPoints() == 0)
  {
    // Nothing to splat: the surface shows its emission alone.
    return true;
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
  // Neighbours next to each other, for the culling nodes' runs.
  vtkShepardSplatNodes::SortLevels(this->PointTexels, FloatsPerPoint, this->LevelOffsets);
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
    this->NodesReady = false;
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
  if (this->Evaluation == SURFACE_TEXELS &&
    (!this->NodesReady || this->NodesFieldTime != this->PointTexelsTime.GetMTime() ||
      this->NodesCellTime != this->CellTexelsSourceTime || this->NodesSpacing != this->TexelSpacing ||
      this->NodesMaximum != this->MaximumTexels))
  {
    // Once per field and surface: E at the nodes of every polygon's grid.
    this->TexelSpacingUsed = vtkShepardSplatSurfaceTexels::Evaluate(input, this->PointTexels,
      this->LevelOffsets, this->TexelSpacing, static_cast<size_t>(this->MaximumTexels),
      this->CellTexels, FloatsPerCell, FrameOffset, this->Nodes);
    this->NodesFieldTime = this->PointTexelsTime.GetMTime();
    this->NodesCellTime = this->CellTexelsSourceTime;
    this->NodesSpacing = this->TexelSpacing;
    this->NodesMaximum = this->MaximumTexels;
    this->NodesReady = true;
    this->NodesTime.Modified();
    if (this->TexelSpacingUsed < 0.0)
    {
      vtkErrorMacro(<< "SURFACE_TEXELS: " << input->GetNumberOfCells()
                    << " polygons need more than 2^24 texels at four each; use SPLATS.");
    }
    this->CellTexelsTime.Modified();
  }
  if (this->Evaluation == SURFACE_TEXELS && this->TexelSpacingUsed < 0.0)
  {
    return; // refused above, once
  }
  this->DrawPiece = true;
  this->DrawnPolyData = input;
  this->Superclass::UpdateCameraShiftScale(ren, actor);
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
  if (this->Evaluation == SURFACE_TEXELS)
  {
    // One pass over the surface into the renderer's framebuffer; the nodes
    // are (re)evaluated in UpdateCameraShiftScale and bound in
    // RenderPieceStart.
    this->Superclass::RenderPiece(ren, actor);
    vtkOpenGLCheckErrorMacro("failed after drawing the Shepard field's surface texels");
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
  vtkShepardSplatPasses& passes = *this->Passes;
  if (!passes.Allocate(window, viewport[2], viewport[3]))
  {
    vtkErrorMacro(<< "Cannot allocate the G-buffer (" << viewport[2] << " x " << viewport[3]
                  << " RGBA32F targets).");
    return;
  }
  std::string error;
  if (!this->PointTexels.empty() && !this->PointBuffer->IsCurrent(this->PointTexelsTime, -1) &&
    !this->PointBuffer->Upload(window, this->PointTexels, "the Shepard field's points", error))
  {
    vtkErrorMacro(<< error);
    return;
  }

  vtkShepardSplatPasses::Culling culling;
  if (this->Culling && !this->PointTexels.empty())
  {
    vtkShepardSplatNodes& nodes = *this->CullingNodes;
    if (this->CullingNodesTime < this->PointTexelsTime ||
      nodes.GetPointsPerNode() != this->PointsPerNode)
    {
      nodes.Build(this->PointTexels, FloatsPerPoint, this->LevelOffsets, this->PointsPerNode);
      this->CullingNodesTime.Modified();
    }
    culling.Nodes = &nodes;
    if (this->OcclusionQueries)
    {
      if (!this->BoxBuffer->IsCurrent(this->CullingNodesTime, -1) &&
        !this->BoxBuffer->Upload(window, nodes.GetBoxTexels(), "the Shepard field's node boxes", error))
      {
        vtkErrorMacro(<< error);
        return;
      }
      culling.Boxes = this->BoxBuffer.get();
    }
  }

  bool drawn = false;
  state->PushFramebufferBindings();
  passes.GetFramebuffer()->Bind();
  {
    vtkOpenGLState::ScopedglViewport viewportSaver(state);
    vtkOpenGLState::ScopedglClearColor clearSaver(state);
    vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
    vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(state);
    vtkOpenGLState::ScopedglEnableDisable scissorSaver(state, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);

    // Pass 1: the surface into the G-buffer.
    passes.BeginGBuffer(state);
    this->Superclass::RenderPiece(ren, actor);
    drawn = this->DrawPiece && this->CellTexelsReady;
    passes.EndGBuffer();

    // Pass 2: the splats.
    if (drawn)
    {
      vtkNew<vtkMatrix4x4> modelToClip;
      this->ModelToClip(ren, actor, modelToClip);
      drawn = passes.Splat(window, modelToClip,
        this->PointTexels.empty() ? nullptr : this->PointBuffer.get(), this->LevelOffsets, culling,
        error);
      this->SplattedPoints = static_cast<vtkIdType>(culling.Splatted);
      this->FrustumCulledPoints = static_cast<vtkIdType>(culling.FrustumCulled);
      this->OcclusionCulledPoints = static_cast<vtkIdType>(culling.OcclusionCulled);
      this->OcclusionQueryCount = static_cast<vtkIdType>(culling.Queries);
    }
  }
  state->PopFramebufferBindings();

  // Pass 3: into the renderer's framebuffer.
  if (drawn)
  {
    drawn = passes.Composite(window, this->Exposure, this->Gamma, this->ToneMapping, error);
  }
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
  }
  vtkOpenGLCheckErrorMacro("failed after splatting the Shepard field");
}

//------------------------------------------------------------------------------
void vtkShepardSplatMapper::ModelToClip(vtkRenderer* ren, vtkActor* actor, vtkMatrix4x4* out)
{
  // As vtkOpenGLPolyDataMapper forms MCDCMatrix (the key matrices are
  // transposed for OpenGL).
  vtkMatrix4x4* wcvc = nullptr;
  vtkMatrix4x4* vcdc = nullptr;
  vtkMatrix4x4* wcdc = nullptr;
  vtkMatrix3x3* normals = nullptr;
  static_cast<vtkOpenGLCamera*>(ren->GetActiveCamera())
    ->GetKeyMatrices(ren, wcvc, normals, vcdc, wcdc);
  out->DeepCopy(wcdc);
  if (!actor->GetIsIdentity())
  {
    vtkMatrix4x4* mcwc = nullptr;
    vtkMatrix3x3* actorNormals = nullptr;
    static_cast<vtkOpenGLActor*>(actor)->GetKeyMatrices(mcwc, actorNormals);
    vtkMatrix4x4::Multiply4x4(mcwc, wcdc, out);
  }
}

//------------------------------------------------------------------------------
void vtkShepardSplatMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor)
{
  // The model-coordinate position of the fragment, for the G-buffer.
  vtkRadiosityAddVarying(shaders, "vec3", "splatPositionMC", ModelPositionDeclarations(), ModelPosition(),
    std::string("uniform samplerBuffer splatCellTexels;\nuniform samplerBuffer splatNodes;\n") +
      (this->Evaluation == SURFACE_TEXELS ? RadianceUniforms() : std::string()));
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
  if (this->Evaluation == SURFACE_TEXELS)
  {
    vtkShaderProgram::Substitute(FSSource, "//VTK::Light::Impl",
      // The cell's grid: node (i, j) at texel first + j * rowLength + i, at
      // origin + i * ds * A + j * dt * B; frame texels hold (origin, first),
      // (A / ds, rowLength), (B / dt, rows). Bilinear between four nodes.
      "  int splatCell = " + this->CellTexelIndex() + ";\n"
      "  vec4 cell0 = texelFetchBuffer(splatCellTexels, splatCell);\n"
      "  vec4 cell1 = texelFetchBuffer(splatCellTexels, splatCell + 1);\n"
      "  vec4 frame0 = texelFetchBuffer(splatCellTexels, splatCell + 3);\n"
      "  vec4 frame1 = texelFetchBuffer(splatCellTexels, splatCell + 4);\n"
      "  vec4 frame2 = texelFetchBuffer(splatCellTexels, splatCell + 5);\n"
      "  vec3 d = splatPositionMCVSOutput - frame0.xyz;\n"
      "  vec2 cells = vec2(frame1.w, frame2.w) - vec2(1.0);\n"
      "  vec2 st = clamp(vec2(dot(d, frame1.xyz), dot(d, frame2.xyz)), vec2(0.0), cells);\n"
      "  vec2 ij = min(floor(st), cells - vec2(1.0));\n"
      "  vec2 f = st - ij;\n"
      "  int row = int(frame1.w);\n"
      "  int node = int(frame0.w) + int(ij.y) * row + int(ij.x);\n"
      "  vec3 e = mix(mix(texelFetchBuffer(splatNodes, node).rgb,\n"
      "                   texelFetchBuffer(splatNodes, node + 1).rgb, f.x),\n"
      "               mix(texelFetchBuffer(splatNodes, node + row).rgb,\n"
      "                   texelFetchBuffer(splatNodes, node + row + 1).rgb, f.x), f.y);\n"
      "  gl_FragData[0] = vec4(" + EncodedRadiance("cell1.xyz + cell0.xyz * e") + ", 1.0);\n");
    shaders[vtkShader::Fragment]->SetSource(FSSource);
    return;
  }
  vtkShaderProgram::Substitute(FSSource, "//VTK::Light::Impl",
    // Three texels per OpenGL primitive: (Reflectance, group), (Emission, 0),
    // (normal, 0).
    "  int splatCell = " + this->CellTexelIndex() + ";\n"
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
void vtkShepardSplatMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* actor)
{
  this->Superclass::RenderPieceStart(ren, actor);
  this->NodesActive = false;
  if (this->Evaluation != SURFACE_TEXELS || !this->CellTexelsReady || !this->NodesReady ||
    ren->GetSelector())
  {
    return;
  }
  std::string error;
  if (!this->NodeBuffer->IsCurrent(this->NodesTime, -1) &&
    !this->NodeBuffer->Upload(static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow()),
      this->Nodes, "the Shepard field's surface texels", error))
  {
    vtkErrorMacro(<< error);
    this->CellTexelsReady = false; // nothing drawn
    return;
  }
  this->NodeBuffer->Activate();
  this->NodesActive = true;
}

//------------------------------------------------------------------------------
void vtkShepardSplatMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* actor)
{
  if (this->NodesActive)
  {
    this->NodeBuffer->Deactivate();
    this->NodesActive = false;
  }
  this->Superclass::RenderPieceFinish(ren, actor);
}

//------------------------------------------------------------------------------
void vtkShepardSplatMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, actor);
  if (this->NodesActive && cellBO.Program->IsUniformUsed("splatNodes"))
  {
    cellBO.Program->SetUniformi("splatNodes", this->NodeBuffer->GetTextureUnit());
  }
}

//------------------------------------------------------------------------------
void vtkShepardSplatMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  this->NodeBuffer->ReleaseGraphicsResources(win);
  this->PointBuffer->ReleaseGraphicsResources(win);
  this->BoxBuffer->ReleaseGraphicsResources(win);
  this->Passes->ReleaseGraphicsResources(win);
  this->Superclass::ReleaseGraphicsResources(win);
}

//------------------------------------------------------------------------------
void vtkShepardSplatMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Field: " << this->GetField() << "\n";
  os << indent << "NumberOfLevels: " << this->GetNumberOfLevels() << "\n";
  os << indent << "FieldPoints: " << this->PointTexels.size() / FloatsPerPoint << "\n";
  if (!this->FieldError.empty())
  {
    os << indent << "FieldError: " << this->FieldError << "\n";
  }
  os << indent << "Evaluation: " << (this->Evaluation == SPLATS ? "SPLATS" : "SURFACE_TEXELS")
     << "\n";
  os << indent << "TexelSpacing: " << this->TexelSpacing << "\n";
  os << indent << "MaximumTexels: " << this->MaximumTexels << "\n";
  os << indent << "TexelSpacingUsed: " << this->TexelSpacingUsed << "\n";
  os << indent << "NumberOfTexels: " << this->GetNumberOfTexels() << "\n";
  os << indent << "Culling: " << (this->Culling ? "On" : "Off") << "\n";
  os << indent << "OcclusionQueries: " << (this->OcclusionQueries ? "On" : "Off") << "\n";
  os << indent << "PointsPerNode: " << this->PointsPerNode << "\n";
  os << indent << "NumberOfCullingNodes: " << this->GetNumberOfCullingNodes() << "\n";
  os << indent << "NumberOfSplattedPoints: " << this->SplattedPoints << "\n";
  os << indent << "NumberOfFrustumCulledPoints: " << this->FrustumCulledPoints << "\n";
  os << indent << "NumberOfOcclusionCulledPoints: " << this->OcclusionCulledPoints << "\n";
  os << indent << "NumberOfOcclusionQueries: " << this->OcclusionQueryCount << "\n";
  os << indent << "SurfaceValid: " << (this->SurfaceValid ? "true" : "false") << "\n";
  if (!this->SurfaceValid && !this->SurfaceError.empty())
  {
    os << indent << "SurfaceError: " << this->SurfaceError << "\n";
  }
  os << indent << "Passes:\n";
  this->Passes->PrintSelf(os, indent.GetNextIndent());
  os << indent << "PointBuffer:\n";
  this->PointBuffer->PrintSelf(os, indent.GetNextIndent());
  os << indent << "WarnedNoReflectance: " << (this->WarnedNoReflectance ? "true" : "false")
     << "\n";
}
