// The point-to-polygon form factor against closed forms (Howell's catalogue).
#include "Radiosity/Common/ClosedFormFactors.h"
#include "Radiosity/Common/FormFactor.h"

#include <gtest/gtest.h>

#include <iostream>

#include <cmath>
#include <vector>

using namespace radiosity;

namespace
{

/// Area-to-area form factor from rectangle R1 to polygon P by Gauss-Legendre
/// integration of the exact point-to-polygon factor over R1 (receiver side,
/// then reciprocity is not needed: F_{1->2} = 1/A1 int_A1 F_{dA1->A2} dA1).
double IntegrateOverRectangle(const Vec3& origin, const Vec3& u, const Vec3& v, const Vec3& n,
  const std::vector<Vec3>& poly, int order)
{
  // Composite midpoint-free Gauss-Legendre (4 points per panel, `order` panels).
  const double gx[4] = { -0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
    0.8611363115940526 };
  const double gw[4] = { 0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
    0.3478548451374538 };
  double sum = 0.0;
  for (int pi = 0; pi < order; ++pi)
  {
    for (int pj = 0; pj < order; ++pj)
    {
      for (int i = 0; i < 4; ++i)
      {
        for (int j = 0; j < 4; ++j)
        {
          const double s = (pi + 0.5 + 0.5 * gx[i]) / order;
          const double t = (pj + 0.5 + 0.5 * gx[j]) / order;
          const Vec3 p = origin + s * u + t * v;
          sum += gw[i] * gw[j] / 4.0 / (order * order) *
            PointToPolygonFormFactor(p, n, poly.data(), poly.size());
        }
      }
    }
  }
  return sum;
}
}

TEST(FormFactor, CoaxialDiscManySides)
{
  // With 720 sides the polygon is the disc to 1e-5: the closed form must match.
  const double r = 0.7, h = 0.3;
  std::vector<Vec3> poly;
  const int sides = 720;
  for (int k = 0; k < sides; ++k)
  {
    const double a = -2 * Pi * k / sides;
    poly.emplace_back(r * std::cos(a), r * std::sin(a), h);
  }
  // PointToPolygonFormFactor takes at most 8 vertices; fan it into triangles.
  double f = 0.0;
  for (int k = 0; k < sides; ++k)
  {
    const Vec3 tri[3] = { Vec3(0, 0, h), poly[k], poly[(k + 1) % sides] };
    f += PointToPolygonFormFactor(Vec3(0.0), Vec3(0, 0, 1), tri, 3);
  }
  std::cout << "disc: " << f - closedform::PointToCoaxialDisc(r, h) << "\n";
  EXPECT_NEAR(f, closedform::PointToCoaxialDisc(r, h), 5e-6); // measured 1.66e-6 (the inscribed polygon)
}

TEST(FormFactor, PointToRectangleCorner)
{
  const double a = 1.3, b = 0.6, c = 0.9;
  const Vec3 rect[4] = { Vec3(0, 0, c), Vec3(0, b, c), Vec3(a, b, c), Vec3(a, 0, c) };
  const double f = PointToPolygonFormFactor(Vec3(0.0), Vec3(0, 0, 1), rect, 4);
  EXPECT_NEAR(f, closedform::PointToParallelRectangleCorner(a, b, c), 1e-12);
}

TEST(FormFactor, OneSidedAndHorizonClipped)
{
  const Vec3 up[3] = { Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, 1) }; // faces +z, away
  EXPECT_EQ(PointToPolygonFormFactor(Vec3(0.2, 0.2, 0), Vec3(0, 0, 1), up, 3), 0.0);
  // A wall standing on the receiver's plane: the part below the horizon is clipped.
  // Faces -x, towards the receiver at the origin.
  const Vec3 wall[4] = { Vec3(1, -1, 1), Vec3(1, 1, 1), Vec3(1, 1, -1), Vec3(1, -1, -1) };
  const Vec3 wallUp[4] = { Vec3(1, -1, 1), Vec3(1, 1, 1), Vec3(1, 1, 0), Vec3(1, -1, 0) };
  const double full = PointToPolygonFormFactor(Vec3(0.0), Vec3(0, 0, 1), wall, 4);
  const double clipped = PointToPolygonFormFactor(Vec3(0.0), Vec3(0, 0, 1), wallUp, 4);
  EXPECT_GT(full, 0.0);
  EXPECT_NEAR(full, clipped, 1e-14);
}

