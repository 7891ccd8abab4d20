// The precomputed direct-to-indirect transfer of Lehtinen et al. 2007,
// section 6.5 ("Indirect diffuse PRT for local light sources", after
// Kontkanen et al. 2006): the indirect irradiance is a linear operator
// applied to the direct irradiance's coefficients, so once the operator is
// known a moved or recoloured light costs one direct-lighting pass and the
// operator's application, not a solve.
//
// The operator kept is the one-bounce operator T of section 6.3 in the
// coefficient space of the Shepard basis, as a sparse matrix: one row per
// receiver (the basis functions the solve gathered to, and the two coarsest
// levels whole), each row the gather's weights on the senders' coefficients
// (GatherWeights: the same rays and sender levels as the solve, so T is the
// solve's own bounce) followed by the fit of eq. 10 (each finer receiver's
// coefficient the difference to the coarser receivers' reconstruction at
// its point, rows of the coarser levels' basis values). Its sparsity is the
// paper's: a row holds only the senders down to the level whose supports
// look small from the receiver (epsilon_Omega), a few hundred of the
// field's functions. When every object has one reflectance (a basis
// function acts within its object), a weight is one float and the
// reflectance is applied per sender: half the bytes read per bounce. The series T e + T^2 e + ... is summed at each relight
// (BounceSeries, with the solve's geometric tail), as the paper's runtime
// follows the links from the senders; precomputing the powers of T as
// Kontkanen et al. do would fill the matrix in (a closed room's T^k couples
// every pair) for no gain at the few bounces the tail needs.
//
// A new lighting can want receivers the solved one did not (a lamp moved
// to where the solve found no detail): those rows are gathered when a
// relight first asks for them and kept, and the series is summed again, so
// a relight is always the answer a fresh solve of its lighting gives.
#ifndef Radiosity_MeshlessTransfer_h
#define Radiosity_MeshlessTransfer_h

#include "Radiosity/Common/Types.h"
#include "Radiosity/Meshless/MeshlessRadiosity.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace radiosity
{
class Visibility;
class MeshlessNeighbourhoods;
class ShepardField;

class MeshlessTransfer
{
public:
  /**
   * The one-bounce operator onto `receivers` (point indices, any order;
   * kept sorted by level); `lists` give its fit and oracle in rows. `keepGoing` is asked every few thousand rows
   * (false: PlacementAborted is thrown). Throws SceneError when the rows
   * outgrow `memoryBudgetBytes` (0: no limit), naming what it needed.
   */
  MeshlessTransfer(const Scene& scene, const PointHierarchy& points, const Visibility& rays,
    const MeshlessNeighbourhoods& lists, const MeshlessOptions& options, std::vector<std::uint32_t> receivers,
    const std::function<bool()>& keepGoing = {}, double memoryBudgetBytes = 0.0);

  struct Series
  {
    std::vector<RGB> Indirect; ///< coefficients of T e + T^2 e + ..., one per point
    int Bounces = 0;
    bool Converged = false;
    /// Magnitude (sum over the coarsest receivers, largest channel) per bounce, the direct light's first.
    std::vector<double> Magnitudes;
    std::size_t RowsComputed = 0; ///< over every bounce
    /// Receivers the lighting wanted that were not rows, gathered for it
    /// (and kept for the relights after it).
    std::size_t RowsAdded = 0;
    double RowsAddedSeconds = 0.0;
    /// Receivers wanted but not gathered: past `gatherSeconds`.
    std::size_t RowsDeferred = 0;
  };
  /**
   * The indirect light of the direct field `direct` (coefficients, one per
   * point): bounces until one carries less than `tolerance` of the direct
   * light, or the ratio is steady (the tail added), or `maxBounces`. Each
   * bounce computes the rows the solve's receiver oracle would (section
   * 6.3: the coarsest level, then the children of the rows whose variation
   * or coefficient exceeds `threshold`, irradiance units), so that the
   * lighting solved gives the solve back; a receiver the oracle wants that
   * is not a row is gathered then (its row added, the series summed
   * again). With `gatherSeconds` > 0 the gathers stop once they took that
   * long (the coarsest wanted first; the rest wait for the next call, the
   * series summed over the rows there are). Throws SceneError when the
   * added rows outgrow the memory budget.
   */
  Series Indirect(const std::vector<RGB>& direct, double tolerance, int maxBounces, double threshold,
    double gatherSeconds = 0.0);

  /// The scene the rows added later gather from: a relit scene (the same
  /// surfaces, SameSurfaces) replaces the one the transfer was built on,
  /// which its owner may then release.
  void SetScene(const Scene& scene) { this->SourceScene = &scene; }

  std::size_t Receivers() const { return this->Rows.size(); }
  std::size_t Entries() const { return this->Senders.size() + this->FitColumns.size(); }
  std::size_t MemoryBytes() const;

private:
  /// One receiver's gather weights: senders sorted, WeightComponents each.
  void GatherRow(std::uint32_t j, const ShepardField& basis, std::vector<std::uint32_t>& senders,
    std::vector<float>& weights) const;
  /// Everything indexed by row (levels, the oracle's lists and the fit of
  /// eq. 10 in rows), from Rows and the neighbourhood lists.
  void IndexRows();
  /// Gathers the rows of `extra` (points that are not rows yet) and merges them in.
  void AddRows(std::vector<std::uint32_t> extra);
  /// The series over the rows as they are; `missing` gets the points the
  /// oracle wanted that are not rows.
  Series Sum(const std::vector<RGB>& direct, double tolerance, int maxBounces, double threshold,
    std::vector<std::uint32_t>& missing) const;
  void CheckMemory(std::size_t done, std::size_t of) const;

  const Scene* SourceScene;
  const Visibility& Rays;
  const MeshlessNeighbourhoods& Lists;
  MeshlessOptions Options;
  double MemoryBudgetBytes = 0.0;
  const PointHierarchy& Points;
  std::vector<std::uint32_t> RowOf; ///< per point, its row or UINT32_MAX
  std::vector<std::uint32_t> Rows;        ///< receivers, sorted by index (so by level)
  std::vector<std::size_t> LevelStart;    ///< into Rows, per level (+1)
  /// Per row, its range in Senders (and Weights, times WeightComponents):
  /// the precomputed rows in order, rows added later at the table's end.
  std::vector<std::size_t> RowStart, RowEnd;
  std::vector<std::uint32_t> Senders;
  /// Per sender: the weight (one float) when every object has one
  /// reflectance, applied per point (SenderReflectance) at each bounce;
  /// else three: the weight times the reflectance where the rays hit.
  std::vector<float> Weights;
  int WeightComponents = 3;
  std::vector<RGB> SenderReflectance;     ///< per point, with one-float weights
  std::vector<std::size_t> FitStart;      ///< into FitColumns/FitWeights (+1)
  std::vector<std::uint32_t> FitColumns;  ///< positions in Rows of coarser receivers
  std::vector<float> FitWeights;          ///< their basis value at the row's point
  std::size_t CoarseRows = 0;             ///< rows of level 0 (the magnitude's)
  /// The oracle's lists, in rows (CSR): a coarsest row's neighbours, a
  /// row's children on the next level, its coarser functions to compute first.
  std::vector<std::size_t> NeighbourStart, ChildStart, AncestorStart;
  std::vector<std::uint32_t> Neighbours, Children, Ancestors;
};
} // namespace radiosity

#endif
