#include "Radiosity/FaceCluster/ClusterBasis.h"

#include <cmath>

namespace radiosity
{
const char* BasisName(BasisKind kind)
{
  switch (kind)
  {
    case BasisKind::Constant:
      return "constant";
    case BasisKind::Linear:
      return "linear";
    case BasisKind::Bilinear:
      return "bilinear";
    case BasisKind::Quadratic:
      return "quadratic";
    case BasisKind::Cubic:
      return "cubic";
  }
  return "unknown";
}

namespace
{
// Monomial exponents (a, b) of u^a v^b, in the paper's order.
constexpr int Exponents[PolynomialBasis::MaximumSize][2] = { { 0, 0 }, { 1, 0 }, { 0, 1 },
  { 1, 1 }, { 2, 0 }, { 0, 2 }, { 3, 0 }, { 2, 1 }, { 1, 2 }, { 0, 3 } };

// Integral of u^a v^b over the unit square.
double MonomialIntegral(int i, int j)
{
  const int a = Exponents[i][0] + Exponents[j][0];
  const int b = Exponents[i][1] + Exponents[j][1];
  return 1.0 / ((a + 1.0) * (b + 1.0));
}

// 5-point Gauss-Legendre on [0, 1]: exact to degree 9 per axis, enough for
// the product of two cubics (degree 6).
constexpr double GaussNodes[5] = { 0.04691007703066800, 0.23076534494715845, 0.5,
  0.76923465505284155, 0.95308992296933200 };
constexpr double GaussWeights[5] = { 0.11846344252809454, 0.23931433524968324,
  0.28444444444444444, 0.23931433524968324, 0.11846344252809454 };
}

void EvaluateMonomials(double u, double v, double* out)
{
  out[0] = 1.0;
  out[1] = u;
  out[2] = v;
  out[3] = u * v;
  out[4] = u * u;
  out[5] = v * v;
  out[6] = u * u * u;
  out[7] = u * u * v;
  out[8] = u * v * v;
  out[9] = v * v * v;
}

PolynomialBasis::PolynomialBasis(BasisKind kind)
  : Type(kind)
{
  // Gram-Schmidt in the L2 inner product of the unit square, with the
  // monomials' exact integrals; modified Gram-Schmidt for stability.
  const int n = this->Size();
  auto inner = [](const std::array<double, MaximumSize>& x, const std::array<double, MaximumSize>& y) {
    double s = 0.0;
    for (int i = 0; i < MaximumSize; ++i)
    {
      for (int j = 0; j < MaximumSize; ++j)
      {
        s += x[i] * y[j] * MonomialIntegral(i, j);
      }
    }
    return s;
  };
  for (int k = 0; k < n; ++k)
  {
    std::array<double, MaximumSize> f{};
    f[k] = 1.0;
    for (int j = 0; j < k; ++j)
    {
      const double projection = inner(f, this->Coefficients[j]);
      for (int i = 0; i < MaximumSize; ++i)
      {
        f[i] -= projection * this->Coefficients[j][i];
      }
    }
    const double norm = std::sqrt(inner(f, f));
    for (int i = 0; i < MaximumSize; ++i)
    {
      this->Coefficients[k][i] = f[i] / norm;
    }
  }
}

void PolynomialBasis::Evaluate(double u, double v, double* out) const
{
  double m[MaximumSize];
  EvaluateMonomials(u, v, m);
  for (int k = 0; k < this->Size(); ++k)
  {
    double s = 0.0;
    for (int i = 0; i <= k; ++i)
    {
      s += this->Coefficients[k][i] * m[i];
    }
    out[k] = s;
  }
}

glm::dvec2 BoxCoordinates(const FaceCluster& c, const Vec3& x)
{
  const Vec3 d = x - Vec3(c.Centre);
  glm::dvec2 uv;
  for (int j = 0; j < 2; ++j)
  {
    const double h = c.HalfSize[j];
    uv[j] = h > 0.0 ? 0.5 * (glm::dot(d, Vec3(c.Axis[j])) / h + 1.0) : 0.5;
  }
  return uv;
}

Vec3 BoxPoint(const FaceCluster& c, double u, double v)
{
  return Vec3(c.Centre) + (2.0 * u - 1.0) * double(c.HalfSize[0]) * Vec3(c.Axis[0]) +
    (2.0 * v - 1.0) * double(c.HalfSize[1]) * Vec3(c.Axis[1]);
}

double RectangleArea(const FaceCluster& c)
{
  return 4.0 * double(c.HalfSize[0]) * double(c.HalfSize[1]);
}

std::vector<double> PushMatrix(const PolynomialBasis& basis, const FaceCluster& parent, const FaceCluster& child)
{
  const int n = basis.Size();
  std::vector<double> p(static_cast<std::size_t>(n) * n, 0.0);
  double fp[PolynomialBasis::MaximumSize], fc[PolynomialBasis::MaximumSize];
  for (int i = 0; i < 5; ++i)
  {
    for (int j = 0; j < 5; ++j)
    {
      const double u = GaussNodes[i], v = GaussNodes[j];
      const double w = GaussWeights[i] * GaussWeights[j];
      const glm::dvec2 up = BoxCoordinates(parent, BoxPoint(child, u, v));
      basis.Evaluate(up.x, up.y, fp);
      basis.Evaluate(u, v, fc);
      for (int a = 0; a < n; ++a)
      {
        for (int b = 0; b < n; ++b)
        {
          p[a * n + b] += w * fp[a] * fc[b];
        }
      }
    }
  }
  return p;
}
} // namespace radiosity
