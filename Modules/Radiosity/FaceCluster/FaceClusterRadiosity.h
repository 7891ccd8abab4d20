// Hierarchical higher-order face cluster radiosity (Gobbetti, Spano & Agus
// 2003, sections 3.2 to 3.4, Algorithm 1): vector irradiance and radiosity
// expanded in orthonormal polynomial bases on the face clusters' box planes
// (ClusterBasis), a solution hierarchy of elements over the face cluster
// hierarchy, and the linkless shooting iteration: per iteration every
// top-level element receives from the top-level elements with unshot
// radiosity that face it, and TRANSPORT-LIGHT walks its hierarchy top-down
// with a list of potential shooters per element; a transfer is accepted
// when its BFA error (3.3.2) is below the tolerance, else the larger of the
// emitter and the receiver is subdivided; non-convex elements refine their
// self-transfer (3.3.3). Unshot vector irradiance is pushed down to the
// leaves (only there is irradiance stored) and the leaves' new unshot
// radiosity, (1 - F_ii) rho_i n_i . dE, is pulled back up (3.3.4). The
// iteration stops on the infinity norm of the unshot radiosity relative to
// the brightest emission; the geometric tail of the series is then added
// (Aitken), as in the other solvers.
//
// Departures, as in DESIGN.md's note for this method: emission is the
// elements' own (each element's first shot is its own cluster's mean
// emission, not the parent's pushed average), pull weights are surface
// areas (energy is conserved whatever the children's boxes), a triangle
// emitter's constant part uses the exact vector form factor, and input
// triangles are halved below the hierarchy where the light they receive in
// all is more than their basis can follow (MaxBisections; README.md).
#ifndef Radiosity_FaceClusterRadiosity_h
#define Radiosity_FaceClusterRadiosity_h

#include "Radiosity/Common/DirectLighting.h"
#include "Radiosity/FaceCluster/FaceClusterExactEmitters.h"
#include "Radiosity/FaceCluster/FaceClusterTransfer.h"
#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Common/SolutionMesh.h"
#include "Radiosity/Common/SolverTypes.h"
#include "Radiosity/Common/WorkShare.h"

#include <array>
#include <deque>
#include <memory>
#include <unordered_map>

