#include "vtkShepardSplatPasses.h"

#include "vtkIndent.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkRadiosityCellTexelMapper.h"
#include "vtkRadiosityTexelBuffer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <array>

namespace
{
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

// Pass 3: the radiance (Emission + Reflectance E) / pi * Exposure, encoded as
// the mappers encode it (vtkRadiosityCellTexelMapper::RadianceUniforms), with
// the surface's depth.
std::string CompositeFS()
{
  return std::string(R"(//VTK::System::Dec
//VTK::Output::Dec
in vec2 texCoord;
uniform sampler2D gReflectance;
uniform sampler2D gEmission;
uniform sampler2D gDepth;
uniform sampler2D irradiance;
)") + vtkRadiosityCellTexelMapper::RadianceUniforms() +
    R"(void main()
{
  ivec2 pixel = ivec2(texCoord * vec2(textureSize(gReflectance, 0)));
  vec4 reflectance = texelFetch(gReflectance, pixel, 0);
  if (reflectance.w < 0.5)
  {
    discard;
  }
  vec3 e = texelFetch(irradiance, pixel, 0).rgb;
  gl_FragData[0] = vec4()" +
    vtkRadiosityCellTexelMapper::EncodedRadiance(
      "texelFetch(gEmission, pixel, 0).rgb + reflectance.rgb * e") +
    R"(, 1.0);
  gl_FragDepth = texelFetch(gDepth, pixel, 0).r;
}
)";
}
}

vtkShepardSplatPasses::vtkShepardSplatPasses() = default;
vtkShepardSplatPasses::~vtkShepardSplatPasses() = default;

vtkOpenGLFramebufferObject* vtkShepardSplatPasses::GetFramebuffer()
{
  return this->Framebuffer;
}

