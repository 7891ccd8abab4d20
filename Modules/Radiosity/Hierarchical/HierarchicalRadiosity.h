// Hierarchical radiosity (Hanrahan, Salzman & Aupperle 1991), the solver that
// Hardt & Teller section 3 assumes: a quadtree per input triangle, links
// between nodes refined until each carries a small enough transfer, Jacobi
// gathering over the links with push-pull through the quadtrees, and for
// every partially visible link the blockers that its shaft meets, recorded
// for discontinuity meshing (Hardt & Teller sections 4 and 5).
//
// - Refinement (HSA91 section 4, "BF refinement"): a link from source q to
//   receiver p is accepted when B_q * max(F_pq, F_qp) <= epsilon, epsilon an
//   irradiance in W/m^2; otherwise the node with the larger form factor
//   (the larger one seen from the other) is split. F is estimated with the
//   exact point-to-polygon contour formula from a few points of each node.
//   Links are refined again with the new radiosities after each solve,
//   until no link changes (HSA91's iterated BF refinement).
// - Transfer: the link's coefficient is the receiver-area mean of the point
//   form factor to the source (centroids of a midpoint subdivision of the
//   receiver, finer for close pairs). Blockers: the occluders whose BVH boxes
//   meet the shaft's bounding sphere (an Embree point query) and that have a
//   vertex in front of both nodes; a link with any is partial, keeps them,
//   and its coefficient is computed through them exactly by backprojection
//   (Backprojection.h). No link is classified by sampled rays: a shadow edge
//   that four sample points miss would otherwise vanish from the link and
//   from the discontinuity mesh (measured: 5.6% error along the penumbra line
//   with 16-ray classification, 0.14% without).
// - Gathering: Jacobi sweeps, H_p = sum over p's links of F B_q, pushed down
//   the quadtree as irradiance (a flux density, the same for children) and
//   pulled up as area-weighted radiosity. The sweep's change shrinks
//   geometrically by the spectral radius r (up to the mean reflectance), so
//   the remaining change is estimated as delta r / (1 - r), which is the
//   stop criterion, and once r is steady the tail of the Neumann series is
//   added at once (Aitken extrapolation), so that closed rooms with
//   reflectance 0.999 converge in tens of sweeps instead of thousands.
// - Normalisation: a leaf receives its ancestors' links at their node-mean
//   factors, so the sum of its factors departs from the exact form factor of
//   everything it is linked to by up to the link tolerance, and interreflection
//   amplifies that by 1 / (1 - rho). Each leaf's unoccluded transfers are
//   scaled by the ratio of the exact sum (point form factors at the leaf's own
//   points, to every source of its chain of links) to the approximate one: the
//   row-sum normalisation of Baum, Rushmeier & Winget 1989, which makes closed
//   uniform rooms exact at any link tolerance.
#ifndef Radiosity_HierarchicalRadiosity_h
#define Radiosity_HierarchicalRadiosity_h

#include "Radiosity/Hierarchical/Backprojection.h"
#include "Radiosity/Common/WorkShare.h"
#include "Radiosity/Common/ElementMesh.h"
#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Common/SceneAnalysis.h"
#include "Radiosity/Common/SolverTypes.h"

#include "Radiosity/Common/DirectLighting.h"

#include <boost/range/irange.hpp>

#include <functional>
#include <memory>
#include <vector>

