#include "Radiosity/Progressive/ProgressiveRadiosity.h"

#include "Radiosity/Common/DirectLighting.h"
#include "Radiosity/Common/Divergence.h"
#include "Radiosity/Common/ErrorMetrics.h"
#include "Radiosity/Common/Stopwatch.h"
#include "Radiosity/Common/ThreadLimit.h"
#include "Radiosity/Common/FormFactor.h"
#include "Radiosity/Common/MemoryBudget.h"
#include "Radiosity/Common/MeshProbeTracker.h"
#include "Radiosity/Progressive/ShooterSamples.h"
#include "Radiosity/Common/Visibility.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>

namespace radiosity
{
namespace
{
// Corner samples sit this fraction of the way towards their element's centre.
constexpr double CornerInset = 1e-6;

struct Selection
{
  std::uint32_t Best = 0;
  double BestPower = -1.0;
  double AbsPower = 0.0;   ///< sum |unshot| * area, mean over RGB
  RGB SignedPower{ 0.0 };  ///< sum unshot * area, per channel
};
}

struct ProgressiveRadiosity::ShotResult
{
  ElementSamples Delta;
  double ShooterSideFormFactor = 0.0; ///< F from the shooter's centroid to this element
  std::uint32_t Analytic = 0, Disc = 0;
  bool FacingAway = false;
  bool Split = false;
  ElementSamples History; ///< for new children: everything received before this shot
};

namespace
{
// Bytes per element: the quadtree node with its pool point and midpoint
// entry, its corner samples (shared with the neighbours: about one each) and
// their index entries.
constexpr double BytesPerElement = sizeof(Element) + 24.0 + 48.0 + 12.0 + 72.0 + 48.0 + 12.0;
}

ProgressiveRadiosity::ProgressiveRadiosity(const Scene& scene, const ProgressiveOptions& options)
  : SourceScene(scene)
  , Settings(options)
{
  this->SceneInfo = AnalyzeScene(scene);
  this->Rays = std::make_unique<Visibility>(scene, this->SceneInfo.CanOcclude);
  const double diag = this->SceneInfo.Diagonal;
  const double initialEdge = std::max(options.InitialElementSize, 1e-6) * diag;
  const double shooterEdge = std::max(options.ShooterElementSize, options.InitialElementSize) * diag;
  // The uniform initial mesh, 4/3 nodes per leaf, must fit before it is made.
  this->Budget = ResolveMemoryBudget(options.MemoryBudgetBytes);
  const double leaves = UniformQuadtreeLeaves(scene, initialEdge, 12);
  CheckMemoryBudget(4.0 / 3.0 * leaves * BytesPerElement, this->Budget,
    "progressive radiosity: the initial mesh of " + FormatCount(leaves) + " elements",
    "raise --element-size (InitialElementSize)");
  this->ElementCapacity = this->Budget > 0
    ? static_cast<std::size_t>(std::min(this->Budget / BytesPerElement, 1e18))
    : std::numeric_limits<std::size_t>::max();
  this->Elements = std::make_unique<ElementMesh>(scene, shooterEdge, initialEdge, 12);
  this->MaxLevel = this->Elements->MaxLevels(options.MaxSubdivisionLevels);
  double rhoArea = 0.0, area = 0.0;
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    rhoArea += MaxComponent(scene.Materials[t].Reflectance) * scene.Area(t);
    area += scene.Area(t);
  }
  this->DiscTolerance = options.FormFactorTolerance * (1.0 - rhoArea / std::max(area, 1e-300));
  this->PlaneTolerance = 1e-9 * this->SceneInfo.Diagonal;
  const auto& shooters = this->Elements->Shooters();
  this->ShooterSlot.assign(this->Elements->Elements().size(), 0);
  this->ShotTotal.assign(shooters.size(), RGB(0.0));
  this->EscapeFraction.assign(shooters.size(), -1.0);
  for (std::uint32_t e : this->Elements->Leaves())
  {
    this->RegisterCorners(e);
  }
  this->SampleFactor.resize(this->Samples.size());
  this->SampleStamp.resize(this->Samples.size(), 0);
  for (std::size_t i = 0; i < shooters.size(); ++i)
  {
    const std::uint32_t n = shooters[i];
    this->ShooterSlot[n] = static_cast<std::uint32_t>(i);
    const bool emitter = MaxComponent(this->Elements->MaterialOf(n).Emission) > 0;
    this->Targets.push_back(ShooterSamplePoints(this->Elements->Corner(n, 0),
      this->Elements->Corner(n, 1), this->Elements->Corner(n, 2),
      emitter ? options.VisibilitySamples : options.IndirectVisibilitySamples));
    this->TargetWeights.emplace_back(
      this->Targets.back().size(), 1.0 / static_cast<double>(this->Targets.back().size()));
  }
}

