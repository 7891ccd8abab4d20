#include "Radiosity/FaceCluster/FaceClusterTransfer.h"

#include "Radiosity/Common/FormFactor.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace radiosity
{
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
  // All of `to` lies below `from`'s box, yet a curved cluster's faces can
  // still look at it: a face whose normal leans away from the cluster's
  // mean normal sees below the box's base (measured: on the glossy statue
  // the ceiling light was culled from a 99-triangle cluster of the bunny's
  // head whose upper faces it lights fully; a vertex there got 0.105 W/m^2
  // upward against 1.71 gathered). Willmott's bound on the projected area
  // seen along r, sum_j (u_j . r)_+ D_j^+ + (-u_j . r)_+ D_j^- (3.1), is zero
  // only when no face looks along r; it is convex and positively
  // homogeneous in r, so zero at the 64 differences of the two boxes'
  // corners means zero along every segment between the boxes (their
  // Minkowski difference is those differences' hull).
  const Vec3 fromCentre(from.Centre), toCentre(to.Centre);
  for (int a = 0; a < 8; ++a)
  {
    Vec3 x = fromCentre;
    for (int j = 0; j < 3; ++j)
    {
      x += ((a >> j) & 1 ? 1.0 : -1.0) * double(from.HalfSize[j]) * Vec3(from.Axis[j]);
    }
    for (int b = 0; b < 8; ++b)
    {
      Vec3 y = toCentre;
      for (int j = 0; j < 3; ++j)
      {
        y += ((b >> j) & 1 ? 1.0 : -1.0) * double(to.HalfSize[j]) * Vec3(to.Axis[j]);
      }
      const Vec3 r = y - x;
      if (from.MaxProjectedArea(r) > 1e-6 * double(from.Area) * glm::length(r))
      {
        return true;
      }
    }
  }
  return false;
}

double SelfTransferError(const FaceCluster& c, double radiosityMax)
{
  return radiosityMax * (c.SelfFormFactorUpper() - c.SelfFormFactorLower()) * c.Area;
}

namespace
{
/**
 * The fraction of the form factor from x (normal n) to `count` triangles
 * (corners three by three) that is visible: the point kernel
 * cos_x cos_y / r^2 over an equal-area stratified set on each triangle
 * (8 x 8 on one, fewer on each of several: about 64 points in all), weighted
 * by `transmittance`. For a partially hidden emitter of a few triangles:
 * its own 3 x 3 rule's nodes left a penumbra in steps (21% of the peak on
 * the exact-penumbra floor, which no halving of the receiver improved).
 */
template <typename Transmittance>
double VisibleFraction(
  const Vec3& x, const Vec3& n, const Vec3* corners, std::size_t count, const Transmittance& transmittance)
{
  const int strata = std::max(2, static_cast<int>(std::lround(8.0 / std::sqrt(double(count)))));
  double visible = 0.0, total = 0.0;
  for (std::size_t t = 0; t < count; ++t)
  {
    const Vec3* c = corners + 3 * t;
    const Vec3 normal = glm::cross(c[1] - c[0], c[2] - c[0]);
    const double area2 = glm::length(normal);
    if (!(area2 > 0.0))
    {
      continue;
    }
    const Vec3 ny = normal / area2;
    const double weight = area2 / (strata * strata); // each point's share of the area (x 2)
    for (int i = 0; i < strata; ++i)
    {
      for (int j = 0; j < strata; ++j)
      {
        const double su = std::sqrt((i + 0.5) / strata), w = (j + 0.5) / strata;
        const Vec3 y = (1.0 - su) * c[0] + su * (1.0 - w) * c[1] + su * w * c[2];
        const Vec3 r = y - x;
        const double d2 = glm::dot(r, r);
        const double k =
          d2 > 0.0 ? weight * std::max(glm::dot(n, r), 0.0) * std::max(-glm::dot(ny, r), 0.0) / (d2 * d2) : 0.0;
        if (k > 0.0)
        {
          total += k;
          visible += k * transmittance(y);
        }
      }
    }
  }
  return total > 0.0 ? visible / total : 1.0;
}
// The blockers of each source triangle (`corners`, three per triangle) as
// seen from receiver triangle `receiver` (its own corners, or its input
// triangle's), at most MaxExactBlockers each; false when there are more
// (the sampled fraction is used then).
bool ExactFractionBlockers(const TransferEnd& receiver, const TransferEnd& emitter,
  const std::vector<Vec3>& corners, const FaceClusterVisibility& visibility,
  std::vector<std::vector<TriangleCorners>>& blockers)
{
  constexpr std::size_t MaxExactBlockers = 64;
  const Scene& scene = visibility.Hierarchy().GetScene();
  const TriangleCorners r = receiver.Corners
    ? TriangleCorners{ receiver.Corners[0], receiver.Corners[1], receiver.Corners[2] }
    : TriangleCorners{ scene.Vertex(receiver.Id, 0), scene.Vertex(receiver.Id, 1), scene.Vertex(receiver.Id, 2) };
  blockers.assign(corners.size() / 3, {});
  for (std::size_t t = 0; t < blockers.size(); ++t)
  {
    const TriangleCorners source{ corners[3 * t], corners[3 * t + 1], corners[3 * t + 2] };
    if (!visibility.ShaftBlockers(r, source, receiver.Id, emitter.Id, MaxExactBlockers, blockers[t]))
    {
      return false;
    }
  }
  return true;
}
}