TEST(FormFactor, ParallelRectanglesClosedForm)
{
  const double a = 1.0, b = 2.0, c = 0.5;
  // Receiver rectangle at z = 0 facing up, emitter at z = c facing down.
  const std::vector<Vec3> emitter = { Vec3(0, 0, c), Vec3(0, b, c), Vec3(a, b, c), Vec3(a, 0, c) };
  const double f = IntegrateOverRectangle(Vec3(0.0), Vec3(a, 0, 0), Vec3(0, b, 0), Vec3(0, 0, 1),
    emitter, 16);
  std::cout << "parallel: " << f - closedform::ParallelRectangles(a, b, c) << "\n";
  EXPECT_NEAR(f, closedform::ParallelRectangles(a, b, c), 1e-11); // measured 3.4e-12
}

TEST(FormFactor, PerpendicularRectanglesSharingAnEdge)
{
  // Common edge along y (length l), receiver in z = 0 (x in [0, w]), emitter in
  // x = 0 (z in [0, h]) facing +x. The receiver touches the emitter: the
  // kernel is singular at the common edge, the contour formula is not.
  const double l = 1.0, w = 0.7, h = 1.4;
  const std::vector<Vec3> emitter = { Vec3(0, 0, 0), Vec3(0, l, 0), Vec3(0, l, h), Vec3(0, 0, h) };
  const double f = IntegrateOverRectangle(Vec3(0.0), Vec3(w, 0, 0), Vec3(0, l, 0), Vec3(0, 0, 1),
    emitter, 32);
  std::cout << "perpendicular: " << f - closedform::PerpendicularRectangles(l, w, h) << "\n";
  EXPECT_NEAR(f, closedform::PerpendicularRectangles(l, w, h), 8e-7); // measured 2.9e-7
}

TEST(FormFactor, DiscApproximationConvergesFarAway)
{
  const Vec3 tri[3] = { Vec3(0, 0, 10), Vec3(0, 0.1, 10), Vec3(0.1, 0, 10) };
  const Vec3 c = (tri[0] + tri[1] + tri[2]) / 3.0;
  const double area = 0.005;
  const double exact = PointToPolygonFormFactor(Vec3(0.0), Vec3(0, 0, 1), tri, 3);
  const double disc = DiscFormFactor(Vec3(0.0), Vec3(0, 0, 1), c, Vec3(0, 0, -1), area);
  std::cout << "disc approximation: " << disc / exact - 1 << "\n";
  EXPECT_NEAR(disc, exact, 2e-5 * exact); // measured 6.3e-6
}

TEST(FormFactor, PolygonsOfManyVertices)
{
  // A polygon of more than 8 vertices used to get a form factor of 0. The
  // 720-gon whole must match the coaxial disc's closed form as its fan does.
  const double r = 0.7, h = 0.3;
  const int sides = 720;
  std::vector<Vec3> poly;
  for (int k = 0; k < sides; ++k)
  {
    const double a = -2 * Pi * k / sides;
    poly.emplace_back(r * std::cos(a), r * std::sin(a), h);
  }
  const Vec3 up(0, 0, 1);
  EXPECT_NEAR(PointToPolygonFormFactor(Vec3(0.0), up, poly.data(), poly.size()),
    closedform::PointToCoaxialDisc(r, h), 2e-5);
  EXPECT_NEAR(glm::dot(up, PointToPolygonVectorFormFactor(Vec3(0.0), poly.data(), poly.size(), &up)),
    closedform::PointToCoaxialDisc(r, h), 2e-5);
  // Horizon clipped: a receiver tilted by 60 degrees sees part of the disc
  // below its tangent plane; the whole polygon and its fan of triangles
  // (each clipped on its own, 3 vertices) must agree.
  const Vec3 tilted = glm::normalize(Vec3(std::sin(Pi / 3), 0, std::cos(Pi / 3)));
  double fan = 0.0;
  for (int k = 0; k < sides; ++k)
  {
    const Vec3 tri[3] = { Vec3(0, 0, h), poly[k], poly[(k + 1) % sides] };
    fan += PointToPolygonFormFactor(Vec3(0.0), tilted, tri, 3);
  }
  const double whole = PointToPolygonFormFactor(Vec3(0.0), tilted, poly.data(), poly.size());
  EXPECT_GT(fan, 0.1);
  EXPECT_NEAR(whole, fan, 1e-12);
  EXPECT_NEAR(glm::dot(tilted,
                PointToPolygonVectorFormFactor(Vec3(0.0), poly.data(), poly.size(), &tilted)),
    fan, 1e-12);
}