namespace radiosity
{
struct FaceClusterSettings
{
  BasisKind RadiosityBasis = BasisKind::Constant;
  BasisKind IrradianceBasis = BasisKind::Linear;
  /// Transfer error (W) accepted, relative to the scene's emitted power.
  double TransferTolerance = 1e-5; // the paper's "relative transfer accuracy"
  /// Stop when the largest unshot radiosity is below this fraction of the
  /// brightest emission.
  double Tolerance = 1e-4;
  int MaxIterations = 200;
  double MaxTimeSeconds = 0.0; ///< 0: no limit
  int Threads = 0;
  /// How many times an input triangle may be halved (longest-edge
  /// bisection) below the face cluster hierarchy's leaves where its basis
  /// cannot follow the light it receives in all (SubdivisionTolerance); 0
  /// keeps the paper's leaves. A coarse input otherwise keeps one expansion
  /// per triangle whatever the light: 11.8% of the peak on the Cornell
  /// box's 32 triangles, 22% on the exact penumbra, 5.9% at the contact
  /// edge; halved, 1.6%, 1.8% and 0.12% (bench/results/facecluster.md).
  int MaxBisections = 5;
  /// Transfer error (W) accepted below the input triangles, relative to the
  /// scene's emitted power: a leaf triangle is halved where the fits of the
  /// light it received in an iteration depart from that light by more, in
  /// all (FaceClusterRadiosity::BisectOnTotals), and a halved emitter
  /// sends from its parts where the spread of its radiosity over them would
  /// change a transfer by more. Coarser than TransferTolerance, which
  /// refines the clusters: at 1e-5 the Cornell box took 15 s for 1.1% of
  /// the peak, at this value 3.9 s for 1.6%.
  double SubdivisionTolerance = 1e-4;
  /// Bytes the hierarchy and the elements may use; 0: 75% of physical
  /// memory. Checked before the hierarchy is built and as elements are made.
  double MemoryBudgetBytes = 0.0;
  TransferRule Rule;
  FaceClusterOptions Clustering;
  int SkySamples = 1024; ///< sky quadrature directions per node (DirectLighting)
  /// How many times an input triangle may be halved where the lights' direct
  /// irradiance varies over it by more than the transfer tolerance (a
  /// lamp's falloff, a hard shadow edge): the lights are exact at every
  /// node, and the basis can only follow them on elements small enough.
  int MaxLightBisections = 10;
  /// Up to this many emitting triangles, the output shows their direct
  /// light exactly, as it shows the punctual lights' (ShownExact): each
  /// output point takes the visible part of each lamp
  /// (FaceClusterExactEmitters: coplanar emitting triangles sharing
  /// vertices) plus the expansion less the first iteration's fit of them.
  /// The fit of a lamp's light drew the glossy statue's blotches and dark
  /// rims. 0: the fit everywhere.
  int ExactEmitterTriangles = 1024;
  /// And while input triangles times lamps stays within this (a lamp
  /// counted once where its outline is convex and its emission uniform,
  /// else once per triangle): the cost is a shaft per input triangle and
  /// lamp and a backprojection per output point and lamp. Measured: the
  /// 235k bunny room (one lamp) 12.2 s with the fit, 19.4 s exact (the
  /// CLI's solve and output); the glossy statue (15k triangles, a lamp of
  /// 32) output 0.015 s, exact 0.86 s, beside an 11 s solve. Beyond it
  /// (the 940k bunny room) the fit.
  double ExactLampPairs = 262144.0;
  /// In a scene that encloses every triangle (SceneIsEnclosed: no ray from
  /// a surface escapes), all the light shot lands on a surface, so from
  /// the second bounce on each iteration's received power is scaled to the
  /// power shot (per channel; BalanceEnergy). The transfers' own errors
  /// otherwise lose or gain a little per bounce, and interreflection
  /// multiplies that by 1 / (1 - rho): the inside of a 1280-facet sphere at
  /// reflectance 0.99 came out 3.0% low (3e-4 lost per bounce).
  bool BalanceEnclosedScenes = true;
  /// Relighting: keep every transfer's coupling (TransferCoupling: what a
  /// transfer owes to its two elements, not to the light) as the solve
  /// computes it, so that a later solve of new lights or sky on the same
  /// surfaces (Relight) casts no ray and computes no form factor for a pair
  /// it had already. Memory: about 0.5 to 1 kB per pair (the statistics
  /// say how much), at most a quarter of MemoryBudgetBytes with the sky
  /// masks; the rest is
  /// computed again when needed. One rank only.
  bool KeepTransfers = false;
  /// MPI ranks: every rank holds the whole hierarchy and computes its share
  /// of each round's transfers and of the lights at the leaves; the shares
  /// are exchanged (WorkShare.h) and the time limit agreed, so every rank
  /// refines alike and stops at the same iteration. None: one rank.
  std::shared_ptr<WorkShare> Share;
};

/// Irradiance vector: one vector per colour channel.
using IrradianceVector = std::array<Vec3, 3>;

struct FaceClusterElement
{
  std::uint32_t Cluster = 0;
  std::int32_t Parent = -1;
  std::int32_t Child[2]{ -1, -1 };
  FaceCluster Data;
  SurfaceRule Rule;                  ///< nodes on its surface, irradiance basis
  std::vector<double> RadiosityDual; ///< least-squares weights of the radiosity basis
  std::vector<double> PushE;         ///< irradiance from the parent, N_e x N_e
  std::vector<double> PushB;         ///< radiosity from the parent, N_b x N_b
  std::vector<double> PullB;         ///< radiosity to the parent, N_b x N_b
  std::vector<RGB> Unshot, Next;           ///< radiosity coefficients, N_b
  /// The range of the unshot radiosity (mean of the channels) over the
  /// leaves' nodes below: the emitter bounds of the transfer error (3.3.2).
  double UnshotMin = 0.0, UnshotMax = 0.0, NextMin = 0.0, NextMax = 0.0;
  std::vector<IrradianceVector> Irradiance; ///< N_e coefficients, leaves only
  /// The part of Irradiance that the output replaces by the exact light
  /// (ShownExpansion, ShownExact): the first iteration's fit of the
  /// punctual lights and, where they are few (ExactEmitterTriangles), of
  /// the emitters' direct light; pushed down as Irradiance is when the
  /// leaf is subdivided later. Empty where nothing is shown exactly.
  std::vector<IrradianceVector> ExactFit;
  std::vector<IrradianceVector> LastIncrement;
  /// Per channel, the bounds of the expansion's components at the nodes:
  /// the limiter of Expansion (leaves, after the solve); Shown: of the
  /// expansion less ExactFit.
  IrradianceVector Lowest{}, Highest{}, ShownLowest{}, ShownHighest{};
  /// A single triangle's corners (an input triangle, or a part of one).
  std::array<Vec3, 3> Corners{};
  int Bisections = 0; ///< halvings below the input triangle
  /// The same for the same element in every solve on the hierarchy: its
  /// cluster, or for a part of a triangle its parent's key and which half
  /// (the kept transfers' key).
  std::uint64_t Key = 0;
  bool IsLeaf() const { return this->Child[0] < 0; }
  /// An input triangle or a part of one (its cluster data is a leaf's).
  bool IsTriangle() const { return this->Data.IsLeaf(); }
};

struct FaceClusterStatistics
{
  std::size_t Elements = 0;
  std::size_t LeafElements = 0;
  std::size_t Transfers = 0;     ///< accepted energy transfers, all iterations
  std::size_t Refinements = 0;   ///< transfers refined instead
  std::size_t SolutionBytes = 0; ///< the element hierarchy
  double HierarchySeconds = 0.0;
  double SolveSeconds = 0.0;
  bool Enclosed = false; ///< the scene encloses every triangle (BalanceEnclosedScenes)
  /// The smallest and largest scale BalanceEnergy applied (1: none).
  double EnergyScaleMin = 1.0, EnergyScaleMax = 1.0;
  double EnclosureSeconds = 0.0; ///< the enclosure test
  /// Relighting (KeepTransfers): the couplings kept, their memory, and in
  /// the last solve how many transfers reused a kept coupling and how many
  /// were computed (kept, unless the memory for them was spent).
  std::size_t KeptCouplings = 0;
  std::size_t KeptBytes = 0;
  std::size_t CouplingsReused = 0;
  std::size_t CouplingsComputed = 0;
  std::size_t CouplingsNotKept = 0;
  /// Emitting triangles whose direct light the output shows exactly
  /// (ExactEmitterTriangles, ExactLampPairs); 0: the fit shows it.
  std::size_t ExactEmitterTriangles = 0;
};

class FaceClusterRadiosity
{
public:
  /// Takes (or builds, through FaceClusterHierarchy::Shared) the hierarchy.
  FaceClusterRadiosity(const Scene& scene, const FaceClusterSettings& settings,
    std::shared_ptr<const FaceClusterHierarchy> hierarchy = nullptr);

