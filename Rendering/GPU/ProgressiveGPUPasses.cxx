#include "ProgressiveGPUPasses.h"

#include "ProgressiveGPUShaders.h"
#include "Radiosity/Common/Scene.h"
#include "vtkAutoInit.h"
#include "vtkNew.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkRadiosityView.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>

// The OpenGL render window comes from RenderingOpenGL2's object factory,
// which a library must register itself (an executable's autoinit may not name it).
VTK_MODULE_INIT(vtkRenderingOpenGL2);

namespace radiosity
{
namespace
{
vtkSmartPointer<vtkTextureObject> FloatTexture(vtkOpenGLRenderWindow* window, int width, int height,
  const std::vector<float>* data)
{
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(window);
  texture->SetInternalFormat(GL_RGBA32F);
  texture->SetFormat(GL_RGBA);
  texture->SetDataType(GL_FLOAT);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  const bool ok = data
    ? texture->Create2DFromRaw(width, height, 4, VTK_FLOAT, const_cast<float*>(data->data()))
    : texture->Allocate2D(width, height, 4, VTK_FLOAT);
  return ok ? texture : nullptr;
}

/// Binds `fbo` and draws into its first `count` colour attachments. The
/// draw buffers are set by OpenGL directly: vtkOpenGLState's cache of them
/// is shared by every framebuffer and left a second one writing its first
/// attachment alone.
void DrawTo(vtkOpenGLFramebufferObject* fbo, int count)
{
  fbo->Bind();
  GLenum buffers[8];
  for (int k = 0; k < count; ++k)
  {
    buffers[k] = GL_COLOR_ATTACHMENT0 + k;
  }
  glDrawBuffers(count, buffers);
}

void Uniform3(vtkShaderProgram* program, const char* name, const std::array<float, 3>& v)
{
  program->SetUniform3f(name, v.data());
}
} // namespace

struct ProgressiveGPUPasses::Internals
{
  vtkSmartPointer<vtkOpenGLRenderWindow> Window;
  std::string Renderer;
  int MaxTexture = 0;
  int AtlasWidth = 0, AtlasHeight = 0;
  std::size_t ElementCount = 0;
  int NodeWidth = 0;
  std::size_t NodeCount = 0;
  int Hemicube = 0;
  std::size_t TriangleCount = 0;
  bool ItemCleared = false;
  // Element atlas: inputs, then the five targets (corner 0-2, centre, unshot).
  vtkSmartPointer<vtkTextureObject> Centre, Corner[3], CentreLo, CornerLo[3], Normal, Reflectance;
  vtkSmartPointer<vtkTextureObject> Target[5];
  vtkSmartPointer<vtkTextureObject> Delta[4], Flag; ///< one shot's irradiance; split flags
  vtkSmartPointer<vtkTextureObject> NodeRange, NodeReflectance, NodePower;
  vtkSmartPointer<vtkTextureObject> Item, ItemDepth, Pick, PickDepth;
  vtkNew<vtkOpenGLFramebufferObject> ElementFBO, DeltaFBO, FlagFBO, NodeFBO, ItemFBO, PickFBO;
  GLuint SplitQuery = 0;
  vtkNew<vtkOpenGLBufferObject> TriangleBuffer;
  vtkNew<vtkOpenGLVertexArrayObject> TriangleArrays, PointArrays;
  std::unique_ptr<vtkOpenGLQuadHelper> ShotQuad, CommitQuad, SplitQuad, NodeQuad;
  vtkShaderProgram* ItemProgram = nullptr;
  vtkShaderProgram* PickProgram = nullptr;