bool vtkShepardSplatPasses::Allocate(vtkOpenGLRenderWindow* window, int width, int height)
{
  if (width == this->Width && height == this->Height && this->Position->GetHandle() != 0 &&
    this->Position->GetContext() == window)
  {
    return true;
  }
  this->Width = this->Height = 0;
  for (vtkTextureObject* target : { this->Position.Get(), this->Normal.Get(),
         this->Reflectance.Get(), this->Emission.Get(), this->LevelSums.Get(),
         this->Irradiance.Get() })
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

void vtkShepardSplatPasses::BeginGBuffer(vtkOpenGLState* state)
{
  this->Framebuffer->AddColorAttachment(0, this->Position);
  this->Framebuffer->AddColorAttachment(1, this->Normal);
  this->Framebuffer->AddColorAttachment(2, this->Reflectance);
  this->Framebuffer->AddColorAttachment(3, this->Emission);
  this->Framebuffer->AddDepthAttachment(this->Depth);
  this->Framebuffer->ActivateDrawBuffers(4);
  state->vtkglViewport(0, 0, this->Width, this->Height);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void vtkShepardSplatPasses::EndGBuffer()
{
  this->Framebuffer->RemoveColorAttachments(4);
  this->Framebuffer->RemoveDepthAttachment();
}

bool vtkShepardSplatPasses::Splat(vtkOpenGLRenderWindow* window, vtkMatrix4x4* modelToClip,
  vtkRadiosityTexelBuffer* points, const std::vector<size_t>& levelOffsets, std::string& error)
{
  vtkOpenGLState* state = window->GetState();
  this->Framebuffer->AddColorAttachment(0, this->Irradiance);
  this->Framebuffer->ActivateDrawBuffers(1);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  if (!points || levelOffsets.size() < 2 || levelOffsets.back() == 0)
  {
    this->Framebuffer->RemoveColorAttachments(1);
    return true; // no basis functions: zero irradiance
  }

  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  state->vtkglBlendEquation(GL_FUNC_ADD);
  this->Position->Activate();
  this->Normal->Activate();
  points->Activate();
  bool ok = true;
  vtkOpenGLShaderCache* cache = window->GetShaderCache();
  for (size_t level = 0; ok && level + 1 < levelOffsets.size(); ++level)
  {
    const size_t first = levelOffsets[level];
    const size_t count = levelOffsets[level + 1] - first;
    if (count == 0)
    {
      continue;
    }
    this->Framebuffer->AddColorAttachment(0, this->LevelSums);
    state->vtkglClear(GL_COLOR_BUFFER_BIT);
    vtkShaderProgram* splat = cache->ReadyShaderProgram(SplatVS, SplatFS, "");
    if (!splat || !splat->GetCompiled())
    {
      error = "Cannot build the splat shader program.";
      ok = false;
      break;
    }
    splat->SetUniformi("splatPoints", points->GetTextureUnit());
    splat->SetUniformi("gPosition", this->Position->GetTextureUnit());
    splat->SetUniformi("gNormal", this->Normal->GetTextureUnit());
    splat->SetUniformi("firstPoint", static_cast<int>(first));
    splat->SetUniformMatrix("MCDCMatrix", modelToClip);
    this->SplatArrays->Bind();
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(6 * count));
    this->SplatArrays->Release();

    this->Framebuffer->AddColorAttachment(0, this->Irradiance);
    if (!this->Normalise)
    {
      this->Normalise.reset(new vtkOpenGLQuadHelper(window, nullptr, NormaliseFS, ""));
    }
    else
    {
      cache->ReadyShaderProgram(this->Normalise->Program);
    }
    if (!this->Normalise->Program || !this->Normalise->Program->GetCompiled())
    {
      error = "Cannot build the normalisation shader program.";
      ok = false;
      break;
    }
    this->LevelSums->Activate();
    this->Normalise->Program->SetUniformi("levelSums", this->LevelSums->GetTextureUnit());
    this->Normalise->Render();
    this->LevelSums->Deactivate();
  }
  points->Deactivate();
  this->Normal->Deactivate();
  this->Position->Deactivate();
  this->Framebuffer->RemoveColorAttachments(1);
  return ok;
}

bool vtkShepardSplatPasses::Composite(vtkOpenGLRenderWindow* window, double exposure, double gamma,
  int toneMapping, std::string& error)
{
  vtkOpenGLState* state = window->GetState();
  if (!this->CompositeQuad)
  {
    this->CompositeQuad.reset(new vtkOpenGLQuadHelper(window, nullptr, CompositeFS().c_str(), ""));
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(this->CompositeQuad->Program);
  }
  vtkShaderProgram* program = this->CompositeQuad->Program;
  if (!program || !program->GetCompiled())
  {
    error = "Cannot build the composite shader program.";
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

  vtkTextureObject* inputs[4] = { this->Reflectance, this->Emission, this->Depth, this->Irradiance };
  const char* names[4] = { "gReflectance", "gEmission", "gDepth", "irradiance" };
  for (int i = 0; i < 4; ++i)
  {
    inputs[i]->Activate();
    program->SetUniformi(names[i], inputs[i]->GetTextureUnit());
  }
  vtkRadiosityCellTexelMapper::SetRadianceUniforms(program, exposure, gamma, toneMapping);
  this->CompositeQuad->Render();
  for (vtkTextureObject* input : inputs)
  {
    input->Deactivate();
  }
  return true;
}

void vtkShepardSplatPasses::ReleaseGraphicsResources(vtkWindow* window)
{
  for (vtkTextureObject* target : { this->Position.Get(), this->Normal.Get(),
         this->Reflectance.Get(), this->Emission.Get(), this->LevelSums.Get(),
         this->Irradiance.Get() })
  {
    target->ReleaseGraphicsResources(window);
  }
  this->Depth->ReleaseGraphicsResources(window);
  this->Framebuffer->ReleaseGraphicsResources(window);
  this->SplatArrays->ReleaseGraphicsResources();
  for (auto* quad : { &this->Normalise, &this->CompositeQuad })
  {
    if (*quad)
    {
      (*quad)->ReleaseGraphicsResources(window);
      quad->reset();
    }
  }
  this->Width = this->Height = 0;
}

void vtkShepardSplatPasses::PrintSelf(std::ostream& os, vtkIndent indent) const
{
  os << indent << "Width: " << this->Width << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "Normalise: " << (this->Normalise ? "built" : "(none)") << "\n";
  os << indent << "CompositeQuad: " << (this->CompositeQuad ? "built" : "(none)") << "\n";
}