  SolverStatistics Solve(const ProgressCallback& progress = {});

  ///@{
  /**
   * Relighting (Lehtinen et al. 2007, section 6.5, for this method): the
   * transfers kept (KeepTransfers) make a solve of new lighting (lights,
   * sky, emission) a replay
   * of the oracle and the push-pull over kept couplings: the rays and form
   * factors of every pair seen before are not computed again, and a pair
   * the new light needs (an element it halves, a coarser or finer
   * transfer) is computed then and kept. The answer is the fresh solve's
   * of the new lighting, to the bit: the same code runs, on the same
   * couplings.
   *
   * PrecomputeTransfer: keeps the transfers, solving again to collect them
   * unless this solve kept them already; false when aborted.
   * Relight: solves for the lights, sky and emission of `scene`, whose
   * surfaces (SameSurfaces) must be those of the solver's scene
   * (SceneError naming the difference otherwise).
   */
  bool PrecomputeTransfer(const ProgressCallback& progress = {});
  bool HasTransfer() const { return this->Couplings != nullptr && !this->Couplings->empty(); }
  SolverStatistics Relight(std::shared_ptr<const Scene> scene, const ProgressCallback& progress = {});
  ///@}

  /// The irradiance vector at x on triangle t, from the leaf element there.
  IrradianceVector IrradianceVectorAt(std::uint32_t t, const Vec3& x) const;
  /// Irradiance (W/m^2) at x with normal n on triangle t: (n . E_c)_+,
  /// the punctual lights' part exact at x (DirectLighting::Punctual) and
  /// the expansion carrying the rest (the sensors' value, SPEC --probes).
  RGB IrradianceAt(std::uint32_t t, const Vec3& x, const Vec3& n) const;
  /// Per scene point: the irradiance vector (9 values: R, G, B vectors),
  /// the mean over the triangles using the point of their leaf elements'
  /// expansions at it (section 3.5: what the display interpolates), kept in
  /// the half-space n . E >= 0 of the point's area-weighted normal n, where
  /// the light arriving from above its surface lies.
  std::vector<std::array<double, 9>> VertexIrradianceVectors() const;
  /// Irradiance at probes, on the nearest input triangle facing each.
  std::vector<RGB> Evaluate(const std::vector<Probe>& probes) const;
  /// The input triangles with the SPEC output fields: per triangle, the
  /// irradiance of its leaf element's expansion at its corners and centre;
  /// `ElementId` is the leaf element's cluster, `Level` its depth.
  SolutionMesh Surface() const;
  /// The leaf element holding x on triangle t (triangle t itself, a part
  /// of it, or a cluster holding it).
  std::int32_t LeafAt(std::uint32_t t, const Vec3& x) const;
  /// The element of triangle t itself, or the leaf cluster holding it: the
  /// descent through the clusters, once per triangle.
  std::int32_t ElementOf(std::uint32_t t) const;
  /// The leaf below element e (a triangle's parts) that x is in.
  std::int32_t PartAt(std::int32_t e, const Vec3& x) const;

