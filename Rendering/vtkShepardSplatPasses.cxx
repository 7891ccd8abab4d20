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
#include "vtkShepardSplatNodes.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <array>

namespace
{
// Pass 2: one quad (two triangles, six vertices) per basis function, read
// from the level-sorted point texels at gl_VertexID / 6 (the draw's first
// vertex is six times the first point). Only
// where the G-buffer's point lies in the support ball |x - x_j| < r_j can
// w_j be nonzero, so the quad is the ball's exact screen bound and the
// quad's depth the ball's farthest: the depth test (GEQUAL against the
// G-buffer's depth) rejects the pixels whose surface lies behind the ball
// before the fragment shader runs. On llvmpipe every fragment costs, and the
// support cube's projection (the bound before) covered the office's screen
// about 90 times over for nothing.
//
// The bound: for a linear-fractional NDC coordinate t = (m.p) / (m3.p) over
// the ball |p - c| <= r (m a row of MCDCMatrix, p homogeneous), t's extremes
// are where the plane (m - t m3).p = 0 touches the ball:
//   (a - t b)^2 = r^2 |u - t v|^2,  a = m.c, b = m3.c, u = m.xyz, v = m3.xyz,
// whose two roots are the range when the ball lies in front of the eye
// (b > r |v|: all of it at w > 0). This holds for any affine model matrix
// and for parallel projections (v = 0). The discriminant is written as
// r^2 (|a v - b u|^2 - r^2 |u x v|^2), which float evaluates without the
// cancellation of B^2 - AC; a ball within 5% of touching the eye plane
// (A near 0) covers the viewport instead. The depth: NDC z is a function
// of w alone in a perspective projection (clip z = alpha w + beta) and
// grows with it, and affine in p in a parallel one, so the ball's depth
// range is that of its points of extreme w or z, evaluated directly (the
// quadratic lost up to 17/255 of the office's corners to float
// cancellation, cutting fragments near the back of balls). A ball wholly
// behind the eye or outside the frustum draws nothing (a degenerate quad);
// one reaching behind the eye covers the viewport. The radius is widened by
// 1e-4 (w_j < 3e-8 there), the quad by a pixel and the depth by 1e-5, so
// that float rounding never cuts a fragment with a weight.
const char* const SplatVS = R"(//VTK::System::Dec
uniform samplerBuffer splatPoints;
uniform mat4 MCDCMatrix;
uniform vec2 pixelSize;
flat out vec4 splatCentre;
flat out vec4 splatNormal;
flat out vec3 splatCoefficient;
// The range of (row . p) / (m3 . p) over the ball (c, r), b > r |v|.
vec2 Range(vec4 row, vec4 m3, vec3 c, float r)
{
  float a = dot(row.xyz, c) + row.w;
  float b = dot(m3.xyz, c) + m3.w;
  float r2 = r * r;
  float A = b * b - r2 * dot(m3.xyz, m3.xyz);
  float B = a * b - r2 * dot(row.xyz, m3.xyz);
  vec3 e = a * m3.xyz - b * row.xyz;
  vec3 f = cross(row.xyz, m3.xyz);
  float s = r * sqrt(max(dot(e, e) - r2 * dot(f, f), 0.0));
  return vec2(B - s, B + s) / A;
}
// The NDC depth at c + r * dir (w > 0 there).
float Depth(vec3 c, float r, vec3 dir)
{
  vec4 q = MCDCMatrix * vec4(c + r * dir, 1.0);
  return q.z / q.w;
}
void main()
{
  int point = gl_VertexID / 6;
  int corner = gl_VertexID - 6 * (gl_VertexID / 6);
  splatCentre = texelFetch(splatPoints, 3 * point);
  splatNormal = texelFetch(splatPoints, 3 * point + 1);
  splatCoefficient = texelFetch(splatPoints, 3 * point + 2).xyz;
  // GLSL matrices are indexed by column: row k is (M[0][k], ..., M[3][k]).
  mat4 t = transpose(MCDCMatrix);
  vec3 c = splatCentre.xyz;
  float r = splatCentre.w * 1.0001;
  float b = dot(t[3].xyz, c) + t[3].w;
  float reach = r * length(t[3].xyz);
  vec2 lo = vec2(-1.0);
  vec2 hi = vec2(1.0);
  float depth = 1.0;
  bool culled = b + reach <= 0.0;
  if (!culled && reach > 0.0)
  {
    // Perspective: the points of largest and (in front of the eye) smallest w.
    vec3 v = normalize(t[3].xyz);
    depth = Depth(c, r, v) + 1.0e-5;
    culled = depth < -1.0 || (b > reach && Depth(c, -r, v) - 1.0e-5 > 1.0);
  }
  else if (!culled)
  {
    // Parallel: z affine in p, extreme along the z row.
    vec3 z = length(t[2].xyz) > 0.0 ? normalize(t[2].xyz) : vec3(0.0);
    float z0 = Depth(c, r, z), z1 = Depth(c, -r, z);
    depth = max(z0, z1) + 1.0e-5;
    culled = depth < -1.0 || min(z0, z1) - 1.0e-5 > 1.0;
  }
  if (!culled && b > 1.05 * reach)
  {
    vec2 x = Range(t[0], t[3], c, r);
    vec2 y = Range(t[1], t[3], c, r);
    lo = vec2(x.x, y.x) - pixelSize;
    hi = vec2(x.y, y.y) + pixelSize;
  }
  lo = clamp(lo, vec2(-1.0), vec2(1.0));
  hi = clamp(hi, vec2(-1.0), vec2(1.0));
  if (culled || !(lo.x < hi.x) || !(lo.y < hi.y))
  {
    hi = lo; // nothing to draw
  }
  const vec2 quad[6] = vec2[6](vec2(0.0, 0.0), vec2(1.0, 0.0), vec2(1.0, 1.0),
    vec2(0.0, 0.0), vec2(1.0, 1.0), vec2(0.0, 1.0));
  gl_Position = vec4(mix(lo, hi, quad[corner]), clamp(depth, -1.0, 1.0), 1.0);
}
)";

