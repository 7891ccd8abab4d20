#include "Radiosity/Hierarchical/HierarchicalRadiosity.h"

#include "Radiosity/Common/ErrorMetrics.h"
#include "Radiosity/Common/Stopwatch.h"
#include "Radiosity/Common/ThreadLimit.h"
#include "Radiosity/Common/FormFactor.h"
#include "Radiosity/Common/MemoryBudget.h"
#include "Radiosity/Common/MeshProbeTracker.h"
#include "Radiosity/Hierarchical/ClusterLinks.h"
#include "Radiosity/Hierarchical/HierarchicalNodeRules.h"
#include "Radiosity/Common/Visibility.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace radiosity
{
namespace
{

using hierarchical::At;
using hierarchical::RuleA;

// Bytes per link while links are made: the pending pair, ComputeLinks'
// result (the link and its blocker vector) and the link kept, whose list
// grows by doubling (1.5 times its size on average); per node: the quadtree
// element with its pool point and midpoint entry, and the solver's five
// per-node arrays. Measured: the sphere interior's 1.64 million links
// (1,280 triangles) raise the peak resident memory by 183 MB, 112 bytes each.
constexpr double BytesPerLink = 8.0 + 32.0 + 24.0 + 1.5 * 32.0;
constexpr double NodeBytes = sizeof(Element) + 24.0 + 48.0 + 4 * sizeof(RGB) + sizeof(double);
} // namespace

double HierarchicalRadiosity::BytesPerNode()
{
  return NodeBytes;
}

HierarchicalRadiosity::HierarchicalRadiosity(const Scene& scene, const HierarchicalOptions& options)
  : SourceScene(scene)
  , Settings(options)
  , SceneInfo(AnalyzeScene(scene))
{
  // Every facing pair of input triangles is linked before any refinement:
  // refuse a scene whose initial links do not fit before making them.
  // Clustered, the first links are between the objects' cluster roots
  // (checked in InitialClusterLinks).
  this->Budget = ResolveMemoryBudget(this->Settings.MemoryBudgetBytes);
  const std::size_t n = scene.Triangles.size();
  this->UseClusters = this->Settings.Clustering == HierarchicalClustering::On ||
    (this->Settings.Clustering == HierarchicalClustering::Auto && n > this->Settings.ClusterAbove);
  const double initial = this->UseClusters ? 0.0 : FacingTrianglePairs(scene);
  CheckMemoryBudget(initial * BytesPerLink + static_cast<double>(n) * NodeBytes, this->Budget,
    "hierarchical radiosity: the initial links between every facing pair of the " + std::to_string(n) +
      " input triangles (" + FormatCount(initial) + " links, before any refinement)",
    "plain hierarchical radiosity links every pair of input triangles; for this many, use "
    "--method facecluster or --method meshless (clustered), or fewer triangles");
  this->LinkCapacity = this->Budget > 0 ? static_cast<std::size_t>(std::min(this->Budget / BytesPerLink, 1e18))
                                        : std::numeric_limits<std::size_t>::max();
  this->NodeCapacity = this->Budget > 0 ? static_cast<std::size_t>(std::min(this->Budget / NodeBytes, 1e18))
                                        : std::numeric_limits<std::size_t>::max();
  this->Rays = std::make_unique<Visibility>(scene, this->SceneInfo.CanOcclude);
  // Roots only: one node per input triangle, split where the links ask.
  this->Elements = std::make_unique<ElementMesh>(scene, 1e300, 1e300, 0);
  const double diag = this->SceneInfo.Diagonal > 0 ? this->SceneInfo.Diagonal : 1.0;
  this->MinEdge = this->Settings.MinElementSize * diag;
  this->PlaneTolerance = 1e-9 * diag;
  // Lights count in the ambient estimate with the irradiance they bring
  // (at each triangle's centroid): a scene lit only by lights gets the same
  // relative tolerance as one lit by emitters.
  std::vector<double> lightAtRoot(scene.Triangles.size(), 0.0);
  if (!scene.Lighting.Empty())
  {
    this->Lights = std::make_unique<DirectLighting>(scene, this->Settings.SkySamples);
    tbb::parallel_for(std::size_t(0), scene.Triangles.size(), [&](std::size_t t) {
      lightAtRoot[t] = MaxComponent(this->Lights->Irradiance(scene.Centroid(t), scene.Normal(t)));
    });
  }
  double power = 0.0, area = 0.0, reflected = 0.0;
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    const double a = scene.Area(t);
    power += (MaxComponent(scene.Materials[t].Emission) + lightAtRoot[t]) * a;
    reflected += MaxComponent(scene.Materials[t].Reflectance) * a;
    area += a;
  }
  area = std::max(area, 1e-300);
  const double ambient = power / area / (1.0 - reflected / area);
  this->Epsilon = this->Settings.LinkTolerance > 0
    ? this->Settings.LinkTolerance
    : this->Settings.RelativeLinkTolerance * ambient;
  this->NodeRadiosity.resize(n);
  this->NodeGathered.assign(n, RGB(0.0));
  this->NodeGatheredVisible.assign(n, RGB(0.0));
  this->Normalization.assign(n, 1.0);
  this->NodeIrradiance.assign(n, RGB(0.0));
  this->NodeDirect.assign(n, RGB(0.0));
  for (std::uint32_t e = 0; e < n; ++e)
  {
    this->NodeRadiosity[e] = this->Elements->MaterialOf(e).Emission;
    this->Roots.push_back(e);
  }
}