  vtkOpenGLState* State() { return this->Window->GetState(); }
};

ProgressiveGPUPasses::ProgressiveGPUPasses()
  : GL(new Internals)
{
  std::string why;
  if (!vtkRadiosityView::CanOpenWindow(why))
  {
    throw SceneError("progressive-gpu needs an OpenGL context and cannot open one: " + why +
      " (run under a display, e.g. xvfb-run, or choose --method progressive)");
  }
  vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::Take(vtkRenderWindow::New());
  this->GL->Window = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!this->GL->Window)
  {
    throw SceneError("progressive-gpu: VTK's render window is not an OpenGL one");
  }
  this->GL->Window->SetOffScreenRendering(1);
  this->GL->Window->SetSize(8, 8);
  // The context current now (a render pass solving in the middle of its
  // frame) is recorded here and made current again by the destructor.
  this->GL->Window->PushContext();
  this->GL->Window->Initialize();
  this->GL->Window->MakeCurrent();
  auto fail = [this](const std::string& message) {
    this->GL->Window->Finalize();
    this->GL->Window->PopContext();
    throw SceneError(message);
  };
  if (!this->GL->Window->IsCurrent())
  {
    fail("progressive-gpu: the offscreen OpenGL context could not be made current");
  }
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  this->GL->Renderer = renderer ? renderer : "unknown";
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &this->GL->MaxTexture);
  GLint drawBuffers = 0;
  glGetIntegerv(GL_MAX_DRAW_BUFFERS, &drawBuffers);
  if (drawBuffers < 5)
  {
    fail("progressive-gpu: the OpenGL context (" + this->GL->Renderer + ") has " +
      std::to_string(drawBuffers) + " draw buffers; the shot writes 5");
  }
}

ProgressiveGPUPasses::~ProgressiveGPUPasses()
{
  if (this->GL->Window)
  {
    this->GL->Window->MakeCurrent();
    this->GL->ShotQuad.reset();
    this->GL->CommitQuad.reset();
    this->GL->SplitQuad.reset();
    this->GL->NodeQuad.reset();
    if (this->GL->SplitQuery != 0)
    {
      glDeleteQueries(1, &this->GL->SplitQuery);
    }
    this->GL->TriangleArrays->ReleaseGraphicsResources();
    this->GL->PointArrays->ReleaseGraphicsResources();
    this->GL->TriangleBuffer->ReleaseGraphicsResources();
    for (vtkOpenGLFramebufferObject* fbo : { this->GL->ElementFBO.Get(), this->GL->DeltaFBO.Get(),
           this->GL->FlagFBO.Get(), this->GL->NodeFBO.Get(), this->GL->ItemFBO.Get(), this->GL->PickFBO.Get() })
    {
      fbo->ReleaseGraphicsResources(this->GL->Window);
    }
    this->GL->Window->Finalize();
    this->GL->Window->PopContext();
  }
}

const std::string& ProgressiveGPUPasses::Renderer() const
{
  return this->GL->Renderer;
}

int ProgressiveGPUPasses::MaxTextureSize() const
{
  return this->GL->MaxTexture;
}

