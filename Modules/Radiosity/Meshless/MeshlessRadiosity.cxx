#include "Radiosity/Meshless/MeshlessRadiosity.h"

#include "Radiosity/Common/ElementMesh.h"
#include "Radiosity/Common/ErrorMetrics.h"
#include "Radiosity/Common/FormFactor.h"
#include "Radiosity/Common/MemoryBudget.h"
#include "Radiosity/Common/Morton.h"
#include "Radiosity/Common/MeshProbeTracker.h"
#include "Radiosity/Common/SceneAnalysis.h"
#include "Radiosity/Common/Stopwatch.h"
#include "Radiosity/Common/ThreadLimit.h"
#include "Radiosity/Common/Visibility.h"
#include "Radiosity/Meshless/BounceSeries.h"
#include "Radiosity/Meshless/MeshlessGather.h"
#include "Radiosity/Meshless/MeshlessNeighbourhoods.h"
#include "Radiosity/Meshless/ReceiverOracle.h"
#include "Radiosity/Meshless/MeshlessTransfer.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace radiosity
{

/// One term of the Neumann series: point values where computed, coefficients.
struct MeshlessRadiosity::Bounce
{
  std::vector<RGB> Value;
  std::vector<unsigned char> Computed;
  std::unique_ptr<ShepardField> Field;
  double Magnitude = 0.0; ///< sum of the coarsest level's values (largest channel)
  /// The receivers in the order their coefficients were set (each sorted by
  /// index, so by level): the fit is linear in the values, and replaying it
  /// with other values gives their approximation on the same functions.
  std::vector<std::vector<std::uint32_t>> Batches;
};

namespace
{
/// Eq. 10 for receivers sorted by level: each coefficient is its point's
/// value less the approximation of the coarser levels there.
void FitBatch(const PointHierarchy& points, const std::vector<std::uint32_t>& set,
  const std::vector<RGB>& value, ShepardField& field, const MeshlessNeighbourhoods* lists = nullptr)
{
  const auto& all = points.Points();
  std::vector<RGB>& alpha = field.Coefficients();
  std::size_t begin = 0;
  while (begin < set.size())
  {
    const int level = all[set[begin]].Level;
    std::size_t end = begin;
    while (end < set.size() && all[set[end]].Level == level)
    {
      ++end;
    }
    tbb::parallel_for(begin, end, [&](std::size_t k) {
      const std::uint32_t j = set[k];
      const MeshlessPoint& p = all[j];
      if (level == 0)
      {
        alpha[j] = value[j];
      }
      else if (lists)
      {
        // ShepardField::Evaluate's sum, from the listed basis values.
        RGB f(0.0);
        for (const auto& [i, w] : lists->Fit(j))
        {
          f += w * alpha[i];
        }
        alpha[j] = value[j] - f;
      }
      else
      {
        alpha[j] = value[j] - field.Evaluate(p.Position, p.Normal, p.Group, level - 1);
      }
    });
    begin = end;
  }
}
}

MeshlessRadiosity::MeshlessRadiosity(const Scene& scene, const MeshlessOptions& options)
  : SourceScene(&scene)
  , Settings(options)
{
  this->FindEmitters();
}

void MeshlessRadiosity::FindEmitters()
{
  this->Emitters.clear();
  const Scene& scene = *this->SourceScene;
  for (std::uint32_t t = 0; t < scene.Triangles.size(); ++t)
  {
    if (MaxComponent(scene.Materials[t].Emission) > 0)
    {
      this->Emitters.push_back(t);
    }
  }
}

MeshlessRadiosity::~MeshlessRadiosity() = default;

RGB MeshlessRadiosity::DirectAt(std::uint32_t receiver) const
{
  const MeshlessPoint& p = this->Hierarchy->Points()[receiver];
  const Vec3 origin = p.Position + this->Rays->Offset() * p.Normal;
  const int n = std::max(1, this->Settings.EmitterSamples);
  const int side = std::max(1, static_cast<int>(std::lround(std::sqrt(static_cast<double>(n)))));
  RGB e(0.0);
  Vec3 from[64], to[64];
  unsigned char visible[64];
  for (std::uint32_t t : this->Emitters)
  {
    const Vec3 a = this->SourceScene->Vertex(t, 0), b = this->SourceScene->Vertex(t, 1),
               c = this->SourceScene->Vertex(t, 2);
    const Vec3 emitterNormal = this->SourceScene->Normal(t);
    // A receiver on a surface coplanar with the emitter (the emitter itself,
    // a neighbour) sees none of it: the contour integral around a point
    // inside the polygon would count the whole hemisphere instead. A receiver
    // on another surface that touches the emitter's plane (a floor at the foot
    // of an emitting wall) takes the limit from the emitter's front.
    const double height = glm::dot(p.Position - a, emitterNormal);
    Vec3 x = p.Position;
    if (height <= this->Rays->Offset())
    {
      if (glm::dot(p.Normal, emitterNormal) > 1.0 - 1e-6 || height < -this->Rays->Offset())
      {
        continue;
      }
      x += (this->Rays->Offset() - height) * emitterNormal;
    }
    const double f = PointToTriangleFormFactor(x, p.Normal, a, b, c);
    if (!(f > 0))
    {
      continue;
    }
    // Stratified points strictly inside the emitter (the unit square mapped
    // onto the triangle by the square-root map): a point on an edge shared
    // with a neighbour's plane would be hidden by that neighbour.
    int count = 0;
    for (int i = 0; i < side && count < 64; ++i)
    {
      for (int j = 0; j < side && count < 64; ++j)
      {
        const double sq = std::sqrt((i + 0.5) / side), t2 = (j + 0.5) / side;
        // The target sits just in front of the emitter: at grazing angles a
        // segment ending on the plane itself would hit it in float precision.
        from[count] = origin;
        to[count++] = (1.0 - sq) * a + sq * (1.0 - t2) * b + sq * t2 * c +
          this->Rays->Offset() * emitterNormal;
      }
    }
    this->Shadows->TestSegments(from, to, static_cast<std::size_t>(count), visible);
    int seen = 0;
    for (int k = 0; k < count; ++k)
    {
      seen += visible[k];
    }
    e += f * (static_cast<double>(seen) / count) * this->SourceScene->Materials[t].Emission;
  }
  if (this->Lights)
  {
    // Punctual lights exactly (one shadow ray each), the sky by its
    // quadrature; kept for the lights' own fit (KeepDirect).
    const RGB light = this->SkyMaskWords > 0 && this->Lights->HasSky()
      ? this->Lights->Punctual(p.Position, p.Normal) + this->CachedSky(receiver)
      : this->Lights->Irradiance(p.Position, p.Normal);
    if (receiver < this->LightValue.size())
    {
      this->LightValue[receiver] = light;
      this->LightKnown[receiver] = 1;
    }
    e += light;
  }
  return e;
}

RGB MeshlessRadiosity::Gather(std::uint32_t receiver, const ShepardField& previous) const
{
  const std::vector<RGB>& alpha = previous.Coefficients();
  RGB sum(0.0);
  GatherWeights(*this->SourceScene, *this->Hierarchy, previous, *this->Rays, this->Settings, receiver,
    [&](std::uint32_t j, double w, const RGB& reflectance) { sum += w * reflectance * alpha[j]; });
  return sum;
}

template <typename ValueAt>
void MeshlessRadiosity::Refine(Bounce& out, const ValueAt& valueAt)
{
  const PointHierarchy& points = *this->Hierarchy;
  const auto& all = points.Points();
  const int levels = points.NumberOfLevels();
  const double threshold = this->Settings.VariationThreshold * this->Scale;
  out.Value.assign(all.size(), RGB(0.0));
  out.Computed.assign(all.size(), 0);
  out.Field = std::make_unique<ShepardField>(points);
  std::vector<RGB>& alpha = out.Field->Coefficients();

  // Point values of a set of receivers in parallel, then their coefficients
  // level by level (a difference to the coarser levels, eq. 10).
  bool pastLimit = false;
  auto computeChunk = [&](const std::vector<std::uint32_t>& set) {
    // This rank's share of the gathers; every rank then holds every value.
    WorkShare& share = ShareOrAlone(this->Settings.Share);
    std::vector<RGB> values(set.size());
    const auto mine = share.Range(set.size());
    tbb::parallel_for(mine.first, mine.second, [&](std::size_t k) { values[k] = valueAt(set[k]); });
    share.Combine(values.data(), values.size());
    for (std::size_t k = 0; k < set.size(); ++k)
    {
      out.Value[set[k]] = values[k];
    }
    FitBatch(points, set, out.Value, *out.Field, this->Lists.get());
    for (std::uint32_t j : set)
    {
      out.Computed[j] = 1;
      this->Touched[j] = 1;
    }
    out.Batches.push_back(set);
    this->Stats.GatherOperations += set.size();
    // One rank's clock stops every rank after the same chunk.
    pastLimit = share.AnyRank(this->HasDeadline && std::chrono::steady_clock::now() >= this->Deadline);
  };
  auto compute = [&](std::vector<std::uint32_t>& set) {
    std::sort(set.begin(), set.end()); // sorted by index is sorted by level
    set.erase(std::unique(set.begin(), set.end()), set.end());
    // In chunks (a coefficient depends on the coarser levels only, eq. 10:
    // the same fit): past the time limit the finer points left are not
    // computed and keep the coarser levels' fit, while the coarsest level is
    // always whole. A wave of a large scene can take far longer than the
    // limit (30 s of gathers on a 110k-triangle engine). Always in chunks,
    // limit or not: MPI ranks with different limits make the same exchanges.
    constexpr std::size_t Chunk = 1024;
    std::vector<std::uint32_t> chunk;
    for (std::size_t begin = 0; begin < set.size(); begin += Chunk)
    {
      if (pastLimit && points.Points()[set[begin]].Level > 0)
      {
        set.resize(begin);
        return;
      }
      chunk.assign(set.begin() + begin, set.begin() + std::min(set.size(), begin + Chunk));
      computeChunk(chunk);
    }
  };

  std::vector<std::uint32_t> wave;
  for (std::size_t j = points.LevelBegin(0); j < points.LevelEnd(0); ++j)
  {
    wave.push_back(static_cast<std::uint32_t>(j));
  }
  // The oracle's neighbourhoods: listed (a relight), or searched in the
  // point index, facing the point's side.
  const MeshlessNeighbourhoods* lists = this->Lists.get();
  const auto search = [&](int level, std::uint32_t j, const Vec3& at, double within, std::vector<std::uint32_t>& into) {
    thread_local std::vector<std::uint32_t> near;
    near.clear();
    points.Supporting(level, all[j].Group, at, near);
    for (std::uint32_t k : near)
    {
      if (glm::dot(all[k].Normal, all[j].Normal) > 0 && (within <= 0 || glm::length(all[k].Position - at) < within))
      {
        into.push_back(k);
      }
    }
  };
  RunReceiverOracle(std::move(wave), threshold, out.Value, alpha, out.Computed, compute,
    [&](std::uint32_t j, std::vector<std::uint32_t>& into) {
      if (lists)
      {
        into.insert(into.end(), lists->Neighbours(j).begin(), lists->Neighbours(j).end());
        return;
      }
      search(0, j, all[j].Position, 0.0, into);
    },
    [&](std::uint32_t k, std::vector<std::uint32_t>& into) {
      if (pastLimit)
      {
        return;
      }
      if (lists)
      {
        into.insert(into.end(), lists->Children(k).begin(), lists->Children(k).end());
      }
      else if (all[k].Level + 1 < levels)
      {
        search(all[k].Level + 1, k, all[k].Position, all[k].Radius, into);
      }
    },
    [&](std::uint32_t c, std::vector<std::uint32_t>& into) {
      if (lists)
      {
        into.insert(into.end(), lists->Ancestors(c).begin(), lists->Ancestors(c).end());
        return;
      }
      for (int coarser = 1; coarser < all[c].Level; ++coarser)
      {
        search(coarser, c, all[c].Position, 0.0, into);
      }
    });
  out.Magnitude = 0.0;
  for (std::size_t j = points.LevelBegin(0); j < points.LevelEnd(0); ++j)
  {
    out.Magnitude += MaxComponent(out.Value[j]);
  }
}

void MeshlessRadiosity::DirectLight(Bounce& out)
{
  // The thresholds are relative to the direct light's scale, known only from
  // the coarsest level: compute it first.
  const PointHierarchy& points = *this->Hierarchy;
  this->Scale = 0.0;
  this->LightValue.assign(this->Lights ? points.Points().size() : 0, RGB(0.0));
  this->LightKnown.assign(this->LightValue.size(), 0);
  std::vector<RGB> coarse(points.LevelEnd(0) - points.LevelBegin(0));
  tbb::parallel_for(std::size_t(0), coarse.size(), [&](std::size_t k) {
    coarse[k] = this->DirectAt(static_cast<std::uint32_t>(points.LevelBegin(0) + k));
  });
  for (const RGB& c : coarse)
  {
    this->Scale = std::max(this->Scale, MaxComponent(c));
  }
  this->Refine(out, [&](std::uint32_t j) {
    return j < points.LevelEnd(0) ? coarse[j - points.LevelBegin(0)] : this->DirectAt(j);
  });
}

void MeshlessRadiosity::KeepDirect(const Bounce& direct)
{
  const PointHierarchy& points = *this->Hierarchy;
  this->Direct = std::make_unique<ShepardField>(points);
  this->Direct->Coefficients() = direct.Field->Coefficients();
  this->Solution->Coefficients() = direct.Field->Coefficients();
  this->LightFit.reset();
  if (!this->Lights)
  {
    return;
  }
  // The lights' share of the direct field: the same fit replayed with their
  // values alone at the same points (the direct field itself when no
  // triangle emits).
  this->LightFit = std::make_unique<ShepardField>(points);
  if (this->Emitters.empty())
  {
    this->LightFit->Coefficients() = direct.Field->Coefficients();
    return;
  }
  std::vector<RGB> value(points.Points().size(), RGB(0.0));
  for (const std::vector<std::uint32_t>& set : direct.Batches)
  {
    tbb::parallel_for(std::size_t(0), set.size(), [&](std::size_t k) {
      const std::uint32_t j = set[k];
      const MeshlessPoint& p = points.Points()[j];
      // Another rank's gathers were not evaluated here.
      value[j] = this->LightKnown[j] ? this->LightValue[j] : this->Lights->Irradiance(p.Position, p.Normal);
    });
    FitBatch(points, set, value, *this->LightFit, this->Lists.get());
  }
}

double MeshlessRadiosity::ComputeDirect()
{
  Bounce direct;
  this->DirectLight(direct);
  this->KeepDirect(direct);
  return direct.Magnitude;
}

RGB MeshlessRadiosity::CachedSky(std::uint32_t j) const
{
  const MeshlessPoint& p = this->Hierarchy->Points()[j];
  std::uint64_t* mask = this->SkyMask.data() + j * this->SkyMaskWords;
  if (!this->SkyKnown[j])
  {
    this->Lights->SkyVisibility(p.Position, p.Normal, mask);
    this->SkyKnown[j] = 1;
    this->SkyMomentsKnown[j] = 0;
  }
  // The moments hold for every sky of the Up they were taken with
  // (Relight forgets them when Up changes).
  if (!this->SkyMomentsKnown[j])
  {
    this->SkyMoment[j] = this->Lights->SkyMomentsOf(p.Normal, mask);
    this->SkyMomentsKnown[j] = 1;
  }
  return this->Lights->SkyIrradianceFromMoments(this->SkyMoment[j]);
}

double MeshlessRadiosity::CoarseLightIrradiance() const
{
  const PointHierarchy& points = *this->Hierarchy;
  double light = 0.0;
  for (std::size_t j = points.LevelBegin(0); j < points.LevelEnd(0); ++j)
  {
    const MeshlessPoint& p = points.Points()[j];
    light += Mean(this->LightKnown[j] ? this->LightValue[j] : this->Lights->Irradiance(p.Position, p.Normal));
  }
  return light;
}

void MeshlessRadiosity::ComputeBounce(const ShepardField& previous, Bounce& out)
{
  this->Refine(out, [&](std::uint32_t j) { return this->Gather(j, previous); });
}

RGB MeshlessRadiosity::IrradianceAt(const Vec3& x, const Vec3& n, std::uint32_t triangle) const
{
  return this->ExactLightsAt(x, this->SourceScene->Centroid(triangle), n, triangle);
}

RGB MeshlessRadiosity::ExactLightsAt(const Vec3& x, const Vec3& inner, const Vec3& n, std::uint32_t triangle) const
{
  if (!this->Solution)
  {
    return RGB(0.0); // no emitter, or aborted before the points were placed: the zero solution
  }
  const auto group = static_cast<std::uint32_t>(this->SourceScene->ObjectIds[triangle]);
  if (this->LightFit)
  {
    // The lights and the sky exact at x (their rays from inside the
    // triangle, DirectLighting::VisibilityPoint), the field carrying the rest.
    return NonNegative(this->Solution->Evaluate(x, n, group) - this->LightFit->Evaluate(x, n, group)) +
      this->Lights->IrradianceSeenFrom(x, this->Lights->VisibilityPoint(x, inner), n);
  }
  return NonNegative(this->Solution->Evaluate(x, n, group));
}

namespace
{
/// The leaves of `mesh` (those `evaluated` marks, all when empty) in tiles
/// of at most `size` neighbours of one object: sorted by object, then
/// along a Morton curve of their centroids. Returns the tiles' starts into
/// `order` (one past the last at the end).
std::vector<std::size_t> Tiles(const ElementMesh& mesh, const Scene& scene,
  const std::vector<std::uint32_t>& leaves, const std::vector<char>& evaluated, std::size_t size,
  std::vector<std::uint32_t>& order)
{
  Vec3 low, high;
  scene.BoundingBox(low, high);
  const Vec3 extent = glm::max(high - low, Vec3(1e-300));
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
  keyed.reserve(leaves.size());
  for (std::size_t i = 0; i < leaves.size(); ++i)
  {
    if (evaluated.empty() || evaluated[i])
    {
      keyed.emplace_back(Morton((mesh[leaves[i]].Centroid - low) / extent), leaves[i]);
    }
  }
  const auto object = [&](std::uint32_t leaf) { return scene.ObjectIds[mesh[leaf].Source]; };
  std::sort(keyed.begin(), keyed.end(), [&](const auto& a, const auto& b) {
    const auto oa = object(a.second), ob = object(b.second);
    return oa != ob ? oa < ob : a.first < b.first;
  });
  order.clear();
  std::vector<std::size_t> starts;
  for (std::size_t i = 0; i < keyed.size(); ++i)
  {
    if (starts.empty() || i - starts.back() == size || object(keyed[i].second) != object(order.back()))
    {
      starts.push_back(i);
    }
    order.push_back(keyed[i].second);
  }
  starts.push_back(order.size());
  return starts;
}
}

SolutionMesh MeshlessRadiosity::SampledSurface(const TileSampler& value, const std::vector<char>* keep) const
{
  const Scene& scene = *this->SourceScene;
  const double diagonal = scene.Diagonal();
  ElementMesh mesh(scene, 1e300, this->Settings.SurfaceElementSize * diagonal, 12);
  const std::vector<std::uint32_t> leaves = mesh.Leaves();
  if (!this->Solution)
  {
    return ExtractSolution(mesh); // the zero solution (no emitter, or aborted before placement)
  }
  // With `keep`: the kept triangles' elements and the elements that share a
  // point with them (a vertex's value is the area-weighted mean of every
  // element around it); the others stay zero.
  std::vector<char> evaluated;
  if (keep)
  {
    std::vector<char> marked(mesh.Points().size(), 0);
    for (std::uint32_t l : leaves)
    {
      if ((*keep)[mesh[l].Source])
      {
        for (std::uint32_t v : mesh[l].V)
        {
          marked[v] = 1;
        }
      }
    }
    evaluated.assign(leaves.size(), 0);
    for (std::size_t i = 0; i < leaves.size(); ++i)
    {
      const Element& el = mesh[leaves[i]];
      evaluated[i] = (*keep)[el.Source] || marked[el.V[0]] || marked[el.V[1]] || marked[el.V[2]];
    }
  }
  std::vector<std::uint32_t> order;
  const std::vector<std::size_t> tiles = Tiles(mesh, scene, leaves, evaluated, 32, order);
  tbb::parallel_for(std::size_t(0), tiles.size() - 1, [&](std::size_t t) {
    const std::size_t first = tiles[t], count = tiles[t + 1] - first;
    thread_local std::vector<Vec3> x, n;
    thread_local std::vector<RGB> h;
    x.resize(4 * count);
    n.resize(count);
    h.resize(4 * count);
    for (std::size_t e = 0; e < count; ++e)
    {
      const std::uint32_t leaf = order[first + e];
      const Element& el = mesh[leaf];
      // Corners just inside the element: a corner on a neighbour's plane
      // would take that neighbour's basis functions at a grazing normal.
      for (int k = 0; k < 3; ++k)
      {
        x[4 * e + k] = mesh.Corner(leaf, k) + 1e-7 * (el.Centroid - mesh.Corner(leaf, k));
      }
      x[4 * e + 3] = el.Centroid;
      n[e] = el.Normal;
    }
    value(x.data(), n.data(), order.data() + first, count, mesh, h.data());
    for (std::size_t e = 0; e < count; ++e)
    {
      // The finer levels carry signed residuals: beside a sharp shadow their
      // sum can dip below zero (-0.039 of a point light's peak on assimp's
      // Wuson), which no irradiance does.
      Element& el = mesh[order[first + e]];
      el.Irradiance.Corner = { NonNegative(h[4 * e]), NonNegative(h[4 * e + 1]), NonNegative(h[4 * e + 2]) };
      el.Irradiance.Centre = NonNegative(h[4 * e + 3]);
    }
  });
  return ExtractSolution(mesh);
}

SolutionMesh MeshlessRadiosity::Surface(const std::vector<char>* keep) const
{
  // A tile's samples from one search of the point index per level
  // (ShepardField::EvaluateTile), not one per sample.
  return this->SampledSurface(
    [this](const Vec3* x, const Vec3* n, const std::uint32_t* leaves, std::size_t count,
      const ElementMesh& mesh, RGB* h) {
      const auto group = static_cast<std::uint32_t>(this->SourceScene->ObjectIds[mesh[leaves[0]].Source]);
      this->Solution->EvaluateTile(x, n, count, 4, group, h);
    },
    keep);
}

SolutionMesh MeshlessRadiosity::GatherSurface() const
{
  return this->SampledSurface([this](const Vec3* x, const Vec3* n, const std::uint32_t* leaves,
                                std::size_t count, const ElementMesh& mesh, RGB* h) {
    for (std::size_t e = 0; e < count; ++e)
    {
      const Element& el = mesh[leaves[e]];
      for (std::size_t k = 0; k < 4; ++k)
      {
        h[4 * e + k] = this->ExactLightsAt(x[4 * e + k], el.Centroid, n[e], el.Source);
      }
    }
  });
}

std::vector<RGB> MeshlessRadiosity::Evaluate(const std::vector<Probe>& probes) const
{
  return EvaluateOnNearestTriangles(*this->SourceScene, probes,
    [this](std::uint32_t t, const Vec3& x, const Vec3& n) { return this->IrradianceAt(x, n, t); },
    this->Rays.get()); // over every triangle; null before a solve (then built there)
}

namespace
{
// Bytes per point: the point, its coefficients in the solution, the direct
// field and the two live bounces, its k-d tree entry and placement grid cell.
constexpr double BytesPerMeshlessPoint = sizeof(MeshlessPoint) + 4 * 2 * sizeof(RGB) + 32.0 + 16.0;
}

SolverStatistics MeshlessRadiosity::Solve(const ProgressCallback& progress)
{
  SolverStatistics stats;
  const Stopwatch clock;
  this->HasDeadline = this->Settings.MaxTimeSeconds > 0;
  this->Deadline = std::chrono::steady_clock::now() +
    std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(this->HasDeadline ? this->Settings.MaxTimeSeconds : 0.0));
  struct EndOfSolve // no deadline outside Solve (a relight has none)
  {
    bool& Flag;
    ~EndOfSolve() { this->Flag = false; }
  } endOfSolve{ this->HasDeadline };
  // The thread limit applies to this solve alone (a task arena of its own).
  return RunWithThreads(this->Settings.Threads, [&]() -> SolverStatistics {
    const Scene& scene = *this->SourceScene;
    double emitted = 0.0, area = 0.0;
    for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
    {
      emitted += Mean(scene.Materials[t].Emission) * scene.Area(t);
      area += scene.Area(t);
    }
    stats.EmittedPowerW = emitted;
    if (!(emitted > 0.0) && scene.Lighting.Empty())
    {
      stats.Stop = StopReason::NoEmitters;
      return stats;
    }
    auto report = [&](const char* phase, long long iteration, double residual) {
      return ReportProgress(progress, phase, iteration, residual, this->Settings.Tolerance);
    };
    if (!report("placing points", 0, 1.0))
    {
      stats.Stop = StopReason::Aborted;
      return stats;
    }
    const double pointBound = MaxPoissonDiskPoints(scene, this->Settings.Placement);
    CheckMemoryBudget(pointBound * BytesPerMeshlessPoint, ResolveMemoryBudget(this->Settings.MemoryBudgetBytes),
      "meshless radiosity: up to " + FormatCount(pointBound) + " points",
      "raise --point-radius (PointRadius) or lower --point-levels (PointLevels)");
    this->Rays = std::make_unique<Visibility>(scene, Visibility::AllTriangles(scene));
    // Only what can occlude casts shadows (SceneAnalysis): no rays, and no
    // grazing-angle misses, inside a convex enclosure.
    this->Shadows = std::make_unique<Visibility>(scene, AnalyzeScene(scene).CanOcclude);
    if (!scene.Lighting.Empty())
    {
      this->Lights = std::make_unique<DirectLighting>(scene, this->Settings.SkySamples);
    }
    try
  {
    this->Hierarchy = std::make_unique<PointHierarchy>(scene, this->Settings.Placement, this->Rays.get(),
      [&]() { return report("placing points", 0, 1.0); });
  }
  catch (const PlacementAborted&)
  {
    stats.Stop = StopReason::Aborted;
    return stats;
  }
    const PointHierarchy& points = *this->Hierarchy;
    this->Touched.assign(points.Points().size(), 0);
    this->Stats.SamplesGenerated = points.Points().size();
    this->Stats.Levels = points.NumberOfLevels();
    this->Stats.CoarsestSamples = points.NumberOfLevels() > 0 ? points.LevelEnd(0) : 0;
    this->Stats.PlacementSeconds = clock.Seconds();
    this->Solution = std::make_unique<ShepardField>(points);
    if (points.Points().empty() || points.LevelEnd(0) == 0)
    {
      throw SceneError("meshless radiosity: no points could be placed on the surfaces");
    }

    if (!report("direct light", 0, 1.0))
    {
      stats.Stop = StopReason::Aborted;
      return stats;
    }
    Bounce direct;
    this->DirectLight(direct);
    this->KeepDirect(direct);
    this->Stats.DirectSeconds = clock.Seconds() - this->Stats.PlacementSeconds;
    const double base = std::max(direct.Magnitude, 1e-300);
    const double perPoint = area / static_cast<double>(points.LevelEnd(0));
    if (this->Lights)
    {
      // The lights' power reaching the surfaces, from the coarsest level's
      // direct values (each point stands for area / points of surface).
      stats.LightPowerW = this->CoarseLightIrradiance() * perPoint;
      stats.EmittedPowerW += stats.LightPowerW;
      if (!(stats.EmittedPowerW > 0.0))
      {
        stats.Stop = StopReason::NoEmitters;
        return stats;
      }
    }

    auto row = [&](long long iteration, double remaining) {
      ConvergenceRow r;
      r.Iteration = iteration;
      r.TimeSeconds = clock.Seconds();
      r.UnshotPowerW = remaining * perPoint;
      r.EnergyBalance = std::numeric_limits<double>::quiet_NaN();
      if (!this->Settings.ErrorProbes.empty() &&
        this->Settings.ErrorReference.size() == this->Settings.ErrorProbes.size())
      {
        const ErrorFigures e = RelativeErrors(this->Evaluate(this->Settings.ErrorProbes), this->Settings.ErrorReference);
        r.RmsError = e.Rms;
        r.MaxRelError = e.Max;
      }
      stats.History.Rows.push_back(r);
    };
    row(0, direct.Magnitude);

    std::unique_ptr<Bounce> previous = std::make_unique<Bounce>(std::move(direct));
    BounceSeries series;
    stats.Stop = StopReason::IterationLimit;
    for (int bounce = 1; bounce <= this->Settings.MaxBounces; ++bounce)
    {
      auto next = std::make_unique<Bounce>();
      this->ComputeBounce(*previous->Field, *next);
      std::vector<RGB>& b = this->Solution->Coefficients();
      const std::vector<RGB>& add = next->Field->Coefficients();
      // Aitken: a steady ratio makes the rest of the series geometric.
      const BounceSeries::Step step = series.Next(previous->Magnitude, next->Magnitude);
      const bool steady = step.Steady;
      for (std::size_t j = 0; j < b.size(); ++j)
      {
        b[j] += step.Gain * add[j];
      }
      row(bounce, step.Remaining);
      stats.Iterations = bounce;
      const double relative = next->Magnitude / base;
      if (!report("bounces", bounce, relative))
      {
        stats.Stop = StopReason::Aborted;
        break;
      }
      if (steady || relative <= this->Settings.Tolerance)
      {
        stats.Stop = StopReason::Converged;
        break;
      }
      // One rank's clock stops every rank at the same bounce.
      if (ShareOrAlone(this->Settings.Share).AnyRank(
            this->Settings.MaxTimeSeconds > 0 && clock.Seconds() >= this->Settings.MaxTimeSeconds))
      {
        stats.Stop = StopReason::TimeLimit;
        break;
      }
      previous = std::move(next);
    }
    this->Stats.BounceSeconds = clock.Seconds() - this->Stats.PlacementSeconds - this->Stats.DirectSeconds;
    this->Stats.SamplesGatheredTo = static_cast<std::size_t>(std::count(this->Touched.begin(), this->Touched.end(), 1));
    this->Stats.VisibilityRays = this->Rays->RaysCast() + this->Shadows->RaysCast();
    this->Stats.MemoryBytes = points.Points().size() * (sizeof(MeshlessPoint) + 3 * sizeof(RGB) + 2);
    stats.Elements = points.Points().size();
    stats.RaysCast = this->Stats.VisibilityRays;
    stats.SolveSeconds = clock.Seconds();
    stats.PreprocessSeconds = this->Stats.PlacementSeconds;
    return stats;
  });
}
} // namespace radiosity
