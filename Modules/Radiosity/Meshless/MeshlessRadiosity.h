// Meshless hierarchical radiosity (Lehtinen et al. 2007, section 6.3).
//
// The irradiance is a multilevel Shepard field over a hierarchical
// Poisson-disk point set (MeshlessPoints.h, ShepardField.h). The discrete
// radiosity equation b = T b + e is solved by its Neumann series, bounce by
// bounce: e holds the approximation coefficients of the direct light, and
// each COMPUTE-BOUNCE gathers the previous bounce onto the receiving basis
// functions, coarse to fine:
// - GATHER: a fixed Hammersley pattern of cosine-distributed hemisphere rays,
//   rotated by a random angle about the normal at each receiver; at each hit
//   the previous bounce's irradiance is reconstructed from the levels down to
//   the first whose supporting bounding spheres subtend, on average, less than
//   the solid angle epsilon_Omega seen from the receiver (the sender level,
//   after Bekaert et al. 1998), times the reflectance there;
// - RECEIVER-ORACLE: a coarsest-level receiver is refined (its children, the
//   next level's functions whose centres lie in its support, are gathered to)
//   when its value differs from its neighbours' by more than epsilon_E; on
//   finer levels when its coefficient (a difference to the coarser levels,
//   eq. 10) exceeds epsilon_E. A receiver's parents (the coarser functions
//   non-zero at it) are computed first, recursively, so that its coefficient
//   is the difference to their reconstruction.
// The direct light e is represented the same way, its point values being the
// exact irradiance of the polygonal emitters (Lambert's contour formula) times
// the visible fraction of the emitter (Embree rays to emitter samples).
// Both thresholds are relative to the largest coarse-level irradiance of the
// direct light, so that the defaults do not depend on units. The series is
// summed until a bounce carries less than Tolerance of the direct light, with
// the geometric tail added at once (Aitken) once the bounce ratio is steady,
// so that closed rooms of high reflectance converge in few bounces.
#ifndef Radiosity_MeshlessRadiosity_h
#define Radiosity_MeshlessRadiosity_h

#include "Radiosity/Common/DirectLighting.h"
#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Meshless/ShepardField.h"
#include "Radiosity/Common/SolutionMesh.h"
#include "Radiosity/Common/SolverTypes.h"

#include <functional>
#include "Radiosity/Common/WorkShare.h"

#include <chrono>
#include <memory>
#include <vector>

namespace radiosity
{
class Visibility;
class ElementMesh;
class MeshlessTransfer;
class MeshlessNeighbourhoods;

struct MeshlessOptions
{
  PointPlacementOptions Placement;
  int GatherRays = 256;                    ///< hemisphere rays per receiver (the paper: 512)
  double SolidAngleThreshold = 3.14159265358979323846 / 10.0; ///< epsilon_Omega, steradians
  double VariationThreshold = 0.01;        ///< epsilon_E, relative to the largest direct irradiance
  int EmitterSamples = 16;                 ///< visibility rays per receiver and emitter triangle
  int SkySamples = 1024;                    ///< sky quadrature directions per point (DirectLighting)
  int MaxBounces = 1000;
  /// Relighting: the time a relight may spend gathering the receivers its
  /// lighting wants beyond the transfer's rows (MeshlessTransfer::Indirect);
  /// those left are gathered by the next relights, and until then the
  /// coarser rows' fit stands in for them. 0: no limit (a relight is then
  /// a fresh solve's answer).
  double RelightGatherSeconds = 0.0;
  double Tolerance = 1e-3;                 ///< stop when a bounce carries less than this of the direct light
  double MaxTimeSeconds = 0.0;             ///< 0: no limit
  int Threads = 0;                         ///< 0: all cores
  std::uint64_t Seed = 1;
  /// Surface(): the input triangles split uniformly to this longest edge
  /// (fraction of the scene diagonal) to carry the field as point data.
  double SurfaceElementSize = 1.0 / 32.0;
  /// Bytes the point hierarchy may use; 0: 75% of physical memory. Checked
  /// before the points are placed, from the densest packing the radii allow.
  double MemoryBudgetBytes = 0.0;
  std::vector<Probe> ErrorProbes;          ///< reference irradiance: error after every bounce
  std::vector<RGB> ErrorReference;
  /// MPI ranks: the gathers split over them (WorkShare.h); none: all here.
  std::shared_ptr<WorkShare> Share;
};

/// What the method did, in the columns of the paper's Table 1.
struct MeshlessStatistics
{
  std::size_t SamplesGenerated = 0;
  std::size_t SamplesGatheredTo = 0; ///< points whose coefficient was computed at least once
  std::size_t GatherOperations = 0;  ///< receiver gathers over all bounces
  std::size_t VisibilityRays = 0;
  int Levels = 0;
  std::size_t CoarsestSamples = 0;
  double PlacementSeconds = 0.0;
  double DirectSeconds = 0.0;
  double BounceSeconds = 0.0;
  std::size_t MemoryBytes = 0;       ///< points, coefficients and bookkeeping
  /// Relighting (section 6.5): the precomputed transfer and the last relight.
  std::size_t TransferReceivers = 0;
  std::size_t TransferEntries = 0;
  std::size_t TransferBytes = 0;
  double TransferSeconds = 0.0;
  double RelightDirectSeconds = 0.0;   ///< the new direct light, fitted
  double RelightIndirectSeconds = 0.0; ///< the transfer applied
  int RelightBounces = 0;
  /// Receivers the last relight wanted that the transfer lacked, gathered
  /// for it and kept (MeshlessTransfer::Indirect), and their time (part of
  /// RelightIndirectSeconds).
  std::size_t RelightRowsAdded = 0;
  double RelightRowsAddedSeconds = 0.0;
  /// Receivers the last relight wanted but left for later (RelightGatherSeconds).
  std::size_t RelightRowsDeferred = 0;
};

class MeshlessRadiosity
{
public:
  MeshlessRadiosity(const Scene& scene, const MeshlessOptions& options);
  ~MeshlessRadiosity();

