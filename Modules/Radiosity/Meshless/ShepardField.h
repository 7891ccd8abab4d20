// The meshless multilevel Shepard basis (Lehtinen et al. 2007, section 4):
// weights w_j(x, n) = K(|x - x_j| / r_j) max(0, n . n_j) with the cubic
// K(r) = 2r^3 - 3r^2 + 1 on [0, 1] (eqs. 12, 13); per level the normalised
// basis B_j = w_j / sum of the level's w_k (eqs. 4, 8), so each level's
// functions sum to one wherever the level has support; a field is
// F(x) = sum over levels of sum_j alpha_j B_j(x) (eq. 9), the coefficients on
// a finer level being differences to the approximation of the coarser ones
// (eqs. 6, 10), so that they tend to zero where the data are smooth.
// Basis functions act only within their reconstruction group.
#ifndef Radiosity_ShepardField_h
#define Radiosity_ShepardField_h

#include "Radiosity/Meshless/MeshlessPoints.h"

#include <utility>
#include <vector>

namespace radiosity
{
/// Eq. 13: 1 at r = 0, 0 from r = 1 on, C1.
inline double ShepardKernel(double r)
{
  return r >= 1.0 ? 0.0 : (2.0 * r - 3.0) * r * r + 1.0;
}

/// Eq. 12 for point p at (x, n).
inline double ShepardWeight(const MeshlessPoint& p, const Vec3& x, const Vec3& n)
{
  const double c = glm::dot(n, p.Normal);
  if (!(c > 0.0) || !(p.Radius > 0.0))
  {
    return 0.0;
  }
  return ShepardKernel(glm::length(x - p.Position) / p.Radius) * c;
}

class ShepardField
{
public:
  explicit ShepardField(const PointHierarchy& points);

  const PointHierarchy& Points() const { return *this->Hierarchy; }
  /// alpha_j, one per point (RGB); zero until set or fitted.
  std::vector<RGB>& Coefficients() { return this->Alpha; }
  const std::vector<RGB>& Coefficients() const { return this->Alpha; }

  /// The normalised basis functions of `level` that are non-zero at (x, n) in
  /// `group`, with their values (eq. 8); empty where the level has no support.
  void Basis(int level, std::uint32_t group, const Vec3& x, const Vec3& n,
    std::vector<std::pair<std::uint32_t, double>>& out) const;

  /// F at (x, n) from levels 0..maxLevel (all levels when maxLevel < 0), eq. 9.
  RGB Evaluate(const Vec3& x, const Vec3& n, std::uint32_t group, int maxLevel = -1) const;

  /// F (all levels) at `sets` sets of `perSet` points each (an output
  /// element's corners and centre), each set with its normal n[set], all
  /// in `group` and near one another (a tile of neighbouring elements):
  /// Evaluate at every point (the same basis functions, summed in another
  /// order), from one search of the point index per level for the whole
  /// tile (PointHierarchy::Reaching), narrowed per set, instead of one
  /// search per point. `out`: sets x perSet values.
  void EvaluateTile(const Vec3* x, const Vec3* n, std::size_t sets, std::size_t perSet,
    std::uint32_t group, RGB* out) const;

  /// Sets the coefficients that approximate `values` given at the points
  /// (eq. 10): level 0 takes the values, each finer level the difference to
  /// the approximation by the coarser levels at its points.
  void Fit(const std::vector<RGB>& values);

private:
  const PointHierarchy* Hierarchy;
  std::vector<RGB> Alpha;
};
} // namespace radiosity

#endif
