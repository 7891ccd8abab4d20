// The GPU passes of vtkShepardSplatMapper (Lehtinen et al. 2007, section
// 6.2, deferred shading of a meshless field): the G-buffer targets, the
// level-by-level splatting of the basis functions with their per-level
// normalisation, and the composite into the renderer's framebuffer. The
// mapper draws the surface into the G-buffer between BeginGBuffer and
// EndGBuffer; see its class description for the algorithm. Not wrapped.
#ifndef vtkShepardSplatPasses_h
#define vtkShepardSplatPasses_h

#include "vtkNew.h"

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

class vtkIndent;
class vtkMatrix4x4;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkOpenGLVertexArrayObject;
class vtkRadiosityTexelBuffer;
class vtkShepardSplatNodes;
class vtkTextureObject;
class vtkWindow;

class vtkShepardSplatPasses
{
public:
  vtkShepardSplatPasses();
  ~vtkShepardSplatPasses();
  vtkShepardSplatPasses(const vtkShepardSplatPasses&) = delete;
  vtkShepardSplatPasses& operator=(const vtkShepardSplatPasses&) = delete;

  /// (Re)allocates the float targets for a width x height viewport.
  bool Allocate(vtkOpenGLRenderWindow* window, int width, int height);
  int GetWidth() const { return this->Width; }
  int GetHeight() const { return this->Height; }

  /// The framebuffer of the passes; the caller binds it between its own
  /// PushFramebufferBindings and PopFramebufferBindings.
  vtkOpenGLFramebufferObject* GetFramebuffer();

  /// Attaches and clears the G-buffer targets (position and coverage,
  /// normal and group, reflectance and coverage, emission; depth) and sets
  /// the viewport and the depth, blend and scissor state for drawing the
  /// surface into them; EndGBuffer detaches them.
  void BeginGBuffer(vtkOpenGLState* state);
  void EndGBuffer();

  /// Which basis functions Splat draws, and what it dropped.
  struct Culling
  {
    /// The nodes of the points; null: every point is drawn.
    const vtkShepardSplatNodes* Nodes = nullptr;
    /// The nodes' boxes (vtkShepardSplatNodes::GetBoxTexels) for the
    /// occlusion queries; null: none (the frustum alone).
    vtkRadiosityTexelBuffer* Boxes = nullptr;
    size_t Splatted = 0;        ///< points drawn
    size_t FrustumCulled = 0;   ///< in nodes outside the view frustum
    size_t OcclusionCulled = 0; ///< in nodes whose box holds no G-buffer point
    size_t Queries = 0;         ///< occlusion queries issued
  };

  /**
   * Splats the level-sorted points (three texels each, `points` active)
   * level by level into the irradiance target, levelOffsets[l] being the
   * first point of level l; `modelToClip` is MCDCMatrix. With
   * `culling.Nodes`, only the nodes that can contribute (see the .cxx). No
   * points leave the irradiance zero. False with `error` when a shader does
   * not build.
   */
  bool Splat(vtkOpenGLRenderWindow* window, vtkMatrix4x4* modelToClip,
    vtkRadiosityTexelBuffer* points, const std::vector<size_t>& levelOffsets, Culling& culling,
    std::string& error);

  /// Writes the radiance (Emission + Reflectance E) / pi * exposure, tone
  /// mapped and encoded as vtkRadiosityCellTexelMapper does, and the
  /// G-buffer's depth into the bound framebuffer.
  bool Composite(vtkOpenGLRenderWindow* window, double exposure, double gamma, int toneMapping,
    std::string& error);

  void ReleaseGraphicsResources(vtkWindow* window);

  /// The G-buffer's size and which shaders are built (for the mapper's PrintSelf).
  void PrintSelf(std::ostream& os, vtkIndent indent) const;

private:
  // Clears draw[n] for the nodes whose box holds no G-buffer point
  // (one occlusion query each); false with `error` when the shader does
  // not build.
  bool Occlude(vtkOpenGLRenderWindow* window, vtkMatrix4x4* modelToClip,
    const vtkShepardSplatNodes& nodes, vtkRadiosityTexelBuffer* boxes,
    std::vector<unsigned char>& draw, Culling& culling, std::string& error);

  vtkNew<vtkOpenGLFramebufferObject> Framebuffer;
  vtkNew<vtkTextureObject> Position;
  vtkNew<vtkTextureObject> Normal;
  vtkNew<vtkTextureObject> Reflectance;
  vtkNew<vtkTextureObject> Emission;
  vtkNew<vtkTextureObject> LevelSums;
  vtkNew<vtkTextureObject> Irradiance;
  vtkNew<vtkTextureObject> Depth;
  vtkNew<vtkOpenGLVertexArrayObject> SplatArrays; // none: an empty VAO
  std::unique_ptr<vtkOpenGLQuadHelper> Normalise;
  std::unique_ptr<vtkOpenGLQuadHelper> CompositeQuad;
  std::vector<unsigned int> Queries; // occlusion query objects, reused
  vtkOpenGLRenderWindow* QueriesContext = nullptr;
  int Width = 0;
  int Height = 0;
};

#endif