  /// Places the points, computes the direct light and the bounces; once.
  SolverStatistics Solve(const ProgressCallback& progress = {});

  /**
   * Relighting (Lehtinen et al. 2007, section 6.5; MeshlessTransfer.h):
   * after Solve, precomputes the one-bounce operator onto the basis
   * functions the solve gathered to and the two coarsest levels. False when
   * aborted through `progress`. Throws SceneError when there is no field to
   * precompute on (nothing lit, or aborted before placement) or when the
   * operator outgrows the memory budget.
   */
  bool PrecomputeTransfer(const ProgressCallback& progress = {});
  bool HasTransfer() const { return this->Transfer != nullptr; }
  /**
   * The solution for the lighting of `lit` (its emission, lights and sky),
   * which must have the solved scene's surfaces (SameSurfaces; otherwise
   * SceneError naming the difference, and nothing changes): the direct
   * light computed and refined anew, the indirect light from the
   * precomputed transfer. `lit` is the solver's scene from then on (the
   * caller keeps it alive).
   */
  SolverStatistics Relight(const Scene& lit, const ProgressCallback& progress = {});

  const Scene& GetScene() const { return *this->SourceScene; }
  const MeshlessOptions& Options() const { return this->Settings; }
  /// MeshlessOptions::RelightGatherSeconds for the next relights (not a
  /// setting the transfer depends on: it only paces the gathers).
  void SetRelightGatherSeconds(double seconds)
  {
    this->Settings.RelightGatherSeconds = seconds > 0.0 ? seconds : 0.0;
  }
  /// False before placement: a scene without emitters, or an abort before
  /// the points were placed (Points(), Irradiance() and DirectIrradiance()
  /// are then not to be called).
  bool HasField() const { return this->Hierarchy && this->Solution && this->Direct; }
  const PointHierarchy& Points() const { return *this->Hierarchy; }
  /// The irradiance field b (direct plus every bounce).
  const ShepardField& Irradiance() const { return *this->Solution; }
  /// The direct light alone, e.
  const ShepardField& DirectIrradiance() const { return *this->Direct; }
  const MeshlessStatistics& Statistics() const { return this->Stats; }
  /// Whether point j's coefficient was computed in some bounce (sparsity).
  bool WasGatheredTo(std::size_t j) const { return j < this->Touched.size() && this->Touched[j]; }