ProgressiveRadiosity::~ProgressiveRadiosity() = default;

struct ProgressiveRadiosity::TransferScratch
{
  std::vector<Vec3> From, To;
  std::vector<unsigned char> Visible;
};

bool ProgressiveRadiosity::FacesShooter(std::uint32_t receiver, std::uint32_t shooter) const
{
  // Leave out pairs with no transfer: receiver wholly behind the shooter's
  // plane, or shooter wholly behind the receiver's.
  const ElementMesh& mesh = *this->Elements;
  const Element& r = mesh[receiver];
  const Element& s = mesh[shooter];
  bool anyFront = false, anyAbove = false;
  for (int k = 0; k < 3; ++k)
  {
    anyFront = anyFront || glm::dot(mesh.Corner(receiver, k) - mesh.Corner(shooter, 0), s.Normal) > 0;
    anyAbove = anyAbove || glm::dot(mesh.Corner(shooter, k) - mesh.Corner(receiver, 0), r.Normal) > 0;
  }
  return anyFront && anyAbove;
}

void ProgressiveRadiosity::RegisterCorners(std::uint32_t e)
{
  const ElementMesh& mesh = *this->Elements;
  const Element& el = mesh[e];
  if (this->CornerSamples.size() <= e)
  {
    this->CornerSamples.resize(mesh.Elements().size());
  }
  for (int k = 0; k < 3; ++k)
  {
    // Shared by the leaves of one input triangle that meet at this vertex.
    const std::uint64_t key = (static_cast<std::uint64_t>(el.V[k]) << 32) | el.Source;
    auto found = this->SampleIndex.find(key);
    if (found == this->SampleIndex.end())
    {
      // The limit from inside the element: a corner on another surface's
      // plane (a room's edge, a contact) would otherwise see that surface
      // edge-on and miss its half of the hemisphere.
      const Vec3 corner = mesh.Corner(e, k);
      SharedSample sample;
      sample.Point = corner + CornerInset * (el.Centroid - corner);
      sample.RayOrigin = corner + 1e-3 * (el.Centroid - corner) + this->Rays->Offset() * el.Normal;
      sample.Normal = el.Normal;
      sample.Source = el.Source;
      found = this->SampleIndex.emplace(key, static_cast<std::uint32_t>(this->Samples.size())).first;
      this->Samples.push_back(sample);
    }
    this->CornerSamples[e][k] = found->second;
  }
}

double ProgressiveRadiosity::VisibleFraction(std::uint32_t shooter, const unsigned char* visible) const
{
  const std::vector<double>& weights = this->TargetWeights[this->ShooterSlot[shooter]];
  double seen = 0.0;
  for (std::size_t k = 0; k < weights.size(); ++k)
  {
    seen += visible[k] ? weights[k] : 0.0;
  }
  return seen;
}

