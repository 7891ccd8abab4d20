/**
 * @class   vtkRadiosityPass
 * @brief   a render pass that solves a renderer's scene by radiosity and
 *          draws the solution per pixel
 *
 * Set on any vtkOpenGLRenderer (`renderer->SetPass(pass)`), after
 * vtkOSPRayPass: the pass mirrors the renderer with VTK's scene graph (its
 * own vtkViewNodeFactory, vtkRadiosityViewNodeFactory: renderer, actor,
 * polydata and composite polydata mapper, and light nodes), gathers the
 * renderer's visible opaque surface actors and its scene lights into a
 * scene, solves it with GetFilter() (a vtkRadiosityFilter owned by the pass,
 * which holds every setting of the method) and draws the cached solution
 * with the method's mapper (vtkQuadraticInterpolantMapper for Hierarchical,
 * vtkShepardSplatMapper for Meshless, vtkVectorIrradianceMapper for
 * FaceCluster, vtkIrradianceSamplesMapper for Progressive and Progressive
 * (GPU): each element from its own samples) through private
 * actors and a delegate pass (a vtkRenderStepsPass by default), so depth,
 * translucent props, 2D actors and overlays compose as usual.
 *
 * What is solved (SPEC.md, "Scenes from VTK's scene graph and importers"):
 * - actors that are visible, have a mapper with polygons or strips, a
 *   Surface representation and Opacity 1 (and do not ForceTranslucent).
 *   Translucent actors (Opacity < 1), wireframe and points representations
 *   and 2D actors are not solved: they are drawn by the delegate pass as VTK
 *   draws them, over the solution; a solved actor's light does not reach
 *   them and they cast no shadow in the solution.
 * - world transforms: the actor's matrix (GetMatrix) applied to the points;
 *   a part of a vtkAssembly (at any depth) by its assembly path's matrix,
 *   the assembly's and every level's concatenated as vtkAssembly draws it,
 *   and only while the assembly is visible. An assembly some of whose parts
 *   were solved draws its other parts (translucent, wireframe, ...) itself
 *   through the delegate pass, each with its path's matrix; one actor placed
 *   in two assemblies is solved and drawn at its first path only.
 * - reflectance: Diffuse x DiffuseColor, or the mapped scalar colours
 *   (point colours averaged per triangle) when the mapper maps scalars; a
 *   composite block colour replaces DiffuseColor. With interpolation PBR the
 *   base colour x (1 - Metallic). A colour texture with texture coordinates
 *   (the actor's texture; for PBR the property's base colour texture)
 *   multiplies it by the texture's mean over each triangle
 *   (vtkRadiosityTextureColour), as the emissive texture multiplies
 *   EmissiveFactor. These are display colours: each component
 *   is clamped to MaxReflectance (0.95, SPEC "Scenes"), with a warning
 *   counting the actors clamped.
 * - emission: a cell array `Emission` on the input (W/m^2), plus for PBR
 *   EmissiveFactor x LightScale (so that an EmissiveFactor of 1 is drawn as
 *   white, as VTK draws it).
 * - Specular x SpecularColor and SpecularPower become the `Specular` and
 *   `Shininess` of the glossy display (FaceCluster's mapper draws them).
 * - sides: surfaces are one-sided (SPEC "Scenes"): the side the triangle's
 *   right-hand normal points to is solved, or only the back side when the
 *   property culls front faces (FrontfaceCulling). TwoSided on solves every
 *   surface on both sides (SPEC `TwoSided`: twice the triangles), as VTK's
 *   two-sided lighting shows them; vtkRadiosityRendererNode::TWO_SIDED() set
 *   to 1 in an actor's PropertyKeys does so for that actor alone (the
 *   command line sets it on a glTF doubleSided material's actors). The solution is drawn with back faces
 *   culled, so a one-sided surface seen from behind is not drawn.
 * - composite input (vtkCompositePolyDataMapper2): each visible leaf one
 *   object with its block colour; blocks with an opacity below 1 are left
 *   out of the solve and, since the actor is drawn by the solution, not
 *   drawn at all.
 * - ParaView's LOD actor: the actor node follows GetMapper(), the
 *   full-resolution mapper, never the LOD one, so interaction does not
 *   re-solve.
 * - lights: the renderer's scene lights (vtkLight::LightTypeIsSceneLight),
 *   mapped by vtkRadiositySceneConverter::ToLight (positional with
 *   ConeAngle < 90 a spot, positional a point, else directional) with the
 *   filter's LightScale. Headlights and camera lights are not solved: they
 *   move with the camera, and a solution lit by them would be solved again
 *   at every camera move.
 *
 * The solution is solved again only when what was gathered changed: the
 * actors' and their properties', mappers', inputs' (each block's),
 * transforms' and composite display attributes' MTimes, the set of solved
 * actors, the scene lights' MTimes, or the filter's settings (its MTime).
 * A camera move only redraws. A pass keeps the scene graph of one renderer:
 * give each renderer a pass of its own. During a solve the pass invokes StartEvent,
 * ProgressEvent (call data: a double* fraction in [0, 1]) and EndEvent.
 *
 * Bad input (a NaN colour, a bad Emission array, a bad light) fails
 * UpdateSolution with an error naming the actor (its index among the
 * renderer's actors and its class), the array or the light; no partial
 * solution is kept, and until the input changes the solved actors are drawn
 * as VTK draws them. During hardware selection (vtkHardwareSelector) the
 * selector draws the renderer's own props, as for a renderer without a
 * pass, and nothing is solved.
 */
