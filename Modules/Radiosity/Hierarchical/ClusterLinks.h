// Clustering for hierarchical radiosity (Smits, Arvo & Greenberg 1994,
// "A clustering algorithm for radiosity in complex environments"; Sillion
// 1995, "A unified hierarchical algorithm for global illumination with
// scattering volumes and object clusters"), on the face cluster hierarchy of
// Willmott, Heckbert & Garland 1999 (FaceCluster/FaceClusterHierarchy.h) as
// Willmott's face cluster radiosity uses it.
//
// Plain hierarchical radiosity links every facing pair of input triangles
// before it refines: its cost is quadratic in the input. Here the links start
// between the roots of the face cluster hierarchy (one per object) and are
// refined down through the clusters into the polygons' quadtrees: a node is
// an internal cluster or a quadtree element (an input triangle is its root
// element). A pair of two elements is handed to the polygon solver
// (HierarchicalRadiosity::Refine), which computes blockers and exact form
// factors, and so keeps discontinuity meshing on the links that end on
// polygons; a large polygon facing a distant cluster is split in its
// quadtree against the cluster, as a pair of polygons would be.
//
// - Refinement (BF refinement with cluster bounds, as Smits et al. 2.3): the
//   transfer from Q to R is at most B_Q max(A_Q, A_R) / (pi d^2), d the gap
//   between the clusters' bounding spheres; a link is accepted when that is
//   at most the link tolerance, else the cluster with the larger sphere is
//   split. A pair with no gap is always split.
// - Receiver clusters take vector irradiance (Willmott et al. 1999, section
//   4; Gobbetti et al. 2003, 3.3.4): a triangle of the cluster receives
//   n_t . E. That is exact only when every triangle of the cluster faces the
//   whole source, so a link to a cluster is accepted only when the cluster's
//   normal cone (half angle beta around its mean normal) and the cone of
//   directions to the source (half angle alpha from the two spheres) keep
//   every n_t . (y - x) positive: angle(axis, direction) + beta + alpha < 90
//   degrees, or when the cluster is nearly flat (beta at most 0.125 rad:
//   the source's samples behind its plane are then left out of the
//   transfer, as an element's are), and its radius is at most a quarter of
//   the distance; otherwise the receiver is split. The vector is kept to first order about the
//   cluster's centroid (its gradient from the source's samples, as the
//   higher-order bases of Gobbetti et al. 2003 do): at zeroth order a
//   triangle away from the centroid was off by up to 20% on the inside of a
//   sphere, at first order 0.4%. Element receivers take scalar irradiance,
//   each sample clamped to its own half-space.
// - Leaves: a cluster no larger than the smallest element is never split
//   (face cluster radiosity's leaves), whatever its normal cone, so the links
//   stop at a size, not at the input's triangles; two nodes that cannot be
//   split are sampled at any distance, each source point a disc of its area.
//   A curved leaf receives links that some of its triangles face away from:
//   each triangle takes max(0, n_t . E_l) of each such link (the sum of
//   opposite links cancels on a triangle facing across them), found down the
//   leaf's subtree only where the link's terminator passes
//   (ClusterLinksCurvedLeaves.cxx).
// - Pairs that cannot exchange light are dropped before any work: a flat
//   cluster and a cluster wholly behind its plane, or cones that face away.
// - Transfer: K sample points per cluster (the centroids of the triangles at
//   its K area quantiles, weight A/K; every triangle when it has at most K),
//   the kernel cos cos / (pi r^2) between the receiver's and the source's
//   samples, and visibility by one ray per pair of samples (Smits et al.'s
//   sampled visibility for cluster links: no blockers are kept for them).
// - Gathering: the source's area-mean radiosity B_Q (pulled up the face
//   cluster tree, or the element's own), the expansions pushed down to the
//   triangles, where they join the polygon solver's irradiance (a constant
//   per input triangle, and per element for the scalar links).
// - Row-sum normalisation where the scene is closed around a triangle (see
//   Normalize): the cluster links' form factors are approximations, and a
//   closed room multiplies their error by 1 / (1 - rho).
#ifndef Radiosity_ClusterLinks_h
#define Radiosity_ClusterLinks_h

#include "Radiosity/Common/ElementMesh.h"
#include "Radiosity/Common/Scene.h"
#include "Radiosity/Common/SolverTypes.h"

