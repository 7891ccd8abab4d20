#include "Radiosity/FaceClusterRadiosity.h"

#include "Radiosity/Stopwatch.h"
#include "Radiosity/ThreadLimit.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace radiosity
{
namespace
{
// The largest |Phi| of the Legendre products up to cubic: sqrt(7) * sqrt(7)
// bounds every function on [0, 1]^2; a bound on an expansion's range.
constexpr double BasisBound = 7.0;

double Magnitude(const std::vector<RGB>& coefficients)
{
  double m = 0.0;
  for (const RGB& c : coefficients)
  {
    m = std::max(m, MaxComponent(glm::abs(c)));
  }
  return m;
}
}

FaceClusterRadiosity::FaceClusterRadiosity(const Scene& scene, const FaceClusterSettings& settings,
  std::shared_ptr<const FaceClusterHierarchy> hierarchy)
  : Settings(settings)
  , RadiosityBasis(static_cast<int>(settings.RadiosityBasis) <= static_cast<int>(settings.IrradianceBasis)
        ? settings.RadiosityBasis
        : settings.IrradianceBasis)
  , IrradianceBasis(settings.IrradianceBasis)
{
  const Stopwatch clock;
  this->Clusters = hierarchy ? std::move(hierarchy) : FaceClusterHierarchy::Shared(scene, settings.Clustering);
  this->Stats.HierarchySeconds = clock.Seconds();
  this->Visibility = std::make_unique<FaceClusterVisibility>(*this->Clusters);
}

std::int32_t FaceClusterRadiosity::NewElement(std::uint32_t cluster, std::int32_t parent)
{
  const int ne = this->IrradianceBasis.Size(), nb = this->RadiosityBasis.Size();
  const auto id = static_cast<std::int32_t>(this->Nodes.size());
  this->Nodes.emplace_back();
  FaceClusterElement& e = this->Nodes.back();
  e.Cluster = cluster;
  e.Parent = parent;
  e.Data = this->Clusters->Cluster(cluster);
  e.Rule = MakeSurfaceRule(*this->Clusters, cluster, e.Data, this->IrradianceBasis, this->Settings.Rule.Nodes);
  e.RadiosityDual = DualWeights(e.Data, this->RadiosityBasis, e.Rule.Points, e.Rule.Weights);
  e.Unshot.assign(nb, RGB(0.0));
  e.Next.assign(nb, RGB(0.0));
  e.Irradiance.assign(ne, IrradianceVector{});
  e.LastIncrement.assign(ne, IrradianceVector{});
  if (parent < 0)
  {
    e.Unshot[0] = RGB(e.Data.EmissionMean);
    return id;
  }
  const FaceClusterElement& p = this->Nodes[parent];
  // 3.3.4: the child's least-squares fit of the parent's expansions at its
  // own nodes, for the irradiance and the radiosity bases.
  e.PushE.assign(static_cast<std::size_t>(ne) * ne, 0.0);
  e.PushB.assign(static_cast<std::size_t>(nb) * nb, 0.0);
  double phi[PolynomialBasis::MaximumSize];
  for (std::size_t q = 0; q < e.Rule.Size(); ++q)
  {
    const glm::dvec2 uv = BoxCoordinates(p.Data, e.Rule.Points[q]);
    this->IrradianceBasis.Evaluate(uv.x, uv.y, phi);
    for (int a = 0; a < ne; ++a)
    {
      for (int b = 0; b < ne; ++b)
      {
        e.PushE[a * ne + b] += phi[a] * e.Rule.Dual[q * ne + b];
      }
    }
    for (int a = 0; a < nb; ++a)
    {
      for (int b = 0; b < nb; ++b)
      {
        e.PushB[a * nb + b] += phi[a] * e.RadiosityDual[q * nb + b];
      }
    }
  }
  // The first shot is the element's own emission, not its parent's average.
  for (int b = 0; b < nb; ++b)
  {
    for (int a = 0; a < nb; ++a)
    {
      if (this->Iteration > 0)
      {
        e.Unshot[b] += e.PushB[a * nb + b] * p.Unshot[a];
      }
      e.Next[b] += e.PushB[a * nb + b] * p.Next[a];
    }
  }
  if (this->Iteration == 0)
  {
    e.Unshot[0] = RGB(e.Data.EmissionMean);
  }
  const Vec3 n = e.Data.MeanNormal();
  for (int c = 0; c < 3; ++c)
  {
    // Vector irradiance is pushed only into a child it faces (3.3.4).
    if (glm::dot(n, p.Irradiance[0][c]) <= 0.0 && glm::dot(n, p.LastIncrement[0][c]) <= 0.0)
    {
      continue;
    }
    for (int b = 0; b < ne; ++b)
    {
      for (int a = 0; a < ne; ++a)
      {
        e.Irradiance[b][c] += e.PushE[a * ne + b] * p.Irradiance[a][c];
        e.LastIncrement[b][c] += e.PushE[a * ne + b] * p.LastIncrement[a][c];
      }
    }
  }
  return id;
}

void FaceClusterRadiosity::Subdivide(std::int32_t e)
{
  if (!this->Nodes[e].IsLeaf() || this->Nodes[e].Data.IsLeaf())
  {
    return;
  }
  const std::uint32_t c0 = this->Nodes[e].Data.Child[0], c1 = this->Nodes[e].Data.Child[1];
  const std::int32_t k0 = this->NewElement(c0, e);
  const std::int32_t k1 = this->NewElement(c1, e);
  FaceClusterElement& parent = this->Nodes[e];
  parent.Child[0] = k0;
  parent.Child[1] = k1;
  // Pull: the parent's least-squares fit over the union of its children's
  // nodes (whose weights sum to its area, so the constant coefficient is
  // the area-weighted mean and no energy is lost).
  const int nb = this->RadiosityBasis.Size();
  std::vector<Vec3> points;
  std::vector<double> weights;
  for (std::int32_t k : { k0, k1 })
  {
    const SurfaceRule& r = this->Nodes[k].Rule;
    points.insert(points.end(), r.Points.begin(), r.Points.end());
    weights.insert(weights.end(), r.Weights.begin(), r.Weights.end());
  }
  const std::vector<double> dual = DualWeights(parent.Data, this->RadiosityBasis, points, weights);
  std::size_t offset = 0;
  double phi[PolynomialBasis::MaximumSize];
  for (std::int32_t k : { k0, k1 })
  {
    FaceClusterElement& child = this->Nodes[k];
    child.PullB.assign(static_cast<std::size_t>(nb) * nb, 0.0);
    for (std::size_t q = 0; q < child.Rule.Size(); ++q, ++offset)
    {
      const glm::dvec2 uv = BoxCoordinates(child.Data, child.Rule.Points[q]);
      this->RadiosityBasis.Evaluate(uv.x, uv.y, phi);
      for (int a = 0; a < nb; ++a)
      {
        for (int b = 0; b < nb; ++b)
        {
          child.PullB[a * nb + b] += dual[offset * nb + a] * phi[b];
        }
      }
    }
  }
  // Irradiance lives at the leaves only.
  std::fill(parent.Irradiance.begin(), parent.Irradiance.end(), IrradianceVector{});
  std::fill(parent.LastIncrement.begin(), parent.LastIncrement.end(), IrradianceVector{});
}

bool FaceClusterRadiosity::HasUnshot(const FaceClusterElement& e) const
{
  return Magnitude(e.Unshot) > 0.0;
}

void FaceClusterRadiosity::AddShooter(std::int32_t receiver, std::int32_t emitter)
{
  const FaceClusterElement& i = this->Nodes[receiver];
  const FaceClusterElement& j = this->Nodes[emitter];
  if (receiver != emitter && this->HasUnshot(j) && ClusterFaces(i.Data, j.Data) &&
    ClusterFaces(j.Data, i.Data))
  {
    this->Nodes[receiver].Shooters.push_back(emitter);
  }
}

void FaceClusterRadiosity::Gather(std::int32_t i, std::int32_t j, std::vector<IrradianceVector>& into)
{
  const FaceClusterElement& receiver = this->Nodes[i];
  const FaceClusterElement& emitter = this->Nodes[j];
  // Bounds on the emitter's radiosity: its emission's range in the first
  // shot, the expansion's range later.
  double bMin, bMax;
  if (this->Iteration == 0)
  {
    bMin = Mean(RGB(emitter.Data.EmissionMin));
    bMax = Mean(RGB(emitter.Data.EmissionMax));
  }
  else
  {
    double higher = 0.0;
    for (std::size_t b = 1; b < emitter.Unshot.size(); ++b)
    {
      higher += std::abs(Mean(emitter.Unshot[b]));
    }
    const double mean = Mean(emitter.Unshot[0]);
    bMin = std::max(0.0, mean - BasisBound * higher);
    bMax = mean + BasisBound * higher;
  }
  const Transfer t = ComputeTransfer(
    { &receiver.Data, receiver.Cluster, &receiver.Rule, this->IrradianceBasis.Size() },
    { &emitter.Data, emitter.Cluster, &emitter.Rule, this->RadiosityBasis.Size() }, emitter.Unshot,
    bMin, bMax, *this->Visibility, this->Settings.Rule);
  const bool splitReceiver = !receiver.Data.IsLeaf();
  const bool splitEmitter = !emitter.Data.IsLeaf();
  if (t.Error <= this->Epsilon || (!splitReceiver && !splitEmitter))
  {
    const int ne = t.Receivers, nb = t.Emitters;
    for (int a = 0; a < ne; ++a)
    {
      for (int b = 0; b < nb; ++b)
      {
        const Vec3& k = t.K[a * nb + b];
        for (int c = 0; c < 3; ++c)
        {
          into[a][c] += emitter.Unshot[b][c] * k;
        }
      }
    }
    ++this->Stats.Transfers;
    return;
  }
  ++this->Stats.Refinements;
  if (splitEmitter && (!splitReceiver || emitter.Data.Area > receiver.Data.Area))
  {
    this->Subdivide(j);
    const std::int32_t k0 = this->Nodes[j].Child[0], k1 = this->Nodes[j].Child[1];
    this->AddShooter(i, k0);
    this->AddShooter(i, k1);
  }
  else
  {
    this->Subdivide(i);
    const std::int32_t k0 = this->Nodes[i].Child[0], k1 = this->Nodes[i].Child[1];
    this->AddShooter(k0, j);
    this->AddShooter(k1, j);
  }
}

void FaceClusterRadiosity::TransportLight(std::int32_t i, const std::vector<IrradianceVector>& up)
{
  const int ne = this->IrradianceBasis.Size(), nb = this->RadiosityBasis.Size();
  std::vector<IrradianceVector> dE(ne, IrradianceVector{});
  if (!up.empty())
  {
    const FaceClusterElement& e = this->Nodes[i];
    const Vec3 n = e.Data.MeanNormal();
    for (int c = 0; c < 3; ++c)
    {
      if (glm::dot(n, up[0][c]) <= 0.0)
      {
        continue; // 3.3.4: not into a child it does not face
      }
      for (int b = 0; b < ne; ++b)
      {
        for (int a = 0; a < ne; ++a)
        {
          dE[b][c] += e.PushE[a * ne + b] * up[a][c];
        }
      }
    }
  }
  while (!this->Nodes[i].Shooters.empty())
  {
    const std::int32_t j = this->Nodes[i].Shooters.back();
    this->Nodes[i].Shooters.pop_back();
    this->Gather(i, j, dE);
  }
  // 3.3.3: the self-transfer of a non-convex element, refined into its
  // children's mutual transfers when its error bound is too large.
  {
    const FaceClusterElement& e = this->Nodes[i];
    if (!e.Data.Convex && !e.Data.IsLeaf() && this->HasUnshot(e))
    {
      const double bMax = this->Iteration == 0 ? Mean(RGB(e.Data.EmissionMax))
                                               : Magnitude(e.Unshot) * BasisBound;
      if (SelfTransferError(e.Data, bMax) > this->Epsilon)
      {
        this->Subdivide(i);
        const std::int32_t k0 = this->Nodes[i].Child[0], k1 = this->Nodes[i].Child[1];
        this->AddShooter(k0, k1);
        this->AddShooter(k1, k0);
      }
    }
  }
  FaceClusterElement& e = this->Nodes[i];
  std::fill(e.Next.begin(), e.Next.end(), RGB(0.0));
  if (e.IsLeaf())
  {
    const double self = 0.5 * (e.Data.SelfFormFactorLower() + e.Data.SelfFormFactorUpper());
    for (int a = 0; a < ne; ++a)
    {
      for (int c = 0; c < 3; ++c)
      {
        e.Irradiance[a][c] += dE[a][c];
        e.LastIncrement[a][c] = dE[a][c];
      }
    }
    // The reflected radiosity at the element's nodes, (1 - F_ii) rho n . dE
    // with each node's own normal, fitted by the radiosity basis.
    const SurfaceRule& rule = e.Rule;
    for (std::size_t q = 0; q < rule.Size(); ++q)
    {
      for (int c = 0; c < 3; ++c)
      {
        Vec3 atNode(0.0);
        for (int a = 0; a < ne; ++a)
        {
          atNode += rule.Phi[q * ne + a] * dE[a][c];
        }
        const double b = (1.0 - self) * e.Data.ReflectanceMean[c] * std::max(glm::dot(rule.Normals[q], atNode), 0.0);
        for (int a = 0; a < nb; ++a)
        {
          e.Next[a][c] += e.RadiosityDual[q * nb + a] * b;
        }
      }
    }
    return;
  }
  const std::int32_t children[2] = { e.Child[0], e.Child[1] };
  for (std::int32_t k : children)
  {
    this->TransportLight(k, dE);
  }
  // Pull: the children's radiosity fitted by the parent's basis.
  FaceClusterElement& p = this->Nodes[i];
  for (std::int32_t k : children)
  {
    const FaceClusterElement& child = this->Nodes[k];
    for (int a = 0; a < nb; ++a)
    {
      for (int b = 0; b < nb; ++b)
      {
        p.Next[a] += child.PullB[a * nb + b] * child.Next[b];
      }
    }
  }
}

SolverStatistics FaceClusterRadiosity::Solve(const ProgressCallback& progress)
{
  SolverStatistics stats;
  const Stopwatch clock;
  const auto threads = LimitThreads(this->Settings.Threads);
  const Scene& scene = this->GetScene();
  double emitted = 0.0, brightest = 0.0;
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    emitted += Mean(scene.Materials[t].Emission) * scene.Area(t);
    brightest = std::max(brightest, Mean(scene.Materials[t].Emission));
  }
  stats.EmittedPowerW = emitted;
  this->Nodes.clear();
  this->Top.clear();
  this->Iteration = 0;
  if (!(emitted > 0.0))
  {
    stats.Stop = StopReason::NoEmitters;
    return stats;
  }
  this->Epsilon = this->Settings.TransferTolerance * emitted;
  for (std::uint32_t root : this->Clusters->Roots())
  {
    this->Top.push_back(this->NewElement(root, -1));
  }

  std::vector<double> residuals;
  for (;;)
  {
    if (ReachedLimit(this->Iteration, this->Settings.MaxIterations, clock.Seconds(),
          this->Settings.MaxTimeSeconds, stats.Stop))
    {
      break;
    }
    for (std::int32_t i : this->Top)
    {
      this->Nodes[i].Shooters.clear();
      for (std::int32_t j : this->Top)
      {
        this->AddShooter(i, j);
      }
    }
    for (std::int32_t i : this->Top)
    {
      this->TransportLight(i, {});
    }
    double residual = 0.0;
    for (FaceClusterElement& e : this->Nodes)
    {
      e.Unshot.swap(e.Next);
      std::fill(e.Next.begin(), e.Next.end(), RGB(0.0));
      if (e.IsLeaf())
      {
        residual = std::max(residual, Magnitude(e.Unshot));
      }
    }
    ++this->Iteration;
    const double relative = residual / brightest;
    residuals.push_back(relative);
    ConvergenceRow row;
    row.Iteration = this->Iteration;
    row.TimeSeconds = clock.Seconds();
    row.UnshotPowerW = relative * emitted; // the relative residual in power units
    row.EnergyBalance = std::numeric_limits<double>::quiet_NaN();
    stats.History.Rows.push_back(row);
    if (!ReportProgress(progress, "shooting", this->Iteration, relative, this->Settings.Tolerance))
    {
      stats.Stop = StopReason::Aborted;
      break;
    }
    if (relative < this->Settings.Tolerance)
    {
      stats.Stop = StopReason::Converged;
      break;
    }
    // A steady geometric decay: the tail of the series is added at once.
    const std::size_t k = residuals.size();
    if (k >= 3 && residuals[k - 2] > 0.0 && residuals[k - 3] > 0.0)
    {
      const double r = residuals[k - 1] / residuals[k - 2];
      const double previous = residuals[k - 2] / residuals[k - 3];
      if (r < 1.0 && std::abs(r - previous) < 0.01 * r)
      {
        stats.Stop = StopReason::Converged;
        break;
      }
    }
  }
  // Aitken: the increments still to come, r / (1 - r) times the last one.
  const std::size_t k = residuals.size();
  if (stats.Stop != StopReason::Aborted && k >= 2 && residuals[k - 2] > 0.0)
  {
    const double r = residuals[k - 1] / residuals[k - 2];
    if (r > 0.0 && r < 1.0)
    {
      const double tail = r / (1.0 - r);
      for (FaceClusterElement& e : this->Nodes)
      {
        if (e.IsLeaf())
        {
          for (std::size_t a = 0; a < e.Irradiance.size(); ++a)
          {
            for (int c = 0; c < 3; ++c)
            {
              e.Irradiance[a][c] += tail * e.LastIncrement[a][c];
            }
          }
        }
      }
    }
  }

  this->Stats.Elements = this->Nodes.size();
  this->Stats.LeafElements = 0;
  std::size_t bytes = 0;
  for (const FaceClusterElement& e : this->Nodes)
  {
    this->Stats.LeafElements += e.IsLeaf() ? 1 : 0;
    bytes += sizeof(FaceClusterElement) +
      (e.PushE.capacity() + e.PushB.capacity() + e.PullB.capacity() + e.RadiosityDual.capacity() +
        e.Rule.Phi.capacity() + e.Rule.Dual.capacity() + e.Rule.Weights.capacity()) * sizeof(double) +
      (e.Rule.Points.capacity() + e.Rule.Normals.capacity()) * sizeof(Vec3) +
      (e.Unshot.capacity() + e.Next.capacity()) * sizeof(RGB) +
      (e.Irradiance.capacity() + e.LastIncrement.capacity()) * sizeof(IrradianceVector);
  }
  this->Stats.SolutionBytes = bytes;
  this->Stats.SolveSeconds = clock.Seconds();
  stats.Iterations = this->Iteration;
  stats.Elements = this->Stats.LeafElements;
  stats.Subdivisions = this->Stats.Refinements;
  stats.Links = this->Stats.Transfers;
  stats.SolveSeconds = this->Stats.SolveSeconds;
  stats.PreprocessSeconds = this->Stats.HierarchySeconds;
  return stats;
}