bool ProgressiveGPUPasses::Prepare(const std::vector<float>& triangles, int hemicubeResolution, std::string& error)
{
  Internals& gl = *this->GL;
  vtkOpenGLRenderWindow* window = gl.Window;
  window->MakeCurrent();
  gl.Hemicube = hemicubeResolution;
  gl.TriangleCount = triangles.size() / 12;
  gl.Item = FloatTexture(window, 5 * hemicubeResolution, hemicubeResolution, nullptr);
  gl.Pick = FloatTexture(window, 1, 1, nullptr);
  gl.ItemDepth = vtkSmartPointer<vtkTextureObject>::New();
  gl.ItemDepth->SetContext(window);
  gl.PickDepth = vtkSmartPointer<vtkTextureObject>::New();
  gl.PickDepth->SetContext(window);
  if (!gl.Item || !gl.Pick ||
    !gl.ItemDepth->AllocateDepth(5 * hemicubeResolution, hemicubeResolution, vtkTextureObject::Float32) ||
    !gl.PickDepth->AllocateDepth(1, 1, vtkTextureObject::Float32))
  {
    error = "progressive-gpu: the OpenGL context (" + gl.Renderer + ") could not allocate the item buffer";
    return false;
  }
  for (vtkOpenGLFramebufferObject* fbo : { gl.ElementFBO.Get(), gl.DeltaFBO.Get(), gl.FlagFBO.Get(),
         gl.NodeFBO.Get(), gl.ItemFBO.Get(), gl.PickFBO.Get() })
  {
    fbo->SetContext(window);
  }
  gl.ItemFBO->Bind();
  gl.ItemFBO->AddColorAttachment(0, gl.Item);
  gl.ItemFBO->AddDepthAttachment(gl.ItemDepth);
  gl.ItemFBO->ActivateDrawBuffers(1);
  gl.PickFBO->Bind();
  gl.PickFBO->AddColorAttachment(0, gl.Pick);
  gl.PickFBO->AddDepthAttachment(gl.PickDepth);
  gl.PickFBO->ActivateDrawBuffers(1);

  vtkOpenGLShaderCache* cache = window->GetShaderCache();
  gl.ShotQuad.reset(new vtkOpenGLQuadHelper(window, nullptr, gpu_shaders::ShotFragment, ""));
  gl.CommitQuad.reset(new vtkOpenGLQuadHelper(window, nullptr, gpu_shaders::CommitFragment, ""));
  gl.SplitQuad.reset(new vtkOpenGLQuadHelper(window, nullptr, gpu_shaders::SplitFragment, ""));
  gl.NodeQuad.reset(new vtkOpenGLQuadHelper(window, nullptr, gpu_shaders::NodePowerFragment, ""));
  gl.ItemProgram = cache->ReadyShaderProgram(gpu_shaders::HemicubeItemVertex, gpu_shaders::HemicubeItemFragment, "");
  gl.PickProgram = cache->ReadyShaderProgram(gpu_shaders::SelectionVertex, gpu_shaders::SelectionFragment, "");
  for (vtkOpenGLQuadHelper* quad : { gl.ShotQuad.get(), gl.CommitQuad.get(), gl.SplitQuad.get(), gl.NodeQuad.get() })
  {
    if (!quad->Program || !quad->Program->GetCompiled())
    {
      error = "progressive-gpu: a shader program did not build on " + gl.Renderer;
      return false;
    }
  }
  if (!gl.ItemProgram || !gl.PickProgram)
  {
    error = "progressive-gpu: a shader program did not build on " + gl.Renderer;
    return false;
  }
  glGenQueries(1, &gl.SplitQuery);
  if (gl.TriangleCount == 0)
  {
    return true; // nothing can occlude: the item buffer stays empty
  }
  gl.TriangleBuffer->Upload(triangles, vtkOpenGLBufferObject::ArrayBuffer);
  cache->ReadyShaderProgram(gl.ItemProgram);
  gl.TriangleArrays->Bind();
  if (!gl.TriangleArrays->AddAttributeArray(
        gl.ItemProgram, gl.TriangleBuffer, "vertexMC", 0, 4 * sizeof(float), VTK_FLOAT, 3, false) ||
    !gl.TriangleArrays->AddAttributeArray(
      gl.ItemProgram, gl.TriangleBuffer, "triangleId", 3 * sizeof(float), 4 * sizeof(float), VTK_FLOAT, 1, false))
  {
    error = "progressive-gpu: the triangles could not be bound to the item buffer program";
    return false;
  }
  gl.TriangleArrays->Release();
  return true;
}

