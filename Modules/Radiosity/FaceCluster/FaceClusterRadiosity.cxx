#include "Radiosity/FaceCluster/FaceClusterRadiosity.h"
#include "Radiosity/Common/MemoryBudget.h"

#include "Radiosity/FaceCluster/FaceClusterGeometry.h"
#include "Radiosity/Common/Stopwatch.h"
#include "Radiosity/Common/ThreadLimit.h"

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
  this->Budget = ResolveMemoryBudget(settings.MemoryBudgetBytes);
  const double ne = this->IrradianceBasis.Size(), nb = this->RadiosityBasis.Size();
  this->BytesPerElement = sizeof(FaceClusterElement) +
    sizeof(double) * (ne * ne + 3 * nb * nb + nb) + sizeof(RGB) * 2 * nb + sizeof(IrradianceVector) * 2 * ne;
  if (!hierarchy)
  {
    // The hierarchy: about two clusters per input triangle (a binary tree
    // over the leaves) and the per-leaf tables.
    const double triangles = static_cast<double>(scene.Triangles.size());
    CheckMemoryBudget(triangles * (2.0 * sizeof(FaceCluster) + 5 * sizeof(std::uint32_t) + sizeof(double)),
      this->Budget, "face cluster radiosity: the hierarchy of " + FormatCount(triangles) + " triangles",
      "use fewer triangles or raise --max-memory");
  }
  this->Clusters = hierarchy ? std::move(hierarchy) : FaceClusterHierarchy::Shared(scene, settings.Clustering);
  this->Stats.HierarchySeconds = clock.Seconds();
  this->Visibility = std::make_unique<FaceClusterVisibility>(*this->Clusters);
}