void ProgressiveRadiosity::WeighTargets(std::uint32_t shooter, const std::vector<std::uint32_t>& own)
{
  // The visibility targets of a shooter are the centres of its level-j
  // sub-triangles, in the order of ElementMesh::Subdivide's children. Each is
  // weighted by the unshot power of the leaves inside it, so that a shooter
  // partly hidden (a floor node under a block) is seen where its power is.
  const ElementMesh& mesh = *this->Elements;
  std::vector<double>& weights = this->TargetWeights[this->ShooterSlot[shooter]];
  const std::size_t nt = weights.size();
  const int depth = nt >= 16 ? 2 : (nt >= 4 ? 1 : 0);
  std::vector<double> w(nt, 0.0);
  std::vector<std::uint32_t> path;
  for (std::uint32_t e : own)
  {
    path.clear();
    for (std::uint32_t a = e; a != shooter; a = static_cast<std::uint32_t>(mesh[a].Parent))
    {
      const Element& parent = mesh[static_cast<std::uint32_t>(mesh[a].Parent)];
      path.push_back(a - static_cast<std::uint32_t>(parent.FirstChild));
    }
    std::reverse(path.begin(), path.end()); // child indices from the shooter down
    std::size_t first = 0, span = nt;
    for (int level = 0; level < depth && level < static_cast<int>(path.size()); ++level)
    {
      span /= 4;
      first += path[level] * span;
    }
    const double power = std::fabs(SumComponents(mesh[e].Unshot)) * mesh[e].Area / span;
    for (std::size_t k = first; k < first + span; ++k)
    {
      w[k] += power;
    }
  }
  double total = 0.0;
  for (double x : w)
  {
    total += x;
  }
  for (std::size_t k = 0; k < nt; ++k)
  {
    weights[k] = total > 0.0 ? w[k] / total : 1.0 / static_cast<double>(nt);
  }
}

double ProgressiveRadiosity::PointTransfer(const Vec3& p, const Vec3& n, const Vec3& origin,
  std::uint32_t shooter, TransferScratch& scratch, ShotResult& counts, double* visibility) const
{
  double vis = 1.0;
  if (!this->Rays->Empty())
  {
    const std::vector<Vec3>& targets = this->Targets[this->ShooterSlot[shooter]];
    scratch.From.assign(targets.size(), origin);
    scratch.Visible.resize(targets.size());
    this->Rays->TestSegments(
      scratch.From.data(), targets.data(), targets.size(), scratch.Visible.data());
    vis = this->VisibleFraction(shooter, scratch.Visible.data());
  }
  if (visibility)
  {
    *visibility = vis;
  }
  return vis > 0.0 ? vis * this->PointFormFactor(p, n, shooter, counts) : 0.0;
}

double ProgressiveRadiosity::PointFormFactor(
  const Vec3& p, const Vec3& n, std::uint32_t shooter, ShotResult& counts) const
{
  const ElementMesh& mesh = *this->Elements;
  const Element& s = mesh[shooter];
  if (ApparentSize(p, s.Centroid, s.Area) < this->DiscTolerance)
  {
    ++counts.Disc;
    return DiscFormFactor(p, n, s.Centroid, s.Normal, s.Area);
  }
  ++counts.Analytic;
  const Vec3 poly[3] = { mesh.Corner(shooter, 0), mesh.Corner(shooter, 1), mesh.Corner(shooter, 2) };
  return PointToPolygonFormFactor(p, n, poly, 3);
}

void ProgressiveRadiosity::SampleTransfers(
  const std::uint32_t* ids, std::size_t count, std::uint32_t shooter, ShotResult& counts)
{
  // One batch of visibility rays for all the samples of this range.
  std::vector<unsigned char> visible;
  const std::vector<Vec3>& targets = this->Targets[this->ShooterSlot[shooter]];
  const std::size_t nv = targets.size();
  if (!this->Rays->Empty())
  {
    std::vector<Vec3> from, to;
    from.reserve(count * nv);
    to.reserve(count * nv);
    for (std::size_t i = 0; i < count; ++i)
    {
      for (const Vec3& q : targets)
      {
        from.push_back(this->Samples[ids[i]].RayOrigin);
        to.push_back(q);
      }
    }
    visible.resize(from.size());
    this->Rays->TestSegments(from.data(), to.data(), from.size(), visible.data());
  }
  for (std::size_t i = 0; i < count; ++i)
  {
    const SharedSample& sample = this->Samples[ids[i]];
    double vis = 1.0;
    if (!visible.empty())
    {
      vis = this->VisibleFraction(shooter, visible.data() + i * nv);
    }
    this->SampleFactor[ids[i]] =
      vis > 0.0 ? vis * this->PointFormFactor(sample.Point, sample.Normal, shooter, counts) : 0.0;
  }
}

