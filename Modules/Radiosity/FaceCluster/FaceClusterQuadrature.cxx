#include "Radiosity/FaceCluster/FaceClusterQuadrature.h"

#include "Radiosity/FaceCluster/FaceClusterTransfer.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace radiosity
{
namespace
{
// The hit of the line p + t n, |t| <= reach, with cluster id's triangles
// nearest t = 0: true with the point and the triangle's unit normal.
bool ProjectOntoCluster(const FaceClusterHierarchy& h, std::uint32_t id, const Vec3& p,
  const Vec3& n, double reach, Vec3& hit, Vec3& normal)
{
  const Scene& scene = h.GetScene();
  double best = std::numeric_limits<double>::infinity();
  std::vector<std::uint32_t> stack{ id };
  while (!stack.empty())
  {
    const std::uint32_t node = stack.back();
    stack.pop_back();
    if (const FaceCluster* c = h.InternalCluster(node))
    {
      if (SegmentCrossesBox(*c, p - reach * n, 2.0 * reach * n, 0.0, 1.0))
      {
        stack.push_back(c->Child[0]);
        stack.push_back(c->Child[1]);
      }
      continue;
    }
    double t = 0.0;
    if (!LineHitsTriangle(scene.Vertex(node, 0), scene.Vertex(node, 1), scene.Vertex(node, 2), p, n, t) ||
      std::abs(t) > reach || std::abs(t) >= best)
    {
      continue;
    }
    best = std::abs(t);
    hit = p + t * n;
    normal = scene.Normal(node);
  }
  return std::isfinite(best);
}
}

namespace
{
// Whether the basis at these points has full rank (a unique fit).
bool FcqNodesDetermineBasis(const FaceCluster& c, const PolynomialBasis& basis, const std::vector<Vec3>& points)
{
  const int n = basis.Size();
  if (static_cast<int>(points.size()) < n)
  {
    return false;
  }
  Eigen::MatrixXd phi(static_cast<Eigen::Index>(points.size()), n);
  double values[PolynomialBasis::MaximumSize];
  for (std::size_t p = 0; p < points.size(); ++p)
  {
    const glm::dvec2 uv = BoxCoordinates(c, points[p]);
    basis.Evaluate(uv.x, uv.y, values);
    for (int a = 0; a < n; ++a)
    {
      phi(static_cast<Eigen::Index>(p), a) = values[a];
    }
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(phi);
  qr.setThreshold(1e-6);
  return qr.rank() == n;
}

// `count` nodes at the centroids of the triangles at cluster c's area
// quantiles (k + 1/2) / count, in the hierarchy's order of its triangles.
void FcqQuantileNodes(const FaceClusterHierarchy& hierarchy, const FaceCluster& c, int count, SurfaceRule& rule)
{
  const std::vector<double>& cumulative = hierarchy.CumulativeArea();
  const double start = cumulative[c.First], total = cumulative[c.First + c.Count] - start;
  const Scene& scene = hierarchy.GetScene();
  for (int k = 0; k < count; ++k)
  {
    const double target = start + (k + 0.5) / count * total;
    const auto it = std::upper_bound(cumulative.begin() + c.First + 1,
      cumulative.begin() + c.First + c.Count + 1, target);
    const std::size_t position = static_cast<std::size_t>(it - cumulative.begin()) - 1;
    const std::uint32_t t = hierarchy.TriangleOrder()[std::min<std::size_t>(position, c.First + c.Count - 1)];
    rule.Points.push_back(scene.Centroid(t));
    rule.Normals.push_back(scene.Normal(t));
    rule.Weights.push_back(1.0);
  }
}

// Stroud's conical product nodes, m x m on every triangle of cluster c.
void FcqTriangleNodes(const FaceClusterHierarchy& h, const FaceCluster& c, int functions, int n, SurfaceRule& rule)
{
  const std::uint32_t count = std::max<std::uint32_t>(c.Count, 1u);
  int m = 1;
  while (m < 5 && count * static_cast<std::uint32_t>(m * m) < static_cast<std::uint32_t>(std::max(n * n, functions)))
  {
    ++m;
  }
  double nodes[5], weights[5];
  GaussLegendre(m, nodes, weights);
  const Scene& scene = h.GetScene();
  rule.Points.clear();
  rule.Normals.clear();
  rule.Weights.clear();
  for (std::uint32_t k = 0; k < c.Count; ++k)
  {
    const std::uint32_t t = h.TriangleOrder()[c.First + k];
    const Vec3 a = scene.Vertex(t, 0), e1 = scene.Vertex(t, 1) - a, e2 = scene.Vertex(t, 2) - a;
    const double area = scene.Area(t);
    for (int i = 0; i < m; ++i)
    {
      for (int j = 0; j < m; ++j)
      {
        rule.Points.push_back(a + nodes[i] * e1 + (1.0 - nodes[i]) * nodes[j] * e2);
        rule.Normals.push_back(scene.Normal(t));
        rule.Weights.push_back(2.0 * area * weights[i] * weights[j] * (1.0 - nodes[i]));
      }
    }
  }
}
}

void SurfaceRule::Fit(const double* values, std::size_t stride, double* coefficients) const
{
  for (int a = 0; a < this->Functions; ++a)
  {
    double s = 0.0;
    for (std::size_t p = 0; p < this->Size(); ++p)
    {
      s += this->Dual[p * this->Functions + a] * values[p * stride];
    }
    coefficients[a] = s;
  }
}

std::vector<double> DualWeights(const FaceCluster& frame, const PolynomialBasis& basis,
  const std::vector<Vec3>& points, const std::vector<double>& weights)
{
  const int n = basis.Size();
  const auto m = static_cast<Eigen::Index>(points.size());
  Eigen::MatrixXd phi(m, n);
  double total = 0.0;
  double values[PolynomialBasis::MaximumSize];
  for (Eigen::Index p = 0; p < m; ++p)
  {
    const glm::dvec2 uv = BoxCoordinates(frame, points[p]);
    basis.Evaluate(uv.x, uv.y, values);
    for (int a = 0; a < n; ++a)
    {
      phi(p, a) = values[a];
    }
    total += weights[p];
  }
  // Weighted least squares: c = (Phi^T W Phi)^+ Phi^T W f.
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index p = 0; p < m; ++p)
  {
    gram += (weights[p] / total) * phi.row(p).transpose() * phi.row(p);
  }
  // The directions of the basis the nodes barely tell apart are left out of
  // the fit (their coefficients 0), not fitted with weights of thousands:
  // on a cluster whose nodes line up (quantile centroids along a window
  // frame) the gradient across the line was determined to 1e-6 of the gram
  // and the fit's coefficients came out 2,000 times the values at the
  // nodes; pushed down to the cluster's leaves off that line they gave
  // 1e5 W/m^2 next to 24, and the classroom's solve diverged. A gram
  // eigenvalue below GramThreshold of the largest is such a direction: the
  // basis value then moves by less than 1e-3 of the constant's across the
  // nodes. Well-spread nodes keep every direction, bit for bit.
  constexpr double GramThreshold = 1e-6;
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(gram.rows(), gram.cols());
  cod.setThreshold(GramThreshold);
  cod.compute(gram);
  const Eigen::MatrixXd inverse = cod.pseudoInverse();
  std::vector<double> dual(static_cast<std::size_t>(m) * n);
  for (Eigen::Index p = 0; p < m; ++p)
  {
    const Eigen::VectorXd d = inverse * phi.row(p).transpose() * (weights[p] / total);
    for (int a = 0; a < n; ++a)
    {
      dual[p * n + a] = d(a);
    }
  }
  return dual;
}

namespace
{
// The basis at the rule's nodes, its least-squares weights, and the weights
// scaled to sum to the cluster's area.
void FinishRule(const FaceCluster& c, const PolynomialBasis& basis, SurfaceRule& rule)
{
  double total = 0.0;
  for (double w : rule.Weights)
  {
    total += w;
  }
  for (double& w : rule.Weights)
  {
    w *= double(c.Area) / total;
  }
  double values[PolynomialBasis::MaximumSize];
  for (const Vec3& p : rule.Points)
  {
    const glm::dvec2 uv = BoxCoordinates(c, p);
    basis.Evaluate(uv.x, uv.y, values);
    rule.Phi.insert(rule.Phi.end(), values, values + rule.Functions);
  }
  rule.Dual = DualWeights(c, basis, rule.Points, rule.Weights);
}
}

SurfaceRule MakeTriangleRule(const Vec3 corner[3], const FaceCluster& c, const PolynomialBasis& basis,
  int nodesPerAxis)
{
  SurfaceRule rule;
  rule.Functions = basis.Size();
  double nodes[5], weights[5];
  const int n = std::clamp(nodesPerAxis, 1, 5);
  GaussLegendre(n, nodes, weights);
  // Stroud's conical product: (s, t) in the square to corner0 + s e1 +
  // (1 - s) t e2, Jacobian (1 - s).
  const Vec3 e1 = corner[1] - corner[0], e2 = corner[2] - corner[0];
  const Vec3 normal = c.MeanNormal();
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      rule.Points.push_back(corner[0] + nodes[i] * e1 + (1.0 - nodes[i]) * nodes[j] * e2);
      rule.Normals.push_back(normal);
      rule.Weights.push_back(weights[i] * weights[j] * (1.0 - nodes[i]));
    }
  }
  FinishRule(c, basis, rule);
  // Just inside, so that a corner on an emitter's edge (a contact edge) is
  // not on the kernel's singularity.
  const Vec3 centroid = (corner[0] + corner[1] + corner[2]) / 3.0;
  double values[PolynomialBasis::MaximumSize];
  for (int k = 0; k < 3; ++k)
  {
    const Vec3 x = corner[k] + 0.01 * (centroid - corner[k]);
    rule.Controls.push_back(x);
    rule.ControlNormals.push_back(normal);
    const glm::dvec2 uv = BoxCoordinates(c, x);
    basis.Evaluate(uv.x, uv.y, values);
    rule.ControlPhi.insert(rule.ControlPhi.end(), values, values + rule.Functions);
  }
  return rule;
}