  const FaceClusterStatistics& Statistics() const { return this->Stats; }
  const std::deque<FaceClusterElement>& Elements() const { return this->Nodes; }
  const FaceClusterHierarchy& Hierarchy() const { return *this->Clusters; }
  std::shared_ptr<const FaceClusterHierarchy> SharedHierarchy() const { return this->Clusters; }
  const Scene& GetScene() const { return this->Clusters->GetScene(); }

private:
  FaceClusterSettings Settings;
  std::shared_ptr<const FaceClusterHierarchy> Clusters;
  std::unique_ptr<FaceClusterVisibility> Visibility;
  PolynomialBasis RadiosityBasis;
  PolynomialBasis IrradianceBasis;
  std::deque<FaceClusterElement> Nodes;
  /// The lights and sky: the scene's given to the constructor, then each
  /// Relight's. Not the hierarchy's scene's: a hierarchy is shared by every
  /// scene of the same surfaces (FaceClusterHierarchy::Shared), whatever
  /// their lights.
  LightSet Lighting;
  /// Relighting: kept couplings by (receiver, emitter) key, and the keys
  /// of the parts below input triangles by (parent key, half).
  struct PairKey
  {
    std::uint64_t Receiver, Emitter;
    bool operator==(const PairKey& o) const { return this->Receiver == o.Receiver && this->Emitter == o.Emitter; }
  };
  struct PairKeyHash
  {
    std::size_t operator()(const PairKey& k) const
    {
      return std::hash<std::uint64_t>()(k.Receiver * 0x9E3779B97F4A7C15ull ^ k.Emitter);
    }
  };
  std::unique_ptr<std::unordered_map<PairKey, TransferCoupling, PairKeyHash>> Couplings;
  /// The kept coupling's key of receiver i and emitter j: their elements'
  /// keys, the emitter's marked when it emits (ComputeCoupling takes an
  /// emitting cluster's visible fraction more finely).
  PairKey KeyOf(std::int32_t i, std::int32_t j) const;
  /// Relighting with new emission: per triangle its emission, and per
  /// internal cluster its emission's bounds and mean as the hierarchy would
  /// hold them (MergeClusterAttributes), in place of the hierarchy's, whose
  /// scene had the old; each element's copy of its cluster takes them
  /// (NewElement). Empty: the hierarchy's own.
  struct EmissionBounds
  {
    glm::vec3 Min{ 0.0f }, Max{ 0.0f }, Mean{ 0.0f };
  };
  std::vector<RGB> OwnEmission;
  std::vector<EmissionBounds> InternalEmission;
  void SetEmission(const Scene& scene);
  RGB EmissionOf(std::uint32_t t) const
  {
    return this->OwnEmission.empty() ? this->GetScene().Materials[t].Emission : this->OwnEmission[t];
  }
  std::unordered_map<std::uint64_t, std::uint64_t> PartKeys;
  /// Relighting: per element key, which sky directions each of its nodes
  /// sees (DirectLighting::SkyVisibility, SkyMaskWords per node): geometry
  /// alone, so a relight replays any sky's quadrature without a ray.
  struct KeptSky
  {
    std::vector<std::uint64_t> Masks;               ///< SkyMaskWords per node
    std::vector<DirectLighting::SkyMoments> Moments; ///< per node, for Up
    Vec3 Up{ 0.0 };
  };
  std::unordered_map<std::uint64_t, KeptSky> SkyMasks;
  std::uint64_t PartKeyOf(std::uint64_t parent, int half);
  std::vector<std::int32_t> Top;
  FaceClusterStatistics Stats;
  int Iteration = 0;
  double Epsilon = 0.0;
  double PartEpsilon = 0.0; ///< SubdivisionTolerance in W
  double Budget = 0.0;        ///< bytes (MemoryBudgetBytes resolved)
  double BytesPerElement = 0.0; ///< an element with its basis coefficients