namespace radiosity
{
class ClusterLinks;
class Visibility;

/// Whether links start from the face cluster hierarchy (ClusterLinks.h)
/// instead of every facing pair of input triangles.
enum class HierarchicalClustering
{
  Off,
  On,
  Auto ///< on above HierarchicalOptions::ClusterAbove triangles
};

struct HierarchicalOptions
{
  double Tolerance = 1e-3;          ///< stop when the estimated remaining change / total power is below
  long long MaxIterations = 100000; ///< gather sweeps
  double MaxTimeSeconds = 0.0;      ///< 0: no limit
  int Threads = 0;                  ///< 0: all cores
  /// Link refinement threshold epsilon on B F, W/m^2; 0: RelativeLinkTolerance
  /// times the scene's mean irradiance as Cohen's ambient term estimates it,
  /// emitted power over total area over (1 - mean reflectance), so that the
  /// default is free of scale and of emission units and does not explode in
  /// bright closed rooms.
  double LinkTolerance = 0.0;
  double RelativeLinkTolerance = 0.05;
  /// Nodes whose longest edge is at or below this fraction of the scene diagonal are not split.
  double MinElementSize = 1.0 / 64.0;
  int MaxRefinementRounds = 4;      ///< BF refinement passes after the first solve
  /// Candidate blockers kept per link; links with more keep those the rays
  /// between the nodes meet, and are counted (SolverStatistics::LinksWithBlockersCut).
  std::size_t MaxBlockersPerLink = 64;
  /// Bytes the solve may use (links, nodes); 0: 75% of physical memory.
  /// Checked before the first allocation (the initial links of every facing
  /// pair of input triangles) and while links and nodes are refined.
  double MemoryBudgetBytes = 0.0;
  HierarchicalClustering Clustering = HierarchicalClustering::Auto;
  std::size_t ClusterAbove = 2048; ///< Auto: clustered for more input triangles than this
  int SkySamples = 1024; ///< sky quadrature directions per light-link sample (DirectLighting)
  std::vector<Probe> ErrorProbes;   ///< reference irradiance: error in every history row
  std::vector<RGB> ErrorReference;
  /// MPI ranks: the links' form factors and blockers split over them (WorkShare.h); none: all here.
  std::shared_ptr<WorkShare> Share;
};

/// A transfer from a source node to a receiver node.
struct HierarchicalLink
{
  enum VisibilityKind : std::uint8_t
  {
    Visible = 0, ///< no occluder between the nodes (no blockers)
    Partial = 1, ///< blockers recorded
    Hidden = 2   ///< no transfer (kept in the statistics; the solver does not drop links)
  };
  std::uint32_t Receiver = 0;
  std::uint32_t Source = 0;
  double Factor = 0.0; ///< receiver-area mean form factor to the source, times visibility
  std::uint32_t FirstBlocker = 0;
  std::uint32_t BlockerCount = 0;
  VisibilityKind Kind = Visible;
  /// More candidate blockers than MaxBlockersPerLink: only those the rays
  /// between the nodes meet were kept (SolverStatistics::LinksWithBlockersCut).
  /// Those few cannot stand for the whole occluder (the light leaked through
  /// the gaps between them: the 3,868-triangle bunny room absorbed 3% more
  /// than it emitted), so such a link's visibility is the fraction of those
  /// rays that pass, `VisibleFraction`, times the unoccluded form factor; its
  /// blockers serve the discontinuity mesher's events only.
  bool BlockersCut = false;
  float VisibleFraction = 1.0f; ///< BlockersCut: the passing fraction of the rays
};

class HierarchicalRadiosity
{
public:
  HierarchicalRadiosity(const Scene& scene, const HierarchicalOptions& options);
  ~HierarchicalRadiosity();

  /// Runs to a stop condition; can be called once.
  SolverStatistics Solve(const ProgressCallback& progress = {});