HierarchicalRadiosity::~HierarchicalRadiosity() = default;

TriangleCorners HierarchicalRadiosity::Corners(std::uint32_t e) const
{
  const ElementMesh& mesh = *this->Elements;
  return { mesh.Corner(e, 0), mesh.Corner(e, 1), mesh.Corner(e, 2) };
}

double HierarchicalRadiosity::FormFactorEstimate(std::uint32_t from, std::uint32_t to) const
{
  const TriangleCorners a = this->Corners(from);
  const TriangleCorners b = this->Corners(to);
  const Vec3& n = (*this->Elements)[from].Normal;
  double f = 0.0;
  for (const auto& w : RuleA)
  {
    f = std::max(f, PointToPolygonFormFactor(At(a, w), n, b.data(), 3));
  }
  return f;
}

bool HierarchicalRadiosity::Splittable(std::uint32_t e) const
{
  return this->Elements->LongestEdge(e) > this->MinEdge;
}

std::uint32_t HierarchicalRadiosity::Children(std::uint32_t e)
{
  ElementMesh& mesh = *this->Elements;
  if (!mesh[e].IsLeaf())
  {
    return static_cast<std::uint32_t>(mesh[e].FirstChild);
  }
  if (mesh.Elements().size() + 4 > this->NodeCapacity)
  {
    CheckMemoryBudget(static_cast<double>(mesh.Elements().size() + 4) * NodeBytes +
        static_cast<double>(this->LinkList.size()) * BytesPerLink,
      this->Budget,
      "hierarchical radiosity: refining to " + std::to_string(mesh.Elements().size() + 4) + " quadtree nodes",
      "raise --min-element-size (MinElementSize) or --link-tolerance (LinkTolerance)");
  }
  const std::uint32_t first = mesh.Subdivide(e);
  const std::size_t n = mesh.Elements().size();
  const RGB b = this->NodeRadiosity[e], h = this->NodeIrradiance[e];
  this->NodeRadiosity.resize(n, b);
  this->NodeGathered.resize(n, RGB(0.0));
  this->NodeGatheredVisible.resize(n, RGB(0.0));
  this->Normalization.resize(n, 1.0);
  this->NodeIrradiance.resize(n, h);
  this->NodeDirect.resize(n, RGB(0.0));
  return first;
}

