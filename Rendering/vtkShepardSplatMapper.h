/**
 * @class   vtkShepardSplatMapper
 * @brief   Draws a meshless multilevel Shepard irradiance field per pixel by
 *          splatting its basis functions (Lehtinen et al. 2007, section 6.2).
 *
 * Two inputs:
 *
 * - port 0, the surface to draw: a vtkPolyData of polygons (vertices, lines
 *   and strips are refused with an error naming the cell) with the optional
 *   cell arrays of SPEC.md `Reflectance` (3; 0.5 grey without), `Emission`
 *   (3, W/m^2; none without) and `ObjectId` (1; the reconstruction group);
 * - port 1 (SetFieldConnection), the field: the output of
 *   port 1 of vtkRadiosityFilter (Method Meshless), one point per basis function with the point
 *   arrays `Level` (0 = coarsest), `Radius` (support radius r_j), `Normal`
 *   (n_j), `Group` and `Coefficient` (RGB alpha_j, W/m^2). A missing or
 *   malformed array is refused with an error naming it.
 *
 * Every pixel shows the radiance of the visible point x with normal n,
 * L = (Emission + Reflectance * E(x, n)) / pi * Exposure, where E is the
 * irradiance of eq. 9, the sum over levels of the level's normalised Shepard
 * interpolation (eqs. 8, 12, 13):
 *
 *   E(x, n) = sum_l  sum_{j in l} w_j alpha_j / sum_{j in l} w_j,
 *   w_j = K(|x - x_j| / r_j) max(0, n . n_j),  K(r) = 2r^3 - 3r^2 + 1,
 *
 * over the field points of the surface cell's group (`ObjectId`; all points
 * when the surface has no such array), a level with no weight at x adding
 * nothing. This is what vtkShepardFieldProbe evaluates on the CPU: with
 * Evaluation SPLATS the two agree to the float precision of the GPU. The
 * default, SURFACE_TEXELS, evaluates E once per field and surface at the
 * nodes of a grid on each polygon and interpolates it bilinearly per pixel,
 * a redraw 100 times faster on llvmpipe at the price of a measured
 * interpolation error (see SetEvaluation).
 *
 * How SPLATS works (the paper's deferred shading, section 6.2), once per render:
 *
 * 1. G-buffer. The superclass draws the surface into float targets of the
 *    viewport's size: model-coordinate position and group, the cell's normal
 *    (Newell's, from its points: the field's normals are the cells'), and the
 *    cell's reflectance and emission, read from a texture buffer at
 *    gl_PrimitiveID as for cell scalars; and the depth.
 * 2. Splats, level by level. Every basis function of the level is drawn as a
 *    screen quad bounding the exact projection of its support ball (nothing
 *    when the ball lies behind the eye or outside the frustum, the whole
 *    viewport when it reaches behind the eye), at the ball's farthest depth,
 *    depth-tested against the G-buffer so that pixels whose surface lies
 *    behind the ball are rejected before shading; the quads are
 *    issued from a texture buffer of the level-sorted points (three texels a
 *    point), with no vertex data. With Culling (the default), only the
 *    points of the nodes that can contribute are issued: each level's
 *    points lie along a Morton curve, cut into nodes with the boxes of
 *    their balls; the nodes outside the view frustum are dropped on the CPU,
 *    and each other node's box is drawn in an occlusion query whose
 *    fragments pass where the G-buffer's point lies in the box (its back
 *    faces, with depth clamping), the node dropped when none does (see
 *    SetCulling). The fragment shader evaluates w_j at the
 *    G-buffer's point and adds (w_j alpha_j, w_j) into a float target with
 *    additive blending; a full-screen pass then adds the level's
 *    sum(w alpha) / sum(w) into the irradiance target.
 * 3. Composite. A full-screen pass writes L^(1/Gamma) and the G-buffer's
 *    depth into the framebuffer the renderer draws into, so other actors
 *    occlude and are occluded as usual.
 *
 * The output is meant for the float framebuffer of a vtkToneMappingPass
 * (see vtkQuadraticInterpolantMapper for the Gamma convention). Lighting,
 * colour, scalar colouring, textures and surface edges are ignored; the actor
 * is drawn opaque. Hardware picking draws the surface as any polydata mapper.
 *
 * @code
 * radiosity->SetMethodToMeshless();
 * vtkNew<vtkShepardSplatMapper> mapper;
 * mapper->SetInputConnection(surface->GetOutputPort());
 * mapper->SetFieldConnection(radiosity->GetOutputPort(1)); // the Shepard field
 * @endcode
 *
 * @sa vtkRadiosityFilter, vtkShepardFieldProbe, vtkToneMappingPass
 */

#ifndef vtkShepardSplatMapper_h
#define vtkShepardSplatMapper_h

#include "RadiosityRenderingModule.h" // For export macro
#include "vtkRadiosityCellTexelMapper.h"

#include <memory> // For members
#include <string> // For ValidateSurface
#include <vector> // For members