#ifndef vtkRadiosityPass_h
#define vtkRadiosityPass_h

#include "RadiosityRenderingSceneGraphModule.h" // for export macro
#include "vtkRenderPass.h"
#include "vtkSmartPointer.h" // for members
#include <vector> // for AddUnsolvedParts

class vtkAssembly;
class vtkProp;
class vtkProp3D;
class vtkRadiosityFilter;
class vtkRadiosityPassDisplay;
class vtkRadiosityRendererNode;
class vtkRenderStepsPass;
class vtkRenderer;
class vtkViewNodeFactory;
class vtkCallbackCommand;

class RADIOSITYRENDERINGSCENEGRAPH_EXPORT vtkRadiosityPass : public vtkRenderPass
{
public:
  static vtkRadiosityPass* New();
  vtkTypeMacro(vtkRadiosityPass, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Solves the renderer's scene when it changed (UpdateSolution), then draws
   * the cached solution and the props that are not solved through the
   * delegate pass.
   */
  void Render(const vtkRenderState* s) override;

  /**
   * Gathers the renderer's scene through the view nodes (Build and
   * Synchronize; no OpenGL context needed) and solves it when what was
   * gathered changed since the last solve. Returns false, with an error
   * naming the actor, array or light, when the scene cannot be solved (then
   * no solution is kept); true otherwise (also when nothing changed).
   */
  bool UpdateSolution(vtkRenderer* renderer);

  /// How many solves ran (failed ones included).
  vtkGetMacro(NumberOfSolves, int);

  /// Whether a solution is cached (the last solve succeeded).
  bool HasSolution() const;

  /**
   * The filter that solves, owned by the pass: every setting of the method
   * lives there (Method, Tolerance, ..., LightScale, SkyModel, SkyRadiance,
   * SkyUp). After a solve its GetSolution(), GetScene(), GetStatistics() and
   * GetOutput(0), GetOutput(1) hold the result. Its input and vtkLights are
   * set by the pass.
   */
  vtkRadiosityFilter* GetFilter();

  ///@{
  /// Forwards to GetFilter().
  void SetMethod(int method);
  int GetMethod();
  void SetLightScale(double scale);
  double GetLightScale();
  void SetSkyModel(int model);
  int GetSkyModel();
  void SetSkyRadiance(double r, double g, double b);
  void SetSkyRadiance(const double radiance[3]);
  double* GetSkyRadiance() VTK_SIZEHINT(3);
  void SetSkyUp(double x, double y, double z);
  void SetSkyUp(const double up[3]);
  double* GetSkyUp() VTK_SIZEHINT(3);
  ///@}

  ///@{
  /**
   * Display colours (vtkProperty, scalar colours) at or above this are
   * clamped to it (SPEC "Scenes": white is a display colour, not an albedo).
   * Default 0.95, clamped to [0.01, 0.999].
   */
  vtkSetClampMacro(MaxReflectance, double, 0.01, 0.999);
  vtkGetMacro(MaxReflectance, double);
  ///@}

  ///@{
  /// Whether every solved surface is solved on both sides (see the class
  /// doc). Default off.
  vtkSetMacro(TwoSided, bool);
  vtkGetMacro(TwoSided, bool);
  vtkBooleanMacro(TwoSided, bool);
  ///@}

  ///@{
  /**
   * Whether Render solves (calls UpdateSolution) before it draws. Default
   * on. Off: the application calls UpdateSolution before each render, and
   * Render only draws the last solution. ParaView's Radiosity Render View
   * does so on MPI ranks: there IceT calls the pass's Render only on the
   * ranks with something in view, and a distributed solve is a collective
   * that every rank must enter.
   */
  vtkSetMacro(SolveOnRender, bool);
  vtkGetMacro(SolveOnRender, bool);
  vtkBooleanMacro(SolveOnRender, bool);
  ///@}

  ///@{
  /// Scale of the drawn radiance B / pi (the mappers' Exposure). Default 1,
  /// clamped to [0, 1e12]. Redraws; does not solve again.
  vtkSetClampMacro(Exposure, double, 0.0, 1e12);
  vtkGetMacro(Exposure, double);
  ///@}

  ///@{
  /**
   * The per-fragment tone mapping of the drawn radiance
   * (vtkRadiosityCellTexelMapper::ToneMappingOperator): CLAMP (0, the
   * default: the radiance as VTK's own shading would show it, LightScale's
   * calibration), REINHARD (1) or EXPONENTIAL (2). Redraws only.
   */
  vtkSetClampMacro(ToneMapping, int, 0, 2);
  vtkGetMacro(ToneMapping, int);
  ///@}

  ///@{
  /// The pass that draws (default a vtkRenderStepsPass); null restores the default.
  void SetDelegatePass(vtkRenderPass* pass);
  vtkRenderPass* GetDelegatePass();
  ///@}

  /// The pass's own factory of scene-graph nodes.
  vtkViewNodeFactory* GetFactory();

  /// The scene graph of the last renderer gathered (null before one).
  vtkRadiosityRendererNode* GetSceneGraph();

  /**
   * The private actors that draw the solution, and through them the
   * method's mappers: for Meshless, GetDisplay()->GetSplatMapper() chooses
   * between the Shepard field evaluated once per solve on a grid of texels
   * on the surface (SURFACE_TEXELS, the default: a redraw as fast as the
   * other methods') and the exact per-pixel splats (SPLATS: seconds a
   * redraw without a GPU). Display settings never re-solve.
   */
  vtkRadiosityPassDisplay* GetDisplay();

  /// Releases the private actors' and the delegate's graphics resources.
  void ReleaseGraphicsResources(vtkWindow* window) override;

  /// The filter's MTime too (its settings).
  vtkMTimeType GetMTime() override;

protected:
  vtkRadiosityPass();
  ~vtkRadiosityPass() override;

  double MaxReflectance = 0.95;
  bool TwoSided = false;
  bool SolveOnRender = true;
  double Exposure = 1.0;
  int ToneMapping = 0;
  int NumberOfSolves = 0;

private:
  /// Writes the settings into the renderer's information (vtkRadiosityRendererNode's keys).
  void PublishSettings(vtkRenderer* renderer);
  /// An assembly with a solved part: its parts not solved are added to
  /// `props` with their path's matrix poked (`poked`, restored after the
  /// draw) and true returned; false when no part was solved (the assembly
  /// is drawn as it is).
  bool AddUnsolvedParts(vtkAssembly* assembly, std::vector<vtkProp*>& props,
    std::vector<vtkProp3D*>& poked);

  vtkRadiosityPass(const vtkRadiosityPass&) = delete;
  void operator=(const vtkRadiosityPass&) = delete;

  /// Forwards the filter's ProgressEvent during a solve.
  static void ForwardProgress(vtkObject* caller, unsigned long event, void* self, void* data);

  vtkSmartPointer<vtkRadiosityFilter> Filter;
  vtkSmartPointer<vtkViewNodeFactory> Factory;
  vtkSmartPointer<vtkRadiosityRendererNode> SceneGraph;
  vtkSmartPointer<vtkRadiosityPassDisplay> Display;
  vtkSmartPointer<vtkRenderPass> DelegatePass;
  vtkSmartPointer<vtkRenderStepsPass> DefaultPass;
  vtkSmartPointer<vtkCallbackCommand> ProgressObserver;
};

#endif