TransferCoupling ComputeCoupling(const TransferEnd& receiver, const TransferEnd& emitter,
  const FaceClusterVisibility& visibility, const TransferRule& rule)
{
  const FaceCluster& ri = *receiver.Cluster;
  const FaceCluster& ej = *emitter.Cluster;
  const SurfaceRule& rr = *receiver.Rule;
  const SurfaceRule& er = *emitter.Rule;
  const int ne = receiver.Functions, nb = emitter.Functions;
  TransferCoupling out;
  out.Receivers = ne;
  out.Emitters = nb;
  out.K.assign(static_cast<std::size_t>(ne) * nb, Vec3(0.0));
  const double spacing = 2.0 * std::max(double(ri.HalfSize.x), double(ri.HalfSize.y)) /
    std::max(rule.Nodes, 1) * rule.VisibilityThreshold;

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
  // Clipped to each receiver node's hemisphere: the parts of an emitter
  // below a node's tangent plane would otherwise cancel the parts above in
  // n . E (a floor running under a block's face).
  auto exactVector = [&](const Vec3& x, const Vec3& n) {
    if (emitter.Corners)
    {
      return PointToPolygonVectorFormFactor(x, emitter.Corners, 3, &n);
    }
    if (flat)
    {
      return coverage * PointToPolygonVectorFormFactor(x, rectangle, 4, &n);
    }
    Vec3 sum(0.0);
    for (std::uint32_t k = ej.First; k < ej.First + ej.Count; ++k)
    {
      const std::uint32_t t = hierarchy.TriangleOrder()[k];
      const Vec3 tri[3] = { scene.Vertex(t, 0), scene.Vertex(t, 1), scene.Vertex(t, 2) };
      sum += PointToPolygonVectorFormFactor(x, tri, 3, &n);
    }
    return sum;
  };

  // The receiver's nodes, then its control points.
  const std::size_t np = rr.Size(), nc = rr.Controls.size(), nq = er.Size();
  std::vector<Vec3>& atNode = out.AtPoint; // sum_q Phi_b(y_q) g_pq
  atNode.assign((np + nc) * nb, Vec3(0.0));
  std::vector<double>& upper = out.UpperScale;
  std::vector<double>& lower = out.LowerScale;
  upper.assign(np, 0.0);
  lower.assign(np, std::numeric_limits<double>::infinity());
  std::vector<char> shadowed(np + nc, 0);
  // The constant part's exact vector form factor at each point (unoccluded).
  std::vector<Vec3> exactAt(exactConstant ? np + nc : 0);
  // In parallel: each point's emitter nodes' rays.
  tbb::parallel_for(std::size_t(0), np + nc, [&](std::size_t p) {
    const Vec3& x = p < np ? rr.Points[p] : rr.Controls[p - np];
    const Vec3& normal = p < np ? rr.Normals[p] : rr.ControlNormals[p - np];
    double visibleSum = 0.0, weightSum = 0.0;
    // The emitter's nodes above the point's horizon; exact visibility of
    // them all in one batch of rays.
    thread_local std::vector<std::size_t> above;
    thread_local std::vector<Vec3> ends;
    thread_local std::vector<unsigned char> seen;
    above.clear();
    ends.clear();
    for (std::size_t q = 0; q < nq; ++q)
    {
      const Vec3 r = er.Points[q] - x;
      if (glm::dot(r, r) > 0.0 && glm::dot(normal, r) > 0.0)
      {
        above.push_back(q);
        ends.push_back(er.Points[q]);
      }
    }
    if (spacing <= 0.0)
    {
      seen.resize(ends.size());
      visibility.Visible(x, ends.data(), ends.size(), receiver.Id, emitter.Id, seen.data());
    }
    for (std::size_t k = 0; k < above.size(); ++k)
    {
      const std::size_t q = above[k];
      const Vec3& y = er.Points[q];
      const Vec3 r = y - x;
      const double d2 = glm::dot(r, r);
      const Vec3 dir = r / std::sqrt(d2);
      const double v = spacing <= 0.0 ? double(seen[k]) : visibility.Transmittance(x, y, receiver.Id, emitter.Id, spacing);
      shadowed[p] |= v < 1.0 ? 1 : 0;
      visibleSum += er.Weights[q] * v;
      weightSum += er.Weights[q];
      // The point kernel m(x, y) dA_y of eq. 3 with the node's own normal,
      // as the form factor of a disc of the node's area w facing x, w cos /
      // (pi d^2 + w) (Wallace et al. 1989), not w cos / (pi d^2): the two
      // agree to w / (pi d^2) where the node is small for its distance, and
      // the disc's never exceeds 1 where it is not. Between parts that touch
      // or interpenetrate (a chair's legs through the classroom's floor) a
      // node a micrometre from the point gave a form factor of 1e6, and the
      // solve diverged (bounce power 2.8 kW to 67 kW in one iteration).
      const double cosine = std::max(-glm::dot(er.Normals[q], dir), 0.0);
      const double g = er.Weights[q] * v * cosine / (Pi * d2 + er.Weights[q]);
      for (int b = exactConstant ? 1 : 0; b < nb; ++b)
      {
        atNode[p * nb + b] += (er.Phi[q * er.Functions + b] * g) * dir;
      }
      // 3.3.2: bounds on B F A over the emitter's nodes, per unit
      // radiosity (EvaluateCoupling scales them by the radiosity's bounds).
      if (p < np)
      {
        const double scale = v / (Pi * d2);
        upper[p] = std::max(upper[p], scale * ri.MaxProjectedArea(dir) * ej.MaxProjectedArea(-dir));
        lower[p] = std::min(lower[p], scale * ri.MinProjectedArea(dir) * ej.MinProjectedArea(-dir));
      }
    }
    // A unit radiosity brings at most the whole hemisphere, |F| <= 1: where
    // the nodes' discs overlap (a point next to a large curved cluster, or
    // inside one that interpenetrates its surface) their sum exceeded that
    // by 2.3 times on the classroom, and each bounce created light. The
    // kernel is scaled back to the hemisphere's worth.
    if (!exactConstant)
    {
      const double magnitude = glm::length(atNode[p * nb]);
      if (magnitude > 1.0)
      {
        for (int b = 0; b < nb; ++b)
        {
          atNode[p * nb + b] /= magnitude;
        }
      }
    }
    if (exactConstant)
    {
      const double v = weightSum > 0.0 ? visibleSum / weightSum : 1.0;
      exactAt[p] = exactVector(x, normal);
      atNode[p * nb] = v * exactAt[p];
    }
  });
  // A light source of a few triangles (an emitting cluster: the sharp
  // shadows are the direct light's) hidden in part from any of the
  // receiver's points: its visible fraction at every point from the finer
  // sets (a point whose nine nodes all happened to be visible, or all
  // hidden, is not spared). For every partly hidden emitter it doubled the
  // bunny room's solve (100k triangles: 30.6 s against 17.8 s).
  constexpr std::uint32_t FineTriangles = 4;
  const bool source = std::max({ ej.EmissionMax.x, ej.EmissionMax.y, ej.EmissionMax.z }) > 0.0f;
  if (exactConstant && source && (emitter.Corners || ej.Count <= FineTriangles) &&
    std::any_of(shadowed.begin(), shadowed.end(), [](char c) { return c != 0; }))
  {
    std::vector<Vec3> corners;
    if (emitter.Corners)
    {
      corners.assign(emitter.Corners, emitter.Corners + 3);
    }
    else
    {
      for (std::uint32_t k = ej.First; k < ej.First + ej.Count; ++k)
      {
        const std::uint32_t t = hierarchy.TriangleOrder()[k];
        corners.insert(corners.end(), { scene.Vertex(t, 0), scene.Vertex(t, 1), scene.Vertex(t, 2) });
      }
    }
    // A receiver that is one triangle (or a part of one) and few blockers:
    // the fraction exactly, by backprojection (Hardt & Teller, section 5:
    // the source minus the blockers' shadows, Lambert's formula over the
    // visible fragments; Backprojection.h), per source triangle.
    std::vector<std::vector<TriangleCorners>> blockers;
    const bool exactFraction = rule.VisibilityThreshold <= 0.0 &&
      (receiver.Corners || ri.IsLeaf()) && ExactFractionBlockers(receiver, emitter, corners, visibility, blockers);
    tbb::parallel_for(std::size_t(0), np + nc, [&](std::size_t p) {
      const Vec3& x = p < np ? rr.Points[p] : rr.Controls[p - np];
      const Vec3& normal = p < np ? rr.Normals[p] : rr.ControlNormals[p - np];
      double v = 0.0;
      if (exactFraction)
      {
        double visible = 0.0, total = 0.0;
        for (std::size_t t = 0; t < blockers.size(); ++t)
        {
          const TriangleCorners source{ corners[3 * t], corners[3 * t + 1], corners[3 * t + 2] };
          total += VisibleFormFactor(x, normal, source, static_cast<const TriangleCorners*>(nullptr), 0);
          visible += VisibleFormFactor(x, normal, source, blockers[t].data(), blockers[t].size());
        }
        v = total > 0.0 ? std::clamp(visible / total, 0.0, 1.0) : 1.0;
      }
      else
      {
        v = VisibleFraction(x, normal, corners.data(), corners.size() / 3,
          [&](const Vec3& y) { return visibility.Transmittance(x, y, receiver.Id, emitter.Id, spacing); });
      }
      atNode[p * nb] = v * exactAt[p];
    });
  }
  for (std::size_t p = 0; p < np; ++p)
  {
    for (int a = 0; a < ne; ++a)
    {
      const double d = rr.Dual[p * rr.Functions + a];
      for (int b = 0; b < nb; ++b)
      {
        out.K[a * nb + b] += d * atNode[p * nb + b];
      }
    }
  }
  out.ExactConstant = exactConstant;
  out.Shadowed = std::any_of(shadowed.begin(), shadowed.end(), [](char c) { return c != 0; });
  out.Residuals = receiver.Corners || ri.IsLeaf();
  return out;
}