bool ProgressiveGPUPasses::UploadAtlas(const GPUElementTexels& elements, const GPUNodeTexels& nodes, std::string& error)
{
  Internals& gl = *this->GL;
  vtkOpenGLRenderWindow* window = gl.Window;
  window->MakeCurrent();
  gl.AtlasWidth = elements.Width;
  gl.AtlasHeight = elements.Height;
  gl.ElementCount = elements.Count;
  gl.NodeWidth = nodes.Width;
  gl.NodeCount = nodes.Count;
  const int w = elements.Width, h = elements.Height;
  const std::vector<float>* inputs[10] = { &elements.Centre, &elements.Corner0, &elements.Corner1,
    &elements.Corner2, &elements.CentreLo, &elements.Corner0Lo, &elements.Corner1Lo, &elements.Corner2Lo,
    &elements.Normal, &elements.Reflectance };
  vtkSmartPointer<vtkTextureObject>* slots[10] = { &gl.Centre, &gl.Corner[0], &gl.Corner[1], &gl.Corner[2],
    &gl.CentreLo, &gl.CornerLo[0], &gl.CornerLo[1], &gl.CornerLo[2], &gl.Normal, &gl.Reflectance };
  bool ok = true;
  for (int k = 0; k < 10; ++k)
  {
    *slots[k] = FloatTexture(window, w, h, inputs[k]);
    ok = ok && *slots[k];
  }
  const std::vector<float>* initial[5] = { &elements.Irradiance0, &elements.Irradiance1,
    &elements.Irradiance2, &elements.IrradianceCentre, &elements.Unshot };
  for (int k = 0; k < 5; ++k)
  {
    gl.Target[k] = FloatTexture(window, w, h, initial[k]);
    ok = ok && gl.Target[k];
  }
  for (int k = 0; k < 4; ++k)
  {
    gl.Delta[k] = FloatTexture(window, w, h, nullptr);
    ok = ok && gl.Delta[k];
  }
  gl.Flag = FloatTexture(window, w, h, nullptr);
  gl.NodeRange = FloatTexture(window, nodes.Width, nodes.Width, &nodes.Range);
  gl.NodeReflectance = FloatTexture(window, nodes.Width, nodes.Width, &nodes.Reflectance);
  gl.NodePower = FloatTexture(window, nodes.Width, nodes.Width, nullptr);
  ok = ok && gl.Flag && gl.NodeRange && gl.NodeReflectance && gl.NodePower;
  if (!ok)
  {
    error = "progressive-gpu: the OpenGL context (" + gl.Renderer + ") could not allocate the " +
      std::to_string(w) + "x" + std::to_string(h) + " element atlas";
    return false;
  }
  gl.ElementFBO->Bind();
  for (int k = 0; k < 5; ++k)
  {
    gl.ElementFBO->AddColorAttachment(k, gl.Target[k]);
  }
  gl.ElementFBO->ActivateDrawBuffers(5);
  gl.DeltaFBO->Bind();
  for (int k = 0; k < 4; ++k)
  {
    gl.DeltaFBO->AddColorAttachment(k, gl.Delta[k]);
  }
  gl.DeltaFBO->ActivateDrawBuffers(4);
  gl.FlagFBO->Bind();
  gl.FlagFBO->AddColorAttachment(0, gl.Flag);
  gl.FlagFBO->ActivateDrawBuffers(1);
  gl.NodeFBO->Bind();
  gl.NodeFBO->AddColorAttachment(0, gl.NodePower);
  gl.NodeFBO->ActivateDrawBuffers(1);
  return true;
}

std::array<double, 4> ProgressiveGPUPasses::NodeTotals()
{
  Internals& gl = *this->GL;
  vtkOpenGLState* state = gl.State();
  DrawTo(gl.NodeFBO, 1);
  state->vtkglViewport(0, 0, gl.NodeWidth, gl.NodeWidth);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  gl.Window->GetShaderCache()->ReadyShaderProgram(gl.NodeQuad->Program);
  vtkShaderProgram* program = gl.NodeQuad->Program;
  gl.NodeRange->Activate();
  gl.Centre->Activate();
  gl.Target[4]->Activate();
  program->SetUniformi("nodeTex", gl.NodeRange->GetTextureUnit());
  program->SetUniformi("centreTex", gl.Centre->GetTextureUnit());
  program->SetUniformi("unshotTex", gl.Target[4]->GetTextureUnit());
  program->SetUniformi("nodeWidth", gl.NodeWidth);
  program->SetUniformi("nodeCount", static_cast<int>(gl.NodeCount));
  program->SetUniformi("atlasWidth", gl.AtlasWidth);
  gl.NodeQuad->Render();
  gl.NodeRange->Deactivate();
  gl.Centre->Deactivate();
  gl.Target[4]->Deactivate();
  // The mean over the power-of-two texture, by the mipmap's 2x2 box filter
  // (exact pairwise sums), read at its one-texel top level.
  int top = 0;
  while ((1 << top) < gl.NodeWidth)
  {
    ++top;
  }
  gl.NodePower->Bind();
  // VTK allocates level 0 alone (GL_TEXTURE_MAX_LEVEL 0).
  gl.NodePower->SetMaxLevel(top);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, top);
  glGenerateMipmap(GL_TEXTURE_2D);
  float mean[4] = { 0, 0, 0, 0 };
  glGetTexImage(GL_TEXTURE_2D, top, GL_RGBA, GL_FLOAT, mean);
  const double texels = static_cast<double>(gl.NodeWidth) * gl.NodeWidth;
  return { mean[0] * texels, mean[1] * texels, mean[2] * texels, mean[3] * texels };
}