bool ProgressiveRadiosity::Transfer(std::uint32_t receiver, std::uint32_t shooter,
  TransferScratch& scratch, std::array<double, 4>& factors, ShotResult& counts,
  bool shooterSide, const double* cornerFactors) const
{
  const ElementMesh& mesh = *this->Elements;
  const Element& r = mesh[receiver];
  const Element& s = mesh[shooter];
  const Vec3 corners[3] = { mesh.Corner(receiver, 0), mesh.Corner(receiver, 1),
    mesh.Corner(receiver, 2) };
  const Vec3 shooterPoly[3] = { mesh.Corner(shooter, 0), mesh.Corner(shooter, 1),
    mesh.Corner(shooter, 2) };
  if (!this->FacesShooter(receiver, shooter))
  {
    factors = { 0, 0, 0, 0 };
    return false;
  }
  const Vec3 centreOrigin = r.Centroid + this->Rays->Offset() * r.Normal;
  double visCentre = 0.0;
  factors[3] =
    this->PointTransfer(r.Centroid, r.Normal, centreOrigin, shooter, scratch, counts, &visCentre);
  for (int k = 0; k < 3; ++k)
  {
    // A shared value holds unless the corner lies in the shooter's plane:
    // there the form factor jumps (a receiver touching the shooter) and each
    // element needs its own limit from inside.
    if (cornerFactors &&
      std::fabs(glm::dot(corners[k] - shooterPoly[0], s.Normal)) > this->PlaneTolerance)
    {
      factors[k] = cornerFactors[k];
      continue;
    }
    const Vec3 p = corners[k] + CornerInset * (r.Centroid - corners[k]);
    const Vec3 origin = corners[k] + 1e-3 * (r.Centroid - corners[k]) + this->Rays->Offset() * r.Normal;
    factors[k] = this->PointTransfer(p, r.Normal, origin, shooter, scratch, counts);
  }
  // Shooter-side form factor for the energy balance: an independent
  // discretisation of the same transfer (the shooter's points looking at the
  // receiving element), integrated over the shooter with the same degree-2
  // rule and the same choice of kernel as the receivers.
  if (shooterSide && visCentre > 0.0)
  {
    const auto pointToReceiver = [&](const Vec3& q)
    {
      return ApparentSize(q, r.Centroid, r.Area) < this->DiscTolerance
        ? DiscFormFactor(q, s.Normal, r.Centroid, r.Normal, r.Area)
        : PointToPolygonFormFactor(q, s.Normal, corners, 3);
    };
    double f = 0.75 * pointToReceiver(s.Centroid);
    for (int k = 0; k < 3; ++k)
    {
      f += pointToReceiver(shooterPoly[k] + CornerInset * (s.Centroid - shooterPoly[k])) / 12.0;
    }
    counts.ShooterSideFormFactor = visCentre * f;
  }
  return true;
}

