// Orthonormal polynomial bases on a face cluster's box plane and the
// push-pull matrices between a cluster and its children (Gobbetti, Spano &
// Agus 2003, sections 3.2, 3.3.4 and 4): Gram-Schmidt orthonormalisation of
// 1, u, v, uv, u^2, v^2, u^3, u^2 v, u v^2, v^3 on the unit square of the
// box's x/y rectangle, (u, v) in [0, 1]^2. The result is products of
// Legendre polynomials (the paper's appendix: f_u = sqrt(3) (2u - 1),
// f_u2 = sqrt(5)/2 (3 (2u - 1)^2 - 1), ...). Each basis is a prefix of the
// next, so a radiosity basis is a subset of a larger irradiance basis and
// one push-pull matrix serves both (section 3.3.4).
#ifndef Radiosity_ClusterBasis_h
#define Radiosity_ClusterBasis_h

#include "Radiosity/FaceCluster/FaceClusterHierarchy.h"

#include <glm/vec2.hpp>

#include <array>
#include <vector>

namespace radiosity
{
/// The bases of the paper, by their number of functions.
enum class BasisKind
{
  Constant = 1,
  Linear = 3,
  Bilinear = 4,
  Quadratic = 6,
  Cubic = 10
};

/// "constant", "linear", "bilinear", "quadratic" or "cubic".
const char* BasisName(BasisKind kind);

class PolynomialBasis
{
public:
  static constexpr int MaximumSize = 10;
  explicit PolynomialBasis(BasisKind kind);

  BasisKind Kind() const { return this->Type; }
  int Size() const { return static_cast<int>(this->Type); }
  /// The basis functions at (u, v): out[0 .. Size()).
  void Evaluate(double u, double v, double* out) const;
  /// Function k as coefficients of the monomials 1, u, v, uv, u^2, v^2, u^3,
  /// u^2 v, u v^2, v^3.
  const std::array<double, MaximumSize>& Monomials(int k) const { return this->Coefficients[k]; }

private:
  BasisKind Type;
  std::array<std::array<double, MaximumSize>, MaximumSize> Coefficients{};
};

/// The monomials 1, u, v, uv, u^2, v^2, u^3, u^2 v, u v^2, v^3 at (u, v).
void EvaluateMonomials(double u, double v, double* out);

/// (u, v) of point x in cluster c's box: its projection on the box's x/y
/// rectangle, [0, 1]^2 inside (0.5 along a side of zero length).
glm::dvec2 BoxCoordinates(const FaceCluster& c, const Vec3& x);

/// The point of cluster c's mid-plane at box coordinates (u, v).
Vec3 BoxPoint(const FaceCluster& c, double u, double v);

/// Area of cluster c's box rectangle (the measure the basis is orthonormal in).
double RectangleArea(const FaceCluster& c);

/**
 * The push matrix from `parent` to `child` (row-major, Size() x Size()):
 * P[a][b] = (1 / |R_c|) integral over the child's rectangle R_c of
 * Phi^parent_a Phi^child_b dA, by Gauss-Legendre cubature exact for the
 * bases' degrees. Push: the child's coefficients of the parent's expansion
 * sum_a x_a Phi^parent_a are sum_a x_a P[a][b]. Pull: the parent's
 * coefficients of functions given on its children are
 * sum_children |R_c| / |R_p| sum_b P_c[a][b] y^c_b.
 */
std::vector<double> PushMatrix(const PolynomialBasis& basis, const FaceCluster& parent, const FaceCluster& child);
} // namespace radiosity

#endif