std::int32_t FaceClusterRadiosity::NewElement(
  std::uint32_t cluster, std::int32_t parent, const Vec3* corners)
{
  const int ne = this->IrradianceBasis.Size(), nb = this->RadiosityBasis.Size();
  const auto id = static_cast<std::int32_t>(this->Nodes.size());
  if ((this->Nodes.size() & 4095) == 0)
  {
    CheckMemoryBudget(static_cast<double>(this->Nodes.size() + 4096) * this->BytesPerElement, this->Budget,
      "face cluster radiosity: " + std::to_string(this->Nodes.size() + 4096) + " elements",
      "lower --max-bisections (MaxBisections), raise --transfer-tolerance or use a smaller irradiance basis");
  }
  this->Nodes.emplace_back();
  FaceClusterElement& e = this->Nodes.back();
  e.Cluster = cluster;
  e.Parent = parent;
  if (corners)
  {
    const Scene& scene = this->GetScene();
    const FaceClusterElement& whole = this->Nodes[parent];
    e.Data = TriangleCluster(corners, scene.Materials[cluster], scene.ObjectIds[cluster]);
    e.Data.First = whole.Data.First;
    e.Data.Count = 1;
    e.Data.Depth = whole.Data.Depth + 1;
    e.Bisections = whole.Bisections + 1;
    std::copy(corners, corners + 3, e.Corners.begin());
  }
  else
  {
    e.Data = this->Clusters->Cluster(cluster);
    if (e.Data.IsLeaf())
    {
      const Scene& scene = this->GetScene();
      e.Corners = { scene.Vertex(cluster, 0), scene.Vertex(cluster, 1), scene.Vertex(cluster, 2) };
    }
  }
  // An input triangle's rule is MakeSurfaceRule's too (a leaf cluster).
  e.Rule = corners
    ? MakeTriangleRule(e.Corners.data(), e.Data, this->IrradianceBasis, this->Settings.Rule.Nodes)
    : MakeSurfaceRule(*this->Clusters, cluster, e.Data, this->IrradianceBasis, this->Settings.Rule.Nodes);
  e.RadiosityDual = DualWeights(e.Data, this->RadiosityBasis, e.Rule.Points, e.Rule.Weights);
  e.Unshot.assign(nb, RGB(0.0));
  e.Next.assign(nb, RGB(0.0));
  e.Irradiance.assign(ne, IrradianceVector{});
  e.LastIncrement.assign(ne, IrradianceVector{});
  if (parent < 0)
  {
    e.Unshot[0] = RGB(e.Data.EmissionMean);
    e.UnshotMin = Mean(RGB(e.Data.EmissionMin));
    e.UnshotMax = Mean(RGB(e.Data.EmissionMax));
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
    e.UnshotMin = Mean(RGB(e.Data.EmissionMin));
    e.UnshotMax = Mean(RGB(e.Data.EmissionMax));
  }
  else
  {
    e.UnshotMin = p.UnshotMin;
    e.UnshotMax = p.UnshotMax;
  }
  e.NextMin = p.NextMin;
  e.NextMax = p.NextMax;
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

bool FaceClusterRadiosity::CanSubdivide(const FaceClusterElement& e) const
{
  return !e.Data.IsLeaf() || (e.IsTriangle() && e.Bisections < this->Settings.MaxBisections && e.Data.Area > 0.0f);
}

bool FaceClusterRadiosity::CanSubdivideForLight(const FaceClusterElement& e) const
{
  const int most = std::max(this->Settings.MaxBisections, this->Settings.MaxLightBisections);
  return !e.Data.IsLeaf() || (e.IsTriangle() && e.Bisections < most && e.Data.Area > 0.0f);
}

void FaceClusterRadiosity::Subdivide(std::int32_t e)
{
  if (!this->Nodes[e].IsLeaf() ||
    !(this->CanSubdivide(this->Nodes[e]) || (this->Lights && this->Iteration == 0 && this->CanSubdivideForLight(this->Nodes[e]))))
  {
    return;
  }
  std::int32_t k0, k1;
  if (this->Nodes[e].Data.IsLeaf())
  {
    // Below the input: halve the longest edge, so that slivers become
    // rounder and no T-vertex is left inside the triangle's own parts.
    const std::array<Vec3, 3> c = this->Nodes[e].Corners;
    int longest = 0;
    for (int k = 1; k < 3; ++k)
    {
      if (glm::length(c[(k + 1) % 3] - c[k]) > glm::length(c[(longest + 1) % 3] - c[longest]))
      {
        longest = k;
      }
    }
    const Vec3& a = c[longest];
    const Vec3& b = c[(longest + 1) % 3];
    const Vec3& o = c[(longest + 2) % 3];
    const Vec3 m = 0.5 * (a + b);
    const Vec3 first[3] = { a, m, o }, second[3] = { m, b, o };
    const std::uint32_t triangle = this->Nodes[e].Cluster;
    k0 = this->NewElement(triangle, e, first);
    k1 = this->NewElement(triangle, e, second);
  }
  else
  {
    const std::uint32_t c0 = this->Nodes[e].Data.Child[0], c1 = this->Nodes[e].Data.Child[1];
    k0 = this->NewElement(c0, e);
    k1 = this->NewElement(c1, e);
  }
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
  // Bounds on the emitter's radiosity: the range over its leaves' nodes
  // (its emission's in the first shot), widened by the expansion's own.
  double higher = 0.0;
  for (std::size_t b = 1; b < emitter.Unshot.size(); ++b)
  {
    higher += std::abs(Mean(emitter.Unshot[b]));
  }
  const double mean = Mean(emitter.Unshot[0]);
  const double bMin = std::max(0.0, std::min(emitter.UnshotMin, mean - BasisBound * higher));
  const double bMax = std::max(emitter.UnshotMax, mean + BasisBound * higher);
  const Transfer t = ComputeTransfer(
    { &receiver.Data, receiver.Cluster, &receiver.Rule, this->IrradianceBasis.Size() },
    { &emitter.Data, emitter.Cluster, &emitter.Rule, this->RadiosityBasis.Size(),
      emitter.IsTriangle() ? emitter.Corners.data() : nullptr },
    emitter.Unshot, bMin, bMax, *this->Visibility, this->Settings.Rule);
  // Below the input triangles only receivers are refined, and only where
  // their basis cannot follow the irradiance (the fit error at their nodes
  // and corners, judged at the input triangle's area): an emitter's parts
  // would each cast a field no smoother across the receiver than the whole
  // triangle's, and the bounds of 3.3.2 never tighten next to a shared
  // edge. Measured in a closed room (rho 0.5) halving both ends four times
  // on the bounds: 3.3% worst error against 0.3% without halving.
  const bool clusterReceiver = !receiver.Data.IsLeaf();
  const bool clusterEmitter = !emitter.Data.IsLeaf();
  // A part's error is judged at its input triangle's area, so that halving
  // a receiver does not halve the error of its irradiance that is accepted
  // (3.3.2's delta is a power).
  const double scale = receiver.Bisections > 0 && receiver.Data.Area > 0.0f
    ? this->GetScene().Area(receiver.Cluster) / receiver.Data.Area
    : 1.0;
  const bool fitFails = scale * t.FitError > this->Epsilon;
  const bool bisect = !clusterReceiver && fitFails && this->CanSubdivide(receiver);
  if (scale * t.Error <= this->Epsilon || (!clusterReceiver && !clusterEmitter && !bisect))
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
  // A receiver whose basis cannot follow the irradiance is split whatever
  // the sizes.
  if (clusterEmitter && !bisect && !(clusterReceiver && fitFails) &&
    (!clusterReceiver || emitter.Data.Area > receiver.Data.Area))
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
  // The lights are external emitters of the first iteration (SPEC "Lights
  // and sky"): an element whose light varies over its nodes by more than the
  // transfer tolerance is subdivided, as a transfer would be, and each leaf
  // receives the lights' vector irradiance fitted at its own nodes.
  std::vector<IrradianceVector> lightAtNodes;
  if (this->Lights && this->Iteration == 0 && this->Nodes[i].IsLeaf())
  {
    double spread = 0.0;
    if (this->Nodes[i].Data.IsLeaf())
    {
      lightAtNodes = this->LightAtNodes(i, &spread);
    }
    // A cluster is always opened down to its triangles: its few nodes can
    // miss a spot's cone or a shadow altogether (a floor cluster whose nodes
    // all lay outside a spot's cone received nothing).
    const bool cluster = !this->Nodes[i].Data.IsLeaf();
    if (this->Nodes[i].IsLeaf() && (cluster || spread > this->Epsilon) &&
      this->CanSubdivideForLight(this->Nodes[i]))
    {
      this->Subdivide(i);
      lightAtNodes.clear();
    }
  }
  FaceClusterElement& e = this->Nodes[i];
  if (e.IsLeaf() && !lightAtNodes.empty())
  {
    for (std::size_t q = 0; q < e.Rule.Size(); ++q)
    {
      for (int a = 0; a < ne; ++a)
      {
        for (int c = 0; c < 3; ++c)
        {
          dE[a][c] += e.Rule.Dual[q * ne + a] * lightAtNodes[q][c];
        }
      }
    }
  }
  std::fill(e.Next.begin(), e.Next.end(), RGB(0.0));
  e.NextMin = std::numeric_limits<double>::infinity();
  e.NextMax = 0.0;
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
      RGB reflected(0.0);
      for (int c = 0; c < 3; ++c)
      {
        Vec3 atNode(0.0);
        for (int a = 0; a < ne; ++a)
        {
          atNode += rule.Phi[q * ne + a] * dE[a][c];
        }
        const double b = (1.0 - self) * e.Data.ReflectanceMean[c] * std::max(glm::dot(rule.Normals[q], atNode), 0.0);
        reflected[c] = b;
        for (int a = 0; a < nb; ++a)
        {
          e.Next[a][c] += e.RadiosityDual[q * nb + a] * b;
        }
      }
      e.NextMin = std::min(e.NextMin, Mean(reflected));
      e.NextMax = std::max(e.NextMax, Mean(reflected));
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
    p.NextMin = std::min(p.NextMin, child.NextMin);
    p.NextMax = std::max(p.NextMax, child.NextMax);
  }
}

