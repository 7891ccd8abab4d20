// Transfers between face clusters (Gobbetti et al. 2003, 3.2-3.3): the
// constant-basis coupling of two parallel squares against the closed-form
// form factor, the exact vector form factor of a triangle emitter, and the
// transfer error shrinking with distance.
#include "Radiosity/ClosedFormFactors.h"
#include "Radiosity/FaceClusterTransfer.h"
#include "Radiosity/FormFactor.h"
#include "Radiosity/SceneGenerators.h"

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
}

TEST(FaceClusterTransfer, ConstantCouplingIsTheFormFactor)
{
  const PolynomialBasis constant(BasisKind::Constant);
  for (double c : { 1.0, 2.0, 4.0 })
  {
    Pair pair = MakePair(c, 2);
    const FaceCluster receiver = pair.Hierarchy->Cluster(pair.Receiver);
    const FaceCluster emitter = pair.Hierarchy->Cluster(pair.Emitter);
    TransferRule rule;
    rule.ReceiverNodes = 5;
    rule.EmitterNodes = 5;
    const Transfer t = ComputeTransfer({ &receiver, pair.Receiver, &constant },
      { &emitter, pair.Emitter, &constant }, { RGB(1.0) }, 1.0, 1.0, *pair.Visibility, rule);
    ASSERT_EQ(t.K.size(), 1u);
    // n . K for unit radiosity: the area-averaged form factor receiver -> emitter.
    const double f = t.K[0].z;
    const double exact = closedform::ParallelRectangles(1.0, 1.0, c);
    EXPECT_NEAR(f, exact, 0.01 * exact) << "distance " << c;
    EXPECT_NEAR(t.K[0].x, 0.0, 1e-9);
  }
}

TEST(FaceClusterTransfer, TriangleEmitterUsesTheExactVectorFormFactor)
{
  Pair pair = MakePair(0.1, 1); // close: 1/r^2 cubature would be poor
  const FaceClusterHierarchy& h = *pair.Hierarchy;
  const FaceCluster receiver = h.Cluster(pair.Receiver);
  // A leaf triangle of the emitter.
  const FaceCluster root = h.Cluster(pair.Emitter);
  const std::uint32_t triangle = h.TriangleOrder()[root.First];
  const FaceCluster emitter = h.Cluster(triangle);
  const PolynomialBasis linear(BasisKind::Linear), constant(BasisKind::Constant);
  TransferRule rule;
  const Transfer t = ComputeTransfer({ &receiver, pair.Receiver, &linear },
    { &emitter, triangle, &constant }, { RGB(1.0) }, 1.0, 1.0, *pair.Visibility, rule);
  // The receiver's constant coefficient is the mean over its nodes of the
  // exact vector form factor; check it against a direct evaluation.
  double nodes[5], weights[5];
  GaussLegendre(rule.ReceiverNodes, nodes, weights);
  Vec3 expected(0.0);
  const Vec3 corners[3] = { pair.Geometry.Vertex(triangle, 0), pair.Geometry.Vertex(triangle, 1),
    pair.Geometry.Vertex(triangle, 2) };
  for (int a = 0; a < rule.ReceiverNodes; ++a)
  {
    for (int b = 0; b < rule.ReceiverNodes; ++b)
    {
      expected += weights[a] * weights[b] * PointToPolygonVectorFormFactor(BoxPoint(receiver, nodes[a], nodes[b]), corners, 3);
    }
  }
  EXPECT_NEAR(glm::length(t.K[0] - expected), 0.0, 1e-12);
  EXPECT_GT(t.K[0].z, 0.1);
  // The vector form factor's normal component is the point form factor.
  const Vec3 x(0.3, 0.4, 0.0);
  EXPECT_NEAR(PointToPolygonVectorFormFactor(x, corners, 3).z,
    PointToTriangleFormFactor(x, Vec3(0, 0, 1), corners[0], corners[1], corners[2]), 1e-12);
}

TEST(FaceClusterTransfer, ErrorFallsWithDistanceAndRefinement)
{
  const PolynomialBasis constant(BasisKind::Constant);
  auto relativeError = [&](double c) {
    Pair pair = MakePair(c, 2);
    const FaceCluster receiver = pair.Hierarchy->Cluster(pair.Receiver);
    const FaceCluster emitter = pair.Hierarchy->Cluster(pair.Emitter);
    const Transfer t = ComputeTransfer({ &receiver, pair.Receiver, &constant },
      { &emitter, pair.Emitter, &constant }, { RGB(1.0) }, 1.0, 1.0, *pair.Visibility, TransferRule());
    return t.Error / (receiver.Area * t.K[0].z); // relative to the power received (rho = 0.5)
  };
  const double near = relativeError(0.5), far = relativeError(8.0);
  EXPECT_GT(near, 4.0 * far);
  EXPECT_LT(far, 0.05);
}