long long ProgressiveGPUPasses::SelectShooter(
  const std::array<float, 3>& ambient, float powerScale, std::array<double, 3>& power)
{
  Internals& gl = *this->GL;
  vtkOpenGLState* state = gl.State();
  DrawTo(gl.PickFBO, 1);
  state->vtkglViewport(0, 0, 1, 1);
  state->vtkglDisable(GL_BLEND);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglDepthFunc(GL_LESS);
  state->vtkglClearColor(-1.0f, 0.0f, 0.0f, 0.0f);
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gl.Window->GetShaderCache()->ReadyShaderProgram(gl.PickProgram);
  gl.NodeRange->Activate();
  gl.NodePower->Activate();
  gl.NodeReflectance->Activate();
  gl.PickProgram->SetUniformi("nodeTex", gl.NodeRange->GetTextureUnit());
  gl.PickProgram->SetUniformi("nodePowerTex", gl.NodePower->GetTextureUnit());
  gl.PickProgram->SetUniformi("nodeReflectanceTex", gl.NodeReflectance->GetTextureUnit());
  gl.PickProgram->SetUniformi("nodeWidth", gl.NodeWidth);
  Uniform3(gl.PickProgram, "ambient", ambient);
  gl.PickProgram->SetUniformf("powerScale", powerScale);
  gl.PointArrays->Bind();
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(gl.NodeCount));
  gl.PointArrays->Release();
  gl.NodeRange->Deactivate();
  gl.NodePower->Deactivate();
  gl.NodeReflectance->Deactivate();
  float picked[4] = { -1, 0, 0, 0 };
  gl.PickFBO->ActivateReadBuffer(0);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, picked);
  if (!(picked[0] >= 0.0f))
  {
    return -1;
  }
  const long long node = static_cast<long long>(picked[0] + 0.5f);
  float value[4] = { 0, 0, 0, 0 };
  gl.NodeFBO->Bind();
  gl.NodeFBO->ActivateReadBuffer(0);
  glReadPixels(static_cast<GLint>(node % gl.NodeWidth), static_cast<GLint>(node / gl.NodeWidth), 1, 1,
    GL_RGBA, GL_FLOAT, value);
  power = { value[0], value[1], value[2] };
  return node;
}

