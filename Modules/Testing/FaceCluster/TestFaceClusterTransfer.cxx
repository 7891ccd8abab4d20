// Transfers between face clusters (Gobbetti et al. 2003, 3.2-3.3): surface
// rules, the constant-basis coupling of two parallel squares against the
// closed-form form factor, the exact vector form factor of a triangle
// emitter, and the transfer error shrinking with distance.
#include "Radiosity/Common/ClosedFormFactors.h"
#include "Radiosity/FaceCluster/FaceClusterTransfer.h"
#include "Radiosity/Common/FormFactor.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <gtest/gtest.h>

using namespace radiosity;

namespace
{
struct Pair
{
  Scene Geometry;
  std::unique_ptr<FaceClusterHierarchy> Hierarchy;
  std::unique_ptr<FaceClusterVisibility> Visibility;
  std::uint32_t Receiver = 0, Emitter = 0;
};

// Receiver: the unit square at z = 0 facing up; emitter: the unit square at
// z = c facing down; n x n cells each.
Pair MakePair(double c, int n)
{
  Pair pair;
  Material m;
  AppendQuad(pair.Geometry, Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), m, n, "receiver");
  AppendQuad(pair.Geometry, Vec3(0, 0, c), Vec3(0, 1, c), Vec3(1, 1, c), Vec3(1, 0, c), m, n, "emitter");
  pair.Hierarchy = std::make_unique<FaceClusterHierarchy>(pair.Geometry);
  pair.Visibility = std::make_unique<FaceClusterVisibility>(*pair.Hierarchy);
  for (std::uint32_t r : pair.Hierarchy->Roots())
  {
    const FaceCluster cl = pair.Hierarchy->Cluster(r);
    (cl.Centre.z > 0.5f * float(c) ? pair.Emitter : pair.Receiver) = r;
  }
  return pair;
}

Transfer Between(const Pair& pair, std::uint32_t r, std::uint32_t e, const PolynomialBasis& basis, int nodes)
{
  const FaceCluster receiver = pair.Hierarchy->Cluster(r), emitter = pair.Hierarchy->Cluster(e);
  const SurfaceRule rr = MakeSurfaceRule(*pair.Hierarchy, r, receiver, basis, nodes);
  const SurfaceRule er = MakeSurfaceRule(*pair.Hierarchy, e, emitter, basis, nodes);
  TransferRule rule;
  rule.Nodes = nodes;
  return ComputeTransfer({ &receiver, r, &rr, basis.Size() }, { &emitter, e, &er, 1 }, { RGB(1.0) },
    1.0, 1.0, *pair.Visibility, rule);
}
}

TEST(FaceClusterTransfer, SurfaceRulesLieOnTheSurface)
{
  Pair pair = MakePair(1.0, 3);
  const PolynomialBasis linear(BasisKind::Linear);
  const FaceClusterHierarchy& h = *pair.Hierarchy;
  for (std::uint32_t id = 0; id < h.NumberOfClusters(); ++id)
  {
    const FaceCluster c = h.Cluster(id);
    const SurfaceRule rule = MakeSurfaceRule(h, id, c, linear, 3);
    double total = 0.0;
    for (std::size_t p = 0; p < rule.Size(); ++p)
    {
      total += rule.Weights[p];
      EXPECT_NEAR(rule.Points[p].z, c.Centre.z, 1e-9); // on the flat square
    }
    EXPECT_NEAR(total, c.Area, 1e-6 * c.Area);
    // The fit reproduces a linear function of the box coordinates when the
    // rule has three or more nodes.
    if (rule.Size() >= 3)
    {
      std::vector<double> values(rule.Size());
      for (std::size_t p = 0; p < rule.Size(); ++p)
      {
        const glm::dvec2 uv = BoxCoordinates(c, rule.Points[p]);
        values[p] = 2.0 - 3.0 * uv.x + 0.5 * uv.y;
      }
      double coefficients[3];
      rule.Fit(values.data(), 1, coefficients);
      for (std::size_t p = 0; p < rule.Size(); ++p)
      {
        double fitted = 0.0;
        for (int a = 0; a < 3; ++a)
        {
          fitted += coefficients[a] * rule.Phi[p * 3 + a];
        }
        EXPECT_NEAR(fitted, values[p], 1e-9);
      }
    }
  }
}

TEST(FaceClusterTransfer, ConstantCouplingIsTheFormFactor)
{
  const PolynomialBasis constant(BasisKind::Constant);
  for (double c : { 1.0, 2.0, 4.0 })
  {
    Pair pair = MakePair(c, 2);
    const Transfer t = Between(pair, pair.Receiver, pair.Emitter, constant, 5);
    ASSERT_EQ(t.K.size(), 1u);
    // n . K for unit radiosity: the area-averaged form factor receiver -> emitter.
    const double exact = closedform::ParallelRectangles(1.0, 1.0, c);
    EXPECT_NEAR(t.K[0].z, exact, 0.01 * exact) << "distance " << c;
    EXPECT_NEAR(t.K[0].x, 0.0, 1e-9);
  }
}

TEST(FaceClusterTransfer, TriangleEmitterUsesTheExactVectorFormFactor)
{
  Pair pair = MakePair(0.1, 1); // close: 1/r^2 cubature would be poor
  const FaceClusterHierarchy& h = *pair.Hierarchy;
  const std::uint32_t triangle = h.TriangleOrder()[h.Cluster(pair.Emitter).First];
  const PolynomialBasis linear(BasisKind::Linear);
  const FaceCluster receiver = h.Cluster(pair.Receiver);
  const SurfaceRule rr = MakeSurfaceRule(h, pair.Receiver, receiver, linear, 3);
  const Transfer t = Between(pair, pair.Receiver, triangle, linear, 3);
  // The constant coefficient is the least-squares fit of the exact vector
  // form factor at the receiver's nodes.
  const Vec3 corners[3] = { pair.Geometry.Vertex(triangle, 0), pair.Geometry.Vertex(triangle, 1),
    pair.Geometry.Vertex(triangle, 2) };
  Vec3 expected(0.0);
  for (std::size_t p = 0; p < rr.Size(); ++p)
  {
    expected += rr.Dual[p * 3] * PointToPolygonVectorFormFactor(rr.Points[p], corners, 3);
  }
  EXPECT_NEAR(glm::length(t.K[0] - expected), 0.0, 1e-12);
  EXPECT_GT(t.K[0].z, 0.1);
  // The vector form factor's normal component is the point form factor.
  const Vec3 x(0.3, 0.4, 0.0);
  EXPECT_NEAR(PointToPolygonVectorFormFactor(x, corners, 3).z,
    PointToTriangleFormFactor(x, Vec3(0, 0, 1), corners[0], corners[1], corners[2]), 1e-12);
}

TEST(FaceClusterTransfer, ErrorFallsWithDistance)
{
  const PolynomialBasis constant(BasisKind::Constant);
  auto relativeError = [&](double c) {
    Pair pair = MakePair(c, 2);
    const Transfer t = Between(pair, pair.Receiver, pair.Emitter, constant, 3);
    return t.Error / t.K[0].z; // relative to the power received (area 1, rho 0.5)
  };
  const double near = relativeError(0.5), far = relativeError(8.0);
  EXPECT_GT(near, 4.0 * far);
  EXPECT_LT(far, 0.05);
}
