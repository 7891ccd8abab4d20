// The output side of FaceClusterRadiosity: the leaf elements' irradiance
// expansions evaluated on the input triangles, at their vertices and at
// probes (section 3.5, and SPEC: probes from the vector irradiance bases).
// Punctual lights are shown exactly: each point takes their closed form
// with its own shadow ray (ShownExact) plus the expansion less its fit
// of them (ShownExpansion).
#include "Radiosity/FaceCluster/FaceClusterRadiosity.h"
#include "Radiosity/Common/MeshProbeTracker.h"
#include "Radiosity/Common/Visibility.h"
#include "Radiosity/Common/ThreadLimit.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>

namespace radiosity
{
namespace
{
// The least barycentric coordinate of x (projected into the triangle's
// plane): positive inside, the larger the deeper.
double DepthInside(const std::array<Vec3, 3>& c, const Vec3& x)
{
  double u, v, w;
  if (!ProjectOnTriangle(x, c[0], c[1], c[2], u, v, w))
  {
    return -std::numeric_limits<double>::infinity();
  }
  return std::min({ u, v, w });
}

RGB Received(const IrradianceVector& v, const Vec3& n)
{
  return RGB(std::max(glm::dot(n, v[0]), 0.0), std::max(glm::dot(n, v[1]), 0.0),
    std::max(glm::dot(n, v[2]), 0.0));
}

/// compute(t, item) for every triangle t < n, in parallel blocks (the
/// expansions and the punctual lights' rays) on at most `threads` threads
/// (0: all), then fold(t, item) in order.
template <typename Item, typename Compute, typename Fold>
void PerTriangle(std::size_t n, int threads, const Compute& compute, const Fold& fold)
{
  constexpr std::size_t Block = std::size_t(1) << 16;
  std::vector<Item> items;
  for (std::size_t first = 0; first < n; first += Block)
  {
    const std::size_t count = std::min(Block, n - first);
    items.assign(count, Item{});
    RunWithThreads(threads,
      [&]() { tbb::parallel_for(std::size_t(0), count, [&](std::size_t k) { compute(first + k, items[k]); }); });
    for (std::size_t k = 0; k < count; ++k)
    {
      fold(first + k, items[k]);
    }
  }
}
}

std::int32_t FaceClusterRadiosity::LeafAt(std::uint32_t t, const Vec3& x) const
{
  return this->PartAt(this->ElementOf(t), x);
}

std::int32_t FaceClusterRadiosity::ElementOf(std::uint32_t t) const
{
  const std::uint32_t position = this->Clusters->TrianglePosition(t);
  auto holds = [position](const FaceClusterElement& e) {
    return position >= e.Data.First && position < e.Data.First + e.Data.Count;
  };
  std::int32_t e = -1;
  for (std::int32_t top : this->Top)
  {
    if (holds(this->Nodes[top]))
    {
      e = top;
      break;
    }
  }
  while (e >= 0 && !this->Nodes[e].IsLeaf() && !this->Nodes[e].IsTriangle())
  {
    const std::int32_t k0 = this->Nodes[e].Child[0];
    e = holds(this->Nodes[k0]) ? k0 : this->Nodes[e].Child[1];
  }
  return e;
}

std::int32_t FaceClusterRadiosity::PartAt(std::int32_t e, const Vec3& x) const
{
  while (e >= 0 && !this->Nodes[e].IsLeaf())
  {
    // Parts of one triangle: the one x is deepest inside.
    const std::int32_t k0 = this->Nodes[e].Child[0], k1 = this->Nodes[e].Child[1];
    e = DepthInside(this->Nodes[k0].Corners, x) >= DepthInside(this->Nodes[k1].Corners, x) ? k0 : k1;
  }
  return e;
}

IrradianceVector FaceClusterRadiosity::Expansion(std::int32_t e, const Vec3& x, bool limit, bool shown) const
{
  IrradianceVector v{};
  if (e < 0)
  {
    return v;
  }
  const FaceClusterElement& leaf = this->Nodes[e];
  // Shown: the expansion less its fit of the light shown exactly.
  const bool less = shown && !leaf.ExactFit.empty();
  const auto coefficient = [&](int a, int c) {
    return less ? leaf.Irradiance[a][c] - leaf.ExactFit[a][c] : leaf.Irradiance[a][c];
  };
  const glm::dvec2 uv = glm::clamp(BoxCoordinates(leaf.Data, x), glm::dvec2(0.0), glm::dvec2(1.0));
  double phi[PolynomialBasis::MaximumSize];
  this->IrradianceBasis.Evaluate(uv.x, uv.y, phi);
  for (int a = 0; a < this->IrradianceBasis.Size(); ++a)
  {
    for (int c = 0; c < 3; ++c)
    {
      v[c] += phi[a] * coefficient(a, c);
    }
  }
  // A limiter, as for discontinuous Galerkin solutions (Barth & Jespersen
  // 1989): between its nodes a fit is faithful, but out at a curved
  // cluster's vertices a quadratic one can overshoot, even below zero
  // (black specks on a glossy statue). The part above the mean is scaled
  // back until every component lies within its range at the nodes, widened
  // by half of it.
  const IrradianceVector& lowest = shown ? leaf.ShownLowest : leaf.Lowest;
  const IrradianceVector& highest = shown ? leaf.ShownHighest : leaf.Highest;
  double theta = 1.0;
  for (int c = 0; c < 3 && limit; ++c)
  {
    const Vec3 mean = phi[0] * coefficient(0, c);
    for (int k = 0; k < 3; ++k)
    {
      // Slack of half the range: a steady gradient runs on past the
      // outermost nodes to the element's edge (a contact edge), an
      // overshoot does not.
      const double slack = 0.5 * (highest[c][k] - lowest[c][k]);
      const double high = highest[c][k] + slack, low = lowest[c][k] - slack;
      const double rise = v[c][k] - mean[k];
      if (v[c][k] > high && rise > 0.0)
      {
        theta = std::min(theta, std::max(high - mean[k], 0.0) / rise);
      }
      else if (v[c][k] < low && rise < 0.0)
      {
        theta = std::min(theta, std::min(low - mean[k], 0.0) / rise);
      }
    }
  }
  if (theta < 1.0)
  {
    for (int c = 0; c < 3; ++c)
    {
      const Vec3 mean = phi[0] * coefficient(0, c);
      v[c] = mean + theta * (v[c] - mean);
    }
  }
  return v;
}

void FaceClusterRadiosity::BoundLeafExpansions()
{
  const int ne = this->IrradianceBasis.Size();
  for (FaceClusterElement& e : this->Nodes)
  {
    if (!e.IsLeaf())
    {
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      e.Lowest[c] = e.ShownLowest[c] = Vec3(std::numeric_limits<double>::infinity());
      e.Highest[c] = e.ShownHighest[c] = Vec3(-std::numeric_limits<double>::infinity());
    }
    for (std::size_t q = 0; q < e.Rule.Size(); ++q)
    {
      for (int c = 0; c < 3; ++c)
      {
        Vec3 atNode(0.0), fit(0.0);
        for (int a = 0; a < ne; ++a)
        {
          atNode += e.Rule.Phi[q * ne + a] * e.Irradiance[a][c];
          if (!e.ExactFit.empty())
          {
            fit += e.Rule.Phi[q * ne + a] * e.ExactFit[a][c];
          }
        }
        e.Lowest[c] = glm::min(e.Lowest[c], atNode);
        e.Highest[c] = glm::max(e.Highest[c], atNode);
        e.ShownLowest[c] = glm::min(e.ShownLowest[c], atNode - fit);
        e.ShownHighest[c] = glm::max(e.ShownHighest[c], atNode - fit);
      }
    }
  }
}

IrradianceVector FaceClusterRadiosity::IrradianceVectorAt(std::uint32_t t, const Vec3& x) const
{
  return this->Expansion(this->LeafAt(t, x), x);
}

IrradianceVector FaceClusterRadiosity::ShownExpansion(std::int32_t e, const Vec3& x) const
{
  // With light shown exactly, the expansion less its fit of it, limited
  // to its own range at the nodes: a hard shadow or a spot's rim is a step
  // that no basis follows, and the fit's overshoot there drew black and
  // bright specks; a lamp's fit drew the glossy statue's blotches.
  return this->Expansion(e, x, true, this->ShowsExact());
}

IrradianceVector FaceClusterRadiosity::ShownExact(std::uint32_t t, const Vec3& x, const Vec3& n) const
{
  IrradianceVector v{};
  if (!this->ShowsExact())
  {
    return v;
  }
  // The rays leave from inside t where x is on its boundary, so that a
  // vertex at a seam (the floor's edge at a wall) does not see through the
  // adjacent surface.
  const radiosity::Visibility& rays = this->Visibility->AllTriangles();
  const Vec3 from = SharedVertexPoint(rays.Offset(), this->GetScene(), t, x);
  if (this->ShowsExactPunctual())
  {
    v = this->Lights->PunctualVectorSeenFrom(x, from, n);
  }
  if (this->ExactEmitters)
  {
    const IrradianceVector emitted = this->ExactEmitters->At(t, x, n, RayOriginOff(rays.Offset(), from, n));
    for (int c = 0; c < 3; ++c)
    {
      v[c] += emitted[c];
    }
  }
  return v;
}

RGB FaceClusterRadiosity::IrradianceAt(std::uint32_t t, const Vec3& x, const Vec3& n) const
{
  // The expansion less its fit of the exactly shown light, plus that light
  // at x itself (the punctual lights' with the shadow ray from x itself,
  // as before the emitters were shown exactly).
  RGB exact = this->ShowsExactPunctual() ? this->Lights->Punctual(x, n) : RGB(0.0);
  if (this->ExactEmitters)
  {
    const radiosity::Visibility& rays = this->Visibility->AllTriangles();
    exact += Received(this->ExactEmitters->At(t, x, n, RayOriginOff(rays.Offset(), x, n)), n);
  }
  return Received(this->ShownExpansion(this->LeafAt(t, x), x), n) + exact;
}

IrradianceVector FaceClusterRadiosity::WholeTriangleExpansion(std::int32_t e, const Vec3& x) const
{
  // The parts' expansions at the triangle's own nodes, fitted by its basis
  // (the least-squares pull of 3.3.4, here of irradiance): the display
  // interpolates the vertex vectors across the input triangle, so a vertex
  // gets the triangle's best fit, not the value of the part in its corner
  // (on the Cornell box's 32 triangles the corner parts lit the back wall
  // by the side walls' colours: the lamp's light reaches the corners at
  // grazing angles and its middle not at all in the vertex values).
  const FaceClusterElement& whole = this->Nodes[e];
  const int ne = this->IrradianceBasis.Size();
  IrradianceVector coefficients[PolynomialBasis::MaximumSize]{};
  for (std::size_t q = 0; q < whole.Rule.Size(); ++q)
  {
    const Vec3& y = whole.Rule.Points[q];
    const IrradianceVector at = this->ShownExpansion(this->PartAt(e, y), y);
    for (int a = 0; a < ne; ++a)
    {
      for (int c = 0; c < 3; ++c)
      {
        coefficients[a][c] += whole.Rule.Dual[q * whole.Rule.Functions + a] * at[c];
      }
    }
  }
  const glm::dvec2 uv = glm::clamp(BoxCoordinates(whole.Data, x), glm::dvec2(0.0), glm::dvec2(1.0));
  double phi[PolynomialBasis::MaximumSize];
  this->IrradianceBasis.Evaluate(uv.x, uv.y, phi);
  IrradianceVector v{};
  for (int a = 0; a < ne; ++a)
  {
    for (int c = 0; c < 3; ++c)
    {
      v[c] += phi[a] * coefficients[a][c];
    }
  }
  return v;
}

std::vector<std::array<double, 9>> FaceClusterRadiosity::VertexIrradianceVectors() const
{
  const Scene& scene = this->GetScene();
  std::vector<std::array<double, 9>> out(scene.Points.size(), std::array<double, 9>{});
  std::vector<int> count(scene.Points.size(), 0);
  std::vector<Vec3> normal(scene.Points.size(), Vec3(0.0));
  using Corners = std::array<IrradianceVector, 3>;
  PerTriangle<Corners>(
    scene.Triangles.size(), this->Settings.Threads,
    [&](std::size_t t, Corners& corners) {
      const std::int32_t element = this->ElementOf(static_cast<std::uint32_t>(t));
      for (int k = 0; k < 3; ++k)
      {
        const Vec3& x = scene.Points[scene.Triangles[t].V[k]];
        const IrradianceVector e = element < 0 || this->Nodes[element].IsLeaf()
          ? this->ShownExpansion(element, x) // zero without a solution (no light)
          : this->WholeTriangleExpansion(element, x);
        const IrradianceVector punctual = this->ShownExact(static_cast<std::uint32_t>(t), x, scene.Normal(t));
        for (int c = 0; c < 3; ++c)
        {
          corners[k][c] = e[c] + punctual[c];
        }
      }
    },
    [&](std::size_t t, const Corners& corners) {
      const Vec3 area = scene.Area(t) * scene.Normal(t);
      for (int k = 0; k < 3; ++k)
      {
        const std::uint32_t v = scene.Triangles[t].V[k];
        normal[v] += area;
        for (int c = 0; c < 3; ++c)
        {
          for (int d = 0; d < 3; ++d)
          {
            out[v][3 * c + d] += corners[k][c][d];
          }
        }
        ++count[v];
      }
    });
  for (std::size_t v = 0; v < out.size(); ++v)
  {
    if (count[v] > 0)
    {
      for (double& x : out[v])
      {
        x /= count[v];
      }
    }
    // The light that arrives at a point comes from the hemisphere above
    // it: E = integral over H(n) of L(w) w dw (eq. 3's transport vector
    // summed over the emitters), so n . E >= 0 for its normal n. A fitted
    // expansion can leave that half-space at a vertex (a curved or folded
    // cluster's corner, a leaf beside a contact): the vertex gets the
    // nearest vector inside it, E - min(n . E, 0) n, which removes only the
    // overshoot along the normal and keeps the tangential part the glossy
    // display reads. n is the area-weighted mean of the triangles' normals,
    // as vtkVectorIrradianceMapper computes it. Measured on the glossy
    // statue (TestFaceClusterVectorIrradiance): 5 vertices below zero, down
    // to -0.065 of the peak, before; none after.
    const double l = glm::length(normal[v]);
    if (l > 0.0)
    {
      const Vec3 n = normal[v] / l;
      for (int c = 0; c < 3; ++c)
      {
        Vec3 e(out[v][3 * c], out[v][3 * c + 1], out[v][3 * c + 2]);
        const double h = glm::dot(n, e);
        if (h < 0.0)
        {
          e -= (h / glm::dot(n, n)) * n;
          for (int d = 0; d < 3; ++d)
          {
            out[v][3 * c + d] = e[d];
          }
        }
      }
    }
  }
  return out;
}

SolutionMesh FaceClusterRadiosity::Surface() const
{
  const Scene& scene = this->GetScene();
  SolutionMesh out;
  out.Points = scene.Points;
  out.Triangles = scene.Triangles;
  out.PointIrradiance.assign(scene.Points.size(), RGB(0.0));
  out.PointRadiosity.assign(scene.Points.size(), RGB(0.0));
  std::vector<double> weight(scene.Points.size(), 0.0);
  struct Sampled
  {
    ElementSamples Samples;
    std::int32_t Leaf = -1;
  };
  PerTriangle<Sampled>(
    scene.Triangles.size(), this->Settings.Threads,
    [&](std::size_t t, Sampled& s) {
      const auto id = static_cast<std::uint32_t>(t);
      const Vec3 n = scene.Normal(t);
      const std::int32_t element = this->ElementOf(id);
      const Vec3 centre = scene.Centroid(t);
      s.Leaf = this->PartAt(element, centre);
      for (int k = 0; k < 3; ++k)
      {
        const Vec3 corner = scene.Vertex(t, k);
        s.Samples.Corner[k] = Received(this->ShownExpansion(this->PartAt(element, corner), corner), n) +
          Received(this->ShownExact(id, corner, n), n);
      }
      s.Samples.Centre = Received(this->ShownExpansion(s.Leaf, centre), n) + Received(this->ShownExact(id, centre, n), n);
    },
    [&](std::size_t t, const Sampled& s) {
      const auto id = static_cast<std::uint32_t>(t);
      Material m = scene.Materials[t];
      m.Emission = this->EmissionOf(id); // a relight's
      const ElementSamples& samples = s.Samples;
      const std::int32_t leaf = s.Leaf;
      const RGB h = samples.Mean();
      out.CellIrradiance.push_back(h);
      out.CellRadiosity.push_back(m.Emission + m.Reflectance * h);
      out.ElementId.push_back(leaf >= 0 ? this->Nodes[leaf].Cluster : 0u);
      out.Level.push_back(static_cast<std::uint16_t>(leaf >= 0 ? this->Nodes[leaf].Data.Depth : 0));
      out.SourceTriangle.push_back(id);
      out.Samples.push_back(samples);
      out.Normals.push_back(scene.Normal(t));
      const double area = scene.Area(t);
      for (int k = 0; k < 3; ++k)
      {
        const std::uint32_t v = scene.Triangles[t].V[k];
        out.PointIrradiance[v] += area * samples.Corner[k];
        out.PointRadiosity[v] += area * (m.Emission + m.Reflectance * samples.Corner[k]);
        weight[v] += area;
      }
    });
  for (std::size_t p = 0; p < weight.size(); ++p)
  {
    if (weight[p] > 0.0)
    {
      out.PointIrradiance[p] /= weight[p];
      out.PointRadiosity[p] /= weight[p];
    }
  }
  return out;
}

std::vector<RGB> FaceClusterRadiosity::Evaluate(const std::vector<Probe>& probes) const
{
  return EvaluateOnNearestTriangles(this->GetScene(), probes,
    [this](std::uint32_t t, const Vec3& x, const Vec3& n) { return this->IrradianceAt(t, x, n); });
}
} // namespace radiosity
