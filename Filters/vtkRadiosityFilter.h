/**
 * @class   vtkRadiosityFilter
 * @brief   global illumination of a diffuse surface scene by radiosity
 *
 * Input: vtkPolyData or a composite dataset (each block one object) with the
 * SPEC.md material cell arrays. Output: the solution's elements as polydata
 * with `Irradiance` and `Radiosity` on points and cells, `ElementId` and
 * `Level` on cells, and the field data array `ConvergenceHistory`.
 *
 * Methods: Progressive (progressive refinement radiosity with adaptive
 * quadtrees, Coombe et al. 2004 on the CPU); Hierarchical (hierarchical
 * radiosity with BF refinement and the blockers of every partially visible
 * link, the solver of Hardt & Teller); Meshless (Lehtinen et al. 2007);
 * FaceCluster (Gobbetti et al. 2003); ProgressiveGPU (Coombe et al.'s
 * solver on the GPU, in an offscreen OpenGL context of its own: texture
 * atlases, hemicube item buffers; the Progressive settings apply, and
 * HemicubeResolution). Auto, the default, picks one per scene
 * from the measured rules of radiosity::ChooseMethod (MethodChoice.h): face
 * cluster for a glossy scene, hierarchical up to 2048 triangles, meshless
 * above; GetResolvedMethod and GetMethodChoice say which and why.
 *
 * Port 1 is the method's own product as polydata (field data `ProductKind`
 * names it): for Hierarchical the discontinuity mesh with its quadratic
 * interpolants ("DiscontinuityMesh"), for Meshless the Shepard field's
 * points ("ShepardField", also in port 0's field data, see
 * vtkRadiositySceneConverter::AttachPointProduct), for FaceCluster the
 * input triangles with their leaf cluster and vector irradiance
 * ("LeafClusters"); empty for Progressive. Downstream filters, mappers and
 * representations read it like any input.
 *
 * Lights and sky (SPEC.md "Lights and sky"): besides emitting triangles the
 * scene is lit by the vtkLights given (AddLight, SetLights, mapped with
 * LightScale), by the lights of a LIGHTS.json file (LightsFileName), by
 * radiosity::LightSet lights from C++ (SetSceneLights) and by a sky
 * (SkyModel, SkyRadiance, SkyUp); a scene lit only by lights is lit, not
 * empty. A bad light fails the request with an error naming the light's
 * index and field (and the file).
 *
 * Distributed data (ParaView's MPI ranks, any vtkMultiProcessController of
 * several processes; the global controller by default): light does not
 * stop at a piece's boundary, so the ranks' pieces are gathered into one
 * scene (radiosity::AssembleScenePieces: points welded by global id or
 * position, triangles ordered by their cells' global ids when they have
 * them), the scene is solved on every rank with the work split between the
 * ranks (radiosity::WorkShare: the progressive shots' receivers, the
 * meshless gathers, the hierarchical links, the face cluster refinement
 * rounds' transfers), the same answer as one process's to the bit, and
 * each rank's port 0 carries
 * the solution on its own piece (the elements of its own triangles; point
 * values are the whole scene's). An empty piece is normal; a rank's bad
 * input fails the request on every rank. Port 1 (the product of the whole
 * scene) is on rank 0 only, so that ParaView's delivery does not repeat it.
 * The field data arrays `RankTriangles` and `RankBytesReceived` (one tuple
 * per rank) say what each rank gave and received of the scene,
 * `RankWorkItems` and `RankSolveBytesReceived` each rank's share of the
 * solve's split loops (items computed) and the bytes it received in them.
 * A time limit or an abort on one rank stops every rank at the same point.
 *
 * Bad input gives an error naming the array, cell or point and an empty
 * output (GetLastError() keeps the message). Progress events during the solve;
 * AbortExecute stops it (VTK then empties the output; the solution so far
 * stays available through GetSolution()).
 */
#ifndef vtkRadiosityFilter_h
#define vtkRadiosityFilter_h

#include "vtkPolyDataAlgorithm.h"
#include "RadiosityFiltersModule.h" // for export macro

#include "Radiosity/Common/ProbeEvaluator.h" // for radiosity::Probe
#include "Radiosity/Common/Scene.h"       // for radiosity::SceneCleanupReport
#include "Radiosity/Common/SolverTypes.h" // for radiosity::SolverStatistics

#include "vtkSmartPointer.h" // for vtkSmartPointer

#include <memory> // for std::unique_ptr, std::shared_ptr
#include <string> // for std::string
#include <vector> // for std::vector