#include <glm/vec3.hpp>
#include <tbb/parallel_invoke.h>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace radiosity
{
class FaceClusterHierarchy;
class Visibility;

class ClusterLinks
{
public:
  /// Node ids: an internal face cluster's own id, or ElementBit | a quadtree element.
  static constexpr std::uint32_t ElementBit = 0x80000000u;
  /// A pending pair of nodes.
  struct Pair
  {
    std::uint32_t Receiver, Source;
  };
  /// Called for a pair of two quadtree elements (receiver, source).
  using ElementPair = std::function<void(std::uint32_t, std::uint32_t)>;
  /// Splits a quadtree element, returning the first of its four children.
  using Split = std::function<std::uint32_t(std::uint32_t)>;

  /// `hierarchy` built on `scene`; `mesh` the polygon solver's quadtrees
  /// (root t is triangle t), split only through `split` and not below
  /// `minEdge` (longest edge), and `radiosity` its per-element radiosity;
  /// `diagonal` (SceneAnalysis) and `planeTolerance` in the scene's units.
  ClusterLinks(const Scene& scene, std::shared_ptr<const FaceClusterHierarchy> hierarchy,
    const Visibility& rays, double diagonal, double planeTolerance, const ElementMesh& mesh, Split split,
    double minEdge, const std::vector<RGB>& radiosity);
  ~ClusterLinks();

  const FaceClusterHierarchy& Hierarchy() const { return *this->Clusters; }
  std::size_t NumberOfLinks() const;
  /// Pairs of roots refined at the start (the number of objects squared).
  std::size_t NumberOfRootPairs() const;
  std::size_t MemoryBytes() const;

  /// Area-mean radiosity of every cluster from its triangles' root elements.
  void PullRadiosity();
  /// The first links: every pair of roots refined against `epsilon` with the
  /// radiosities of the last PullRadiosity. False when `keepGoing` said stop.
  bool LinkRoots(double epsilon, std::vector<Pair>& out, const ElementPair& elements,
    const std::function<bool()>& keepGoing);
  /// Links whose bound exceeds `epsilon` with the current radiosities are
  /// removed and refined again, and so are the pairs deferred because their
  /// source had no radiosity; returns how many changed (a pair still dark
  /// stays deferred and does not count).
  std::size_t RefineAgain(double epsilon, std::vector<Pair>& out, const ElementPair& elements);
  /// Only the deferred pairs whose source has radiosity now, refined and
  /// linked (the others stay deferred); returns how many. Light that reaches
  /// a surface only through such a pair is lost without it, whatever the
  /// number of refinement rounds.
  std::size_t LinkDeferred(double epsilon, std::vector<Pair>& out, const ElementPair& elements);
  /// Computes the pending links' transfers and adds those that carry any;
  /// false when `keepGoing` (asked between blocks) said stop.
  bool Compute(const std::vector<Pair>& pending, const std::function<bool()>& keepGoing);
  /// Irradiance through the cluster links from the radiosities of the last
  /// PullRadiosity, W/m^2: per input triangle (the clusters' expansions at
  /// it) and per element (its scalar links), before the normalisation.
  void Gather(std::vector<RGB>& triangleIrradiance, std::vector<RGB>& elementIrradiance) const;

  /// Row-sum normalisation of the cluster links (Baum, Rushmeier & Winget
  /// 1989, as HierarchicalRadiosity::Normalize does for the polygon links):
  /// where a triangle's hemisphere is closed (every one of 32 rays from its
  /// centroid hits a surface), the form factors of everything a leaf of it
  /// sees sum to 1, so the leaf's cluster links' sum (its chain's) is scaled
  /// to 1 less `polygonFactors[leaf]` (the sum of its polygon links): `scale`
  /// per element (1 elsewhere). Returns the number of leaves scaled. Call
  /// PullRadiosity before the next Gather.
  std::size_t Normalize(const std::vector<double>& polygonFactors, std::vector<double>& scale);

  /// Called with the link count before a link is added (memory checks).
  std::function<void(std::size_t)> BeforeLink;

private:
  /// To an element: the mean form factor over its points (visibility included).
  struct ScalarLink
  {
    std::uint32_t Receiver, Source; ///< element id; node id
    float Factor;
  };
  /// To a cluster: the vector irradiance per unit source radiosity at the
  /// receiver's centroid and its gradient (Gradient[3 k + j] = dE_j / dx_k),
  /// a first-order expansion over the receiver.
  struct VectorLink
  {
    std::uint32_t Receiver, Source; ///< cluster id; node id
    glm::vec3 Factor;
    float Gradient[9];
    /// To a curved leaf (Leaf, cone over NearlyFlatCone) some of whose
    /// triangles face away from it: clamped per triangle (Descend).
    bool Straddles;
    /// Its index among the straddling links (Index), for its recorded
    /// FacingOf decisions.
    std::uint32_t Straddling;
  };
  /// Sample points of a node: its triangles' centroids at area quantiles
  /// (every triangle when it has at most Most), an element's four points.
  struct SamplePoints
  {
    static constexpr int Most = 8;
    Vec3 Point[Most];
    Vec3 Normal[Most];
    double Weight[Most]; ///< area each stands for
    int Count = 0;
  };
  /// Bounding sphere, normal cone and area of a node.
  struct Bounds
  {
    Vec3 Centre;
    double Radius;
    Vec3 Axis;
    double ConeAngle; ///< largest angle between Axis and a triangle's normal
    double CosCone, SinCone; ///< of ConeAngle
    double Area;
    bool Flat;        ///< one plane: every triangle in it, one normal
    bool Leaf;        ///< a cluster no larger than an element may become: never split
  };
  /// A cluster whose normal cone is at most this half angle (radians)
  /// receives from a source straddling its plane: the source's samples behind
  /// the plane through its centroid are left out (Compute), so a triangle
  /// tilted by up to this angle from the axis is off by at most sin(angle) of
  /// the link's bound. Without it every cluster grazed by a source was split
  /// down to its triangles.
  static constexpr double NearlyFlatCone = 0.125;
  /// A link sampled at a cluster (K points with sampled visibility) only when
  /// the two spheres' radii sum to at most this fraction of the distance,
  /// unless neither can be split (leaves, elements at the smallest size).
  /// Measured on a closed cube of 192 triangles, rho 0 and emission 1, without
  /// the row normalisation: irradiance 0.93 to 1.16 at 0.5, 0.96 to 1.10 at
  /// 0.35, 0.985 to 1.029 at 0.25 (exact 1).
  static constexpr double SampledOpening = 0.25;
  /// A distant pair with more rays than this tests a stratified quarter of
  /// them first (Compute).
  static constexpr std::size_t QuarterRays = 16;
  std::uint32_t NodeOf(std::uint32_t cluster) const;
  static bool IsElement(std::uint32_t node) { return (node & ElementBit) != 0; }
  static std::uint32_t ElementOf(std::uint32_t node) { return node & ~ElementBit; }
  Bounds BoundsOf(std::uint32_t node) const;
  const RGB& RadiosityOf(std::uint32_t node) const;
  /// True when no light can pass from `source` to `receiver`.
  bool CannotExchange(const Bounds& receiver, const Bounds& source, std::uint32_t sourceNode) const;
  /// HSA91's BF bound: B_Q max(A_Q, A_R) / (pi d^2), infinite without a gap.
  double Bound(const Bounds& r, const Bounds& q, std::uint32_t source) const;
  void Refine(std::uint32_t r, std::uint32_t q, double epsilon, std::vector<Pair>& out, const ElementPair& elements);
  void Index();
  void SamplesOf(std::uint32_t node, SamplePoints& s) const;
  /// How the triangles of a node of bounds `b` face a link's vector
  /// irradiance (its first-order expansion about `origin`, taken at the
  /// node's centre): by the normal cone, or by the axis alone when the node
  /// is nearly flat.
  enum class Facing : unsigned char
  {
    All,
    None,
    Some
  };
  static Facing FacingOf(const VectorLink& link, const Vec3& origin, const Bounds& b);
  /// A link carried into a curved leaf: its source's radiosity and the
  /// centre its expansion is about.
  struct Carried
  {
    const VectorLink* Link;
    RGB B;
    Vec3 Origin;
  };
  /// How the nodes below a curved leaf face one of its straddling links: the
  /// first descent after the links change (Index) records each FacingOf
  /// decision in the order it makes them (depth first; a link's subtree is
  /// walked by one thread), the next descents replay them. They are fixed
  /// while the links are, and they were a third of a sweep's descent.
  mutable std::vector<std::vector<Facing>> FacingDecisions;
  mutable std::vector<std::uint32_t> FacingCursor; ///< per straddling link, its next decision (replay)
  mutable bool FacingRecorded = false;
  Facing FacingAt(const Carried& l, std::size_t internal) const;
  /// Pushes the expansion from above (a cluster_detail::Expansion,
  /// ClusterExpansion.h) down the subtree at `position` of Preorder to the
  /// triangles, with the links `carried`
  /// from a curved leaf above: each is summed where every triangle below
  /// faces it, dropped where none does, and clamped per triangle on the rest.
  void Descend(std::uint32_t position, const void* above, const std::vector<Carried>& carried,
    std::vector<RGB>& out) const;

  const Scene& SourceScene;
  std::shared_ptr<const FaceClusterHierarchy> Clusters;
  const Visibility& Rays;
  double Diagonal;
  double PlaneTolerance;
  const ElementMesh& Mesh;
  Split SplitElement;
  double MinEdge;
  const std::vector<RGB>* ElementRadiosity;
  std::size_t Triangles;
  /// Per input triangle, computed once: the sweeps' descent, the radiosity
  /// pull and the sample points read them for every triangle, every sweep.
  struct TriangleFrame
  {
    Vec3 Centroid;
    Vec3 Normal;
    double Area;
  };
  std::vector<TriangleFrame> Frames;
  /// The hierarchy in depth-first order, each root's tree in turn: what a
  /// sweep's descent reads of every node, in the order it reads it (the
  /// clusters' own records are scattered in memory by their creation order).
  struct DescentNode
  {
    Vec3 Point;          ///< a cluster's centroid, a triangle's
    Vec3 Normal;         ///< a triangle's
    double Area;
    std::uint32_t Id;    ///< cluster id (a triangle below Triangles)
    std::uint32_t End;   ///< the position after its subtree
  };
  /// The area-mean radiosity of the clusters of the subtree at `position`
  /// of Preorder, its children's first (PullRadiosity).
  void Pull(std::uint32_t position);
  /// The positions of the two children of the internal node at `position`
  /// of Preorder: the first follows its parent, the second the first's subtree.
  std::array<std::uint32_t, 2> ChildPositions(std::uint32_t position) const
  {
    return { position + 1, this->Preorder[position + 1].End };
  }
  /// `visit` on both children of the internal node at `position`, in
  /// parallel where `parallel` and its subtree has over 4096 triangles (a
  /// subtree of n triangles has 2 n - 1 nodes).
  template <typename Visit>
  void VisitChildren(std::uint32_t position, bool parallel, const Visit& visit) const
  {
    const std::array<std::uint32_t, 2> c = this->ChildPositions(position);
    if (parallel && this->Preorder[position].End - position > 2 * 4096)
    {
      tbb::parallel_invoke([&]() { visit(c[0]); }, [&]() { visit(c[1]); });
    }
    else
    {
      visit(c[0]);
      visit(c[1]);
    }
  }
  std::vector<DescentNode> Preorder;
  std::vector<std::uint32_t> RootPositions; ///< per root, its position in Preorder
  std::vector<Bounds> InternalBounds; ///< per internal cluster (id - Triangles)
  std::vector<RGB> Radiosity;         ///< per cluster, area mean
  std::vector<ScalarLink> ToElements; ///< sorted by receiver after Index
  std::vector<VectorLink> ToClusters; ///< sorted by receiver after Index
  std::vector<std::uint32_t> ElementOffsets; ///< per element, its first scalar link
  std::vector<std::uint32_t> ClusterOffsets; ///< per internal cluster, its first vector link
  /// Pairs whose source had no radiosity yet: refined by the next RefineAgain.
  std::vector<Pair> Deferred;
  /// The deferred pairs whose source has radiosity now, refined (the rest
  /// stay deferred); how many. The caller indexes the links.
  std::size_t RefineLitDeferred(double epsilon, std::vector<Pair>& out, const ElementPair& elements);
  std::vector<unsigned char> Closed;  ///< per triangle: every ray of its hemisphere hit a surface
};
} // namespace radiosity

#endif