void ProgressiveGPUPasses::Shoot(const GPUShooter& shooter, float discTolerance)
{
  Internals& gl = *this->GL;
  vtkOpenGLState* state = gl.State();
  const std::array<float, 3> frameN = shooter.Normal;
  // The eye a hair above the shooter, so that its own plane is seen edge-on
  // below the horizon rather than through it.
  const float lift = 1e-6f;
  const std::array<float, 3> eye = { shooter.Centre[0] + lift * frameN[0],
    shooter.Centre[1] + lift * frameN[1], shooter.Centre[2] + lift * frameN[2] };

  // Section 3.2, the visibility pass: the item buffer on the five faces
  // (the occluders only; none in a convex room, where it stays as cleared).
  if (gl.TriangleCount > 0 || !gl.ItemCleared)
  {
    DrawTo(gl.ItemFBO, 1);
    state->vtkglViewport(0, 0, 5 * gl.Hemicube, gl.Hemicube);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_SCISSOR_TEST);
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglDepthFunc(GL_LESS);
    state->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    state->vtkglClearDepth(1.0);
    state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.Window->GetShaderCache()->ReadyShaderProgram(gl.ItemProgram);
    Uniform3(gl.ItemProgram, "eye", eye);
    Uniform3(gl.ItemProgram, "frameU", shooter.FrameU);
    Uniform3(gl.ItemProgram, "frameV", shooter.FrameV);
    Uniform3(gl.ItemProgram, "frameN", frameN);
    gl.ItemProgram->SetUniformf("nearDistance", 1e-7f);
    gl.ItemProgram->SetUniformf("farDistance", 4.0f); // the scene lies within its unit diagonal
    gl.TriangleArrays->Bind();
    state->vtkglEnable(GL_SCISSOR_TEST);
    for (int face = 0; face < 5; ++face)
    {
      // A side face's lower half lies behind the shooter's plane, where no
      // receiver takes light: only its upper half (and a row) is drawn.
      const int low = face == 0 ? 0 : gl.Hemicube / 2 - 1;
      state->vtkglViewport(face * gl.Hemicube, 0, gl.Hemicube, gl.Hemicube);
      state->vtkglScissor(face * gl.Hemicube, low, gl.Hemicube, gl.Hemicube - low);
      gl.ItemProgram->SetUniformi("face", face);
      if (gl.TriangleCount > 0)
      {
        glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * gl.TriangleCount));
      }
    }
    state->vtkglDisable(GL_SCISSOR_TEST);
    gl.TriangleArrays->Release();
    gl.ItemCleared = true;
  }

  // Sections 3.2-3.3, the reconstruction pass over the element atlas,
  // into the shot's deltas.
  DrawTo(gl.DeltaFBO, 4);
  state->vtkglViewport(0, 0, gl.AtlasWidth, gl.AtlasHeight);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  state->vtkglBlendEquation(GL_FUNC_ADD);
  gl.Window->GetShaderCache()->ReadyShaderProgram(gl.ShotQuad->Program);
  vtkShaderProgram* program = gl.ShotQuad->Program;
  vtkTextureObject* inputs[11] = { gl.Centre, gl.Corner[0], gl.Corner[1], gl.Corner[2], gl.CentreLo,
    gl.CornerLo[0], gl.CornerLo[1], gl.CornerLo[2], gl.Normal, gl.Reflectance, gl.Item };
  const char* names[11] = { "centreTex", "corner0Tex", "corner1Tex", "corner2Tex", "centreLoTex",
    "corner0LoTex", "corner1LoTex", "corner2LoTex", "normalTex", "reflectanceTex", "itemTex" };
  for (int k = 0; k < 11; ++k)
  {
    inputs[k]->Activate();
    program->SetUniformi(names[k], inputs[k]->GetTextureUnit());
  }
  program->SetUniformi("atlasWidth", gl.AtlasWidth);
  program->SetUniformi("elementCount", static_cast<int>(gl.ElementCount));
  Uniform3(program, "eye", eye);
  Uniform3(program, "frameU", shooter.FrameU);
  Uniform3(program, "frameV", shooter.FrameV);
  Uniform3(program, "frameN", frameN);
  program->SetUniformi("faceResolution", gl.Hemicube);
  // The receiver-plane test's allowance, relative to the distance: the
  // item's distance is exact at the pixel centre, the plane's too, so only
  // float rounding and a plane bending at the sample's edge remain.
  program->SetUniformf("depthSlope", 1e-3f);
  program->SetUniformf("depthFloor", 1e-6f);
  Uniform3(program, "shooterCentre", shooter.Centre);
  Uniform3(program, "shooterCentreLo", shooter.CentreLo);
  Uniform3(program, "shooterV0Lo", shooter.VerticesLo[0]);
  Uniform3(program, "shooterV1Lo", shooter.VerticesLo[1]);
  Uniform3(program, "shooterV2Lo", shooter.VerticesLo[2]);
  Uniform3(program, "shooterNormal", shooter.Normal);
  program->SetUniformf("shooterArea", shooter.Area);
  Uniform3(program, "shooterV0", shooter.Vertices[0]);
  Uniform3(program, "shooterV1", shooter.Vertices[1]);
  Uniform3(program, "shooterV2", shooter.Vertices[2]);
  program->SetUniformf("shooterTriangle", shooter.Triangle);
  Uniform3(program, "shot", shooter.Shot);
  program->SetUniformf("discTolerance", discTolerance);
  gl.ShotQuad->Render();
  for (vtkTextureObject* input : inputs)
  {
    input->Deactivate();
  }
  state->vtkglDisable(GL_BLEND);
}

void ProgressiveGPUPasses::SetUnshot(std::size_t first, std::size_t count, const std::array<float, 3>& value)
{
  Internals& gl = *this->GL;
  if (count == 0)
  {
    return;
  }
  vtkOpenGLState* state = gl.State();
  DrawTo(gl.ElementFBO, 5);
  state->vtkglViewport(0, 0, gl.AtlasWidth, gl.AtlasHeight);
  state->vtkglEnable(GL_SCISSOR_TEST);
  const GLfloat clear[4] = { value[0], value[1], value[2], 0.0f };
  const std::size_t w = static_cast<std::size_t>(gl.AtlasWidth);
  const std::size_t last = first + count - 1;
  const std::size_t r0 = first / w, r1 = last / w;
  auto fill = [&](std::size_t x, std::size_t y, std::size_t width, std::size_t height) {
    state->vtkglScissor(static_cast<GLint>(x), static_cast<GLint>(y), static_cast<GLsizei>(width),
      static_cast<GLsizei>(height));
    glClearBufferfv(GL_COLOR, 4, clear);
  };
  if (r0 == r1)
  {
    fill(first % w, r0, last - first + 1, 1);
  }
  else
  {
    fill(first % w, r0, w - first % w, 1);
    if (r1 > r0 + 1)
    {
      fill(0, r0 + 1, w, r1 - r0 - 1);
    }
    fill(0, r1, last % w + 1, 1);
  }
  state->vtkglDisable(GL_SCISSOR_TEST);
}