Transfer EvaluateCoupling(const TransferCoupling& coupling, const TransferEnd& receiver,
  const std::vector<RGB>& radiosity, double radiosityMin, double radiosityMax)
{
  const FaceCluster& ri = *receiver.Cluster;
  const SurfaceRule& rr = *receiver.Rule;
  const int ne = coupling.Receivers, nb = coupling.Emitters;
  const std::size_t np = rr.Size(), nc = rr.Controls.size();
  const std::vector<Vec3>& atNode = coupling.AtPoint;
  Transfer out;
  out.Receivers = ne;
  out.Emitters = nb;
  out.K = coupling.K;
  double departure = 0.0;
  // 3.3.2, "the value interpolated using the element basis" against direct
  // integration, at the nodes and at the control points.
  if (coupling.Residuals)
  {
    out.Residual.assign(np + nc, 0.0);
  }
  for (std::size_t p = 0; p < np + nc; ++p)
  {
    const double* phi = p < np ? &rr.Phi[p * rr.Functions] : &rr.ControlPhi[(p - np) * rr.Functions];
    const Vec3& normal = p < np ? rr.Normals[p] : rr.ControlNormals[p - np];
    Vec3 fitted(0.0), direct(0.0);
    for (int b = 0; b < nb; ++b)
    {
      const double radiosityB = Mean(radiosity[b]);
      direct += radiosityB * atNode[p * nb + b];
      for (int a = 0; a < ne; ++a)
      {
        fitted += (phi[a] * radiosityB) * out.K[a * nb + b];
      }
    }
    const double departure = ri.Area * glm::dot(normal, fitted - direct);
    out.FitError = std::max(out.FitError, std::abs(departure));
    if (!out.Residual.empty())
    {
      out.Residual[p] = departure;
    }
  }
  // The bounds on BFA over the emitter's nodes (3.3.2) where the direct
  // values are themselves estimates: occluded or sampled emitters, or a
  // radiosity that is not uniform (over the emitter's leaves, as the solver
  // tracks it). An unoccluded uniform emitter's direct values are exact
  // (vector form factors), and its parts' bounds, which never tighten next
  // to a shared edge, would refine it for nothing.
  bool uniform = coupling.ExactConstant && radiosityMax - radiosityMin <= 1e-6 * radiosityMax;
  for (int b = 1; b < nb && uniform; ++b)
  {
    uniform = MaxComponent(glm::abs(radiosity[b])) <= 1e-9 * MaxComponent(glm::abs(radiosity[0]));
  }
  const bool exact = uniform && !coupling.Shadowed;
  for (std::size_t p = 0; p < np && !exact; ++p)
  {
    Vec3 e(0.0);
    for (int a = 0; a < ne; ++a)
    {
      for (int b = 0; b < nb; ++b)
      {
        e += (rr.Phi[p * rr.Functions + a] * Mean(radiosity[b])) * out.K[a * nb + b];
      }
    }
    const double bfa = ri.Area * std::max(glm::dot(rr.Normals[p], e), 0.0);
    const double up = radiosityMax * coupling.UpperScale[p];
    const double lo = std::isfinite(coupling.LowerScale[p]) ? radiosityMin * coupling.LowerScale[p] : 0.0;
    departure = std::max({ departure, std::abs(bfa - up), std::abs(bfa - lo) });
  }
  out.Error = std::max(departure, out.FitError);
  return out;
}

Transfer ComputeTransfer(const TransferEnd& receiver, const TransferEnd& emitter,
  const std::vector<RGB>& radiosity, double radiosityMin, double radiosityMax,
  const FaceClusterVisibility& visibility, const TransferRule& rule)
{
  return EvaluateCoupling(
    ComputeCoupling(receiver, emitter, visibility, rule), receiver, radiosity, radiosityMin, radiosityMax);
}

std::size_t TransferCoupling::Bytes() const
{
  return sizeof(TransferCoupling) + (this->K.capacity() + this->AtPoint.capacity()) * sizeof(Vec3) +
    (this->UpperScale.capacity() + this->LowerScale.capacity()) * sizeof(double);
}
} // namespace radiosity