  const Scene& GetScene() const { return this->SourceScene; }
  const HierarchicalOptions& Options() const { return this->Settings; }
  const SceneAnalysis& Analysis() const { return this->SceneInfo; }
  const Visibility& GetVisibility() const { return *this->Rays; }
  /// The quadtrees; each leaf's irradiance samples hold its constant irradiance.
  const ElementMesh& Mesh() const { return *this->Elements; }
  const std::vector<HierarchicalLink>& Links() const { return this->LinkList; }
  /// Scene triangles blocking a partial link.
  const std::uint32_t* Blockers(const HierarchicalLink& link) const
  {
    return this->BlockerPool.data() + link.FirstBlocker;
  }
  /// Links received by node e (indices into Links(), consecutive: the links
  /// are sorted by receiver); ancestors' links apply to e too.
  boost::integer_range<std::uint32_t> LinksOf(std::uint32_t e) const;
  /// Area-mean radiosity B of a node, W/m^2.
  const RGB& Radiosity(std::uint32_t e) const { return this->NodeRadiosity[e]; }
  /// Total irradiance of a node (its own links and its ancestors'), W/m^2.
  const RGB& Irradiance(std::uint32_t e) const { return this->NodeIrradiance[e]; }
  double GetLinkTolerance() const { return this->Epsilon; }
  /// The punctual lights and the sky (null when the scene has none).
  const DirectLighting* GetDirectLighting() const { return this->Lights.get(); }
  /// Exact direct light of the lights and sky at x (0 without lights): the
  /// value a light-to-node link integrates, and the discontinuity mesher's.
  RGB DirectLight(const Vec3& x, const Vec3& n) const
  {
    return this->Lights ? this->Lights->Irradiance(x, n) : RGB(0.0);
  }
  /// Direct irradiance a node receives through its own light link (0 when
  /// its light arrives through an ancestor's link or not at all).
  const RGB& LightLinkIrradiance(std::uint32_t e) const { return this->NodeDirect[e]; }
  std::size_t NumberOfLightLinks() const { return this->LightLinks; }
  /// Whether the links start from clusters (HierarchicalOptions::Clustering).
  bool Clustered() const { return this->ClusterSolve != nullptr; }
  /// Links with a cluster at one end (0 unclustered); not in Links().
  std::size_t NumberOfClusterLinks() const;
  /// Irradiance quadtree leaf e receives through the cluster links, W/m^2
  /// (a constant over the leaf; 0 unclustered): part of Irradiance(e), and
  /// of every point irradiance the mesher computes on the leaf.
  RGB ClusterIrradiance(std::uint32_t leaf) const;
  TriangleCorners Corners(std::uint32_t e) const;

private:
  struct PendingLink
  {
    std::uint32_t Receiver, Source;
  };
  double FormFactorEstimate(std::uint32_t from, std::uint32_t to) const;
  bool Splittable(std::uint32_t e) const;
  std::uint32_t Children(std::uint32_t e);
  void Refine(std::uint32_t p, std::uint32_t q, std::vector<PendingLink>& out);
  /// false when `keepGoing` (asked once per root) said stop.
  bool InitialLinks(std::vector<PendingLink>& out, const std::function<bool()>& keepGoing);
  /// Clustered: the face cluster hierarchy built and the roots linked
  /// (HierarchicalClusters.cxx); the triangle pairs go to Refine.
  bool InitialClusterLinks(std::vector<PendingLink>& out, const std::function<bool()>& keepGoing,
    const ProgressCallback& progress);
  void GatherClusters();
  /// ClusterLinks::Normalize with each triangle's polygon links' sum.
  void NormalizeClusters();
  std::size_t RefineLinks(std::vector<PendingLink>& out);
  /// Clustered: RefineAgain, or with `deferredOnly` (after the refinement
  /// rounds) only the deferred pairs whose source has radiosity now
  /// (ClusterLinks::LinkDeferred); how many changed.
  std::size_t RefineClusterLinks(std::vector<PendingLink>& out, bool deferredOnly = false);
  static double BytesPerNode();
  /// false when `keepGoing` (asked between blocks of links, on this thread) said stop.
  bool ComputeLinks(const std::vector<PendingLink>& pending, SolverStatistics& stats,
    const std::function<bool()>& keepGoing);
  void IndexLinks();
  /// Light-to-node links (SPEC "Lights and sky"): from each root down, a node
  /// takes the lights' direct irradiance as its own link when the exact
  /// values at its corners, edge midpoints and centre differ by at most the
  /// link tolerance (the BF criterion with the light's B F being the
  /// irradiance itself), else it is split; a hard shadow edge is followed
  /// down to MinElementSize, and discontinuity meshing makes it sharp.
  /// Returns the power the lights deliver to the surfaces.
  double LinkLights();
  double Sweep(std::vector<RGB>& change);
  RGB PushPull(std::uint32_t e, const RGB& downVisible, const RGB& downOther, const RGB& downClustered,
    std::vector<RGB>& change);
  void Normalize();
  RGB Pull(std::uint32_t e);
  void StoreLeafIrradiance();

  const Scene& SourceScene;
  HierarchicalOptions Settings;
  SceneAnalysis SceneInfo;
  std::unique_ptr<Visibility> Rays;
  std::unique_ptr<ElementMesh> Elements;
  std::vector<HierarchicalLink> LinkList;
  std::vector<std::uint32_t> BlockerPool;
  std::vector<std::uint32_t> LinkOffsets; ///< links sorted by receiver: per node, the first
  std::vector<RGB> NodeRadiosity, NodeGathered, NodeGatheredVisible, NodeIrradiance;
  std::vector<RGB> NodeDirect; ///< the light link's irradiance per node
  std::unique_ptr<DirectLighting> Lights;
  std::size_t LightLinks = 0;
  /// Per leaf: exact over approximate sum of the unoccluded form factors of
  /// its links and its ancestors' links (see Normalize).
  std::vector<double> Normalization;
  std::vector<std::uint32_t> Roots;
  bool UseClusters = false;
  std::unique_ptr<ClusterLinks> ClusterSolve;
  std::vector<RGB> ClusterDown; ///< per input triangle: irradiance through the clusters' vector links
  std::vector<RGB> ElementDown; ///< per quadtree node: irradiance through its own scalar cluster links
  std::vector<double> ClusterScale; ///< per leaf: the cluster links' row-sum normalisation (ClusterLinks::Normalize)
  double Epsilon = 0.0;
  double MinEdge = 0.0;
  double PlaneTolerance = 0.0;
  double Budget = 0.0;              ///< bytes (MemoryBudgetBytes resolved)
  std::size_t LinkCapacity = 0;     ///< links (made and pending) the budget holds
  std::size_t NodeCapacity = 0;     ///< quadtree nodes the budget holds
};
} // namespace radiosity

#endif
