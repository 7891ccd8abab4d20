// The OpenGL side of progressive radiosity on the GPU (Coombe, Harris &
// Lastra 2004): an offscreen VTK OpenGL context, the element and node
// texture atlases, and the four passes of one shot (ProgressiveGPUShaders.h
// says what each computes). ProgressiveGPUMethod does the bookkeeping on the
// CPU, as the paper's host does: it reads back one pixel of totals and one
// of the chosen node per shot, and the solution once at the end.
#ifndef Radiosity_ProgressiveGPUPasses_h
#define Radiosity_ProgressiveGPUPasses_h

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace radiosity
{
/// What the element atlas holds per element (texel), in the scene's
/// centred coordinates divided by its diagonal; areas likewise.
struct GPUElementTexels
{
  int Width = 0;  ///< atlas width in texels (the element at y * Width + x)
  int Height = 0;
  std::size_t Count = 0;
  std::vector<float> Centre, Corner0, Corner1, Corner2; ///< xyz, w: area (Centre) or 0
  /// What float rounding dropped of each position (two-float positions:
  /// the form factor kernel subtracts them without losing digits).
  std::vector<float> CentreLo, Corner0Lo, Corner1Lo, Corner2Lo;
  std::vector<float> Normal;      ///< xyz, w: the input triangle's index
  std::vector<float> Reflectance; ///< rgb
  std::vector<float> Irradiance0, Irradiance1, Irradiance2, IrradianceCentre; ///< rgb: initial
  std::vector<float> Unshot; ///< rgb: initial unshot radiosity
};

/// The shooter nodes in a power-of-two square (section 3.4's mipmap).
struct GPUNodeTexels
{
  int Width = 0; ///< a power of two; Width * Width >= Count
  std::size_t Count = 0;
  std::vector<float> Range;       ///< x: first element, y: element count, z: area
  std::vector<float> Reflectance; ///< rgb
};

/// One shooter (a node or a part of it) and the light it shoots.
struct GPUShooter
{
  std::array<std::array<float, 3>, 3> Vertices{}, VerticesLo{}; ///< two-float, as GPUElementTexels
  std::array<float, 3> Centre{}, CentreLo{}, Normal{}, FrameU{}, FrameV{};
  float Area = 0.0f;
  float Triangle = 0.0f; ///< its input triangle
  std::array<float, 3> Shot{}; ///< radiosity shot (W/m^2)
};

class ProgressiveGPUPasses
{
public:
  /// Opens an offscreen OpenGL context (SceneError when none can be
  /// opened, with the reason) and builds the programs.
  ProgressiveGPUPasses();
  ~ProgressiveGPUPasses();
  ProgressiveGPUPasses(const ProgressiveGPUPasses&) = delete;
  ProgressiveGPUPasses& operator=(const ProgressiveGPUPasses&) = delete;

  /// "llvmpipe (LLVM 15.0.6, 256 bits)", the context's GL_RENDERER.
  const std::string& Renderer() const;
  /// The largest texture edge the context allows.
  int MaxTextureSize() const;

  /// Once: the triangles that can occlude, for the item buffer (per vertex
  /// x, y, z in scaled coordinates and the triangle's index: 12 floats a
  /// triangle), the item buffer of `hemicubeResolution` and the programs;
  /// false with `error` when the context cannot hold them.
  bool Prepare(const std::vector<float>& triangles, int hemicubeResolution, std::string& error);
  /// The element and node atlases, at the start and again after elements
  /// were subdivided (the textures are made anew at the new size).
  bool UploadAtlas(const GPUElementTexels& elements, const GPUNodeTexels& nodes, std::string& error);

  /// Section 3.4's totals over every node: signed unshot power (rgb) and
  /// the sum of mean(|U|) A (the fourth), from the node texture's top mipmap level.
  std::array<double, 4> NodeTotals();
  /// The node of largest |mean(P + rho ambient A)| by the z-buffer maximum,
  /// -1 when every node has none; its power P (rgb) in `power`.
  long long SelectShooter(const std::array<float, 3>& ambient, float powerScale, std::array<double, 3>& power);
  /// Clears the shot's deltas (before a shooter's first part).
  void BeginShot();
  /// Section 3.2: the item buffer from `shooter`, then every element adds
  /// its shot to the deltas.
  void Shoot(const GPUShooter& shooter, float discTolerance);
  /// Section 4.1: how many elements the shot's deltas ask to subdivide
  /// (gradient criterion, `threshold` relative); ReadSplitFlags says which
  /// (x of each texel: 1 to split).
  std::size_t CountSplits(float threshold);
  std::vector<float> ReadSplitFlags();
  /// Eq. 1: the deltas join the irradiance, rho times their mean the residual.
  void CommitShot();
  /// Sets the unshot radiosity of elements [first, first + count) to `value`.
  void SetUnshot(std::size_t first, std::size_t count, const std::array<float, 3>& value);
  /// The five element targets read back: corner 0-2 and centre irradiance, unshot (RGBA each).
  std::array<std::vector<float>, 5> ReadElements();

private:
  struct Internals;
  std::unique_ptr<Internals> GL;
};
} // namespace radiosity

#endif
