// The face cluster hierarchy of higher-order face cluster radiosity
// (Gobbetti, Spano & Agus 2003, section 3.1; Willmott, Heckbert & Garland
// 1999): per object, a binary tree whose leaves are the input triangles,
// built by greedy contraction of the dual graph in the manner of Garland,
// Willmott & Heckbert 2001 ("Hierarchical face clustering on polygonal
// surfaces"): the dual edge of least cost is contracted first, the cost being
// the planarity of the merged cluster (the least eigenvalue of its
// area-weighted covariance, the L2 plane-fit error), its orientation error
// (sum of A_k (1 - n . n_k)^2 about the fitted normal) and a compactness
// bias (the rise of the irregularity P^2 / (4 pi A)), all relative to area,
// so the hierarchy does not depend on the scene's scale. Components of an
// object that share no edge are joined along a chain of nearest roots.
//
// Per cluster (section 3.1): an oriented box with z along the area-averaged
// normal and x/y by rotating calipers (the minimum-area rectangle of the
// projected hull of the cluster); total area, the area vector sum A_k n_k
// (its length is the normal-projected area A^(n)); the six directional
// samples D_j^+ = sum A_k (n_k . u_j)_+ and D_j^- = sum A_k (-n_k . u_j)_+;
// whether the cluster is convex (no concave edge inside it), and minimum,
// maximum and area-averaged reflectance and emission.
//
// Leaves are not stored: cluster t < NumberOfTriangles() is triangle t and its
// data are derived from the triangle. Triangles are reordered so that every
// cluster's triangles are one range of TriangleOrder().
#ifndef Radiosity_FaceClusterHierarchy_h
#define Radiosity_FaceClusterHierarchy_h

#include "Radiosity/Common/Scene.h"
#include "Radiosity/Common/SolverTypes.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <vector>

namespace radiosity
{
/// Thrown when the progress callback asks to stop the build.
class FaceClusterBuildAborted : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

struct FaceClusterOptions
{
  /// Weight of the compactness bias against the planarity and orientation
  /// errors (Garland et al. 2001 use a shape bias of this kind).
  double ShapeWeight = 0.5;
  /// Largest number of worker threads (0: all).
  int Threads = 0;
};

struct FaceCluster
{
  static constexpr std::uint32_t None = 0xffffffffu;
  std::uint32_t Child[2]{ None, None };
  std::uint32_t Parent = None;
  std::uint32_t First = 0; ///< first of its triangles in TriangleOrder()
  std::uint32_t Count = 0; ///< number of its triangles
  std::uint32_t Depth = 0; ///< 0 at a root
  int Object = 0;
  bool Convex = true;