void HierarchicalRadiosity::Refine(std::uint32_t p, std::uint32_t q, std::vector<PendingLink>& out)
{
  const ElementMesh& mesh = *this->Elements;
  // Nothing passes between nodes that are wholly behind each other.
  auto inFront = [&](std::uint32_t a, std::uint32_t b) {
    for (int k = 0; k < 3; ++k)
    {
      if (glm::dot(mesh.Corner(a, k) - mesh[b].Centroid, mesh[b].Normal) > this->PlaneTolerance)
      {
        return true;
      }
    }
    return false;
  };
  if (!inFront(q, p) || !inFront(p, q))
  {
    return;
  }
  const double fpq = this->FormFactorEstimate(p, q);
  const double fqp = this->FormFactorEstimate(q, p);
  const double bq = MaxComponent(this->NodeRadiosity[q]);
  const bool sp = this->Splittable(p), sq = this->Splittable(q);
  if (bq * std::max(fpq, fqp) <= this->Epsilon || (!sp && !sq))
  {
    if (out.size() + this->LinkList.size() >= this->LinkCapacity)
    {
      CheckMemoryBudget(static_cast<double>(out.size() + this->LinkList.size() + 1) * BytesPerLink,
        this->Budget,
        "hierarchical radiosity: refining to " + std::to_string(out.size() + this->LinkList.size() + 1) + " links",
        "raise --link-tolerance (LinkTolerance) or --min-element-size (MinElementSize)");
    }
    out.push_back({ p, q });
    return;
  }
  if ((fqp >= fpq && sp) || !sq)
  {
    const std::uint32_t c = this->Children(p);
    for (std::uint32_t i = 0; i < 4; ++i)
    {
      this->Refine(c + i, q, out);
    }
  }
  else
  {
    const std::uint32_t c = this->Children(q);
    for (std::uint32_t i = 0; i < 4; ++i)
    {
      this->Refine(p, c + i, out);
    }
  }
}

bool HierarchicalRadiosity::InitialLinks(std::vector<PendingLink>& out, const std::function<bool()>& keepGoing)
{
  for (std::uint32_t p : this->Roots)
  {
    if (!keepGoing())
    {
      return false;
    }
    for (std::uint32_t q : this->Roots)
    {
      if (p != q)
      {
        this->Refine(p, q, out);
      }
    }
  }
  return true;
}

std::size_t HierarchicalRadiosity::RefineLinks(std::vector<PendingLink>& out)
{
  std::vector<HierarchicalLink> kept;
  kept.reserve(this->LinkList.size());
  std::size_t changed = this->RefineClusterLinks(out);
  for (const HierarchicalLink& l : this->LinkList)
  {
    const double bq = MaxComponent(this->NodeRadiosity[l.Source]);
    const bool refinable = l.Kind != HierarchicalLink::Hidden &&
      (this->Splittable(l.Receiver) || this->Splittable(l.Source));
    if (refinable &&
      bq * std::max(this->FormFactorEstimate(l.Receiver, l.Source),
             this->FormFactorEstimate(l.Source, l.Receiver)) > this->Epsilon)
    {
      this->Refine(l.Receiver, l.Source, out);
      ++changed;
    }
    else
    {
      kept.push_back(l);
    }
  }
  this->LinkList.swap(kept);
  return changed;
}

void HierarchicalRadiosity::IndexLinks()
{
  std::stable_sort(this->LinkList.begin(), this->LinkList.end(),
    [](const HierarchicalLink& a, const HierarchicalLink& b) { return a.Receiver < b.Receiver; });
  const std::size_t n = this->Elements->Elements().size();
  this->LinkOffsets.assign(n + 1, 0);
  for (const HierarchicalLink& l : this->LinkList)
  {
    ++this->LinkOffsets[l.Receiver + 1];
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    this->LinkOffsets[i + 1] += this->LinkOffsets[i];
  }
}


boost::integer_range<std::uint32_t> HierarchicalRadiosity::LinksOf(std::uint32_t e) const
{
  return e + 1 < this->LinkOffsets.size() ? boost::irange(this->LinkOffsets[e], this->LinkOffsets[e + 1])
                                          : boost::irange(0u, 0u);
}