namespace radiosity
{
class WorkShare;
struct SolutionMesh;
struct SceneAnalysis;
class HierarchicalRadiosity;
class MeshlessRadiosity;
class FaceClusterRadiosity;
class RadiositySolver;
struct ProgressiveOptions;
}

class vtkLight;
class vtkLightCollection;
class vtkMultiProcessController;

class RADIOSITYFILTERS_EXPORT vtkRadiosityFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkRadiosityFilter* New();
  vtkTypeMacro(vtkRadiosityFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Methods
  {
    Auto = 0,
    Progressive = 1,
    Hierarchical = 2,
    Meshless = 3,
    FaceCluster = 4,
    ProgressiveGPU = 5
  };

  /// The polynomial bases of face cluster radiosity (Gobbetti et al. 2003).
  enum Bases
  {
    ConstantBasis = 0,
    LinearBasis = 1,
    BilinearBasis = 2,
    QuadraticBasis = 3,
    CubicBasis = 4
  };

  ///@{
  /// The solution method. Default Auto: chosen per scene at each solve
  /// (radiosity::ChooseMethod).
  vtkSetClampMacro(Method, int, Auto, ProgressiveGPU);
  vtkGetMacro(Method, int);
  void SetMethodToAuto() { this->SetMethod(Auto); }
  void SetMethodToProgressive() { this->SetMethod(Progressive); }
  void SetMethodToHierarchical() { this->SetMethod(Hierarchical); }
  void SetMethodToMeshless() { this->SetMethod(Meshless); }
  void SetMethodToFaceCluster() { this->SetMethod(FaceCluster); }
  void SetMethodToProgressiveGPU() { this->SetMethod(ProgressiveGPU); }
  static const char* GetMethodName(int method);
  ///@}

  ///@{
  /// Stop when the unshot power falls to this fraction of the emitted power
  /// (hierarchical: when the estimated remaining change of the gather sweeps
  /// falls to this fraction of the total power). Default 1e-3.
  vtkSetClampMacro(Tolerance, double, 1e-12, 1.0);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /// Stop after this many shots (hierarchical: gather sweeps). Default 200000.
  vtkSetClampMacro(MaxIterations, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(MaxIterations, vtkIdType);
  ///@}

  ///@{
  /// Stop after this many seconds of solving; 0 means no limit. Default 0.
  /// Hierarchical: the search for discontinuities gets as long again (the
  /// leaves left past it are meshed without theirs, with a warning).
  vtkSetClampMacro(MaxTime, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaxTime, double);
  ///@}

  ///@{
  /// Worker threads; 0 uses every core. Default 0.
  vtkSetClampMacro(NumberOfThreads, int, 0, 4096);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /// Overshooting with the ambient estimate (needed for reflectance near 1). Default on.
  vtkSetMacro(Overshooting, bool);
  vtkGetMacro(Overshooting, bool);
  vtkBooleanMacro(Overshooting, bool);
  ///@}

  ///@{
  /// Longest edge of the shooting elements, as a fraction of the scene diagonal. Default 0.25.
  vtkSetClampMacro(ShooterElementSize, double, 1e-6, 1.0);
  vtkGetMacro(ShooterElementSize, double);
  ///@}

  ///@{
  /// Longest edge of the initial receiving elements, fraction of the diagonal. Default 1/16.
  vtkSetClampMacro(InitialElementSize, double, 1e-6, 1.0);
  vtkGetMacro(InitialElementSize, double);
  ///@}

  ///@{
  /// Adaptive quadtree levels below the initial elements. Default 2.
  vtkSetClampMacro(MaxSubdivisionLevels, int, 0, 10);
  vtkGetMacro(MaxSubdivisionLevels, int);
  ///@}

  ///@{
  /// Departure from a linear field that splits an element, relative. Default 0.1.
  vtkSetClampMacro(SubdivisionThreshold, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(SubdivisionThreshold, double);
  ///@}

  ///@{
  /// Use the disc approximation when A / (pi r^2) is below this. Default 2e-3.
  vtkSetClampMacro(FormFactorTolerance, double, 0.0, 1.0);
  vtkGetMacro(FormFactorTolerance, double);
  ///@}

  ///@{
  /// ProgressiveGPU: pixels along a hemicube face's edge (Coombe 3.2's item buffer). Default 256.
  vtkSetClampMacro(HemicubeResolution, int, 16, 4096);
  vtkGetMacro(HemicubeResolution, int);
  ///@}

  ///@{
  /// Visibility rays per receiver sample towards emitters (1, 4 or 16). Default 16.
  vtkSetClampMacro(VisibilitySamples, int, 1, 16);
  vtkGetMacro(VisibilitySamples, int);
  ///@}

  ///@{
  /// Visibility rays per receiver sample towards reflecting shooters (1, 4 or 16). Default 1.
  vtkSetClampMacro(IndirectVisibilitySamples, int, 1, 16);
  vtkGetMacro(IndirectVisibilitySamples, int);
  ///@}

  /// The sky models of SPEC.md "Lights and sky".
  enum SkyModels
  {
    SkyNone = 0,
    SkyUniform = 1,
    SkyCieOvercast = 2
  };

  ///@{
  /**
   * vtkLights that light the scene (SPEC.md: "A vtkLight maps to a SPEC
   * light", vtkRadiositySceneConverter::ToLight). The filter keeps its own
   * list; the lights themselves are shared, so a change to one of them
   * (its MTime) solves again. SetLights replaces the list with the lights of
   * `lights` (null: none). Lights switched off (GetSwitch) are left out
   * of the solve but still checked, and count in the index an error names
   * ("vtkLights (AddLight, SetLights): light 2 (spot): field 'direction' ...").
   */
  void AddLight(vtkLight* light);
  void SetLights(vtkLightCollection* lights);
  void RemoveAllLights();
  vtkLightCollection* GetLights();
  ///@}

  ///@{
  /**
   * Watts per unit of a vtkLight's Intensity x DiffuseColor: W/sr for a
   * point or spot light, W/m^2 for a directional one. Default pi, so that a
   * directional light of Intensity 1 on a white Lambertian surface facing it
   * looks as bright as VTK's OpenGL shading shows it:
   *
   * - VTK (vtkOpenGLPolyDataMapper, a white vtkProperty: Diffuse 1,
   *   DiffuseColor 1, no ambient): the fragment colour is
   *   Intensity x DiffuseColor x Diffuse x cos(theta) = 1 at normal incidence.
   * - This project's per-pixel mappers (vtkRadiosityCellTexelMapper,
   *   vtkQuadraticInterpolantMapper, vtkVectorIrradianceMapper,
   *   vtkShepardSplatMapper; vtkRadiosityView) write the radiance
   *   L = B / pi x Exposure (Exposure 1 by default), encoded as L^(1/Gamma)
   *   for vtkToneMappingPass. A white Lambertian surface (reflectance 1)
   *   under irradiance E has B = E, so L = E / pi; with E = LightScale x
   *   Intensity at normal incidence, L = 1 needs LightScale = pi. L = 1 is
   *   also the one value that 1^(1/Gamma) and the tone mapping pass's
   *   decoding (c^2.2) leave unchanged, so the two agree whatever Gamma:
   *   drawn without a tone mapping pass both are 1, and under the same
   *   vtkToneMappingPass both become its operator's value of 1
   *   (vtkRadiosityView's default, Reinhard, gives 0.5 to both).
   *
   * Away from normal incidence VTK's colour is cos(theta) unencoded while the
   * mappers encode L = cos(theta) with 1/Gamma (physically displayed), so
   * only the peak matches. Display white is clamped to the scene's maximum
   * reflectance (0.95 by default, SPEC "Scenes"), 5% darker than reflectance
   * 1. A positional vtkLight is a SPEC point or spot light: inverse-square,
   * so at 1 m it matches VTK (whose default AttenuationValues (1, 0, 0) do
   * not fall off). LightScale applies to vtkLights only: the lights of
   * LightsFileName and SetSceneLights are already in SI units.
   */
  vtkSetClampMacro(LightScale, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(LightScale, double);
  ///@}

  ///@{
  /**
   * A sky (SPEC.md "Lights and sky"): none (default), uniform radiance
   * SkyRadiance, or the CIE standard overcast sky of zenith radiance
   * SkyRadiance (L = L_z (1 + 2 cos theta) / 3), W/(m^2 sr) per channel,
   * above the horizon of SkyUp (default (0, 0, 1)). SkyRadiance defaults to
   * (1, 1, 1). Refused when LightsFileName or SetSceneLights has a sky too
   * (a scene has at most one).
   */
  vtkSetClampMacro(SkyModel, int, SkyNone, SkyCieOvercast);
  vtkGetMacro(SkyModel, int);
  void SetSkyModelToNone() { this->SetSkyModel(SkyNone); }
  void SetSkyModelToUniform() { this->SetSkyModel(SkyUniform); }
  void SetSkyModelToCieOvercast() { this->SetSkyModel(SkyCieOvercast); }
  static const char* GetSkyModelName(int model);
  vtkSetVector3Macro(SkyRadiance, double);
  vtkGetVector3Macro(SkyRadiance, double);
  vtkSetVector3Macro(SkyUp, double);
  vtkGetVector3Macro(SkyUp, double);
  ///@}

  ///@{
  /**
   * A LIGHTS.json file (SPEC.md "Lights and sky"), read at every request;
   * null or empty: none. A file that cannot be read or a bad light fails the
   * request with the message naming the file, the light's index and field.
   * Like a reader's file name: a change to the file's contents under the
   * same name solves again after Modified().
   */
  vtkSetFilePathMacro(LightsFileName);
  vtkGetFilePathMacro(LightsFileName);
  ///@}

  /**
   * Lights in the core's form (the command line's --lights), added to the
   * others; validated at the request (an error names "scene light" i).
   */
  void SetSceneLights(const radiosity::LightSet& lights);
  const radiosity::LightSet& GetSceneLights() const { return *this->SceneLights; }

  /// The lights of the last request as the solver had them (file, scene
  /// lights, vtkLights in that order, then the sky); empty before one.
  const radiosity::LightSet& GetLastLighting() const { return this->LastScene->Lighting; }

  /// The MTime of the lights too.
  vtkMTimeType GetMTime() override;

  /// Why the last execution failed ("" when it did not).
  const std::string& GetLastError() const { return this->LastError; }

  /// What the last execution ignored or defaulted.
  const std::vector<std::string>& GetWarnings() const { return this->Warnings; }
  /// Statistics of the last solve (history, counts, times).
  const radiosity::SolverStatistics& GetStatistics() const { return this->Statistics; }
  /**
   * The method the last request solved with: Method itself, or for Auto the
   * one chosen for the scene (Progressive .. FaceCluster); Auto before any
   * request. GetMethodChoice: why Auto chose it (one sentence naming the
   * scene's figure and the rule), empty when Method is not Auto. Port 0's
   * field data `MethodChoice` holds "METHOD: why" (or ": asked for by name").
   */
  int GetResolvedMethod() const { return this->ResolvedMethod; }
  const std::string& GetMethodChoice() const { return this->MethodChoiceWhy; }
  /// The last scene as the solver saw it and what was dropped from it.
  const radiosity::Scene& GetScene() const { return *this->LastScene; }
  const radiosity::SceneCleanupReport& GetCleanupReport() const { return this->Cleanup; }
  /// The last solution in the core's form (for probes and images); null
  /// before a solve. The whole scene's, also on MPI ranks (where it is
  /// evaluated at the first call: the output holds a rank's part only).
  const radiosity::SolutionMesh* GetSolution() const;
  double GetPreprocessSeconds() const { return this->PreprocessSeconds; }
  /// Wall-clock seconds of the last request's later phases, which follow
  /// the preprocessing one after another: the solve (the solver's own
  /// SolveSeconds and its bookkeeping), the output evaluation (the surface
  /// solution evaluated and made port 0's arrays) and the method's product
  /// (port 1: the discontinuity mesh, the Shepard field, the leaf clusters).
  double GetSolveWallSeconds() const { return this->SolveWallSeconds; }
  double GetOutputSeconds() const { return this->OutputSeconds; }
  double GetProductSeconds() const { return this->ProductSeconds; }
  /// Of the preprocessing, the face cluster hierarchy's build (0 when one
  /// built upstream was reused, or for another method).
  double GetHierarchySeconds() const { return this->HierarchySeconds; }

  /**
   * Reference irradiance at probe points: every row of the convergence
   * history then carries the solution's RMS and maximum relative error there
   * (error against run time). Empty vectors switch it off.
   */
  void SetErrorReference(
    const std::vector<radiosity::Probe>& probes, const std::vector<radiosity::RGB>& irradiance)
  {
    this->ErrorProbes = probes;
    this->ErrorReference = irradiance;
    this->Modified();
  }

  ///@{
  /**
   * Hierarchical: the link refinement threshold epsilon on B F, relative to
   * the scene's mean irradiance (emitted power over total area over one minus
   * the mean reflectance). Smaller refines more. Default 0.05.
   */
  vtkSetClampMacro(LinkTolerance, double, 1e-6, 10.0);
  vtkGetMacro(LinkTolerance, double);
  ///@}

  ///@{
  /// Hierarchical: quadtree nodes whose longest edge is at or below this
  /// fraction of the scene diagonal are not split. Default 1/64.
  vtkSetClampMacro(MinElementSize, double, 1e-6, 1.0);
  vtkGetMacro(MinElementSize, double);
  ///@}

  ///@{
  /// Hierarchical: BF refinement passes with the new radiosities after the
  /// first solve. Default 4.
  vtkSetClampMacro(MaxRefinementRounds, int, 0, 100);
  vtkGetMacro(MaxRefinementRounds, int);
  ///@}

  ///@{
  /**
   * Hierarchical: whether the links start from the face cluster hierarchy
   * (Smits-Arvo-Greenberg clustering: memory and time grow with the solution,
   * not with the square of the input) instead of every facing pair of input
   * triangles. ClusteringAuto (the default) clusters above 2048 triangles,
   * where the pairs would outgrow memory; ClusteringOn and ClusteringOff
   * force it.
   */
  enum ClusteringModes
  {
    ClusteringOff = 0,
    ClusteringOn = 1,
    ClusteringAuto = 2
  };
  vtkSetClampMacro(Clustering, int, ClusteringOff, ClusteringAuto);
  vtkGetMacro(Clustering, int);
  void SetClusteringToOff() { this->SetClustering(ClusteringOff); }
  void SetClusteringToOn() { this->SetClustering(ClusteringOn); }
  void SetClusteringToAuto() { this->SetClustering(ClusteringAuto); }
  static const char* GetClusteringName(int clustering);
  ///@}

  ///@{
  /// Meshless: the coarsest Poisson-disk radius, a fraction of the scene
  /// diagonal (halved per level). Default 0.1.
  vtkSetClampMacro(PointRadius, double, 1e-6, 1.0);
  vtkGetMacro(PointRadius, double);
  ///@}

  ///@{
  /// Meshless: levels of the point hierarchy. Default 5.
  vtkSetClampMacro(PointLevels, int, 1, 12);
  vtkGetMacro(PointLevels, int);
  ///@}

  ///@{
  /// Meshless: hemisphere rays per gather (the paper: 512). Default 256.
  vtkSetClampMacro(GatherRays, int, 1, 65536);
  vtkGetMacro(GatherRays, int);
  ///@}

  ///@{
  /// Meshless: epsilon_E, the receiver refinement threshold relative to the
  /// largest direct irradiance. Default 0.01.
  vtkSetClampMacro(VariationThreshold, double, 0.0, 1e6);
  vtkGetMacro(VariationThreshold, double);
  ///@}

  ///@{
  /// Meshless: epsilon_Omega, the solid angle (sr) below which the sender
  /// level is fine enough. Default pi/10.
  vtkSetClampMacro(SolidAngleThreshold, double, 1e-9, 12.6);
  vtkGetMacro(SolidAngleThreshold, double);
  ///@}

  ///@{
  /// Face cluster: the basis of the irradiance vectors (one of Bases,
  /// default LinearBasis) and of the radiosity (default ConstantBasis; never
  /// larger than the irradiance basis, section 3.3.4).
  vtkSetClampMacro(IrradianceBasis, int, ConstantBasis, CubicBasis);
  vtkGetMacro(IrradianceBasis, int);
  vtkSetClampMacro(RadiosityBasis, int, ConstantBasis, CubicBasis);
  vtkGetMacro(RadiosityBasis, int);
  static const char* GetBasisName(int basis);
  ///@}

  ///@{
  /// Face cluster: the transfer error accepted, relative to the emitted
  /// power (the paper: 1e-5). Default 1e-5.
  vtkSetClampMacro(TransferTolerance, double, 1e-12, 1.0);
  vtkGetMacro(TransferTolerance, double);
  ///@}

  ///@{
  /// Face cluster: how many times an input triangle may be halved below the
  /// hierarchy's leaves where the light it receives is more than its basis
  /// can follow (a coarse input: a contact edge, slivers, a box of a few
  /// polygons). Default 5; 0 keeps the paper's leaves.
  vtkSetClampMacro(MaxBisections, int, 0, 16);
  vtkGetMacro(MaxBisections, int);
  ///@}

  ///@{
  /// Face cluster: show the emitters' direct light exactly where they are
  /// few (at most 1024 emitting triangles, in lamps whose count times the
  /// input triangles is at most 262,144): every output point takes the
  /// visible part of each lamp, shadows exact, instead of the solution's
  /// fit of it. Off: the fit, without the output's cost of the exact light
  /// (the 235k bunny room's solve and output 19.4 s on, 12.2 s off).
  /// Default on.
  vtkSetMacro(ExactEmitters, bool);
  vtkGetMacro(ExactEmitters, bool);
  vtkBooleanMacro(ExactEmitters, bool);
  ///@}

  ///@{
  /// Memory budget of a solve in gigabytes (1e9 bytes); 0 (the default) is
  /// 75% of physical memory. Every method estimates what it will allocate
  /// (elements, links, points) from the scene's size and its settings before
  /// it starts and checks what it grows while it solves: a solve that would
  /// not fit fails with an error naming the setting to change, instead of
  /// exhausting the machine's memory.
  vtkSetClampMacro(MaxMemory, double, 0.0, 1e9);
  vtkGetMacro(MaxMemory, double);
  ///@}

  ///@{
  /**
   * What the request evaluates beyond the solve, for a caller that needs
   * less (the command line evaluates only what its options ask for):
   * SurfaceOutput off leaves port 0 without the surface (no points, no
   * cells; the field data as usual) and GetSolution() evaluates it at its
   * first call; ProductOutput off leaves port 1 empty. On by default. Both
   * apply to one process (a distributed request evaluates both).
   */
  vtkSetMacro(SurfaceOutput, bool);
  vtkGetMacro(SurfaceOutput, bool);
  vtkBooleanMacro(SurfaceOutput, bool);
  vtkSetMacro(ProductOutput, bool);
  vtkGetMacro(ProductOutput, bool);
  vtkBooleanMacro(ProductOutput, bool);
  ///@}

  ///@{
  /**
   * Method Hierarchical: the product on port 1 is Hardt & Teller's
   * discontinuity mesh with its quadratic irradiance interpolants
   * (cell array `QuadraticInterpolant`, for vtkQuadraticInterpolantMapper).
   * DiscontinuityMeshing off gives one interpolant per quadtree leaf;
   * MaxDiscontinuitiesPerLeaf is k, the strongest EV/VE discontinuities kept
   * per leaf (10); MinDiscontinuityWeight is w_min as a fraction of the
   * brightest emitter's exitance (0.05; where no triangle emits, of the
   * brightest radiosity); ConformingBoundaries inserts every
   * vertex on a leaf's edge into it, so the mesh has no T-junction (On).
   */
  vtkSetMacro(DiscontinuityMeshing, bool);
  vtkGetMacro(DiscontinuityMeshing, bool);
  vtkBooleanMacro(DiscontinuityMeshing, bool);
  vtkSetClampMacro(MaxDiscontinuitiesPerLeaf, int, 0, 1000);
  vtkGetMacro(MaxDiscontinuitiesPerLeaf, int);
  vtkSetClampMacro(MinDiscontinuityWeight, double, 0.0, 1e6);
  vtkGetMacro(MinDiscontinuityWeight, double);
  vtkSetMacro(ConformingBoundaries, bool);
  vtkGetMacro(ConformingBoundaries, bool);
  vtkBooleanMacro(ConformingBoundaries, bool);
  ///@}

  ///@{
  /**
   * Relighting (Lehtinen et al. 2007, section 6.5; Methods Meshless and
   * FaceCluster, one process). Off by default. On: after a solve the filter precomputes the
   * direct-to-indirect transfer (seconds to minutes, and memory:
   * GetRelightingStatus says how much), and keeps it. A later request whose
   * scene has the same surfaces (points, triangles, objects, reflectance
   * and specular colour) and whose meshless settings are unchanged is then
   * not solved again: the lights, the sky and the triangles' emission may
   * move or change intensity and colour, and only the direct light is
   * computed anew, the indirect light following through the transfer
   * (about 10 ms on the Cornell box, a few hundred when the new lighting
   * wants receivers the transfer lacks, gathered then and kept;
   * bench/results/relight.md). A change of geometry, reflectance or settings invalidates
   * the transfer: that request solves and precomputes again, with a
   * warning naming what changed. Method FaceCluster relights too: its solve
   * keeps every transfer's coupling (rays and form factors, about 1 kB a
   * pair; the status says how much), and new lights or sky are solved over
   * them (lights, sky and emission), only pairs no solve made before
   * computed: a fresh solve's answer (bench/results/relight-facecluster.md).
   * Another method, or MPI ranks, solve every time (the status says why).
   */
  vtkSetMacro(Relighting, bool);
  vtkGetMacro(Relighting, bool);
  vtkBooleanMacro(Relighting, bool);
  ///@}

  ///@{
  /**
   * Relighting: the most seconds a relight may spend gathering the
   * receivers its lighting wants beyond the kept transfer (0, the default:
   * no limit, every relight a fresh solve's answer). With a limit the
   * coarsest receivers are gathered first and the rest wait for the next
   * relights, the coarser receivers' fit standing in for them meanwhile (the
   * status counts them: "N receivers deferred"); requesting the same
   * lighting again gathers on. For interactive light moves (e.g. 0.02 with
   * vtkRadiosityPass). Changing it does not invalidate the transfer.
   */
  vtkSetClampMacro(MaxRelightGatherTime, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaxRelightGatherTime, double);
  ///@}

  /**
   * What the last request did about relighting, also in port 0's field
   * data as the string array `Relighting`: "off"; "precomputed: ..." (the
   * transfer's receivers, entries, megabytes and seconds); "relit: ..."
   * (seconds of direct light and of transfer, bounces); "invalidated: ..."
   * (what changed; solved and precomputed again); "unavailable: ..." (why).
   */
  const std::string& GetRelightingStatus() const { return this->RelightingStatus; }
  /// Seconds the last request spent precomputing the transfer (0 when it did not).
  double GetRelightingPrecomputeSeconds() const { return this->RelightingPrecomputeSeconds; }

  /**
   * The last solve's solver behind the common core interface (it keeps its
   * scene alive, and after an abort holds the partial solution); null before
   * a solve.
   */
  std::shared_ptr<const radiosity::RadiositySolver> GetSolver() const { return this->Solver; }

  ///@{
  /// The last solve's method-specific solver; null for another method.
  std::shared_ptr<const radiosity::FaceClusterRadiosity> GetFaceClusterSolution() const;
  std::shared_ptr<const radiosity::MeshlessRadiosity> GetMeshlessSolution() const;
  std::shared_ptr<const radiosity::HierarchicalRadiosity> GetHierarchicalSolution() const;
  ///@}

  ///@{
  /**
   * The processes the input is distributed over (the global controller by
   * default; null or one process: the input is the whole scene). Every rank
   * must execute the filter together (ParaView's pipeline does).
   */
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

  /// Triangles each rank gave to the last distributed solve and bytes each
  /// received (one entry per rank; empty after a solve on one process).
  const std::vector<vtkIdType>& GetRankTriangles() const { return this->RankTriangles; }
  const std::vector<vtkIdType>& GetRankBytesReceived() const { return this->RankBytesReceived; }
  /// Items of the solve's split loops each rank computed, and bytes each
  /// received in them (one entry per rank; empty on one process).
  const std::vector<vtkIdType>& GetRankWorkItems() const { return this->RankWorkItems; }
  const std::vector<vtkIdType>& GetRankSolveBytesReceived() const { return this->RankSolveBytesReceived; }

  /// Called with the solver's phase, iteration and residual besides the
  /// progress events (for terminal progress bars); returning false aborts.
  void SetStatusCallback(radiosity::ProgressCallback callback) { this->StatusCallback = callback; }

protected:
  vtkRadiosityFilter();
  ~vtkRadiosityFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Method = Auto;
  double Tolerance = 1e-3;
  vtkIdType MaxIterations = 200000;
  double MaxTime = 0.0;
  int NumberOfThreads = 0;
  bool Overshooting = true;
  double ShooterElementSize = 0.25;
  double InitialElementSize = 1.0 / 16.0;
  int MaxSubdivisionLevels = 2;
  double SubdivisionThreshold = 0.1;
  double FormFactorTolerance = 2e-3;
  int HemicubeResolution = 256;
  int VisibilitySamples = 16;
  int IndirectVisibilitySamples = 1;
  double LinkTolerance = 0.05;
  double MinElementSize = 1.0 / 64.0;
  int MaxRefinementRounds = 4;
  int Clustering = ClusteringAuto;
  double PointRadius = 0.1;
  int PointLevels = 5;
  int GatherRays = 256;
  double VariationThreshold = 0.01;
  double SolidAngleThreshold = 3.14159265358979323846 / 10.0;
  int IrradianceBasis = LinearBasis;
  int RadiosityBasis = ConstantBasis;
  double TransferTolerance = 1e-5;
  int MaxBisections = 5;
  bool ExactEmitters = true;
  double MaxMemory = 0.0;
  bool DiscontinuityMeshing = true;
  bool SurfaceOutput = true;
  bool ProductOutput = true;
  bool Relighting = false;
  double MaxRelightGatherTime = 0.0;
  int MaxDiscontinuitiesPerLeaf = 10;
  double MinDiscontinuityWeight = 0.05;
  bool ConformingBoundaries = true;
  double LightScale = 3.14159265358979323846;
  int SkyModel = SkyNone;
  double SkyRadiance[3] = { 1.0, 1.0, 1.0 };
  double SkyUp[3] = { 0.0, 0.0, 1.0 };
  char* LightsFileName = nullptr;

private:
  vtkRadiosityFilter(const vtkRadiosityFilter&) = delete;
  void operator=(const vtkRadiosityFilter&) = delete;

  /// Records and reports `message`; returns 0 (a failed request).
  int Fail(const std::string& message);
  /// RequestData inside vtkRadiosityGuardedRequest.
  int ExecuteRequest(vtkInformationVector** inputVector, vtkInformationVector* outputVector);
  /// The scene of the request on one process: the input, validated, with
  /// the lights; false after a Fail.
  bool LocalScene(vtkDataObject* input, radiosity::Scene& scene);
  /// The scene of the request gathered from every rank's piece
  /// (collective); `mine` flags this rank's triangles. False after a Fail
  /// (on every rank alike).
  bool GatheredScene(vtkDataObject* input, radiosity::Scene& scene, std::vector<char>& mine);
  /// Warns of the degenerate triangles Cleanup counts.
  void WarnDropped();
  /// The one branch per method: its solver, built from the scene and the
  /// properties it reads.
  /// ResolvedMethod and MethodChoiceWhy for `scene` (Auto: ChooseMethod).
  void ResolveMethod(const radiosity::Scene& scene);
  std::shared_ptr<radiosity::RadiositySolver> MakeSolver(
    const std::shared_ptr<const radiosity::Scene>& scene) const;
  template <typename Options>
  void FillCommonOptions(Options& options) const;
  template <typename Options>
  void FillErrorReference(Options& options) const;
  /// The Progressive settings, shared by ProgressiveGPU.
  void FillProgressiveOptions(radiosity::ProgressiveOptions& options) const;
  void Warn(const std::string& warning);
  /// Every light of the request: the file's, the scene lights, the
  /// vtkLights, the sky; validated (a SceneError names the light and field).
  radiosity::LightSet GatherLights() const;

  std::string LastError;
  int ResolvedMethod = Auto;
  std::string MethodChoiceWhy;
  std::vector<std::string> Warnings;
  radiosity::SolverStatistics Statistics;
  /// Shared with the hierarchical solution, which references it.
  std::shared_ptr<const radiosity::Scene> LastScene;
  std::shared_ptr<radiosity::RadiositySolver> Solver;
  radiosity::SceneCleanupReport Cleanup;
  mutable std::unique_ptr<radiosity::SolutionMesh> Solution;
  /// A distributed solve's whole solution, not evaluated yet (GetSolution).
  mutable bool SolutionPending = false;
  double PreprocessSeconds = 0.0;
  double SolveWallSeconds = 0.0;
  double OutputSeconds = 0.0;
  double ProductSeconds = 0.0;
  /// Set by MakeSolver (const: it builds the solver, this is its clock).
  mutable double HierarchySeconds = 0.0;
  radiosity::ProgressCallback StatusCallback;
  std::vector<radiosity::Probe> ErrorProbes;
  std::vector<radiosity::RGB> ErrorReference;
  vtkSmartPointer<vtkLightCollection> Lights;
  std::unique_ptr<radiosity::LightSet> SceneLights;
  vtkMultiProcessController* Controller = nullptr;
  std::vector<vtkIdType> RankTriangles, RankBytesReceived, RankWorkItems, RankSolveBytesReceived;
  /// The smallest rank's memory budget, bytes (0 on one process).
  double AgreedMemoryBudget = 0.0;
  /// The ranks' split of the solve (null on one process).
  std::shared_ptr<radiosity::WorkShare> Share;
  /// Relighting: what the last request did, the settings the kept
  /// transfer was precomputed with, and the precomputation's time.
  std::string RelightingStatus = "off";
  std::string RelightingSettings;
  double RelightingPrecomputeSeconds = 0.0;
  /// The settings a precomputed transfer depends on (the method's, not the lights').
  std::string RelightingSettingsKey() const;
  /// After a solve with Relighting on: precompute the transfer, or say why
  /// not (an invalidated transfer's reason kept before the new status).
  void PrecomputeRelighting(const radiosity::ProgressCallback& progress);
  void PrecomputeRelightingAnew(const radiosity::ProgressCallback& progress);
  /// The previous request's solver relit for `scene` when Relighting is on
  /// and its transfer still applies (then it is the solver again); false,
  /// with the status and a warning saying why, when a solve is needed.
  bool RelightWith(std::shared_ptr<radiosity::RadiositySolver> previous,
    const std::shared_ptr<const radiosity::Scene>& scene, const radiosity::ProgressCallback& progress,
    bool distributed);
};

#endif