std::vector<IrradianceVector> FaceClusterRadiosity::LightAtNodes(std::int32_t i, double* spread) const
{
  const FaceClusterElement& e = this->Nodes[i];
  std::vector<IrradianceVector> out(e.Rule.Size());
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (std::size_t q = 0; q < e.Rule.Size(); ++q)
  {
    out[q] = this->Lights->IrradianceVector(e.Rule.Points[q], e.Rule.Normals[q]);
    const double h = Mean(RGB(glm::dot(e.Rule.Normals[q], out[q][0]), glm::dot(e.Rule.Normals[q], out[q][1]),
      glm::dot(e.Rule.Normals[q], out[q][2])));
    lo = std::min(lo, h);
    hi = std::max(hi, h);
  }
  if (spread)
  {
    *spread = e.Rule.Size() > 0 ? (hi - lo) * static_cast<double>(e.Data.Area) : 0.0;
  }
  return out;
}

SolverStatistics FaceClusterRadiosity::Solve(const ProgressCallback& progress)
{
  SolverStatistics stats;
  const Stopwatch clock;
  // The thread limit applies to this solve alone (a task arena of its own).
  return RunWithThreads(this->Settings.Threads, [&]() -> SolverStatistics {
    const Scene& scene = this->GetScene();
    double emitted = 0.0, brightest = 0.0;
    for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
    {
      emitted += Mean(scene.Materials[t].Emission) * scene.Area(t);
      brightest = std::max(brightest, Mean(scene.Materials[t].Emission));
    }
    this->Lights.reset();
    if (!scene.Lighting.Empty())
    {
      this->Lights = std::make_unique<DirectLighting>(scene, this->Settings.SkySamples);
      const DirectLighting::PowerEstimate light = this->Lights->EstimatePower();
      stats.LightPowerW = light.Power;
      emitted += light.Power;
      brightest = std::max(brightest, light.PeakIrradiance);
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
      if (ReachedLimitOnAnyRank(ShareOrAlone(this->Settings.Share), this->Iteration, this->Settings.MaxIterations, clock.Seconds(),
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
        e.UnshotMin = std::isfinite(e.NextMin) ? e.NextMin : 0.0;
        e.UnshotMax = e.NextMax;
        e.NextMin = std::numeric_limits<double>::infinity();
        e.NextMax = 0.0;
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

    this->BoundLeafExpansions();
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
  });
}
} // namespace radiosity