  /// Irradiance at (x, n) on input triangle `triangle` (its object is the
  /// group); the lights' and the sky's direct light exact at x (the sky by
  /// DirectLighting's quadrature, its rays from inside the triangle), the
  /// field carrying the rest (Lehtinen et al., figure 1: direct light per
  /// pixel).
  RGB IrradianceAt(const Vec3& x, const Vec3& n, std::uint32_t triangle) const;
  /// As Surface, but each sample by IrradianceAt: the lights and the sky
  /// exact at the corners and centres (what the sensors in the air gather:
  /// the field's fit of a window's sky patch on the office floor put the
  /// daylight factor 2.4% under at the back). Costs DirectLighting's sky
  /// quadrature per sample.
  SolutionMesh GatherSurface() const;
  /// The field on the input surfaces: the triangles split uniformly to
  /// SurfaceElementSize, each element's corners and centre evaluated from the
  /// field (SPEC output arrays; the field itself is the solution, and
  /// vtkShepardFieldProbe moves it onto any other mesh). `keep` (one entry
  /// per input triangle): only the elements of the kept triangles and their
  /// neighbours are evaluated, the others left zero (an MPI rank's own part).
  SolutionMesh Surface(const std::vector<char>* keep = nullptr) const;
  /// Irradiance at probes: each is assigned to the nearest surface's group
  /// (normals within 90 degrees); NaN when no surface faces it.
  std::vector<RGB> Evaluate(const std::vector<Probe>& probes) const;

private:
  struct Bounce;
  void FindEmitters();
  void DirectLight(Bounce& out);
  /// Direct, the solution's start and LightFit from the direct light.
  void KeepDirect(const Bounce& direct);
  /// DirectLight then KeepDirect; the direct light's magnitude.
  double ComputeDirect();
  /// The sky's irradiance at point j from its visibility mask (SkyMask),
  /// the mask cast first when it is not known yet.
  RGB CachedSky(std::uint32_t j) const;
  /// The lights' irradiance summed over the coarsest level's points.
  double CoarseLightIrradiance() const;
  void ComputeBounce(const ShepardField& previous, Bounce& out);
  RGB Gather(std::uint32_t receiver, const ShepardField& previous) const;
  RGB DirectAt(std::uint32_t receiver) const;
  /// IrradianceAt with the lights' rays from `inner` when x is on the triangle's boundary.
  RGB ExactLightsAt(const Vec3& x, const Vec3& inner, const Vec3& n, std::uint32_t triangle) const;
  template <typename Value>
  void Refine(Bounce& out, const Value& value);

  const Scene* SourceScene; ///< the solved scene, or the last relit one
  MeshlessOptions Settings;
  std::unique_ptr<Visibility> Rays;     ///< every triangle: gather rays, placement
  std::unique_ptr<Visibility> Shadows;  ///< the triangles that can occlude: direct light
  std::unique_ptr<DirectLighting> Lights; ///< punctual lights and sky (null without)
  std::unique_ptr<PointHierarchy> Hierarchy;
  std::unique_ptr<ShepardField> Direct, Solution;
  /// The lights' and the sky's part of Direct (null without lights or sky):
  /// IrradianceAt replaces it by their exact value at the point.
  std::unique_ptr<ShepardField> LightFit;
  /// A tile of `count` neighbouring elements of one object (`leaves`, in
  /// the element mesh): their samples x (four each: the corners, just
  /// inside, and the centre) with the element's normal n, into h.
  using TileSampler = std::function<void(const Vec3* x, const Vec3* n, const std::uint32_t* leaves,
    std::size_t count, const ElementMesh& mesh, RGB* h)>;
  /// The surface split to SurfaceElementSize, every element's samples from
  /// `value`, tile by tile in parallel.
  SolutionMesh SampledSurface(const TileSampler& value, const std::vector<char>* keep = nullptr) const;
  std::vector<std::uint32_t> Emitters;
  std::vector<unsigned char> Touched; ///< per point: gathered to at least once
  /// MaxTimeSeconds from the start of Solve, while it runs: Refine stops
  /// refining a bounce at it (its finer levels keep the coarser fit).
  bool HasDeadline = false;
  std::chrono::steady_clock::time_point Deadline{};
  /// The lights' and the sky's direct irradiance at the points DirectAt
  /// computed (LightKnown), for their own fit without a second quadrature.
  mutable std::vector<RGB> LightValue;
  mutable std::vector<unsigned char> LightKnown;
  std::unique_ptr<MeshlessTransfer> Transfer;
  /// Relighting: every point's oracle and fit neighbourhoods, listed with
  /// the transfer; Refine and the fit read them instead of searching.
  std::unique_ptr<MeshlessNeighbourhoods> Lists;
  /// Relighting: each point's sky visibility (DirectLighting::SkyVisibility),
  /// kept once a transfer is precomputed (SkyMaskWords words a point; 0:
  /// not kept), so that a new sky or sun costs no sky rays.
  std::size_t SkyMaskWords = 0;
  mutable std::vector<std::uint64_t> SkyMask;
  mutable std::vector<unsigned char> SkyKnown;
  /// Per point: the mask's moments for the sky's Up of SkyMomentUp.
  mutable std::vector<DirectLighting::SkyMoments> SkyMoment;
  mutable std::vector<unsigned char> SkyMomentsKnown;
  Vec3 SkyMomentUp{ 0.0 };
  double Scale = 0.0;                 ///< largest coarse direct irradiance (one channel)
  MeshlessStatistics Stats;
};
} // namespace radiosity

#endif
