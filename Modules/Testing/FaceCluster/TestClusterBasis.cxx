// The face cluster bases (Gobbetti et al. 2003, 3.2 and 4): orthonormal on the
// box rectangle, the paper's Legendre products, each a prefix of the next;
// and push-pull consistency between a cluster and its children.
#include "Radiosity/FaceCluster/ClusterBasis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace radiosity;

namespace
{
const BasisKind AllKinds[] = { BasisKind::Constant, BasisKind::Linear, BasisKind::Bilinear,
  BasisKind::Quadratic, BasisKind::Cubic };

// A flat cluster whose box is the rectangle centre +- h0 axis0 +- h1 axis1.
FaceCluster Rectangle(const Vec3& centre, double angle, double h0, double h1)
{
  FaceCluster c;
  c.Centre = glm::vec3(centre);
  c.Axis[0] = glm::vec3(std::cos(angle), std::sin(angle), 0.0);
  c.Axis[1] = glm::vec3(-std::sin(angle), std::cos(angle), 0.0);
  c.Axis[2] = glm::vec3(0, 0, 1);
  c.HalfSize = glm::vec3(h0, h1, 0.0);
  return c;
}

// sum_k x_k Phi_k at (u, v).
double Expand(const PolynomialBasis& basis, const std::vector<double>& x, double u, double v)
{
  double f[PolynomialBasis::MaximumSize];
  basis.Evaluate(u, v, f);
  double s = 0.0;
  for (int k = 0; k < basis.Size(); ++k)
  {
    s += x[k] * f[k];
  }
  return s;
}

std::vector<double> Push(const std::vector<double>& p, const std::vector<double>& x, int n)
{
  std::vector<double> y(n, 0.0);
  for (int a = 0; a < n; ++a)
  {
    for (int b = 0; b < n; ++b)
    {
      y[b] += x[a] * p[a * n + b];
    }
  }
  return y;
}
}

TEST(ClusterBasis, OrthonormalOnTheBoxRectangle)
{
  // A 12 x 12 midpoint rule would not be exact; Gauss-Legendre 6 x 6 is, for
  // products of cubics.
  const double nodes[6] = { 0.033765242898423986, 0.16939530676686776, 0.38069040695840156,
    0.61930959304159844, 0.83060469323313224, 0.96623475710157601 };
  const double weights[6] = { 0.085662246189585173, 0.18038078652406930, 0.23395696728634552,
    0.23395696728634552, 0.18038078652406930, 0.085662246189585173 };
  for (BasisKind kind : AllKinds)
  {
    const PolynomialBasis basis(kind);
    const int n = basis.Size();
    std::vector<double> gram(n * n, 0.0);
    double f[PolynomialBasis::MaximumSize];
    for (int i = 0; i < 6; ++i)
    {
      for (int j = 0; j < 6; ++j)
      {
        basis.Evaluate(nodes[i], nodes[j], f);
        for (int a = 0; a < n; ++a)
        {
          for (int b = 0; b < n; ++b)
          {
            gram[a * n + b] += weights[i] * weights[j] * f[a] * f[b];
          }
        }
      }
    }
    for (int a = 0; a < n; ++a)
    {
      for (int b = 0; b < n; ++b)
      {
        EXPECT_NEAR(gram[a * n + b], a == b ? 1.0 : 0.0, 1e-12) << n << " functions, " << a << "," << b;
      }
    }
  }
}