// The occlusion queries: the back faces of each node's box (two texels a
// node, (lo, 0) and (hi, 0), box i drawn as vertices 36 i to 36 i + 35),
// whose fragments pass where the G-buffer's point lies in the box. A node
// can contribute only where a visible point lies in one of its balls, so in
// its box; the ray through that pixel then leaves the box through a back
// face beyond the point, in front of the eye, and depth clamping keeps that
// face from being clipped at the far plane: the pixel is rasterised and
// passes. (A front face may be clipped at the near plane, hence the back
// ones.) A face is a back face when the eye (homogeneous, model
// coordinates: w = 0 for a parallel projection) lies on the box's side of
// its plane; the front ones collapse to a point.
const char* const BoxVS = R"(//VTK::System::Dec
uniform samplerBuffer nodeBoxes;
uniform mat4 MCDCMatrix;
uniform vec4 eye;
flat out vec3 boxLo;
flat out vec3 boxHi;
void main()
{
  int node = gl_VertexID / 36;
  int vertex = gl_VertexID - 36 * node;
  int face = vertex / 6;
  int corner = vertex - 6 * face;
  boxLo = texelFetch(nodeBoxes, 2 * node).xyz;
  boxHi = texelFetch(nodeBoxes, 2 * node + 1).xyz;
  int axis = face / 2;
  bool upper = face - 2 * axis == 1;
  float plane = upper ? boxHi[axis] : boxLo[axis];
  float side = eye[axis] - plane * eye.w;
  const vec2 quad[6] = vec2[6](vec2(0.0, 0.0), vec2(1.0, 0.0), vec2(1.0, 1.0),
    vec2(0.0, 0.0), vec2(1.0, 1.0), vec2(0.0, 1.0));
  vec2 st = quad[corner];
  int u = axis == 2 ? 0 : axis + 1;
  int v = axis == 0 ? 2 : axis - 1;
  vec3 p;
  p[axis] = plane;
  p[u] = mix(boxLo[u], boxHi[u], st.x);
  p[v] = mix(boxLo[v], boxHi[v], st.y);
  gl_Position = (upper ? side < 0.0 : side > 0.0) ? MCDCMatrix * vec4(p, 1.0)
                                                  : vec4(0.0, 0.0, 0.0, 1.0);
}
)";