SurfaceRule MakeSurfaceRule(const FaceClusterHierarchy& hierarchy, std::uint32_t id,
  const FaceCluster& c, const PolynomialBasis& basis, int nodesPerAxis)
{
  if (!hierarchy.InternalCluster(id))
  {
    const Scene& scene = hierarchy.GetScene();
    const Vec3 corner[3] = { scene.Vertex(id, 0), scene.Vertex(id, 1), scene.Vertex(id, 2) };
    return MakeTriangleRule(corner, c, basis, nodesPerAxis);
  }
  SurfaceRule rule;
  rule.Functions = basis.Size();
  double nodes[5], weights[5];
  const int n = std::clamp(nodesPerAxis, 1, 5);
  GaussLegendre(n, nodes, weights);
  const Vec3 axis(c.Axis[2]);
  const double plane = std::max(double(c.HalfSize.x), double(c.HalfSize.y));
  // The box is kept in single precision: its centre is off the surface by
  // up to a few float ulps of its coordinates, which for a flat cluster far
  // from the origin (a quad of the Cornell box's light, 0.5 m up and 3 cm
  // wide) exceeded 1e-6 of its size, so no node landed on it.
  const double ulps = 8.0 * std::numeric_limits<float>::epsilon() *
    (glm::length(Vec3(c.Centre)) + glm::length(Vec3(c.HalfSize)));
  const double reach = 1.01 * double(c.HalfSize.z) + 1e-6 * plane + ulps + 1e-12;
  // A cluster that is not one flat sheet (its faces do not all look along
  // its normal) gets nodes at its area quantiles instead, on every face:
  // projected along the normal, the nodes would all land on the faces that
  // look that way, and the transfer error would never see the others (the
  // paper: "to ensure subdivision of side-on clusters, we distribute sample
  // points on the entire cluster").
  const bool sheet = c.DMinus[2] <= 1e-6f * c.Area && c.NormalProjectedArea() >= 0.98 * double(c.Area);
  if (!sheet && c.Count > 1)
  {
    FcqQuantileNodes(hierarchy, c, n * n, rule);
  }
  for (int i = 0; i < n && (sheet || c.Count <= 1); ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      Vec3 hit, normal;
      if (ProjectOntoCluster(hierarchy, id, BoxPoint(c, nodes[i], nodes[j]), axis, reach, hit, normal))
      {
        rule.Points.push_back(hit);
        rule.Normals.push_back(normal);
        const double tilt = std::max(std::abs(glm::dot(normal, axis)), 0.05);
        rule.Weights.push_back(weights[i] * weights[j] / tilt);
      }
    }
  }
  const bool determined = FcqNodesDetermineBasis(c, basis, rule.Points);
  // A sheet of more than n^2 triangles on which some of the projected
  // nodes did not land (a band of a sphere covering half of its box: 2 or
  // 3 of the 9 nodes on it): nodes at its area quantiles instead. With 2
  // nodes the linear fit's gradient was the minimum-norm guess, and inside
  // a 20480-facet sphere a 24-triangle leaf below such a cluster got its
  // direct light 16% low at one edge; with 3 the fit is exactly determined
  // and its departures never show at the nodes, so a transfer's error is
  // judged from the control points alone: that sphere at reflectance 0.99
  // was 1.6% of the exact off at one probe, 0.72% with these nodes (0.8:
  // 1.65% -> 0.93%; the bunny room's solve the same to 1%).
  const bool sparse = sheet && c.Count > static_cast<std::uint32_t>(n * n) &&
    rule.Points.size() < static_cast<std::size_t>(n * n);
  if ((!determined && c.Count > 4u * static_cast<std::uint32_t>(n * n)) || sparse)
  {
    rule.Points.clear();
    rule.Normals.clear();
    rule.Weights.clear();
    FcqQuantileNodes(hierarchy, c, std::max(n * n, 2 * basis.Size()), rule);
  }
  if (!determined && !sparse && c.Count <= 4u * static_cast<std::uint32_t>(n * n))
  {
    // Too few distinct nodes for the basis (a folded pair of triangles has
    // two centroids; a flat cluster whose triangles miss most of its box):
    // a least-squares fit through them is underdetermined, and its
    // minimum-norm coefficients swing far from the nodes. Measured on the
    // Cornell box split 16 with the quadratic basis: the light's leaves
    // had irradiance vectors pointing into the ceiling, up to 0.19 of the
    // peak below zero at its vertices. Instead: m x m nodes of Stroud's
    // rule on every triangle of the cluster, m the least with
    // Count m^2 >= max(n^2, basis size).
    FcqTriangleNodes(hierarchy, c, basis.Size(), n, rule);
  }
  if (rule.Points.empty())
  {
    rule.Points.push_back(Vec3(c.Centroid));
    rule.Normals.push_back(c.MeanNormal());
    rule.Weights.push_back(1.0);
  }
  FinishRule(c, basis, rule);
  // Control points (3.3.2's "control points", where the interpolated value
  // is checked against direct integration) on a 5 x 5 grid over a flat
  // cluster's box, its edges and corners included, projected onto its
  // faces. With the Gauss nodes alone, a field that peaks or bends between
  // them or beyond them (a floor cluster reaching past an emitter's
  // footprint) was accepted with up to 9% of the peak wrong at a floor
  // probe beside a square emitter, depending on which clusters the greedy
  // contraction made (its ties on a regular grid round differently at
  // scales 0.9, 1e-3, 1e3 or 1e4); a 3 x 3 grid still left 7.1% at 1e4.
  // FaceClusterRadiosity.SameAnswerAtEveryScale: now within 2.6e-3 of the
  // peak at every scale. Cost (bench/results/facecluster.md): the bunny
  // room's figure-4 solves no slower, the 1280-triangle sphere at 1e-5
  // 2.3x slower (66.6 s against 29.3 s).
  if (sheet || c.Count <= 1)
  {
    const double at[5] = { 0.01, 0.25, 0.5, 0.75, 0.99 };
    double values[PolynomialBasis::MaximumSize];
    for (double u : at)
    {
      for (double v : at)
      {
        Vec3 hit, normal;
        if (ProjectOntoCluster(hierarchy, id, BoxPoint(c, u, v), axis, reach, hit, normal))
        {
          rule.Controls.push_back(hit);
          rule.ControlNormals.push_back(normal);
          const glm::dvec2 uv = BoxCoordinates(c, hit);
          basis.Evaluate(uv.x, uv.y, values);
          rule.ControlPhi.insert(rule.ControlPhi.end(), values, values + rule.Functions);
        }
      }
    }
  }
  return rule;
}
} // namespace radiosity