void ProgressiveGPUPasses::BeginShot()
{
  Internals& gl = *this->GL;
  vtkOpenGLState* state = gl.State();
  DrawTo(gl.DeltaFBO, 4);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
}

std::size_t ProgressiveGPUPasses::CountSplits(float threshold)
{
  Internals& gl = *this->GL;
  vtkOpenGLState* state = gl.State();
  DrawTo(gl.FlagFBO, 1);
  state->vtkglViewport(0, 0, gl.AtlasWidth, gl.AtlasHeight);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  gl.Window->GetShaderCache()->ReadyShaderProgram(gl.SplitQuad->Program);
  vtkShaderProgram* program = gl.SplitQuad->Program;
  vtkTextureObject* inputs[9] = { gl.Delta[0], gl.Delta[1], gl.Delta[2], gl.Delta[3], gl.Target[0], gl.Target[1],
    gl.Target[2], gl.Target[3], gl.Reflectance };
  const char* names[9] = { "delta0Tex", "delta1Tex", "delta2Tex", "deltaCentreTex", "irradiance0Tex",
    "irradiance1Tex", "irradiance2Tex", "irradianceCentreTex", "reflectanceTex" };
  for (int k = 0; k < 9; ++k)
  {
    inputs[k]->Activate();
    program->SetUniformi(names[k], inputs[k]->GetTextureUnit());
  }
  program->SetUniformi("atlasWidth", gl.AtlasWidth);
  program->SetUniformi("elementCount", static_cast<int>(gl.ElementCount));
  program->SetUniformf("threshold", threshold);
  // Section 4.1: "a hardware occlusion query is used to count" the
  // fragments that ask for a split (the others are discarded).
  glBeginQuery(GL_SAMPLES_PASSED, gl.SplitQuery);
  gl.SplitQuad->Render();
  glEndQuery(GL_SAMPLES_PASSED);
  for (vtkTextureObject* input : inputs)
  {
    input->Deactivate();
  }
  GLuint count = 0;
  glGetQueryObjectuiv(gl.SplitQuery, GL_QUERY_RESULT, &count);
  return count;
}

std::vector<float> ProgressiveGPUPasses::ReadSplitFlags()
{
  Internals& gl = *this->GL;
  std::vector<float> flags(4 * static_cast<std::size_t>(gl.AtlasWidth) * gl.AtlasHeight);
  gl.Flag->Bind();
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, flags.data());
  return flags;
}

void ProgressiveGPUPasses::CommitShot()
{
  Internals& gl = *this->GL;
  vtkOpenGLState* state = gl.State();
  DrawTo(gl.ElementFBO, 5);
  state->vtkglViewport(0, 0, gl.AtlasWidth, gl.AtlasHeight);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  state->vtkglBlendEquation(GL_FUNC_ADD);
  gl.Window->GetShaderCache()->ReadyShaderProgram(gl.CommitQuad->Program);
  vtkShaderProgram* program = gl.CommitQuad->Program;
  vtkTextureObject* inputs[5] = { gl.Delta[0], gl.Delta[1], gl.Delta[2], gl.Delta[3], gl.Reflectance };
  const char* names[5] = { "delta0Tex", "delta1Tex", "delta2Tex", "deltaCentreTex", "reflectanceTex" };
  for (int k = 0; k < 5; ++k)
  {
    inputs[k]->Activate();
    program->SetUniformi(names[k], inputs[k]->GetTextureUnit());
  }
  gl.CommitQuad->Render();
  for (vtkTextureObject* input : inputs)
  {
    input->Deactivate();
  }
  state->vtkglDisable(GL_BLEND);
}

std::array<std::vector<float>, 5> ProgressiveGPUPasses::ReadElements()
{
  Internals& gl = *this->GL;
  std::array<std::vector<float>, 5> out;
  for (int k = 0; k < 5; ++k)
  {
    out[k].resize(4 * static_cast<std::size_t>(gl.AtlasWidth) * gl.AtlasHeight);
    gl.Target[k]->Bind();
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, out[k].data());
  }
  return out;
}
} // namespace radiosity