void ProgressiveRadiosity::Shoot(std::uint32_t shooter, const RGB& shot,
  const std::vector<std::uint32_t>& leaves, SolverStatistics& stats)
{
  ElementMesh& mesh = *this->Elements;
  WorkShare& share = ShareOrAlone(this->Settings.Share);
  const double shooterArea = mesh[shooter].Area;
  const double threshold = this->Settings.SubdivisionThreshold;
  const bool raysNeeded = !this->Rays->Empty();

  std::vector<std::uint32_t> pending;
  pending.reserve(mesh.NumberOfLeaves());
  std::vector<std::uint32_t> own;
  for (std::uint32_t e : leaves)
  {
    (mesh[e].ShooterNode == shooter ? own : pending).push_back(e);
  }
  this->WeighTargets(shooter, own);
  std::vector<unsigned char> fresh(pending.size(), 0); // children of this shot's splits
  // The fraction of a shooter's power that leaves the scene depends on
  // geometry only: it is integrated at the shooter's first shot and reused.
  double& escapeFraction = this->EscapeFraction[this->ShooterSlot[shooter]];
  const bool balanceNeeded = escapeFraction < 0.0;

  std::vector<ShotResult> results;
  double shooterSide = 0.0; // children of split receivers join it in later passes
  std::vector<std::uint32_t> needed;
  std::vector<ShotResult> sampleCounts;
  while (!pending.empty())
  {
    // Corner samples are shared between the leaves that meet at a vertex:
    // evaluate each needed one once for this shot.
    ++this->Stamp;
    needed.clear();
    for (std::uint32_t e : pending)
    {
      if (!this->FacesShooter(e, shooter))
      {
        continue;
      }
      for (std::uint32_t id : this->CornerSamples[e])
      {
        if (this->SampleStamp[id] != this->Stamp)
        {
          this->SampleStamp[id] = this->Stamp;
          needed.push_back(id);
        }
      }
    }
    sampleCounts.assign(needed.size(), ShotResult());
    // MPI ranks: this rank's share of the samples and of the receivers
    // below, then every rank holds every value (WorkShare.h).
    const auto mySamples = share.Range(needed.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(mySamples.first, mySamples.second, 32),
      [&](const tbb::blocked_range<std::size_t>& range)
      {
        this->SampleTransfers(needed.data() + range.begin(), range.size(), shooter,
          sampleCounts[range.begin()]);
      });
    if (share.Distributed())
    {
      std::vector<double> factors(needed.size());
      for (std::size_t k = mySamples.first; k < mySamples.second; ++k)
      {
        factors[k] = this->SampleFactor[needed[k]];
      }
      share.Combine(factors.data(), factors.size());
      for (std::size_t k = 0; k < needed.size(); ++k)
      {
        this->SampleFactor[needed[k]] = factors[k];
      }
    }
    for (const ShotResult& c : sampleCounts)
    {
      stats.AnalyticFormFactors += c.Analytic;
      stats.DiscFormFactors += c.Disc;
    }

    if (this->Lights)
    {
      // The new children's corners, for the lights' part of their history.
      std::vector<std::uint32_t> children;
      for (std::size_t i = 0; i < pending.size(); ++i)
      {
        if (fresh[i])
        {
          children.push_back(pending[i]);
        }
      }
      this->LightCornerSamples(children);
    }
    results.assign(pending.size(), ShotResult());
    const auto myReceivers = share.Range(pending.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(myReceivers.first, myReceivers.second, 16),
      [&](const tbb::blocked_range<std::size_t>& range)
      {
        TransferScratch scratch;
        std::array<double, 4> f;
        for (std::size_t i = range.begin(); i != range.end(); ++i)
        {
          const std::uint32_t e = pending[i];
          const Element& r = mesh[e];
          ShotResult& out = results[i];
          ElementSamples total = r.Irradiance;
          if (fresh[i])
          {
            // A new child: its history is gathered exactly rather than
            // interpolated from its parent. Every earlier shot of a node was a
            // uniform radiosity over that node, so what the child received so
            // far is sum_n (total shot by n) * F(sample -> n) * visibility,
            // plus the lights' and the sky's shot, exact at its samples (it
            // was missing: the children of a split near a small box on a sunlit
            // wall lost their sunlight, dark triangles in TestRadiosityPassAssembly's scene).
            ShotResult ignored;
            out.History = this->Lights ? this->LightSamples(e) : ElementSamples();
            for (std::uint32_t n : this->ActiveShooters)
            {
              if (mesh[e].ShooterNode == n || !this->Transfer(e, n, scratch, f, ignored, false))
              {
                continue;
              }
              const RGB& b = this->ShotTotal[this->ShooterSlot[n]];
              for (int k = 0; k < 3; ++k)
              {
                out.History.Corner[k] += b * f[k];
              }
              out.History.Centre += b * f[3];
            }
            total = out.History;
          }
          const auto& ids = this->CornerSamples[e];
          const double corners[3] = { this->SampleFactor[ids[0]], this->SampleFactor[ids[1]],
            this->SampleFactor[ids[2]] };
          if (!this->Transfer(e, shooter, scratch, f, out, balanceNeeded, corners))
          {
            out.FacingAway = true;
            continue;
          }
          for (int k = 0; k < 3; ++k)
          {
            out.Delta.Corner[k] = shot * f[k];
          }
          out.Delta.Centre = shot * f[3];

          // Gradient criterion (Coombe 4.1 after Vedel & Puech 1992): a linear
          // field's centre value is the mean of its corners, so the departure
          // from that mean measures the change of gradient across the element.
          // Judged on this shot's contribution against everything received so
          // far, so that late, weak shots do not split.
          if (r.Level < this->MaxLevel[r.Source])
          {
            total += out.Delta;
            const double departure = std::fabs(Luminance(out.Delta.Centre) -
              (Luminance(out.Delta.Corner[0]) + Luminance(out.Delta.Corner[1]) +
                Luminance(out.Delta.Corner[2])) / 3.0);
            if (departure > threshold * std::fabs(Luminance(total.Mean())))
            {
              out.Split = true;
            }
          }
        }
      });

    // Each receiver's result as the loop below reads it: a receiver facing
    // away or split sends its counts only, a new child its history too.
    share.CombineItems(
      pending.size(),
      [&](std::size_t i, std::vector<char>& bytes) {
        const ShotResult& res = results[i];
        const unsigned char kind = res.FacingAway ? 1 : res.Split ? 2 : 0;
        PutBytes(bytes, kind);
        PutBytes(bytes, res.Analytic);
        PutBytes(bytes, res.Disc);
        if (kind == 0)
        {
          PutBytes(bytes, res.Delta);
          PutBytes(bytes, res.ShooterSideFormFactor);
        }
        if (fresh[i])
        {
          PutBytes(bytes, res.History);
        }
      },
      [&](std::size_t i, const char* data, std::size_t size) {
        ShotResult& res = results[i];
        unsigned char kind = 0;
        std::size_t at = GetBytes(data, size, kind);
        at += GetBytes(data + at, size - at, res.Analytic);
        at += GetBytes(data + at, size - at, res.Disc);
        res.FacingAway = kind == 1;
        res.Split = kind == 2;
        if (kind == 0)
        {
          at += GetBytes(data + at, size - at, res.Delta);
          at += GetBytes(data + at, size - at, res.ShooterSideFormFactor);
        }
        if (fresh[i])
        {
          at += GetBytes(data + at, size - at, res.History);
        }
        return at;
      });
    std::vector<std::uint32_t> next;
    for (std::size_t i = 0; i < pending.size(); ++i)
    {
      const ShotResult& res = results[i];
      const std::uint32_t e = pending[i];
      stats.AnalyticFormFactors += res.Analytic;
      stats.DiscFormFactors += res.Disc;
      const RGB rho = mesh.MaterialOf(e).Reflectance;
      if (fresh[i])
      {
        // Replace the pushed history by the gathered one; the difference in
        // received power joins the residual so that it is shot on.
        Element& r = mesh[e];
        const RGB correction = res.History.Mean() - r.Irradiance.Mean();
        r.Irradiance = res.History;
        r.Unshot += rho * correction;
        this->Absorbed += Mean((RGB(1.0) - rho) * correction) * r.Area;
      }
      if (res.FacingAway)
      {
        ++stats.PairsFacingAway;
        continue;
      }
      if (!raysNeeded)
      {
        ++stats.PairsUnoccludable;
      }
      if (res.Split)
      {
        this->SplitReceiver(e, stats, next);
        continue;
      }
      Element& r = mesh[e];
      r.Irradiance += res.Delta;
      const RGB meanDelta = res.Delta.Mean();
      r.Unshot += rho * meanDelta;
      this->Absorbed += Mean((RGB(1.0) - rho) * meanDelta) * r.Area;
      shooterSide += res.ShooterSideFormFactor;
    }
    pending.swap(next);
    fresh.assign(pending.size(), 1);
    this->SampleFactor.resize(this->Samples.size());
    this->SampleStamp.resize(this->Samples.size(), 0);
  }
  if (balanceNeeded)
  {
    escapeFraction = 1.0 - shooterSide;
  }
  this->Escaped += Mean(shot) * shooterArea * escapeFraction;
  // The shooter's leaves keep what was shot in advance, as a negative residual.
  const RGB left = mesh[shooter].Unshot;
  for (std::uint32_t e : own)
  {
    mesh[e].Unshot = left;
  }
  RGB& total = this->ShotTotal[this->ShooterSlot[shooter]];
  if (total == RGB(0.0))
  {
    this->ActiveShooters.push_back(shooter);
  }
  total += shot;
}