const char* const BoxFS = R"(//VTK::System::Dec
//VTK::Output::Dec
uniform sampler2D gPosition;
flat in vec3 boxLo;
flat in vec3 boxHi;
void main()
{
  vec4 position = texelFetch(gPosition, ivec2(gl_FragCoord.xy), 0);
  if (position.w < 0.5 || any(lessThan(position.xyz, boxLo)) ||
    any(greaterThan(position.xyz, boxHi)))
  {
    discard;
  }
  gl_FragData[0] = vec4(0.0);
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
  vtkRadiosityTexelBuffer* points, const std::vector<size_t>& levelOffsets, Culling& culling,
  std::string& error)
{
  vtkOpenGLState* state = window->GetState();
  this->Framebuffer->AddColorAttachment(0, this->Irradiance);
  this->Framebuffer->ActivateDrawBuffers(1);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  culling.Splatted = culling.FrustumCulled = culling.OcclusionCulled = culling.Queries = 0;
  if (!points || levelOffsets.size() < 2 || levelOffsets.back() == 0)
  {
    this->Framebuffer->RemoveColorAttachments(1);
    return true; // no basis functions: zero irradiance
  }

  // The nodes to draw: those whose box meets the frustum, then those of
  // them whose box holds a visible point.
  const vtkShepardSplatNodes* nodes = culling.Nodes;
  std::vector<unsigned char> draw;
  if (nodes)
  {
    nodes->Cull(modelToClip, draw);
    for (size_t n = 0; n < draw.size(); ++n)
    {
      culling.FrustumCulled += draw[n] ? 0 : nodes->GetNodes()[n].Count;
    }
    if (culling.Boxes &&
      !this->Occlude(window, modelToClip, *nodes, culling.Boxes, draw, culling, error))
    {
      this->Framebuffer->RemoveColorAttachments(1);
      return false;
    }
  }

  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  state->vtkglBlendEquation(GL_FUNC_ADD);
  // The G-buffer's depth, tested (not written) against each splat's
  // farthest depth: see SplatVS. Not sampled in this pass.
  this->Framebuffer->AddDepthAttachment(this->Depth);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(state);
  state->vtkglDepthFunc(GL_GEQUAL);
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
    splat->SetUniformMatrix("MCDCMatrix", modelToClip);
    const float pixelSize[2] = { 2.0f / this->Width, 2.0f / this->Height };
    splat->SetUniform2f("pixelSize", pixelSize);
    state->vtkglEnable(GL_DEPTH_TEST);
    this->SplatArrays->Bind();
    if (!nodes)
    {
      glDrawArrays(GL_TRIANGLES, static_cast<GLint>(6 * first), static_cast<GLsizei>(6 * count));
      culling.Splatted += count;
    }
    else
    {
      // The runs of consecutive nodes to draw, six vertices a point.
      std::vector<GLint> firsts;
      std::vector<GLsizei> counts;
      const std::vector<size_t>& levelNodes = nodes->GetLevelNodes();
      for (size_t n = levelNodes[level]; n < levelNodes[level + 1]; ++n)
      {
        const vtkShepardSplatNodes::Node& node = nodes->GetNodes()[n];
        if (!draw[n])
        {
          continue;
        }
        culling.Splatted += node.Count;
        if (n > levelNodes[level] && draw[n - 1])
        {
          counts.back() += static_cast<GLsizei>(6 * node.Count);
        }
        else
        {
          firsts.push_back(static_cast<GLint>(6 * node.First));
          counts.push_back(static_cast<GLsizei>(6 * node.Count));
        }
      }
      if (!firsts.empty())
      {
        glMultiDrawArrays(
          GL_TRIANGLES, firsts.data(), counts.data(), static_cast<GLsizei>(firsts.size()));
      }
    }
    this->SplatArrays->Release();
    state->vtkglDisable(GL_DEPTH_TEST);

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
  this->Framebuffer->RemoveDepthAttachment();
  return ok;
}