std::int32_t FaceClusterRadiosity::LeafOf(std::uint32_t t) const
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
  while (e >= 0 && !this->Nodes[e].IsLeaf())
  {
    const std::int32_t k0 = this->Nodes[e].Child[0];
    e = holds(this->Nodes[k0]) ? k0 : this->Nodes[e].Child[1];
  }
  return e;
}

IrradianceVector FaceClusterRadiosity::Expansion(std::int32_t e, const Vec3& x) const
{
  IrradianceVector v{};
  if (e < 0)
  {
    return v;
  }
  const FaceClusterElement& leaf = this->Nodes[e];
  const glm::dvec2 uv = glm::clamp(BoxCoordinates(leaf.Data, x), glm::dvec2(0.0), glm::dvec2(1.0));
  double phi[PolynomialBasis::MaximumSize];
  this->IrradianceBasis.Evaluate(uv.x, uv.y, phi);
  for (int a = 0; a < this->IrradianceBasis.Size(); ++a)
  {
    for (int c = 0; c < 3; ++c)
    {
      v[c] += phi[a] * leaf.Irradiance[a][c];
    }
  }
  return v;
}

namespace
{
RGB Received(const IrradianceVector& v, const Vec3& n)
{
  return RGB(std::max(glm::dot(n, v[0]), 0.0), std::max(glm::dot(n, v[1]), 0.0),
    std::max(glm::dot(n, v[2]), 0.0));
}
}