void ProgressiveRadiosity::SplitReceiver(
  std::uint32_t e, SolverStatistics& stats, std::vector<std::uint32_t>& children)
{
  ElementMesh& mesh = *this->Elements;
  if (mesh.Elements().size() + 4 > this->ElementCapacity)
  {
    CheckMemoryBudget(static_cast<double>(mesh.Elements().size() + 4) * BytesPerElement, this->Budget,
      "progressive radiosity: subdividing to " + std::to_string(mesh.Elements().size() + 4) + " elements",
      "lower MaxSubdivisionLevels or raise SubdivisionThreshold or --element-size");
  }
  const std::uint32_t first = mesh.Subdivide(e);
  ++stats.Subdivisions;
  for (std::uint32_t c = 0; c < 4; ++c)
  {
    this->RegisterCorners(first + c);
    children.push_back(first + c);
  }
}

SolverStatistics ProgressiveRadiosity::Solve(const ProgressCallback& progress)
{
  SolverStatistics stats;
  const Stopwatch start;
  // The thread limit applies to this solve alone (a task arena of its own).
  return RunWithThreads(this->Settings.Threads, [&]() -> SolverStatistics {
    ElementMesh& mesh = *this->Elements;
    stats.Occluders = this->SceneInfo.Occluders;
    double emitted = 0.0;
    double area = 0.0;
    RGB rhoMean(0.0);
    for (const Element& e : mesh.Elements())
    {
      if (e.IsLeaf())
      {
        const Material& m = this->SourceScene.Materials[e.Source];
        emitted += Mean(m.Emission) * e.Area;
        rhoMean += m.Reflectance * e.Area;
        area += e.Area;
      }
    }
    rhoMean /= std::max(area, 1e-300);
    stats.LightPowerW = this->ShootLights(stats);
    emitted += stats.LightPowerW;
    stats.EmittedPowerW = emitted;
    stats.Elements = mesh.NumberOfLeaves();
    if (!(emitted > 0.0))
    {
      stats.Stop = StopReason::NoEmitters;
      stats.SolveSeconds = start.Seconds();
      return stats;
    }
    // Cohen 1988's interreflection factor R = 1 / (1 - mean reflectance).
    const RGB interreflection = RGB(1.0) / (RGB(1.0) - rhoMean);

    const std::unique_ptr<MeshProbeTracker> tracker = MeshProbeTracker::ForReference(mesh,
      this->Settings.ErrorProbes, this->Settings.ErrorReference, this->SceneInfo.Diagonal);
    stats.ErrorProbesTracked = tracker ? tracker->Tracked() : 0;
    std::vector<RGB> nodePower(mesh.Elements().size(), RGB(0.0));
    double lowestUnshot = std::numeric_limits<double>::infinity();
    stats.Stop = StopReason::IterationLimit;
    for (long long iteration = 0;; ++iteration)
    {
      // Unshot power per shooter node (Coombe 3.1: the residual is mipmapped
      // to the shooting level and the node of highest power shoots).
      const std::vector<std::uint32_t> leaves = mesh.Leaves();
      Selection sel;
      for (std::uint32_t e : leaves)
      {
        const Element& el = mesh[e];
        nodePower[el.ShooterNode] += el.Unshot * el.Area;
        sel.AbsPower += Mean(glm::abs(el.Unshot)) * el.Area;
        sel.SignedPower += el.Unshot * el.Area;
      }
      // Overshooting (Feda & Purgathofer 1992): each shooter also shoots, in
      // advance, its share rho * ambient of what the unshot power will bring it
      // (Cohen 1988's ambient term), and the shooters are ranked by that total:
      // a shooter left with a negative residual has already shot its future.
      const RGB ambient =
        this->Settings.Overshooting ? interreflection * sel.SignedPower / area : RGB(0.0);
      for (std::uint32_t n : mesh.Shooters())
      {
        const RGB total = nodePower[n] + mesh.MaterialOf(n).Reflectance * ambient * mesh[n].Area;
        const double p = std::fabs(Mean(total));
        if (p > sel.BestPower)
        {
          sel.BestPower = p;
          sel.Best = n;
        }
      }
      const RGB nodeUnshot = nodePower[sel.Best] / mesh[sel.Best].Area;
      for (std::uint32_t n : mesh.Shooters())
      {
        nodePower[n] = RGB(0.0);
      }

      const double elapsed = start.Seconds();
      ConvergenceRow row;
      row.Iteration = iteration;
      row.TimeSeconds = elapsed;
      row.UnshotPowerW = sel.AbsPower;
      const double signedUnshot = Mean(sel.SignedPower);
      row.EnergyBalance = (emitted - this->Absorbed - this->Escaped - signedUnshot) / emitted;
      const RGB overshoot = mesh.MaterialOf(sel.Best).Reflectance * ambient;
      row.OvershootPowerW = Mean(glm::abs(overshoot)) * mesh[sel.Best].Area;
      if (tracker)
      {
        const ErrorFigures errors = RelativeErrors(tracker->Evaluate(), this->Settings.ErrorReference);
        row.RmsError = errors.Rms;
        row.MaxRelError = errors.Max;
      }
      stats.History.Rows.push_back(row);
      stats.Iterations = iteration;
      stats.UnshotPowerW = sel.AbsPower;

      const double relative = sel.AbsPower / emitted;
      if (!ReportProgress(progress, "shooting", iteration, relative, this->Settings.Tolerance))
      {
        stats.Stop = StopReason::Aborted;
        break;
      }
      if (relative <= this->Settings.Tolerance)
      {
        stats.Stop = StopReason::Converged;
        break;
      }
      if (ResidualRoseAboveItsLowest(signedUnshot, lowestUnshot, emitted, iteration,
            "progressive refinement's signed unshot power", stats))
      {
        break;
      }
      if (ReachedLimitOnAnyRank(ShareOrAlone(this->Settings.Share), iteration, this->Settings.MaxIterations, elapsed,
            this->Settings.MaxTimeSeconds, stats.Stop))
      {
        break;
      }
      mesh[sel.Best].Unshot = -overshoot; // handed to the shooter's leaves after the shot
      this->Shoot(sel.Best, nodeUnshot + overshoot, leaves, stats);
    }
    if (this->Settings.Overshooting)
    {
      // Overshooting shoots future light in advance and takes it back later
      // as negative shots: stopped early (a time or iteration limit, an
      // abort), a sample can be left below zero (a lit corpus file stopped
      // at 5 s had -0.007 W/m^2), and converged, by rounding (assimp's
      // 3DS/test1.3ds under two point lights: -1.9e-12 W/m^2 at a peak of
      // 1.2, the negative shots of an unlit element). Irradiance is never
      // negative: such samples are clamped to zero (at most the unshot
      // power the stop left), the rest of the solution is kept.
      for (std::uint32_t e : mesh.Leaves())
      {
        ElementSamples& h = mesh[e].Irradiance;
        for (RGB& c : h.Corner)
        {
          c = glm::max(c, RGB(0.0));
        }
        h.Centre = glm::max(h.Centre, RGB(0.0));
      }
    }
    stats.Elements = mesh.NumberOfLeaves();
    stats.RaysCast += this->Rays->RaysCast() + (this->Lights ? this->Lights->RaysCast() : 0);
    stats.AbsorbedPowerW = this->Absorbed;
    stats.EscapedPowerW = this->Escaped;
    stats.SolveSeconds = start.Seconds();
    return stats;
  });
}
} // namespace radiosity