RGB HierarchicalRadiosity::PushPull(std::uint32_t e, const RGB& downVisible, const RGB& downOther,
  const RGB& downClustered, std::vector<RGB>& change)
{
  const ElementMesh& mesh = *this->Elements;
  const Element& el = mesh[e];
  const RGB hv = downVisible + this->NodeGatheredVisible[e];
  const RGB ho = downOther + this->NodeGathered[e] - this->NodeGatheredVisible[e];
  // Clustered: the cluster links' part, normalised per leaf (ClusterLinks::Normalize).
  const RGB hc = downClustered + (e < this->ClusterDown.size() ? this->ClusterDown[e] : RGB(0.0)) +
    (e < this->ElementDown.size() ? this->ElementDown[e] : RGB(0.0));
  const RGB h = (el.IsLeaf() ? this->Normalization[e] : 1.0) * hv + ho +
    (el.IsLeaf() && e < this->ClusterScale.size() ? this->ClusterScale[e] : 1.0) * hc;
  this->NodeIrradiance[e] = h;
  if (el.IsLeaf())
  {
    const Material& m = mesh.MaterialOf(e);
    const RGB b = m.Emission + m.Reflectance * h;
    change[e] = b - this->NodeRadiosity[e];
    this->NodeRadiosity[e] = b;
    return b;
  }
  RGB sum(0.0);
  double area = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    const std::uint32_t c = static_cast<std::uint32_t>(el.FirstChild + i);
    sum += mesh[c].Area * this->PushPull(c, hv, ho, hc, change);
    area += mesh[c].Area;
  }
  this->NodeRadiosity[e] = area > 0 ? sum / area : this->NodeRadiosity[e];
  return this->NodeRadiosity[e];
}

RGB HierarchicalRadiosity::Pull(std::uint32_t e)
{
  const ElementMesh& mesh = *this->Elements;
  const Element& el = mesh[e];
  if (el.IsLeaf())
  {
    return this->NodeRadiosity[e];
  }
  RGB sum(0.0);
  double area = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    const std::uint32_t c = static_cast<std::uint32_t>(el.FirstChild + i);
    sum += mesh[c].Area * this->Pull(c);
    area += mesh[c].Area;
  }
  this->NodeRadiosity[e] = area > 0 ? sum / area : this->NodeRadiosity[e];
  return this->NodeRadiosity[e];
}

double HierarchicalRadiosity::Sweep(std::vector<RGB>& change)
{
  const std::size_t n = this->Elements->Elements().size();
  change.assign(n, RGB(0.0));
  this->GatherClusters();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256),
    [&](const tbb::blocked_range<std::size_t>& range) {
      for (std::size_t e = range.begin(); e != range.end(); ++e)
      {
        RGB g(0.0), gv(0.0);
        for (std::uint32_t i = this->LinkOffsets[e]; i < this->LinkOffsets[e + 1]; ++i)
        {
          const HierarchicalLink& l = this->LinkList[i];
          const RGB t = l.Factor * this->NodeRadiosity[l.Source];
          g += t;
          if (l.Kind == HierarchicalLink::Visible)
          {
            gv += t;
          }
        }
        // The light link joins the transfers that are not normalised (Normalize
        // rescales the emitters' unoccluded form factors only).
        this->NodeGathered[e] = g + this->NodeDirect[e];
        this->NodeGatheredVisible[e] = gv;
      }
    });
  tbb::parallel_for(std::size_t(0), this->Roots.size(),
    [&](std::size_t r) { this->PushPull(this->Roots[r], RGB(0.0), RGB(0.0), RGB(0.0), change); });
  double delta = 0.0;
  for (std::size_t e = 0; e < n; ++e)
  {
    delta += Mean(glm::abs(change[e])) * (*this->Elements)[static_cast<std::uint32_t>(e)].Area;
  }
  return delta;
}

