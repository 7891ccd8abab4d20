#include "Radiosity/FaceClusterTransfer.h"

#include "Radiosity/FormFactor.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace radiosity
{
namespace
{
constexpr double Pi = 3.14159265358979323846;
}

void GaussLegendre(int n, double* nodes, double* weights)
{
  // On [-1, 1], mapped to [0, 1].
  static const double x[5][5] = { { 0.0 }, { -0.57735026918962576, 0.57735026918962576 },
    { -0.77459666924148338, 0.0, 0.77459666924148338 },
    { -0.86113631159405258, -0.33998104358485626, 0.33998104358485626, 0.86113631159405258 },
    { -0.90617984593866399, -0.53846931010568309, 0.0, 0.53846931010568309, 0.90617984593866399 } };
  static const double w[5][5] = { { 2.0 }, { 1.0, 1.0 },
    { 0.55555555555555556, 0.88888888888888889, 0.55555555555555556 },
    { 0.34785484513745386, 0.65214515486254614, 0.65214515486254614, 0.34785484513745386 },
    { 0.23692688505618909, 0.47862867049936647, 0.56888888888888889, 0.47862867049936647,
      0.23692688505618909 } };
  n = std::clamp(n, 1, 5);
  for (int i = 0; i < n; ++i)
  {
    nodes[i] = 0.5 * (x[n - 1][i] + 1.0);
    weights[i] = 0.5 * w[n - 1][i];
  }
}

bool ClusterFaces(const FaceCluster& from, const FaceCluster& to)
{
  if (from.DMinus[2] > 1e-6f * from.Area)
  {
    return true; // faces pointing both ways
  }
  const Vec3 n(from.Axis[2]);
  const Vec3 c(from.Centre);
  const double below = -double(from.HalfSize.z) - 1e-9 * (1.0 + glm::length(c));
  for (int corner = 0; corner < 8; ++corner)
  {
    Vec3 p(to.Centre);
    for (int j = 0; j < 3; ++j)
    {
      p += ((corner >> j) & 1 ? 1.0 : -1.0) * double(to.HalfSize[j]) * Vec3(to.Axis[j]);
    }
    if (glm::dot(p - c, n) > below)
    {
      return true;
    }
  }
  return false;
}

double SelfTransferError(const FaceCluster& c, double radiosityMax)
{
  const double rho = std::max({ c.ReflectanceMax.x, c.ReflectanceMax.y, c.ReflectanceMax.z });
  return rho * radiosityMax * (c.SelfFormFactorUpper() - c.SelfFormFactorLower()) * c.Area;
}

Transfer ComputeTransfer(const TransferEnd& receiver, const TransferEnd& emitter,
  const std::vector<RGB>& radiosity, double radiosityMin, double radiosityMax,
  const FaceClusterVisibility& visibility, const TransferRule& rule)
{
  const FaceCluster& ri = *receiver.Cluster;
  const FaceCluster& ej = *emitter.Cluster;
  const int ne = receiver.Basis->Size(), nb = emitter.Basis->Size();
  Transfer out;
  out.Receivers = ne;
  out.Emitters = nb;
  out.K.assign(static_cast<std::size_t>(ne) * nb, Vec3(0.0));

  double ru[5], rw[5], eu[5], ew[5];
  const int nr = std::clamp(rule.ReceiverNodes, 1, 5), nq = std::clamp(rule.EmitterNodes, 1, 5);
  GaussLegendre(nr, ru, rw);
  GaussLegendre(nq, eu, ew);
  const double spacing =
    2.0 * std::max(double(ri.HalfSize.x), double(ri.HalfSize.y)) / nr * rule.VisibilityThreshold;

  // The emitter's constant part by exact vector form factors, so that the
  // 1/r^2 singularity next to an adjacent emitter costs no accuracy: the sum
  // over its triangles for a cluster of at most ExactTriangles of them, and
  // for a larger flat one its box rectangle's, scaled by the fraction of the
  // rectangle its surface covers (A^(n) / |R|). Higher orders, and large
  // clusters that are not flat, by the rule.
  constexpr std::uint32_t ExactTriangles = 64;
  const FaceClusterHierarchy& hierarchy = visibility.Hierarchy();
  const Scene& scene = hierarchy.GetScene();
  const double planeSize = std::max(double(ej.HalfSize.x), double(ej.HalfSize.y));
  const bool small = ej.Count <= ExactTriangles;
  const bool flat = !small && ej.DMinus[2] <= 1e-6f * ej.Area &&
    double(ej.HalfSize.z) <= 1e-3 * planeSize && RectangleArea(ej) > 0.0;
  const bool exactConstant = small || flat;
  Vec3 rectangle[4];
  double coverage = 1.0;
  if (flat)
  {
    rectangle[0] = BoxPoint(ej, 0.0, 0.0);
    rectangle[1] = BoxPoint(ej, 1.0, 0.0);
    rectangle[2] = BoxPoint(ej, 1.0, 1.0);
    rectangle[3] = BoxPoint(ej, 0.0, 1.0);
    coverage = ej.NormalProjectedArea() / RectangleArea(ej);
  }
  auto exactVector = [&](const Vec3& x) {
    if (flat)
    {
      return coverage * PointToPolygonVectorFormFactor(x, rectangle, 4);
    }
    Vec3 sum(0.0);
    for (std::uint32_t k = ej.First; k < ej.First + ej.Count; ++k)
    {
      const std::uint32_t t = hierarchy.TriangleOrder()[k];
      const Vec3 tri[3] = { scene.Vertex(t, 0), scene.Vertex(t, 1), scene.Vertex(t, 2) };
      sum += PointToPolygonVectorFormFactor(x, tri, 3);
    }
    return sum;
  };
  const double rhoMax = std::max({ ri.ReflectanceMax.x, ri.ReflectanceMax.y, ri.ReflectanceMax.z });
  const Vec3 normal(ri.Axis[2]);
  double phiR[PolynomialBasis::MaximumSize], phiE[PolynomialBasis::MaximumSize];
  std::vector<double> upper(nr * nr, 0.0), lower(nr * nr, std::numeric_limits<double>::infinity());
  for (int a = 0; a < nr; ++a)
  {
    for (int b = 0; b < nr; ++b)
    {
      const int p = a * nr + b;
      const Vec3 x = BoxPoint(ri, ru[a], ru[b]);
      const double wp = rw[a] * rw[b];
      receiver.Basis->Evaluate(ru[a], ru[b], phiR);
      double visibleSum = 0.0, weightSum = 0.0;
      for (int c = 0; c < nq; ++c)
      {
        for (int d = 0; d < nq; ++d)
        {
          const Vec3 y = BoxPoint(ej, eu[c], eu[d]);
          const Vec3 r = y - x;
          const double d2 = glm::dot(r, r);
          if (!(d2 > 0.0))
          {
            continue;
          }
          const Vec3 dir = r / std::sqrt(d2);
          const double v = visibility.Transmittance(x, y, receiver.Id, emitter.Id, spacing);
          const double wq = ew[c] * ew[d];
          visibleSum += wq * v;
          weightSum += wq;
          const double emitterMin = ej.MinProjectedArea(-dir), emitterMax = ej.MaxProjectedArea(-dir);
          const double g = v * 0.5 * (emitterMin + emitterMax) / (Pi * d2);
          emitter.Basis->Evaluate(eu[c], eu[d], phiE);
          for (int i = 0; i < ne; ++i)
          {
            for (int j = exactConstant ? 1 : 0; j < nb; ++j)
            {
              out.K[i * nb + j] += (wp * wq * phiR[i] * phiE[j] * g) * dir;
            }
          }
          // 3.3.2: bounds on B F A over the emitter's nodes.
          const double scale = v / (Pi * d2);
          upper[p] = std::max(upper[p], radiosityMax * scale * ri.MaxProjectedArea(dir) * emitterMax);
          lower[p] = std::min(lower[p], radiosityMin * scale * ri.MinProjectedArea(dir) * emitterMin);
        }
      }
      if (exactConstant)
      {
        const double v = weightSum > 0.0 ? visibleSum / weightSum : 1.0;
        const Vec3 f = v * exactVector(x);
        for (int i = 0; i < ne; ++i)
        {
          out.K[i * nb] += (wp * phiR[i]) * f;
        }
      }
    }
  }

  // BFA' at the receiver's nodes from the coefficients, against the bounds.
  double departure = 0.0;
  for (int a = 0; a < nr; ++a)
  {
    for (int b = 0; b < nr; ++b)
    {
      receiver.Basis->Evaluate(ru[a], ru[b], phiR);
      Vec3 e(0.0);
      for (int i = 0; i < ne; ++i)
      {
        for (int j = 0; j < nb; ++j)
        {
          e += (phiR[i] * Mean(radiosity[j])) * out.K[i * nb + j];
        }
      }
      const double bfa = ri.Area * std::max(glm::dot(normal, e), 0.0);
      const int p = a * nr + b;
      const double lo = std::isfinite(lower[p]) ? lower[p] : 0.0;
      departure = std::max({ departure, std::abs(bfa - upper[p]), std::abs(bfa - lo) });
    }
  }
  out.Error = rhoMax * departure;
  return out;
}
} // namespace radiosity