TEST(ClusterBasis, LegendreProductsAsInThePaperEachAPrefixOfTheNext)
{
  const PolynomialBasis cubic(BasisKind::Cubic);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial)
  {
    const double u = unit(random), v = unit(random);
    const double fu = std::sqrt(3.0) * (2 * u - 1), fv = std::sqrt(3.0) * (2 * v - 1);
    double f[10];
    cubic.Evaluate(u, v, f);
    // The appendix: 1, f_u, f_v, f_u f_v, sqrt(5)/2 (f_u^2 - 1) ...
    EXPECT_NEAR(f[0], 1.0, 1e-12);
    EXPECT_NEAR(f[1], fu, 1e-12);
    EXPECT_NEAR(f[2], fv, 1e-12);
    EXPECT_NEAR(f[3], fu * fv, 1e-12);
    EXPECT_NEAR(f[4], std::sqrt(5.0) / 2.0 * (fu * fu - 1.0), 1e-12);
    EXPECT_NEAR(f[5], std::sqrt(5.0) / 2.0 * (fv * fv - 1.0), 1e-12);
    // ... and the Legendre P3 of u: sqrt(7) (20 u^3 - 30 u^2 + 12 u - 1).
    EXPECT_NEAR(f[6], std::sqrt(7.0) * (20 * u * u * u - 30 * u * u + 12 * u - 1), 1e-10);
    for (BasisKind kind : AllKinds)
    {
      const PolynomialBasis smaller(kind);
      double g[10];
      smaller.Evaluate(u, v, g);
      for (int k = 0; k < smaller.Size(); ++k)
      {
        EXPECT_NEAR(g[k], f[k], 1e-12);
      }
    }
  }
}

TEST(ClusterBasis, PushReproducesTheParentsFunctionOnARotatedChild)
{
  // Total-degree spaces (constant, linear, quadratic, cubic) are invariant
  // under the rotation and scaling between the frames: the child's expansion
  // of the pushed coefficients is the parent's function, exactly.
  const FaceCluster parent = Rectangle(Vec3(0.0), 0.0, 2.0, 1.0);
  const FaceCluster child = Rectangle(Vec3(0.4, -0.2, 0.0), 0.5, 0.6, 0.3);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (BasisKind kind : { BasisKind::Constant, BasisKind::Linear, BasisKind::Quadratic, BasisKind::Cubic })
  {
    const PolynomialBasis basis(kind);
    const int n = basis.Size();
    std::vector<double> x(n);
    for (double& c : x)
    {
      c = unit(random) - 0.5;
    }
    const std::vector<double> y = Push(PushMatrix(basis, parent, child), x, n);
    for (int trial = 0; trial < 10; ++trial)
    {
      const double u = unit(random), v = unit(random);
      const glm::dvec2 up = BoxCoordinates(parent, BoxPoint(child, u, v));
      EXPECT_NEAR(Expand(basis, y, u, v), Expand(basis, x, up.x, up.y), 1e-9) << n << " functions";
    }
  }
}

TEST(ClusterBasis, PullOfPushIsTheIdentityWhenChildrenTileTheParent)
{
  // Two axis-aligned halves tile the parent's rectangle; one child's frame
  // is turned by 180 degrees (u and v reversed), which every basis survives.
  const FaceCluster parent = Rectangle(Vec3(1.0, 2.0, 0.0), 0.3, 2.0, 1.0);
  const Vec3 a0(parent.Axis[0]);
  const FaceCluster left = Rectangle(Vec3(parent.Centre) - a0, 0.3, 1.0, 1.0);
  const FaceCluster right = Rectangle(Vec3(parent.Centre) + a0, 0.3 + M_PI, 1.0, 1.0);
  for (BasisKind kind : AllKinds)
  {
    const PolynomialBasis basis(kind);
    const int n = basis.Size();
    const std::vector<double> pl = PushMatrix(basis, parent, left);
    const std::vector<double> pr = PushMatrix(basis, parent, right);
    for (int k = 0; k < n; ++k)
    {
      std::vector<double> x(n, 0.0);
      x[k] = 1.0;
      const std::vector<double> yl = Push(pl, x, n), yr = Push(pr, x, n);
      for (int a = 0; a < n; ++a)
      {
        double pulled = 0.0;
        for (int b = 0; b < n; ++b)
        {
          pulled += RectangleArea(left) / RectangleArea(parent) * pl[a * n + b] * yl[b] +
            RectangleArea(right) / RectangleArea(parent) * pr[a * n + b] * yr[b];
        }
        // The frames are stored in float: the halves tile the parent to ~1e-7.
        EXPECT_NEAR(pulled, x[a], 1e-6) << n << " functions, " << k << " -> " << a;
      }
    }
  }
}