void HierarchicalRadiosity::StoreLeafIrradiance()
{
  ElementMesh& mesh = *this->Elements;
  for (std::uint32_t e = 0; e < mesh.Elements().size(); ++e)
  {
    // Aitken's extrapolated tail can leave an unlit leaf a rounding below 0.
    const RGB h = NonNegative(this->NodeIrradiance[e]);
    ElementSamples& s = mesh[e].Irradiance;
    s.Corner = { h, h, h };
    s.Centre = h;
  }
}

SolverStatistics HierarchicalRadiosity::Solve(const ProgressCallback& progress)
{
  SolverStatistics stats;
  const Stopwatch start;
  // The thread limit applies to this solve alone (a task arena of its own).
  return RunWithThreads(this->Settings.Threads, [&]() -> SolverStatistics {
    ElementMesh& mesh = *this->Elements;
    stats.Occluders = this->SceneInfo.Occluders;
    const auto report0 = [&](const char* phase) {
      return ReportProgress(progress, phase, 0, 1.0, this->Settings.Tolerance);
    };
    double emitted = 0.0;
    for (std::uint32_t e : this->Roots)
    {
      emitted += Mean(mesh.MaterialOf(e).Emission) * mesh[e].Area;
    }
    if (this->Lights && !report0("lighting"))
    {
      stats.Stop = StopReason::Aborted;
      stats.SolveSeconds = start.Seconds();
      return stats;
    }
    stats.LightPowerW = this->LinkLights();
    emitted += stats.LightPowerW;
    stats.EmittedPowerW = emitted;
    stats.Elements = mesh.NumberOfLeaves();
    if (!(emitted > 0.0))
    {
      stats.Stop = StopReason::NoEmitters;
      stats.SolveSeconds = start.Seconds();
      return stats;
    }
    const std::unique_ptr<MeshProbeTracker> tracker = MeshProbeTracker::ForReference(mesh,
      this->Settings.ErrorProbes, this->Settings.ErrorReference, this->SceneInfo.Diagonal);
    stats.ErrorProbesTracked = tracker ? tracker->Tracked() : 0;
    auto report = [&](const char* phase, long long iteration, double residual) {
      return ReportProgress(progress, phase, iteration, residual, this->Settings.Tolerance);
    };

    std::vector<PendingLink> pending;
    if (!report("linking", 0, 1.0))
    {
      stats.Stop = StopReason::Aborted;
      stats.SolveSeconds = start.Seconds();
      return stats;
    }
    const auto linking = [&]() { return report("linking", 0, 1.0); };
    const bool linked = this->UseClusters ? this->InitialClusterLinks(pending, linking, progress)
                                          : this->InitialLinks(pending, linking);
    if (!linked || !this->ComputeLinks(pending, stats, linking))
    {
      stats.Stop = StopReason::Aborted;
      stats.SolveSeconds = start.Seconds();
      return stats;
    }
    this->IndexLinks();
    this->Normalize();

    std::vector<RGB> change;
    double previousDelta = -1.0, previousRatio = -1.0;
    bool extrapolated = false;
    int round = 0;
    stats.Stop = StopReason::IterationLimit;
    for (long long iteration = 0;; ++iteration)
    {
      const double delta = this->Sweep(change);
      const double ratio = previousDelta > 0 ? delta / previousDelta : -1.0;
      const double remaining =
        ratio > 0 && ratio < 1 ? delta * ratio / (1.0 - ratio) : std::max(delta, 0.0);
      double total = 0.0, absorbed = 0.0;
      for (std::uint32_t e = 0; e < mesh.Elements().size(); ++e)
      {
        if (mesh[e].IsLeaf())
        {
          const Material& m = mesh.MaterialOf(e);
          total += Mean(this->NodeRadiosity[e]) * mesh[e].Area;
          absorbed += Mean((RGB(1.0) - m.Reflectance) * this->NodeIrradiance[e]) * mesh[e].Area;
        }
      }
      this->StoreLeafIrradiance();

      const double elapsed = start.Seconds();
      ConvergenceRow row;
      row.Iteration = iteration;
      row.TimeSeconds = elapsed;
      row.UnshotPowerW = remaining;
      // Power that leaves the surfaces and is received nowhere: what escapes
      // an open scene, and the form factor error of a closed one. The
      // lights' and the sky's direct light is received without having left
      // a surface: only the rest of the irradiance was sent by the surfaces.
      double received = -stats.LightPowerW;
      for (std::uint32_t e = 0; e < mesh.Elements().size(); ++e)
      {
        if (mesh[e].IsLeaf())
        {
          received += Mean(this->NodeIrradiance[e]) * mesh[e].Area;
        }
      }
      const double escaped = total - received;
      row.EnergyBalance = (emitted - absorbed - escaped) / emitted;
      if (tracker)
      {
        const ErrorFigures errors = RelativeErrors(tracker->Evaluate(), this->Settings.ErrorReference);
        row.RmsError = errors.Rms;
        row.MaxRelError = errors.Max;
      }
      stats.History.Rows.push_back(row);
      stats.Iterations = iteration;
      stats.UnshotPowerW = remaining;
      stats.AbsorbedPowerW = absorbed;
      stats.EscapedPowerW = escaped;

      const double relative = total > 0 ? remaining / total : 0.0;
      if (!report("gathering", iteration, relative))
      {
        stats.Stop = StopReason::Aborted;
        break;
      }
      if (relative <= this->Settings.Tolerance && !extrapolated)
      {
        pending.clear();
        // Past the refinement rounds, the cluster pairs still deferred for a
        // dark source are linked once their source has light.
        if (round < this->Settings.MaxRefinementRounds ? this->RefineLinks(pending) > 0
                                                       : this->RefineClusterLinks(pending, true) > 0)
        {
          ++round;
          if (!report("linking", iteration, relative))
          {
            stats.Stop = StopReason::Aborted;
            break;
          }
          if (!this->ComputeLinks(pending, stats, [&]() { return report("linking", iteration, relative); }))
          {
            stats.Stop = StopReason::Aborted;
            break;
          }
          this->IndexLinks();
          this->Normalize();
          previousDelta = previousRatio = -1.0;
          continue;
        }
        stats.Stop = StopReason::Converged;
        break;
      }
      if (ReachedLimitOnAnyRank(ShareOrAlone(this->Settings.Share), iteration, this->Settings.MaxIterations, elapsed,
            this->Settings.MaxTimeSeconds, stats.Stop))
      {
        break;
      }
      extrapolated = false;
      // Aitken: once the ratio is steady, add the geometric tail of the change.
      if (ratio > 0.5 && ratio < 1.0 && previousRatio > 0 &&
        std::fabs(ratio - previousRatio) < 0.02 * (1.0 - ratio))
      {
        const double gain = ratio / (1.0 - ratio);
        for (std::uint32_t e = 0; e < mesh.Elements().size(); ++e)
        {
          if (mesh[e].IsLeaf())
          {
            this->NodeRadiosity[e] += gain * change[e];
          }
        }
        for (std::uint32_t r : this->Roots)
        {
          this->Pull(r);
        }
        extrapolated = true;
        previousDelta = previousRatio = -1.0;
        continue;
      }
      previousRatio = ratio;
      previousDelta = delta;
    }
    stats.Elements = mesh.NumberOfLeaves();
    stats.Links = this->LinkList.size() + this->NumberOfClusterLinks();
    stats.ClusterLinks = this->NumberOfClusterLinks();
    stats.PartialLinks = 0;
    stats.HiddenLinks = 0;
    stats.LinksWithBlockersCut = 0;
    for (const HierarchicalLink& l : this->LinkList)
    {
      stats.PartialLinks += l.Kind == HierarchicalLink::Partial;
      stats.HiddenLinks += l.Kind == HierarchicalLink::Hidden;
      stats.LinksWithBlockersCut += l.BlockersCut;
    }
    stats.Subdivisions = (mesh.Elements().size() - this->Roots.size()) / 4;
    stats.RaysCast = this->Rays->RaysCast() + (this->Lights ? this->Lights->RaysCast() : 0);
    stats.SolveSeconds = start.Seconds();
    return stats;
  });
}
} // namespace radiosity