IrradianceVector FaceClusterRadiosity::IrradianceVectorAt(std::uint32_t t, const Vec3& x) const
{
  return this->Expansion(this->LeafOf(t), x);
}

RGB FaceClusterRadiosity::IrradianceAt(std::uint32_t t, const Vec3& x, const Vec3& n) const
{
  return Received(this->IrradianceVectorAt(t, x), n);
}

std::vector<std::array<double, 9>> FaceClusterRadiosity::VertexIrradianceVectors() const
{
  const Scene& scene = this->GetScene();
  std::vector<std::array<double, 9>> out(scene.Points.size(), std::array<double, 9>{});
  std::vector<int> count(scene.Points.size(), 0);
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    const std::int32_t leaf = this->LeafOf(static_cast<std::uint32_t>(t));
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t v = scene.Triangles[t].V[k];
      const IrradianceVector e = this->Expansion(leaf, scene.Points[v]);
      for (int c = 0; c < 3; ++c)
      {
        for (int d = 0; d < 3; ++d)
        {
          out[v][3 * c + d] += e[c][d];
        }
      }
      ++count[v];
    }
  }
  for (std::size_t v = 0; v < out.size(); ++v)
  {
    if (count[v] > 0)
    {
      for (double& x : out[v])
      {
        x /= count[v];
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
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    const auto id = static_cast<std::uint32_t>(t);
    const Vec3 n = scene.Normal(t);
    const Material& m = scene.Materials[t];
    const std::int32_t leaf = this->LeafOf(id);
    ElementSamples samples;
    for (int k = 0; k < 3; ++k)
    {
      samples.Corner[k] = Received(this->Expansion(leaf, scene.Vertex(t, k)), n);
    }
    samples.Centre = Received(this->Expansion(leaf, scene.Centroid(t)), n);
    const RGB h = samples.Mean();
    out.CellIrradiance.push_back(h);
    out.CellRadiosity.push_back(m.Emission + m.Reflectance * h);
    out.ElementId.push_back(leaf >= 0 ? this->Nodes[leaf].Cluster : 0u);
    out.Level.push_back(static_cast<std::uint16_t>(leaf >= 0 ? this->Nodes[leaf].Data.Depth : 0));
    out.SourceTriangle.push_back(id);
    out.Samples.push_back(samples);
    out.Normals.push_back(n);
    const double area = scene.Area(t);
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t v = scene.Triangles[t].V[k];
      out.PointIrradiance[v] += area * samples.Corner[k];
      out.PointRadiosity[v] += area * (m.Emission + m.Reflectance * samples.Corner[k]);
      weight[v] += area;
    }
  }
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