class vtkAlgorithmOutput;
class vtkPolyData;
class vtkMatrix4x4;
class vtkRadiosityTexelBuffer;
class vtkShepardSplatNodes;
class vtkShepardSplatPasses;

class RADIOSITYRENDERING_EXPORT vtkShepardSplatMapper : public vtkRadiosityCellTexelMapper
{
public:
  static vtkShepardSplatMapper* New();
  vtkTypeMacro(vtkShepardSplatMapper, vtkRadiosityCellTexelMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The field (input port 1): port 1 of vtkRadiosityFilter with Method Meshless.
   */
  void SetFieldConnection(vtkAlgorithmOutput* output);
  void SetFieldData(vtkPolyData* field);
  vtkPolyData* GetField();
  ///@}

  /**
   * Whether `surface` can be drawn: polygons only, and `Reflectance`,
   * `Emission` (3 components) and `ObjectId` (1), when present, numeric with a
   * tuple per cell. Otherwise false with `message` naming the cell or array.
   */
  static bool ValidateSurface(vtkPolyData* surface, std::string* message);

  /**
   * Whether `field` is a Shepard field: the point arrays `Level`, `Radius`,
   * `Group` (1 component), `Normal` and `Coefficient` (3), numeric with a
   * tuple per point, levels in [0, 64) and radii finite and positive; or a
   * field without points (nothing is splatted: the surface shows its
   * emission alone). Otherwise false with `message` naming the array.
   */
  static bool ValidateField(vtkPolyData* field, std::string* message);

  /// Levels of the field at the last render (0 before).
  int GetNumberOfLevels() const;

  /**
   * How E(x, n) reaches the pixels:
   *
   * - SPLATS: exact per pixel, the deferred splatting of the class
   *   description, every render. Seconds a frame on llvmpipe for a field of
   *   tens of thousands of points (19.2 s, then 5.5 s with the ball bounds,
   *   for the office's 29323 points at 1280 x 720, with another build on
   *   the two cores): the coarse levels' supports each cover most of the
   *   screen, and every pixel is shaded once per support that covers it.
   * - SURFACE_TEXELS (default): E evaluated once per field and surface, on
   *   the CPU, at the nodes of a grid on each polygon's plane
   *   (TexelSpacing times the field's smallest support radius), and
   *   interpolated bilinearly per pixel: one pass over the surface per
   *   render. The difference to SPLATS is the interpolation's, largest
   *   where a level's support ends and E jumps: on the office (whose
   *   levels cover every surface) at most 1/255 of the displayed image, in
   *   0.3% of its channels; 11/255 along the edge of a level that stops
   *   halfway across a face (TestShepardSplatMapper). The evaluation runs on
   *   the first render after the field or surface changes: 1.9 s for the
   *   office's 1916732 texels at spacing 0.125 on two shared cores.
   */
  enum EvaluationModes
  {
    SPLATS = 0,
    SURFACE_TEXELS = 1
  };
  vtkSetClampMacro(Evaluation, int, SPLATS, SURFACE_TEXELS);
  vtkGetMacro(Evaluation, int);
  void SetEvaluationToSplats() { this->SetEvaluation(SPLATS); }
  void SetEvaluationToSurfaceTexels() { this->SetEvaluation(SURFACE_TEXELS); }

  ///@{
  /**
   * SURFACE_TEXELS: the node spacing as a fraction of the smallest support
   * radius of the field (default 0.25), and the most nodes (default 4M,
   * 16 bytes each on the GPU; at most 2^24, the float-exact indices); the
   * spacing grows until the nodes fit, down to four a polygon (a surface
   * of more than 2^22 polygons is refused with an error: use SPLATS).
   */
  vtkSetClampMacro(TexelSpacing, double, 1e-3, 10.0);
  vtkGetMacro(TexelSpacing, double);
  vtkSetClampMacro(MaximumTexels, vtkIdType, 1024, 1 << 24);
  vtkGetMacro(MaximumTexels, vtkIdType);
  ///@}

  ///@{
  /**
   * SPLATS: culling of the basis functions (Lehtinen et al. 2007, section
   * 6.2), on by default. Each level's points are sorted along a Morton curve
   * and cut into nodes of PointsPerNode consecutive points (default 128),
   * each with the box of its support balls. Every render, the nodes whose
   * box lies outside the view frustum are dropped; then, with
   * OcclusionQueries (on by default), each remaining node's box is drawn
   * against the G-buffer in an occlusion query and dropped when no visible
   * surface point lies in it (the box wholly hidden behind the surfaces,
   * or floating in front of them). A basis function contributes only where
   * a visible point lies in its ball, so only functions that add nothing
   * are dropped: the image is the unculled one (TestShepardSplatCulling
   * measures it equal). Off: every point is issued, as before (each still
   * dropped in the vertex shader when its ball is off-screen).
   */
  vtkSetMacro(Culling, bool);
  vtkGetMacro(Culling, bool);
  vtkBooleanMacro(Culling, bool);
  vtkSetMacro(OcclusionQueries, bool);
  vtkGetMacro(OcclusionQueries, bool);
  vtkBooleanMacro(OcclusionQueries, bool);
  vtkSetClampMacro(PointsPerNode, int, 1, 1 << 20);
  vtkGetMacro(PointsPerNode, int);
  ///@}

  ///@{
  /**
   * SPLATS, at the last render: the basis functions drawn, those dropped
   * because their node lies outside the view frustum or its occlusion query
   * found no visible point in its box (all 0 before a SPLATS render; without
   * Culling every point is drawn), and the occlusion queries issued.
   */
  vtkIdType GetNumberOfSplattedPoints() const { return this->SplattedPoints; }
  vtkIdType GetNumberOfFrustumCulledPoints() const { return this->FrustumCulledPoints; }
  vtkIdType GetNumberOfOcclusionCulledPoints() const { return this->OcclusionCulledPoints; }
  vtkIdType GetNumberOfOcclusionQueries() const { return this->OcclusionQueryCount; }
  /// The culling nodes (0 before a SPLATS render with Culling).
  vtkIdType GetNumberOfCullingNodes() const;
  ///@}

  /// SURFACE_TEXELS: the spacing of the last evaluation (model units; 0
  /// before one or without points) and its nodes.
  double GetTexelSpacingUsed() const { return this->TexelSpacingUsed; }
  vtkIdType GetNumberOfTexels() const { return static_cast<vtkIdType>(this->Nodes.size() / 4); }

  void ReleaseGraphicsResources(vtkWindow* win) override;

protected:
  vtkShepardSplatMapper();
  ~vtkShepardSplatMapper() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;

  /**
   * The three passes of the class description; without a selector. Under
   * hardware selection the superclass draws the surface's ids.
   */
  void RenderPiece(vtkRenderer* ren, vtkActor* act) override;

  /**
   * Checks the surface (an error, and nothing drawn, when ValidateSurface
   * refuses it) and rebuilds its per-cell texels when it changed.
   */
  void UpdateCameraShiftScale(vtkRenderer* ren, vtkActor* act) override;

  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderLight(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;

  ///@{
  /// SURFACE_TEXELS: uploads and binds the nodes around the draw.
  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  ///@}


private:
  vtkShepardSplatMapper(const vtkShepardSplatMapper&) = delete;
  void operator=(const vtkShepardSplatMapper&) = delete;

  // Updates port 1 and rebuilds the level-sorted point texels when the field
  // changed; false (with an error) when there is none or it is refused.
  bool UpdateField();
  // MCDCMatrix of the actor and camera, for the splats.
  static void ModelToClip(vtkRenderer* ren, vtkActor* act, vtkMatrix4x4* out);

  // CellTexels per cell: (Reflectance, group), (Emission, 0), (normal, 0).
  vtkPolyData* CellTexelsSource = nullptr; // compared only
  vtkMTimeType CellTexelsSourceTime = 0;
  bool SurfaceValid = false;
  std::string SurfaceError;
  bool WarnedNoReflectance = false;

  // Per point, sorted by level: (x_j, r_j), (n_j, group), (alpha_j, 0);
  // LevelOffsets[l] is the first point of level l.
  std::vector<float> PointTexels;
  std::vector<size_t> LevelOffsets;
  vtkTimeStamp PointTexelsTime;
  vtkPolyData* PointTexelsSource = nullptr; // compared only
  vtkMTimeType PointTexelsSourceTime = 0;
  std::string FieldError;

  int Evaluation = SURFACE_TEXELS;
  double TexelSpacing = 0.25;
  vtkIdType MaximumTexels = 4 << 20;
  // SURFACE_TEXELS: E at the nodes (RGBA), the cells' frames in CellTexels;
  // what they were evaluated for.
  std::vector<float> Nodes;
  vtkTimeStamp NodesTime;
  vtkMTimeType NodesFieldTime = 0;
  vtkMTimeType NodesCellTime = 0;
  double NodesSpacing = 0.0;
  vtkIdType NodesMaximum = 0;
  double TexelSpacingUsed = 0.0;
  bool NodesReady = false;
  bool NodesActive = false;
  std::unique_ptr<vtkRadiosityTexelBuffer> NodeBuffer;

  std::unique_ptr<vtkRadiosityTexelBuffer> PointBuffer;
  std::unique_ptr<vtkShepardSplatPasses> Passes;

  // SPLATS culling: the nodes of the points, built for PointTexelsTime and
  // PointsPerNode, and their boxes on the GPU.
  bool Culling = true;
  bool OcclusionQueries = true;
  int PointsPerNode = 128;
  std::unique_ptr<vtkShepardSplatNodes> CullingNodes;
  vtkTimeStamp CullingNodesTime;
  std::unique_ptr<vtkRadiosityTexelBuffer> BoxBuffer;
  vtkIdType SplattedPoints = 0;
  vtkIdType FrustumCulledPoints = 0;
  vtkIdType OcclusionCulledPoints = 0;
  vtkIdType OcclusionQueryCount = 0;
};

#endif