  /// The irradiance vector of leaf e's expansion at x (zero for e < 0),
  /// limited to the range it takes at the element's nodes (`limit` off:
  /// not); `shown`: of the expansion less ExactFit.
  IrradianceVector Expansion(std::int32_t e, const Vec3& x, bool limit = true, bool shown = false) const;
  /// A halved triangle e's parts' shown expansions (ShownExpansion) fitted
  /// by its own basis, at x (the vertex output's value).
  IrradianceVector WholeTriangleExpansion(std::int32_t e, const Vec3& x) const;
  /// What the output shows of leaf e's expansion at x: with punctual
  /// lights or few emitters, the expansion less its fit of their direct
  /// light (ExactFit, limited in its own range), to which the output adds their exact light
  /// at the point itself (ShownExact); without, the expansion.
  IrradianceVector ShownExpansion(std::int32_t e, const Vec3& x) const;
  /// The punctual lights' and the emitters' (when shown exactly) exact
  /// vector irradiance at x on input triangle t (normal n), seen from
  /// inside t where x is on its boundary (SharedVertexPoint); zero
  /// without them.
  IrradianceVector ShownExact(std::uint32_t t, const Vec3& x, const Vec3& n) const;
  bool ShowsExactPunctual() const { return this->Lights && this->Lights->HasPunctualLights(); }
  bool ShowsExact() const { return this->ShowsExactPunctual() || this->ExactEmitters; }
  /// The emitting triangles whose direct light the output shows exactly
  /// (ExactEmitterTriangles); null: none.
  std::unique_ptr<FaceClusterExactEmitters> ExactEmitters;
  /// Lowest and Highest of every leaf.
  void BoundLeafExpansions();
  /// An element of `cluster`, or with `corners`, of a part of that
  /// triangle (cluster) below the input.
  std::int32_t NewElement(std::uint32_t cluster, std::int32_t parent, const Vec3* corners = nullptr, int half = 0);
  /// Whether e may be subdivided: a cluster always; a triangle or a part
  /// of one up to MaxBisections halvings, MaxLightBisections for the
  /// lights' direct light (the first iteration of a scene with lights).
  bool CanSubdivide(const FaceClusterElement& e) const;
  void Subdivide(std::int32_t e);
  bool HasUnshot(const FaceClusterElement& e) const;
  /// The largest coefficient of e's unshot radiosity (any channel).
  double UnshotMagnitude(const FaceClusterElement& e) const;