  // Oriented box: centre, axes (Axis[2] the area-averaged normal), half sizes.
  glm::vec3 Centre{ 0.0f };
  glm::vec3 Axis[3]{ { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  glm::vec3 HalfSize{ 0.0f };

  float Area = 0.0f;
  glm::vec3 AreaVector{ 0.0f }; ///< sum of A_k n_k
  glm::vec3 Centroid{ 0.0f };   ///< area-weighted centroid of the surface
  float DPlus[3]{ 0, 0, 0 };    ///< sum A_k (n_k . Axis[j])_+
  float DMinus[3]{ 0, 0, 0 };   ///< sum A_k (-n_k . Axis[j])_+

  glm::vec3 ReflectanceMin{ 0.0f }, ReflectanceMax{ 0.0f }, ReflectanceMean{ 0.0f };
  glm::vec3 EmissionMin{ 0.0f }, EmissionMax{ 0.0f }, EmissionMean{ 0.0f };

  bool IsLeaf() const { return this->Child[0] == None; }
  /// A_i^(n) = |sum A_k n_k|.
  double NormalProjectedArea() const;
  /// The area-averaged normal n_i (Axis[2]).
  Vec3 MeanNormal() const { return Vec3(this->Axis[2]); }
  /// Lower bound of the area seen from direction r: A^(n) (n_i . r)_+.
  double MinProjectedArea(const Vec3& r) const;
  /// Upper bound: sum_j (u_j . r)_+ D_j^+ + (-u_j . r)_+ D_j^-.
  double MaxProjectedArea(const Vec3& r) const;
  /// Bounds of the self form factor (Willmott): 1 - (sum of D) / A and
  /// 1 - A^(n) / A; both 0 for a convex cluster (section 3.3.3).
  double SelfFormFactorLower() const;
  double SelfFormFactorUpper() const;
  /// The projected area of the box seen from direction r (for opacity).
  double BoxProjectedArea(const Vec3& r) const;
};

class FaceClusterHierarchy
{
public:
  /// Builds the hierarchy; `progress` (fraction in [0, 1]) may abort by
  /// returning false, which throws FaceClusterBuildAborted. The hierarchy
  /// keeps the scene it was built on: a copy of `scene`, or the shared one.
  explicit FaceClusterHierarchy(const Scene& scene, const FaceClusterOptions& options = {},
    const ProgressCallback& progress = {});
  explicit FaceClusterHierarchy(std::shared_ptr<const Scene> scene,
    const FaceClusterOptions& options = {}, const ProgressCallback& progress = {});

  ///@{
  /// A hierarchy shared by every caller with the same geometry and materials
  /// (a fingerprint of the scene), built at the first call: a second solve on
  /// the same scene does not rebuild it. Held while anyone uses it.
  /// `reused`, when given, tells whether an existing hierarchy was returned.
  /// A scene given by reference is copied only when the hierarchy is built.
  static std::shared_ptr<const FaceClusterHierarchy> Shared(const Scene& scene,
    const FaceClusterOptions& options = {}, const ProgressCallback& progress = {},
    bool* reused = nullptr);
  static std::shared_ptr<const FaceClusterHierarchy> Shared(std::shared_ptr<const Scene> scene,
    const FaceClusterOptions& options = {}, const ProgressCallback& progress = {},
    bool* reused = nullptr);
  ///@}

  std::size_t NumberOfTriangles() const { return this->Triangles; }
  /// Clusters: the leaves (triangles) then the internal ones.
  std::size_t NumberOfClusters() const { return this->Triangles + this->Internal.size(); }
  /// Cluster `id` (a leaf is computed from its triangle).
  FaceCluster Cluster(std::uint32_t id) const;
  const std::vector<std::uint32_t>& Roots() const { return this->RootIds; }
  /// The stored data of an internal cluster; null for a leaf (a triangle).
  const FaceCluster* InternalCluster(std::uint32_t id) const
  {
    return id >= this->Triangles ? &this->Internal[id - this->Triangles] : nullptr;
  }
  /// Where triangle t is in TriangleOrder().
  std::uint32_t TrianglePosition(std::uint32_t t) const { return this->LeafPosition[t]; }
  /// Prefix sums of the triangles' areas in TriangleOrder() (size + 1): a
  /// cluster's area quantiles by binary search.
  const std::vector<double>& CumulativeArea() const { return this->Cumulative; }
  /// Triangles sorted so that each cluster's are [First, First + Count).
  const std::vector<std::uint32_t>& TriangleOrder() const { return this->Order; }
  ///@{
  /// The internal clusters (as indices id - NumberOfTriangles()) by height
  /// above their triangles: those of height h + 1 are HeightOrder()
  /// [HeightLevels()[h], HeightLevels()[h + 1]). A cluster's children are of
  /// smaller height, so a bottom-up pass may take one height at a time, in
  /// parallel (the tree is about 2 log n high: Contract merges in rounds).
  const std::vector<std::uint32_t>& HeightOrder() const { return this->ByHeight; }
  const std::vector<std::uint32_t>& HeightLevels() const { return this->HeightStart; }
  ///@}
  std::uint32_t Parent(std::uint32_t id) const;
  std::uint32_t Depth(std::uint32_t id) const;
  int MaximumDepth() const { return this->MaxDepth; }
  /// The ancestor of `id` at `depth` (itself when it is not deeper).
  std::uint32_t AncestorAtDepth(std::uint32_t id, std::uint32_t depth) const;
  /// Bytes held by the hierarchy (internal clusters, parents, order).
  std::size_t MemoryBytes() const;
  double BuildSeconds() const { return this->Seconds; }
  std::uint64_t Fingerprint() const { return this->Key; }
  const Scene& GetScene() const { return *this->Source; }

  /// The fingerprint Shared() keys on: points, triangles, objects, materials
  /// and the options.
  static std::uint64_t FingerprintOf(const Scene& scene, const FaceClusterOptions& options = {});

private:
  FaceClusterHierarchy(std::shared_ptr<const Scene> scene, std::uint64_t key,
    const FaceClusterOptions& options, const ProgressCallback& progress);
  static std::shared_ptr<const FaceClusterHierarchy> Share(const Scene& scene,
    const std::function<std::shared_ptr<const Scene>()>& own, const FaceClusterOptions& options,
    const ProgressCallback& progress, bool* reused);

  std::shared_ptr<const Scene> Source;
  std::size_t Triangles = 0;
  std::vector<FaceCluster> Internal;       // cluster Triangles + i
  std::vector<std::uint32_t> LeafParent;   // per triangle
  std::vector<std::uint32_t> LeafDepth;    // per triangle
  std::vector<std::uint32_t> LeafPosition; // per triangle: index in Order
  std::vector<std::uint32_t> RootIds;
  std::vector<std::uint32_t> Order;
  std::vector<double> Cumulative;
  std::vector<std::uint32_t> ByHeight, HeightStart;
  int MaxDepth = 0;
  double Seconds = 0.0;
  std::uint64_t Key = 0;

  void Contract(const FaceClusterOptions& options, const ProgressCallback& progress);
  void LayOut();
  void OrderByHeight();
  void ComputeBoxes(const FaceClusterOptions& options);
};
} // namespace radiosity

#endif
