// Light transfer between two face clusters in higher-order vector radiosity
// (Gobbetti, Spano & Agus 2003, sections 3.2 and 3.3):
//
// - the coupling coefficients of eq. 7, K_{i,a; j,b}, transport vectors from
//   the emitter's radiosity basis function b to the receiver's irradiance
//   basis function a: the receiver's least-squares fit (FaceClusterQuadrature,
//   nodes on its surface) of the irradiance vector at its nodes, from the
//   emitter's surface nodes with the point kernel m(x, y) of eq. 3 and exact
//   visibility (FaceClusterVisibility); the emitter's constant part by exact
//   vector form factors, horizon-clipped at each receiver node (its
//   triangles', or for a large flat cluster its box rectangle's scaled by
//   coverage), so that adjacent clusters cost no accuracy;
// - the transfer error of 3.3.2: at each receiver node the power
//   BFA'_ij(x) = A_i n_x . E(x) that the coefficients give, against the upper
//   and lower bounds of B_j V A_i^vis A_j^vis / (pi r^2) over the emitter's
//   nodes from the bounds on the radiosity and on the projected areas;
//   delta_ij is the largest departure;
// - the self-transfer error of 3.3.3.
//
// Departure: the paper weights both errors by the receiver's largest
// reflectance (the error of the reflected power: "it is radiosity that is
// finally displayed"). Irradiance is an output here (SPEC), and a black
// receiver's irradiance would then never be refined (85% RMS error on the
// exact-penumbra floor, 28% unweighted, at the input triangles' resolution),
// so the errors are those of the received power.
#ifndef Radiosity_FaceClusterTransfer_h
#define Radiosity_FaceClusterTransfer_h

#include "Radiosity/FaceCluster/ClusterBasis.h"
#include "Radiosity/FaceCluster/FaceClusterQuadrature.h"
#include "Radiosity/FaceCluster/FaceClusterVisibility.h"

#include <vector>

namespace radiosity
{
struct TransferRule
{
  int Nodes = 3; ///< Gauss-Legendre nodes per axis of a cluster's rectangle
  /// Shadow-size threshold of the multiresolution visibility, in receiver
  /// node spacings; 0 (the default) is exact visibility down to the
  /// triangles. The paper's semi-transparent clusters (1) darken concave
  /// surfaces, whose boxes bulge into the space the rays cross: 4.6% worst
  /// error inside a 1280-facet sphere against 0.98% exact, at equal time.
  double VisibilityThreshold = 0.0;
};

/// One side of a transfer: a cluster, its id, its surface rule, and how many
/// of the rule's basis functions take part. An element below the input
/// triangles has its input triangle's id and its own corners.
struct TransferEnd
{
  const FaceCluster* Cluster;
  std::uint32_t Id;
  const SurfaceRule* Rule;
  int Functions;
  const Vec3* Corners = nullptr; ///< a part of triangle Id, or null
};

struct Transfer
{
  int Receivers = 0; ///< irradiance functions N_e
  int Emitters = 0;  ///< radiosity functions N_b
  /// K[a * Emitters + b], eq. 7 (vectors, W/m^2 per W/m^2 of radiosity).
  std::vector<Vec3> K;
  /// delta_ij (W).
  double Error = 0.0;
  /// The part of it at the receiver's control points: the receiver's basis
  /// cannot follow the irradiance there, so the receiver is the one to split.
  double FitError = 0.0;
  /// For a receiver that is one triangle (or a part of one), per receiver
  /// point (its nodes, then its control points): the fit's departure
  /// A_i n . (fitted - direct) (W), signed. The fits are linear in the
  /// light, so the departures of a receiver's transfers add up to that of
  /// the light it receives in all.
  std::vector<double> Residual;
};

/// What a transfer owes to its two ends alone, not to the emitter's
/// radiosity: K, the irradiance vector per unit of each emitter function
/// at every receiver point, and the bounds of 3.3.2 per unit radiosity.
/// A solve keeps it to relight: the same pair in a later solve is then
/// evaluated (EvaluateCoupling) without a ray or a form factor.
struct TransferCoupling
{
  int Receivers = 0; ///< irradiance functions N_e
  int Emitters = 0;  ///< radiosity functions N_b
  std::vector<Vec3> K; ///< eq. 7, as Transfer::K
  /// Per receiver point (its nodes, then its control points) and emitter
  /// function b: the irradiance vector per unit of b (sum_q Phi_b(y_q) g_pq).
  std::vector<Vec3> AtPoint;
  /// Per receiver node: the largest and smallest B F A per unit radiosity
  /// over the emitter's nodes (3.3.2); +inf where no node lies above it.
  std::vector<double> UpperScale, LowerScale;
  bool ExactConstant = false; ///< the constant part by exact vector form factors
  bool Shadowed = false;      ///< some receiver point saw an emitter node hidden
  bool Residuals = false;     ///< the receiver is one triangle (Transfer::Residual kept)
  std::size_t Bytes() const;
};

/// The coupling of receiver i and emitter j: the rays and form factors.
TransferCoupling ComputeCoupling(const TransferEnd& receiver, const TransferEnd& emitter,
  const FaceClusterVisibility& visibility, const TransferRule& rule);

/// K and delta_ij from a coupling (computed for `receiver`) and the
/// emitter's radiosity, as ComputeTransfer (which is this of ComputeCoupling).
Transfer EvaluateCoupling(const TransferCoupling& coupling, const TransferEnd& receiver,
  const std::vector<RGB>& radiosity, double radiosityMin, double radiosityMax);

/**
 * K and delta_ij for receiver i and emitter j whose radiosity is
 * `radiosity` (coefficients of the emitter's first Functions basis
 * functions, RGB), its bounds over the emitter being [radiosityMin,
 * radiosityMax] (means of the channels). `spacing` is the receiver's node
 * spacing for the visibility threshold.
 */
Transfer ComputeTransfer(const TransferEnd& receiver, const TransferEnd& emitter,
  const std::vector<RGB>& radiosity, double radiosityMin, double radiosityMax,
  const FaceClusterVisibility& visibility, const TransferRule& rule);

/// delta_ii of 3.3.3 (unweighted, see above): max radiosity x (F_ii bounds' gap) x A_i.
double SelfTransferError(const FaceCluster& c, double radiosityMax);

/// Whether any of `to`'s box lies in front of `from` (always true for a
/// cluster with faces pointing both ways), or, below its box, in front of
/// any of its faces: Willmott's bound on the area facing along a corner to
/// corner direction of the two boxes (exact for a curved cluster, whose
/// tilted faces see below its base).
bool ClusterFaces(const FaceCluster& from, const FaceCluster& to);

/// n-point Gauss-Legendre nodes and weights on [0, 1] (n in 1..5).
void GaussLegendre(int n, double* nodes, double* weights);
} // namespace radiosity

#endif