  // One iteration's transport (FaceClusterTransport.cxx): refinement in
  // rounds of pending transfers, then push-pull.
  struct PendingTransfer
  {
    std::int32_t Receiver, Emitter;
  };
  void Transport();
  /// A pending pair when the two elements face each other and the emitter
  /// has unshot radiosity (ASSIGN-SHOOTER).
  void AddShooter(std::int32_t receiver, std::int32_t emitter, std::vector<PendingTransfer>& pending) const;
  /// Coupling and error of 3.3.2 for receiver i and emitter j; from the
  /// kept coupling when there is one, else computed (and handed to `keep`
  /// when given and transfers are kept).
  Transfer TransferOf(std::int32_t i, std::int32_t j, std::unique_ptr<TransferCoupling>* keep = nullptr) const;
  /// TransferOf for n pairs: in parallel, each rank its share (WorkShare).
  std::vector<Transfer> ComputeTransfers(const PendingTransfer* pairs, std::size_t n);
  /// Accepts the pair's transfer into Accepted, or subdivides an end and
  /// appends the children's pairs to `next`.
  void Resolve(const PendingTransfer& pair, const Transfer& t, std::vector<PendingTransfer>& next);
  /// After a round: each leaf triangle (or part) whose transfers' summed
  /// fit departure exceeds SubdivisionTolerance is halved, its irradiance
  /// of this iteration dropped and its transfers queued for its parts in
  /// `pending` (also for one the lights halved since); true when any was.
  bool BisectOnTotals(std::vector<PendingTransfer>& pending);
  /// This iteration, per leaf triangle receiver that may be halved: its
  /// accepted transfers' summed departures (Transfer::Residual) and their emitters.
  std::vector<std::vector<double>> TotalResidual;
  std::vector<std::vector<std::int32_t>> AcceptedFrom;
  /// 3.3.3: a non-convex element's children's mutual pairs.
  void CheckSelfTransfer(std::int32_t i, std::vector<PendingTransfer>& next);
  /// First iteration: the lights at the leaves not checked yet (fitted
  /// into Accepted, or the leaf subdivided); true when any was subdivided.
  bool ResolveLights(std::vector<char>& checked);
  /// 3.3.4: push from the parent (`up`, null at the top; `upExact`: the
  /// part of it shown exactly, first iteration), store at the leaves, pull
  /// the new unshot radiosity.
  void PushPull(std::int32_t i, const IrradianceVector* up, const IrradianceVector* upExact);
  /// Per element, N_e coefficients: the irradiance accepted this iteration
  /// through transfers (in the first, all from the emitters).
  std::vector<IrradianceVector> Accepted;
  /// First iteration, per element, N_e coefficients: the lights' fit
  /// accepted (ResolveLights), and its punctual part. Apart from Accepted
  /// because an element subdivided after it took them drops them, its
  /// children taking the lights anew (Subdivide), where its transfers'
  /// light is pushed down or redone (BisectOnTotals).
  std::vector<IrradianceVector> AcceptedLights, AcceptedPunctual;
  /// The power (W, mean of the channels) that the leaves' new unshot
  /// radiosity sends out of them: the next shot's, for the decay rate.
  double NextPower = 0.0;
  RGB NextPowerRGB{ 0.0 };  ///< NextPower per channel
  /// The power (W per channel) the leaves received this iteration through
  /// transfers (n . dE at their nodes, the self-transfer left out).
  RGB ReceivedPower{ 0.0 };
  /// Scales this iteration's received light, and all that followed from
  /// it (the leaves' increments, the new unshot radiosity), so that the
  /// received power equals `shot` per channel; a scale outside [0.9, 1.1]
  /// is not applied (the transfers, not their rounding, are wrong there).
  void BalanceEnergy(const RGB& shot);
  /// The lights' vector irradiance at element e's rule nodes (external
  /// emitters of the first iteration), and their scalar spread over the
  /// nodes times the element's area, the punctual lights' times its
  /// largest reflectance: a transfer error bound in W. `punctual`, when
  /// given: the punctual lights' part at each node.
  /// With `sky` (transfers kept: SkyMasks), the sky from each node's
  /// mask (cast first when `castMask`) through its moments for the sky's
  /// Up (computed when Up changed).
  std::vector<IrradianceVector> LightAtNodes(std::int32_t e, double* spread, KeptSky* sky = nullptr,
    bool castMask = false, std::vector<IrradianceVector>* punctual = nullptr) const;
  /// A transfer error bound (W) of the punctual lights over cluster e that
  /// its nodes cannot show (see ResolveLights): per light, what it could
  /// bring beyond its nodes (PunctualLightExcess), and when its visibility
  /// samples (ShadowSamples of its triangles' centroids) are partly
  /// shadowed, all it could bring (PunctualLightMost); times its largest
  /// reflectance.
  double PunctualLightsBeyondNodes(const FaceClusterElement& e) const;
  /// Triangles of a cluster whose shadow rays test its lights' visibility.
  static constexpr std::uint32_t ShadowSamples = 16;
  std::unique_ptr<DirectLighting> Lights; ///< null without lights and sky
};
} // namespace radiosity

#endif
