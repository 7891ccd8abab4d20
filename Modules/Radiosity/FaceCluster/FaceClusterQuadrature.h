// Quadrature on a face cluster's surface for higher-order face cluster
// radiosity (Gobbetti et al. 2003, 3.3.1: "we distribute sample points on
// the entire cluster"): the n x n Gauss-Legendre nodes of the cluster's box
// rectangle, each projected along the box normal onto the cluster's own
// triangles (the hit nearest the rectangle's plane, found through the
// cluster's subtree); nodes over no surface are dropped, so no node lies
// off the surface (a node outside a closed room sees nothing and would
// lose light). Weights are the rectangle's, divided by the cosine of the
// hit triangle's tilt, then scaled to sum to the cluster's area.
//
// The basis (ClusterBasis, in the box's coordinates) is fitted to values at
// the nodes by weighted least squares, the Galerkin projection onto the
// basis restricted to the cluster's surface: Dual holds the weights, so
// that coefficient a of f is sum_p Dual[p][a] f(x_p). A rule with fewer
// nodes than functions gives the minimum-norm fit. A single triangle gets a
// triangle rule instead (MakeTriangleRule).
#ifndef Radiosity_FaceClusterQuadrature_h
#define Radiosity_FaceClusterQuadrature_h

#include "Radiosity/FaceCluster/ClusterBasis.h"

#include <vector>

namespace radiosity
{
struct SurfaceRule
{
  std::vector<Vec3> Points;
  std::vector<Vec3> Normals;   ///< of the triangle each node lies on
  std::vector<double> Weights; ///< sum: the cluster's area
  int Functions = 0;
  std::vector<double> Phi;  ///< [p * Functions + a]: basis function a at node p
  std::vector<double> Dual; ///< [p * Functions + a]: least-squares weights
  /// Control points (a triangle's corners, just inside it), where a
  /// transfer's fit is compared with the directly integrated irradiance
  /// (3.3.2): the fit is worst where it extrapolates from the nodes.
  std::vector<Vec3> Controls;
  std::vector<Vec3> ControlNormals;
  std::vector<double> ControlPhi; ///< [c * Functions + a]

  std::size_t Size() const { return this->Points.size(); }
  /// The fitted coefficients of values f[p] at the nodes.
  void Fit(const double* values, std::size_t stride, double* coefficients) const;
};

/// The rule of cluster `id` (data `c`) for `basis`, n x n nodes before the
/// projection (n in 1..5).
SurfaceRule MakeSurfaceRule(const FaceClusterHierarchy& hierarchy, std::uint32_t id,
  const FaceCluster& c, const PolynomialBasis& basis, int nodesPerAxis);

/// The rule of a triangle (an input triangle, or an element below the input
/// triangles) with data `c`: Stroud's conical product of n x n
/// Gauss-Legendre nodes, all inside the triangle, so that no fit is an
/// extrapolation from nodes clustered on one side of it.
SurfaceRule MakeTriangleRule(const Vec3 corner[3], const FaceCluster& c, const PolynomialBasis& basis,
  int nodesPerAxis);

/// Least-squares weights of `basis` (in `frame`'s box coordinates) over the
/// points and weights given: out[p * Size() + a].
std::vector<double> DualWeights(const FaceCluster& frame, const PolynomialBasis& basis,
  const std::vector<Vec3>& points, const std::vector<double>& weights);
} // namespace radiosity

#endif