bool vtkShepardSplatPasses::Occlude(vtkOpenGLRenderWindow* window, vtkMatrix4x4* modelToClip,
  const vtkShepardSplatNodes& nodes, vtkRadiosityTexelBuffer* boxes,
  std::vector<unsigned char>& draw, Culling& culling, std::string& error)
{
  vtkShaderProgram* program = window->GetShaderCache()->ReadyShaderProgram(BoxVS, BoxFS, "");
  if (!program || !program->GetCompiled())
  {
    error = "Cannot build the occlusion query shader program.";
    return false;
  }
  if (this->QueriesContext != window)
  {
    this->Queries.clear(); // another context's names
    this->QueriesContext = window;
  }
  double eye[4];
  vtkShepardSplatNodes::Eye(modelToClip, eye);
  std::vector<size_t> queried;
  for (size_t n = 0; n < draw.size(); ++n)
  {
    // A box around the eye is drawn without asking.
    if (draw[n] && !nodes.Contains(n, eye))
    {
      queried.push_back(n);
    }
  }
  if (queried.empty())
  {
    return true;
  }
  if (this->Queries.size() < queried.size())
  {
    const size_t had = this->Queries.size();
    this->Queries.resize(queried.size());
    glGenQueries(static_cast<GLsizei>(queried.size() - had), this->Queries.data() + had);
  }
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(state);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  state->vtkglDisable(GL_CULL_FACE);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  glEnable(GL_DEPTH_CLAMP);
  this->Position->Activate();
  boxes->Activate();
  program->SetUniformi("gPosition", this->Position->GetTextureUnit());
  program->SetUniformi("nodeBoxes", boxes->GetTextureUnit());
  program->SetUniformMatrix("MCDCMatrix", modelToClip);
  const float eyef[4] = { static_cast<float>(eye[0]), static_cast<float>(eye[1]),
    static_cast<float>(eye[2]), static_cast<float>(eye[3]) };
  program->SetUniform4f("eye", eyef);
  const GLenum target = GLEW_VERSION_3_3 ? GL_ANY_SAMPLES_PASSED : GL_SAMPLES_PASSED;
  this->SplatArrays->Bind();
  for (size_t q = 0; q < queried.size(); ++q)
  {
    glBeginQuery(target, this->Queries[q]);
    glDrawArrays(GL_TRIANGLES, static_cast<GLint>(36 * queried[q]), 36);
    glEndQuery(target);
  }
  this->SplatArrays->Release();
  culling.Queries = queried.size();
  // Waits for the answers: the splats of the level need them anyway.
  for (size_t q = 0; q < queried.size(); ++q)
  {
    GLuint passed = 1;
    glGetQueryObjectuiv(this->Queries[q], GL_QUERY_RESULT, &passed);
    if (passed == 0)
    {
      draw[queried[q]] = 0;
      culling.OcclusionCulled += nodes.GetNodes()[queried[q]].Count;
    }
  }
  glDisable(GL_DEPTH_CLAMP);
  boxes->Deactivate();
  this->Position->Deactivate();
  return true;
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
  if (!this->Queries.empty() && this->QueriesContext == window)
  {
    glDeleteQueries(static_cast<GLsizei>(this->Queries.size()), this->Queries.data());
  }
  this->Queries.clear();
  this->QueriesContext = nullptr;
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
  os << indent << "OcclusionQueries: " << this->Queries.size() << "\n";
}
