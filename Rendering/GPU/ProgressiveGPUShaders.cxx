#include "ProgressiveGPUShaders.h"

namespace radiosity
{
namespace gpu_shaders
{
// Coordinates in every program are the scene's, centred and divided by its
// diagonal (ProgressiveGPUScene), so that float precision and every
// tolerance below are the same at 1e-4 m and at 1e4 m.

// The hemicube's five faces in the shooter's frame (u, v, n), w = x - eye:
// face 0 looks along n, faces 1-4 along +u, -u, +v, -v; (X, Y, W) are the
// face's clip coordinates, X/W and Y/W in [-1, 1] on the face. The shot
// pass projects with the same function, so both agree to the pixel.
#define RADIOSITY_HEMICUBE_PROJECTION                                                              \
  "vec3 FaceXYW(vec3 w, vec3 fu, vec3 fv, vec3 fn, int face)\n"                                    \
  "{\n"                                                                                           \
  "  float a = dot(w, fu), b = dot(w, fv), c = dot(w, fn);\n"                                     \
  "  if (face == 0) return vec3(a, b, c);\n"                                                      \
  "  if (face == 1) return vec3(b, c, a);\n"                                                      \
  "  if (face == 2) return vec3(b, c, -a);\n"                                                     \
  "  if (face == 3) return vec3(a, c, b);\n"                                                      \
  "  return vec3(a, c, -b);\n"                                                                    \
  "}\n"                                                                                           \
  "int FaceOf(vec3 w, vec3 fu, vec3 fv, vec3 fn)\n"                                               \
  "{\n"                                                                                           \
  "  float a = dot(w, fu), b = dot(w, fv), c = dot(w, fn);\n"                                     \
  "  if (c >= abs(a) && c >= abs(b)) return 0;\n"                                                 \
  "  if (abs(a) >= abs(b)) return a > 0.0 ? 1 : 2;\n"                                             \
  "  return b > 0.0 ? 3 : 4;\n"                                                                   \
  "}\n"

const char* const HemicubeItemVertex = "//VTK::System::Dec\n"
                                       "in vec4 vertexMC;\n"
                                       "in float triangleId;\n"
                                       "flat out float itemId;\n"
                                       "uniform vec3 eye;\n"
                                       "uniform vec3 frameU;\n"
                                       "uniform vec3 frameV;\n"
                                       "uniform vec3 frameN;\n"
                                       "uniform int face;\n"
                                       "uniform float nearDistance;\n"
                                       "out vec3 fromEye;\n" RADIOSITY_HEMICUBE_PROJECTION
                                       "void main()\n"
                                       "{\n"
                                       "  fromEye = vertexMC.xyz - eye;\n"
                                       "  itemId = triangleId;\n"
                                       "  vec3 xyw = FaceXYW(fromEye, frameU, frameV, frameN, face);\n"
                                       // NDC z = 1 - 2 near / W: clipped in front of W = near only.
                                       "  gl_Position = vec4(xyw.x, xyw.y, xyw.z - 2.0 * nearDistance, xyw.z);\n"
                                       "}\n";

// The item: the triangle's id + 1 (0: nothing) and its distance from the
// eye; the depth test keeps the nearest by that same linear distance, which
// float holds to 1e-7 of the scene at any range (a projective depth would not).
const char* const HemicubeItemFragment = "//VTK::System::Dec\n"
                                         "//VTK::Output::Dec\n"
                                         "in vec3 fromEye;\n"
                                         "flat in float itemId;\n"
                                         "uniform float farDistance;\n"
                                         "void main()\n"
                                         "{\n"
                                         "  float d = length(fromEye);\n"
                                         "  gl_FragData[0] = vec4(itemId + 1.0, d, 0.0, 1.0);\n"
                                         "  gl_FragDepth = clamp(d / farDistance, 0.0, 1.0);\n"
                                         "}\n";

// One fragment per element texel (the element at index y * atlasWidth + x).
// Targets 0-2: the shot's irradiance at the element's corners, 3: at its
// centroid (CommitFragment adds them and the residual's share).
const char* const ShotFragment =
  "//VTK::System::Dec\n"
  "//VTK::Output::Dec\n"
  "in vec2 texCoord;\n"
  "uniform sampler2D centreTex;\n"
  "uniform sampler2D corner0Tex;\n"
  "uniform sampler2D corner1Tex;\n"
  "uniform sampler2D corner2Tex;\n"
  "uniform sampler2D centreLoTex;\n"
  "uniform sampler2D corner0LoTex;\n"
  "uniform sampler2D corner1LoTex;\n"
  "uniform sampler2D corner2LoTex;\n"
  "uniform sampler2D normalTex;\n"
  "uniform sampler2D reflectanceTex;\n"
  "uniform sampler2D itemTex;\n"
  "uniform int atlasWidth;\n"
  "uniform int elementCount;\n"
  "uniform vec3 eye;\n"
  "uniform vec3 frameU;\n"
  "uniform vec3 frameV;\n"
  "uniform vec3 frameN;\n"
  "uniform int faceResolution;\n"
  "uniform float depthSlope;\n"
  "uniform float depthFloor;\n"
  "uniform vec3 shooterCentre;\n"
  "uniform vec3 shooterCentreLo;\n"
  "uniform vec3 shooterNormal;\n"
  "uniform float shooterArea;\n"
  "uniform vec3 shooterV0;\n"
  "uniform vec3 shooterV1;\n"
  "uniform vec3 shooterV2;\n"
  "uniform vec3 shooterV0Lo;\n"
  "uniform vec3 shooterV1Lo;\n"
  "uniform vec3 shooterV2Lo;\n"
  "uniform float shooterTriangle;\n"
  "uniform vec3 shot;\n"
  "uniform float discTolerance;\n" RADIOSITY_HEMICUBE_PROJECTION
  // Section 3.2's back-projection: the sample is visible where the item
  // buffer holds its own triangle, or where it holds a surface no nearer
  // than the sample's own plane along that pixel's ray (the receiver-plane
  // test of shadow mapping), at its pixel or one beside it: a sample by
  // its triangle's edge, where the neighbour in its plane or the wall it
  // meets was drawn, is not taken for shadowed, whatever the slope; a
  // shadow's edge moves by a pixel at most (the hemicube's aliasing).
  "float Visible(vec3 p, vec3 n, float triangle)\n"
  "{\n"
  "  vec3 w = p - eye;\n"
  "  int face = FaceOf(w, frameU, frameV, frameN);\n"
  "  vec3 xyw = FaceXYW(w, frameU, frameV, frameN, face);\n"
  "  if (!(xyw.z > 0.0)) return 0.0;\n"
  "  vec2 ndc = xyw.xy / xyw.z;\n"
  "  ivec2 px = clamp(ivec2(floor((ndc * 0.5 + 0.5) * float(faceResolution))), ivec2(0),\n"
  "    ivec2(faceResolution - 1));\n"
  "  float d = length(w);\n"
  "  float nw = dot(n, w);\n"
  // The ids first (the common case: a texel sees its own triangle), then
  // the plane test, at the sample's pixel before its neighbours.
  "  vec2 items[9];\n"
  "  for (int k = 0; k < 9; ++k)\n"
  "  {\n"
  "    ivec2 q = clamp(px + ivec2(k % 3 - 1, k / 3 - 1), ivec2(0), ivec2(faceResolution - 1));\n"
  "    items[k] = texelFetch(itemTex, ivec2(face * faceResolution + q.x, q.y), 0).xy;\n"
  "    if (abs(items[k].x - (triangle + 1.0)) < 0.5) return 1.0;\n"
  "  }\n"
  "  for (int j = 0; j < 9; ++j)\n"
  "  {\n"
  "    int k = (j + 4) % 9;\n"
  "    ivec2 q = clamp(px + ivec2(k % 3 - 1, k / 3 - 1), ivec2(0), ivec2(faceResolution - 1));\n"
  // Nothing drawn: no occluder lies that way (only the triangles that can
  // occlude are drawn, SceneAnalysis::CanOcclude).
  "    if (!(items[k].x > 0.5)) return 1.0;\n"
  // The pixel centre's ray, from its clip coordinates back to the frame.
  "    vec2 c = (vec2(q) + 0.5) / float(faceResolution) * 2.0 - 1.0;\n"
  "    vec3 abc = face == 0 ? vec3(c.x, c.y, 1.0) : face == 1 ? vec3(1.0, c.x, c.y)\n"
  "      : face == 2 ? vec3(-1.0, c.x, c.y) : face == 3 ? vec3(c.x, 1.0, c.y) : vec3(c.x, -1.0, c.y);\n"
  "    vec3 u = abc.x * frameU + abc.y * frameV + abc.z * frameN;\n"
  "    float length_u = length(u);\n"
  "    float toward = dot(n, u) / length_u;\n"
  // Where the ray meets the sample's plane (edge-on: the sample's own distance).
  "    float plane = toward < -1e-3 ? nw / toward : d;\n"
  "    if (items[k].y >= min(plane, 4.0) * (1.0 - depthSlope) - depthFloor) return 1.0;\n"
  "  }\n"
  "  return 0.0;\n"
  "}\n"
  // Lambert's contour integral over the shooter clipped to the receiver's
  // side of its plane (vertices in the plane kept: a shooter standing on
  // the receiver's surface): the exact point-to-polygon form factor (as
  // FormFactor.h's PointToPolygonFormFactor), each edge's angle by atan2,
  // which float keeps accurate for a far, small shooter (acos does not).
  // g[i]: the shooter's vertices less the receiving point, formed from the
  // two-float positions (Hi + Lo, see Relative) so that a point 1e-5 from
  // the shooter keeps its digits: a closed room of reflectance 0.999
  // amplifies a form factor's error a thousandfold.
  "float Angle(float y, float x)\n"
  // atan2(y >= 0, x) to float's precision (Cephes' atanf: range reduction
  // to |t| <= tan(pi/8) and its degree-9 odd polynomial): the shader's own
  // atan may be a cheaper approximation (llvmpipe's is good to about 1e-5,
  // which a room of reflectance 0.999 turns into a 1% bias).
  "{\n"
  "  float ax = abs(x);\n"
  "  bool swap = y > ax;\n"
  "  float t = swap ? ax / y : y / max(ax, 1e-38);\n"
  "  float base = 0.0;\n"
  "  if (t > 0.41421356237309503)\n"
  "  {\n"
  "    t = (t - 1.0) / (t + 1.0);\n"
  "    base = 0.7853981633974483;\n"
  "  }\n"
  "  float z = t * t;\n"
  "  float a = base + ((((8.05374449538e-2 * z - 1.38776856032e-1) * z + 1.99777106478e-1) * z -\n"
  "    3.33329491539e-1) * z * t + t);\n"
  "  if (swap) a = 1.5707963267948966 - a;\n"
  "  return x < 0.0 ? 3.141592653589793 - a : a;\n"
  "}\n"
  "float ContourFactor(vec3 g[3], vec3 n)\n"
  "{\n"
  // A shooter in the receiver's plane (a coplanar neighbour) sends nothing.
  "  if (max(max(dot(n, g[0]), dot(n, g[1])), dot(n, g[2])) <= 1e-6) return 0.0;\n"
  "  vec3 poly[4];\n"
  "  int count = 0;\n"
  "  for (int i = 0; i < 3; ++i)\n"
  "  {\n"
  "    vec3 a = g[i];\n"
  "    vec3 b = g[(i + 1) % 3];\n"
  "    float da = dot(n, a), db = dot(n, b);\n"
  "    if (da >= 0.0) poly[count++] = a;\n"
  "    if ((da > 0.0 && db < 0.0) || (da < 0.0 && db > 0.0)) poly[count++] = a + (b - a) * (da / (da - db));\n"
  "  }\n"
  "  if (count < 3) return 0.0;\n"
  "  float sum = 0.0;\n"
  "  for (int k = 0; k < count; ++k)\n"
  "  {\n"
  "    vec3 g0 = poly[k];\n"
  "    vec3 g1 = poly[(k + 1) % count];\n"
  "    vec3 c = cross(g0, g1);\n"
  "    float s = length(c);\n"
  "    if (s > 0.0) sum += Angle(s, dot(g0, g1)) * dot(n, c) / s;\n"
  "  }\n"
  "  return abs(sum) / 6.283185307179586;\n"
  "}\n"
  // a - b for two-float points: the high parts subtract exactly when close
  // (Sterbenz), the low parts carry what float dropped.
  "vec3 Relative(vec3 aHi, vec3 aLo, vec3 bHi, vec3 bLo)\n"
  "{\n"
  "  return (aHi - bHi) + (aLo - bLo);\n"
  "}\n"
  // Eq. 2 with m = 1 where the shooter looks small from p, the exact
  // factor elsewhere (the CPU solver's rule, ProgressiveRadiosity::PointFormFactor).
  "float FormFactor(vec3 pHi, vec3 pLo, vec3 n)\n"
  "{\n"
  "  vec3 d = Relative(shooterCentre, shooterCentreLo, pHi, pLo);\n"
  "  float r2 = dot(d, d);\n"
  // Behind the shooter: nothing. In its plane (a receiver's corner on the
  // edge where it meets the shooter's surface) the contour formula below
  // still holds.
  "  if (!(r2 > 0.0) || dot(shooterNormal, d) > 1e-6) return 0.0;\n"
  "  if (shooterArea / (3.141592653589793 * r2) < discTolerance)\n"
  "  {\n"
  "    float r = sqrt(r2);\n"
  "    float cr = dot(n, d) / r;\n"
  "    float cs = -dot(shooterNormal, d) / r;\n"
  "    if (cr <= 0.0 || cs <= 0.0) return 0.0;\n"
  "    return cr * cs * shooterArea / (3.141592653589793 * r2 + shooterArea);\n"
  "  }\n"
  "  vec3 g[3] = vec3[3](Relative(shooterV0, shooterV0Lo, pHi, pLo), Relative(shooterV1, shooterV1Lo, pHi, pLo),\n"
  "    Relative(shooterV2, shooterV2Lo, pHi, pLo));\n"
  "  return ContourFactor(g, n);\n"
  "}\n"
  "void main()\n"
  "{\n"
  "  ivec2 t = ivec2(texCoord * vec2(textureSize(centreTex, 0)));\n"
  "  if (t.y * atlasWidth + t.x >= elementCount) discard;\n"
  "  vec4 normal = texelFetch(normalTex, t, 0);\n"
  "  if (normal.w == shooterTriangle) discard;\n"
  "  vec3 n = normal.xyz;\n"
  "  vec3 centreHi = texelFetch(centreTex, t, 0).xyz;\n"
  "  vec3 centreLo = texelFetch(centreLoTex, t, 0).xyz;\n"
  "  vec3 cornerHi[3] = vec3[3](texelFetch(corner0Tex, t, 0).xyz, texelFetch(corner1Tex, t, 0).xyz,\n"
  "    texelFetch(corner2Tex, t, 0).xyz);\n"
  "  vec3 cornerLo[3] = vec3[3](texelFetch(corner0LoTex, t, 0).xyz, texelFetch(corner1LoTex, t, 0).xyz,\n"
  "    texelFetch(corner2LoTex, t, 0).xyz);\n"
  "  float f[4];\n"
  "  float any = 0.0;\n"
  "  for (int k = 0; k < 4; ++k)\n"
  "  {\n"
  // A corner takes its limit from inside the element, 1e-3 of the way to
  // the centroid (the CPU solver's CornerInset is 1e-6; float's contour
  // formula erred by 1.5e-3 on a closed cube's edges at 1e-5 and by 3e-6
  // at 1e-3): a corner on another surface's plane (a room's edge, a
  // contact) would see that surface edge-on and miss its half of the
  // hemisphere. Its visibility is looked up at the same point
  // (DirectLighting::VisibilityPoint's 1e-3), off the triangle's edge.
  "    vec3 pHi = k < 3 ? cornerHi[k] : centreHi;\n"
  "    vec3 pLo = k < 3 ? cornerLo[k] + 1e-3 * Relative(centreHi, centreLo, cornerHi[k], cornerLo[k]) : centreLo;\n"
  "    f[k] = FormFactor(pHi, pLo, n);\n"
  "    if (f[k] > 0.0) f[k] *= Visible(pHi + pLo, n, normal.w);\n"
  "    any += f[k];\n"
  "  }\n"
  "  if (!(any > 0.0)) discard;\n"
  "  gl_FragData[0] = vec4(shot * f[0], 0.0);\n"
  "  gl_FragData[1] = vec4(shot * f[1], 0.0);\n"
  "  gl_FragData[2] = vec4(shot * f[2], 0.0);\n"
  "  gl_FragData[3] = vec4(shot * f[3], 0.0);\n"
  "}\n";

// Eq. 1's update once the shot is accepted: the irradiance samples take the
// shot's deltas, the residual rho times their area mean (the degree-2 rule
// 3/4 centre + 1/12 corners, as ElementSamples::Mean). Blended (added) into
// targets 0-3 (irradiance) and 4 (unshot radiosity).
const char* const CommitFragment = "//VTK::System::Dec\n"
                                   "//VTK::Output::Dec\n"
                                   "in vec2 texCoord;\n"
                                   "uniform sampler2D delta0Tex;\n"
                                   "uniform sampler2D delta1Tex;\n"
                                   "uniform sampler2D delta2Tex;\n"
                                   "uniform sampler2D deltaCentreTex;\n"
                                   "uniform sampler2D reflectanceTex;\n"
                                   "void main()\n"
                                   "{\n"
                                   "  ivec2 t = ivec2(texCoord * vec2(textureSize(delta0Tex, 0)));\n"
                                   "  vec3 d0 = texelFetch(delta0Tex, t, 0).rgb;\n"
                                   "  vec3 d1 = texelFetch(delta1Tex, t, 0).rgb;\n"
                                   "  vec3 d2 = texelFetch(delta2Tex, t, 0).rgb;\n"
                                   "  vec3 dc = texelFetch(deltaCentreTex, t, 0).rgb;\n"
                                   "  vec3 rho = texelFetch(reflectanceTex, t, 0).rgb;\n"
                                   "  gl_FragData[0] = vec4(d0, 0.0);\n"
                                   "  gl_FragData[1] = vec4(d1, 0.0);\n"
                                   "  gl_FragData[2] = vec4(d2, 0.0);\n"
                                   "  gl_FragData[3] = vec4(dc, 0.0);\n"
                                   "  gl_FragData[4] = vec4(rho * (0.75 * dc + (d0 + d1 + d2) / 12.0), 0.0);\n"
                                   "}\n";

// Section 4.1's subdivision test on the GPU, the gradient criterion (after
// Vedel & Puech 1992, as ProgressiveRadiosity::Shoot): a linear field's
// centre value is the mean of its corners, so the shot's departure from
// that mean measures the change of gradient across the element; judged
// against everything received so far with the shot, so that late, weak
// shots do not split. Elements at their deepest level (reflectance's w 0)
// never split. Fragments that need no split are discarded: an occlusion
// query counts the rest, and the flag texture says which they are.
const char* const SplitFragment =
  "//VTK::System::Dec\n"
  "//VTK::Output::Dec\n"
  "in vec2 texCoord;\n"
  "uniform sampler2D delta0Tex;\n"
  "uniform sampler2D delta1Tex;\n"
  "uniform sampler2D delta2Tex;\n"
  "uniform sampler2D deltaCentreTex;\n"
  "uniform sampler2D irradiance0Tex;\n"
  "uniform sampler2D irradiance1Tex;\n"
  "uniform sampler2D irradiance2Tex;\n"
  "uniform sampler2D irradianceCentreTex;\n"
  "uniform sampler2D reflectanceTex;\n"
  "uniform int atlasWidth;\n"
  "uniform int elementCount;\n"
  "uniform float threshold;\n"
  "float Luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }\n"
  "void main()\n"
  "{\n"
  "  ivec2 t = ivec2(texCoord * vec2(textureSize(delta0Tex, 0)));\n"
  "  if (t.y * atlasWidth + t.x >= elementCount || texelFetch(reflectanceTex, t, 0).w < 0.5) discard;\n"
  "  float d0 = Luminance(texelFetch(delta0Tex, t, 0).rgb);\n"
  "  float d1 = Luminance(texelFetch(delta1Tex, t, 0).rgb);\n"
  "  float d2 = Luminance(texelFetch(delta2Tex, t, 0).rgb);\n"
  "  float dc = Luminance(texelFetch(deltaCentreTex, t, 0).rgb);\n"
  "  float h0 = Luminance(texelFetch(irradiance0Tex, t, 0).rgb) + d0;\n"
  "  float h1 = Luminance(texelFetch(irradiance1Tex, t, 0).rgb) + d1;\n"
  "  float h2 = Luminance(texelFetch(irradiance2Tex, t, 0).rgb) + d2;\n"
  "  float hc = Luminance(texelFetch(irradianceCentreTex, t, 0).rgb) + dc;\n"
  "  float total = abs(0.75 * hc + (h0 + h1 + h2) / 12.0);\n"
  "  if (!(abs(dc - (d0 + d1 + d2) / 3.0) > threshold * total)) discard;\n"
  "  gl_FragData[0] = vec4(1.0);\n"
  "}\n";

// One fragment per shooter node of the power-of-two node texture: the sum
// over its elements (a contiguous range of the element atlas) of the
// signed unshot power U A (rgb) and of mean(|U|) A (alpha). Nodes past
// nodeCount write zero, so the top mipmap level times the texel count is
// the scene's total (section 3.4 reads the average there).
const char* const NodePowerFragment =
  "//VTK::System::Dec\n"
  "//VTK::Output::Dec\n"
  "in vec2 texCoord;\n"
  "uniform sampler2D nodeTex;\n"
  "uniform sampler2D centreTex;\n"
  "uniform sampler2D unshotTex;\n"
  "uniform int nodeWidth;\n"
  "uniform int nodeCount;\n"
  "uniform int atlasWidth;\n"
  "void main()\n"
  "{\n"
  "  ivec2 t = ivec2(texCoord * vec2(nodeWidth));\n"
  "  vec4 power = vec4(0.0);\n"
  "  if (t.y * nodeWidth + t.x < nodeCount)\n"
  "  {\n"
  "    vec4 node = texelFetch(nodeTex, t, 0);\n"
  "    int first = int(node.x + 0.5);\n"
  "    int count = int(node.y + 0.5);\n"
  "    for (int i = first; i < first + count; ++i)\n"
  "    {\n"
  "      ivec2 e = ivec2(i % atlasWidth, i / atlasWidth);\n"
  "      vec3 u = texelFetch(unshotTex, e, 0).rgb;\n"
  "      float a = texelFetch(centreTex, e, 0).w;\n"
  "      power += vec4(u * a, (abs(u.r) + abs(u.g) + abs(u.b)) / 3.0 * a);\n"
  "    }\n"
  "  }\n"
  "  gl_FragData[0] = power;\n"
  "}\n";

// Every node a point at depth scale / (scale + p), p = |mean(P + rho ambient
// A)| its power with the overshooting share (ProgressiveRadiosity::Solve's
// ranking): with the depth test LESS the one-pixel frame buffer keeps the
// node of largest power; a node of no power (depth 1) never passes.
const char* const SelectionVertex = "//VTK::System::Dec\n"
                                    "uniform sampler2D nodeTex;\n"
                                    "uniform sampler2D nodePowerTex;\n"
                                    "uniform sampler2D nodeReflectanceTex;\n"
                                    "uniform int nodeWidth;\n"
                                    "uniform vec3 ambient;\n"
                                    "uniform float powerScale;\n"
                                    "flat out float nodeId;\n"
                                    "void main()\n"
                                    "{\n"
                                    "  ivec2 t = ivec2(gl_VertexID % nodeWidth, gl_VertexID / nodeWidth);\n"
                                    "  vec3 power = texelFetch(nodePowerTex, t, 0).rgb;\n"
                                    "  float area = texelFetch(nodeTex, t, 0).z;\n"
                                    "  vec3 rho = texelFetch(nodeReflectanceTex, t, 0).rgb;\n"
                                    "  vec3 total = power + rho * ambient * area;\n"
                                    "  float p = abs(total.r + total.g + total.b) / 3.0;\n"
                                    "  float depth = powerScale / (powerScale + p);\n"
                                    "  nodeId = float(gl_VertexID);\n"
                                    "  gl_Position = vec4(0.0, 0.0, 2.0 * depth - 1.0, 1.0);\n"
                                    "}\n";

const char* const SelectionFragment = "//VTK::System::Dec\n"
                                      "//VTK::Output::Dec\n"
                                      "flat in float nodeId;\n"
                                      "void main()\n"
                                      "{\n"
                                      "  gl_FragData[0] = vec4(nodeId, 0.0, 0.0, 1.0);\n"
                                      "}\n";
#undef RADIOSITY_HEMICUBE_PROJECTION
} // namespace gpu_shaders
} // namespace radiosity
