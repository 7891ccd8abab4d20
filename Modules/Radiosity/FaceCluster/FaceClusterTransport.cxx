// One iteration of Algorithm 1's TRANSPORT-LIGHT (Gobbetti, Spano & Agus
// 2003, 3.4.1) for every top-level element, in two passes:
//
// 1. Refinement in rounds. The iteration's transfers start as the pairs of
//    top-level elements that face each other (ASSIGN-SHOOTER); a round
//    computes the coupling and the error of 3.3.2 for every pending pair
//    (ComputeTransfer: in parallel, and on MPI ranks each rank its share,
//    WorkShare.h), then resolves them in order: a transfer within the
//    tolerance is accepted into its receiver's irradiance, else the larger
//    end is subdivided and the children's pairs are the next round's.
//    Non-convex elements add their children's mutual pairs (3.3.3); in the
//    first iteration the lights' vector irradiance is fitted at the leaves'
//    nodes, and a leaf over which it varies by more than the tolerance is
//    subdivided (its children then take part in the rounds).
// 2. Push-pull (3.3.4): top-down, each element's accepted irradiance plus
//    its parent's pushed into the children it faces; at the leaves the
//    irradiance is stored and the new unshot radiosity
//    (1 - F_ii) rho n . dE fitted; bottom-up, the radiosity pulled.
//
// The paper walks each top element depth-first and transfers one pair at a
// time; the rounds accept and refine the same pairs by the same rule (a
// pair's transfer depends only on its two elements, which exist before the
// round), so the hierarchy is the same, and the transfers, nearly all of the
// solve's time, are independent work: threads and ranks share them, and a
// rank's share does not change a value (the same answer on any number of
// ranks, bit for bit).
#include "Radiosity/FaceCluster/FaceClusterRadiosity.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace radiosity
{
namespace
{
// The largest |Phi| of the Legendre products up to cubic: sqrt(7) * sqrt(7)
// bounds every function on [0, 1]^2; a bound on an expansion's range.
constexpr double BasisBound = 7.0;

// Pairs computed and exchanged together: the rounds' memory stays bounded
// on large scenes (a transfer holds N_e x N_b vectors).
constexpr std::size_t TransferBlock = 16384;

// The share of the memory budget that kept couplings and sky masks may
// take (KeepTransfers): the solve's own elements and hierarchy, and the
// caller's other work, need the rest (the 1.5M-triangle bunny room kept to
// half of 75% of 23 GB exhausted the machine).
constexpr double KeptShare = 0.25;

void PutTransfer(std::vector<char>& bytes, const Transfer& t)
{
  PutBytes(bytes, t.Error);
  PutBytes(bytes, t.FitError);
  for (const Vec3& k : t.K)
  {
    PutBytes(bytes, k);
  }
  PutBytes(bytes, static_cast<std::uint32_t>(t.Residual.size()));
  for (double r : t.Residual)
  {
    PutBytes(bytes, r);
  }
}

std::size_t GetTransfer(const char* data, std::size_t available, int receivers, int emitters, Transfer& t)
{
  t.Receivers = receivers;
  t.Emitters = emitters;
  t.K.assign(static_cast<std::size_t>(receivers) * emitters, Vec3(0.0));
  std::size_t at = GetBytes(data, available, t.Error);
  at += GetBytes(data + at, available - at, t.FitError);
  for (Vec3& k : t.K)
  {
    at += GetBytes(data + at, available - at, k);
  }
  std::uint32_t points = 0;
  at += GetBytes(data + at, available - at, points);
  t.Residual.assign(points, 0.0);
  for (double& r : t.Residual)
  {
    at += GetBytes(data + at, available - at, r);
  }
  return at;
}
}

void FaceClusterRadiosity::AddShooter(
  std::int32_t receiver, std::int32_t emitter, std::vector<PendingTransfer>& pending) const
{
  const FaceClusterElement& i = this->Nodes[receiver];
  const FaceClusterElement& j = this->Nodes[emitter];
  if (receiver != emitter && this->HasUnshot(j) && ClusterFaces(i.Data, j.Data) &&
    ClusterFaces(j.Data, i.Data))
  {
    pending.push_back({ receiver, emitter });
  }
}

Transfer FaceClusterRadiosity::TransferOf(
  std::int32_t i, std::int32_t j, std::unique_ptr<TransferCoupling>* keep) const
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
  const TransferEnd to{ &receiver.Data, receiver.Cluster, &receiver.Rule, this->IrradianceBasis.Size() };
  if (this->Couplings)
  {
    const auto kept = this->Couplings->find(this->KeyOf(i, j));
    if (kept != this->Couplings->end())
    {
      return EvaluateCoupling(kept->second, to, emitter.Unshot, bMin, bMax);
    }
  }
  TransferCoupling coupling = ComputeCoupling(to,
    { &emitter.Data, emitter.Cluster, &emitter.Rule, this->RadiosityBasis.Size(),
      emitter.IsTriangle() ? emitter.Corners.data() : nullptr },
    *this->Visibility, this->Settings.Rule);
  Transfer t = EvaluateCoupling(coupling, to, emitter.Unshot, bMin, bMax);
  if (keep)
  {
    *keep = std::make_unique<TransferCoupling>(std::move(coupling));
  }
  return t;
}

std::vector<Transfer> FaceClusterRadiosity::ComputeTransfers(const PendingTransfer* pairs, std::size_t n)
{
  std::vector<Transfer> out(n);
  WorkShare& share = ShareOrAlone(this->Settings.Share);
  const auto mine = share.Range(n);
  if (this->Couplings && share.Ranks() == 1)
  {
    // Relighting: the pairs seen before from their kept couplings; the
    // others computed and kept (in order, after the parallel part) while
    // the memory lasts.
    // A coupling is held past its transfer only when its memory fits
    // (reserved as it is computed: a block's couplings of large clusters,
    // thousands of nodes each, would otherwise all be held at once).
    std::vector<std::unique_ptr<TransferCoupling>> computed(n);
    std::vector<std::size_t> cost(n, 0);
    std::vector<char> dropped(n, 0);
    std::atomic<std::size_t> reserved{ this->Stats.KeptBytes };
    const auto cap = static_cast<std::size_t>(KeptShare * this->Budget);
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t k) {
      out[k] = this->TransferOf(pairs[k].Receiver, pairs[k].Emitter, &computed[k]);
      if (computed[k])
      {
        // The map's node and bucket, and the allocator's overhead on each
        // of the node's and the coupling's four arrays' blocks.
        cost[k] = computed[k]->Bytes() + sizeof(PairKey) + 2 * sizeof(void*) + 5 * 16;
        if (reserved.fetch_add(cost[k]) + cost[k] > cap)
        {
          reserved.fetch_sub(cost[k]);
          computed[k].reset();
          dropped[k] = 1;
        }
      }
    });
    for (std::size_t k = 0; k < n; ++k)
    {
      if (dropped[k])
      {
        ++this->Stats.CouplingsComputed;
        ++this->Stats.CouplingsNotKept;
        continue;
      }
      if (!computed[k])
      {
        ++this->Stats.CouplingsReused;
        continue;
      }
      ++this->Stats.CouplingsComputed;
      if (this->Couplings->emplace(this->KeyOf(pairs[k].Receiver, pairs[k].Emitter), std::move(*computed[k])).second)
      {
        this->Stats.KeptBytes += cost[k];
        ++this->Stats.KeptCouplings;
      }
      computed[k].reset();
    }
    return out;
  }
  tbb::parallel_for(mine.first, mine.second,
    [&](std::size_t k) { out[k] = this->TransferOf(pairs[k].Receiver, pairs[k].Emitter); });
  const int ne = this->IrradianceBasis.Size(), nb = this->RadiosityBasis.Size();
  share.CombineItems(
    n, [&](std::size_t k, std::vector<char>& bytes) { PutTransfer(bytes, out[k]); },
    [&](std::size_t k, const char* data, std::size_t available) {
      return GetTransfer(data, available, ne, nb, out[k]);
    });
  return out;
}

void FaceClusterRadiosity::Resolve(
  const PendingTransfer& pair, const Transfer& t, std::vector<PendingTransfer>& next)
{
  const std::int32_t i = pair.Receiver, j = pair.Emitter;
  const FaceClusterElement& receiver = this->Nodes[i];
  const FaceClusterElement& emitter = this->Nodes[j];
  // Below the input triangles only receivers are halved, and only where
  // their basis cannot follow the irradiance (the fit error at their nodes
  // and corners, judged at the input triangle's area, against
  // SubdivisionTolerance): the bounds of 3.3.2 never tighten next to a
  // shared edge, and halving both ends on them (a closed room, rho 0.5,
  // four times) gave 3.3% worst error against 0.3% without halving. An
  // emitter already halved as a receiver sends from its parts (below).
  const bool clusterReceiver = !receiver.Data.IsLeaf();
  const bool clusterEmitter = !emitter.Data.IsLeaf();
  // A part's error is judged at its input triangle's area, so that halving
  // a receiver does not halve the error of its irradiance that is accepted
  // (3.3.2's delta is a power).
  const double scale = receiver.Bisections > 0 && receiver.Data.Area > 0.0f
    ? this->GetScene().Area(receiver.Cluster) / receiver.Data.Area
    : 1.0;
  // A leaf triangle (or part) is halved on the sum of its transfers' fit
  // departures, after the round (BisectOnTotals), not on one transfer's: in
  // a closed room the adjacent wall's light curves across a triangle that
  // the rest of the room's light evens out, and halving on it alone fitted
  // that light on the parts and the rest on the whole triangle (the closed
  // room of reflectance 0.5: 1.5% of the exact against 7.7e-4 unhalved). A
  // triangle already halved sends a transfer its fit cannot follow down to
  // its parts.
  const bool leafTriangle = !clusterReceiver && receiver.IsLeaf();
  const bool fitFails = clusterReceiver ? t.FitError > this->Epsilon
                                        : !leafTriangle && scale * t.FitError > this->PartEpsilon;
  const bool bisect = !clusterReceiver && fitFails && this->CanSubdivide(receiver);
  // A halved emitter sends from its parts, each with its own radiosity,
  // where the spread of its radiosity over them would change this transfer
  // by more than the tolerance: a whole triangle sends its parts' mean, and
  // next to a wall (the Cornell box's corners) that mean is not what
  // arrives (4.7% of the peak with receivers halved four times, 1.5% with
  // the parts sending).
  bool emitterParts = !clusterEmitter && !emitter.IsLeaf();
  if (emitterParts)
  {
    const double coupling = std::sqrt(double(receiver.Data.Area) * double(emitter.Data.Area)) * glm::length(t.K[0]);
    emitterParts = scale * coupling * 0.5 * (emitter.UnshotMax - emitter.UnshotMin) > this->PartEpsilon;
  }
  // A part facing a cluster: the cluster was refined against the part's
  // input triangle already (its error bounds do not tighten as the part
  // gets smaller: refining them per part opened the 100k bunny room's
  // clusters for 9,000 more leaves and twice the solve).
  const double errorScale = clusterEmitter && !bisect ? 1.0 : scale;
  if (errorScale * t.Error <= this->Epsilon || (!clusterReceiver && !clusterEmitter && !bisect && !emitterParts))
  {
    const int ne = t.Receivers, nb = t.Emitters;
    IrradianceVector* into = &this->Accepted[static_cast<std::size_t>(i) * ne];
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
    if (leafTriangle && !t.Residual.empty() && this->CanSubdivide(receiver))
    {
      if (this->TotalResidual.size() <= static_cast<std::size_t>(i))
      {
        this->TotalResidual.resize(this->Nodes.size());
        this->AcceptedFrom.resize(this->Nodes.size());
      }
      std::vector<double>& total = this->TotalResidual[i];
      total.resize(t.Residual.size(), 0.0);
      for (std::size_t p = 0; p < total.size(); ++p)
      {
        total[p] += t.Residual[p];
      }
      this->AcceptedFrom[i].push_back(j);
    }
    return;
  }
  ++this->Stats.Refinements;
  // A receiver whose basis cannot follow the irradiance is split whatever
  // the sizes.
  if ((clusterEmitter || emitterParts) && !bisect && !(clusterReceiver && fitFails) &&
    (!clusterReceiver || emitter.Data.Area > receiver.Data.Area))
  {
    this->Subdivide(j);
    const std::int32_t k0 = this->Nodes[j].Child[0], k1 = this->Nodes[j].Child[1];
    this->AddShooter(i, k0, next);
    this->AddShooter(i, k1, next);
  }
  else
  {
    this->Subdivide(i);
    const std::int32_t k0 = this->Nodes[i].Child[0], k1 = this->Nodes[i].Child[1];
    this->AddShooter(k0, j, next);
    this->AddShooter(k1, j, next);
  }
}

void FaceClusterRadiosity::CheckSelfTransfer(std::int32_t i, std::vector<PendingTransfer>& next)
{
  // 3.3.3: the self-transfer of a non-convex element, refined into its
  // children's mutual transfers when its error bound is too large. An
  // element that has children exchanges its light between them whatever
  // the bound: only a leaf keeps its self-transfer (PushPull's F_ii), and
  // a subdivided element's own light between its parts went nowhere (the
  // inside of a sphere, one object and so one root, lost 0.2% of the light
  // per bounce: 18% low at reflectance 0.99).
  const FaceClusterElement& e = this->Nodes[i];
  if (e.Data.Convex || e.Data.IsLeaf() || !this->HasUnshot(e))
  {
    return;
  }
  if (e.IsLeaf())
  {
    const double bMax = this->Iteration == 0 ? Mean(RGB(e.Data.EmissionMax)) : this->UnshotMagnitude(e) * BasisBound;
    if (SelfTransferError(e.Data, bMax) <= this->Epsilon)
    {
      return;
    }
    this->Subdivide(i);
  }
  const std::int32_t k0 = this->Nodes[i].Child[0], k1 = this->Nodes[i].Child[1];
  if (k0 >= 0)
  {
    this->AddShooter(k0, k1, next);
    this->AddShooter(k1, k0, next);
  }
}

bool FaceClusterRadiosity::ResolveLights(std::vector<char>& checked)
{
  // The leaves not seen yet, their lights evaluated at their nodes. A leaf
  // is opened when the lights' spread over its nodes is too large, and a
  // cluster also when a point or spot light could bring it more than its
  // nodes see (PunctualLightsBeyondNodes: a spot's cone or a near light
  // between the nodes, a shadow edge among its visibility samples; a floor
  // cluster whose nodes all lay outside a spot's cone received nothing).
  // The punctual lights' part counts times the leaf's reflectance: the
  // output shows their exact light at each point (ShownExact), so their
  // fit serves only the light the leaf reflects. Before, every cluster was
  // opened down to its triangles, and the solution grew with the input (a
  // 940k-triangle bunny room with one point light: 949,638 elements,
  // 8.6 GB, 75 s; now 9,295 elements, 1.0 GB, 8.5 s).
  checked.resize(this->Nodes.size(), 0);
  std::vector<std::int32_t> leaves;
  for (std::size_t e = 0; e < this->Nodes.size(); ++e)
  {
    if (!checked[e] && this->Nodes[e].IsLeaf())
    {
      leaves.push_back(static_cast<std::int32_t>(e));
    }
  }
  if (leaves.empty())
  {
    return false;
  }
  // Per leaf: the spread of the lights over its nodes (W, a transfer error)
  // and their vector irradiance fitted by its basis.
  const int ne = this->IrradianceBasis.Size();
  std::vector<double> spread(leaves.size(), 0.0);
  std::vector<IrradianceVector> fitted(leaves.size() * ne, IrradianceVector{});
  // Their punctual part alone (ExactFit).
  const bool punctual = this->Lights->HasPunctualLights();
  std::vector<IrradianceVector> fittedPunctual(punctual ? leaves.size() * ne : 0, IrradianceVector{});
  WorkShare& share = ShareOrAlone(this->Settings.Share);
  const auto mine = share.Range(leaves.size());
  // Transfers kept (relighting): the sky's visibility kept per node too,
  // cast only at the nodes no solve saw before (the entries made here,
  // filled in parallel below).
  std::vector<KeptSky*> masks(leaves.size(), nullptr);
  std::vector<char> cast(leaves.size(), 0);
  if (this->Couplings && this->Lights->HasSky() && share.Ranks() == 1)
  {
    const std::size_t words = this->Lights->SkyMaskWords();
    for (std::size_t k = 0; k < leaves.size(); ++k)
    {
      const FaceClusterElement& e = this->Nodes[leaves[k]];
      auto found = this->SkyMasks.find(e.Key);
      if (found == this->SkyMasks.end())
      {
        // Kept within the same share of the memory as the couplings; past
        // it the node's sky is cast as without relighting.
        const std::size_t bytes = sizeof(KeptSky) + sizeof(std::uint64_t) + 2 * sizeof(void*) + 3 * 16 +
          e.Rule.Size() * (words * sizeof(std::uint64_t) + sizeof(DirectLighting::SkyMoments));
        if (static_cast<double>(this->Stats.KeptBytes + bytes) > KeptShare * this->Budget)
        {
          continue;
        }
        this->Stats.KeptBytes += bytes;
        found = this->SkyMasks.emplace(e.Key, KeptSky()).first;
        found->second.Masks.assign(e.Rule.Size() * words, 0);
        cast[k] = 1;
      }
      masks[k] = &found->second;
    }
  }
  tbb::parallel_for(mine.first, mine.second, [&](std::size_t k) {
    const FaceClusterElement& e = this->Nodes[leaves[k]];
    std::vector<IrradianceVector> punctualAtNodes;
    const std::vector<IrradianceVector> atNodes =
      this->LightAtNodes(leaves[k], &spread[k], masks[k], cast[k] != 0, punctual ? &punctualAtNodes : nullptr);
    if (!e.Data.IsLeaf())
    {
      spread[k] = std::max(spread[k], this->PunctualLightsBeyondNodes(e));
    }
    for (std::size_t q = 0; q < e.Rule.Size(); ++q)
    {
      for (int a = 0; a < ne; ++a)
      {
        for (int c = 0; c < 3; ++c)
        {
          fitted[k * ne + a][c] += e.Rule.Dual[q * ne + a] * atNodes[q][c];
          if (punctual)
          {
            fittedPunctual[k * ne + a][c] += e.Rule.Dual[q * ne + a] * punctualAtNodes[q][c];
          }
        }
      }
    }
  });
  share.CombineItems(
    leaves.size(),
    [&](std::size_t k, std::vector<char>& bytes) {
      PutBytes(bytes, spread[k]);
      for (int a = 0; a < ne; ++a)
      {
        PutBytes(bytes, fitted[k * ne + a]);
        if (punctual)
        {
          PutBytes(bytes, fittedPunctual[k * ne + a]);
        }
      }
    },
    [&](std::size_t k, const char* data, std::size_t available) {
      std::size_t at = GetBytes(data, available, spread[k]);
      for (int a = 0; a < ne; ++a)
      {
        at += GetBytes(data + at, available - at, fitted[k * ne + a]);
        if (punctual)
        {
          at += GetBytes(data + at, available - at, fittedPunctual[k * ne + a]);
        }
      }
      return at;
    });
  bool subdivided = false;
  for (std::size_t k = 0; k < leaves.size(); ++k)
  {
    const std::int32_t i = leaves[k];
    checked[i] = 1;
    if (spread[k] > this->Epsilon && this->CanSubdivide(this->Nodes[i]))
    {
      this->Subdivide(i);
      if (!this->Nodes[i].IsLeaf())
      {
        subdivided = true;
        continue;
      }
    }
    // An element that stays a leaf receives the lights as a transfer.
    for (int a = 0; a < ne; ++a)
    {
      const std::size_t at = static_cast<std::size_t>(i) * ne + a;
      for (int c = 0; c < 3; ++c)
      {
        this->AcceptedLights[at][c] += fitted[k * ne + a][c];
        if (punctual)
        {
          this->AcceptedPunctual[at][c] += fittedPunctual[k * ne + a][c];
        }
      }
    }
  }
  return subdivided;
}

bool FaceClusterRadiosity::BisectOnTotals(std::vector<PendingTransfer>& pending)
{
  const std::size_t ne = static_cast<std::size_t>(this->IrradianceBasis.Size());
  bool any = false;
  for (std::size_t e = 0; e < this->AcceptedFrom.size(); ++e)
  {
    if (this->AcceptedFrom[e].empty())
    {
      continue;
    }
    FaceClusterElement& receiver = this->Nodes[e];
    // Halved since (the lights' refinement) or too inaccurate in all: its
    // transfers go to its parts.
    bool redo = !receiver.IsLeaf();
    if (!redo)
    {
      const double scale = receiver.Bisections > 0 && receiver.Data.Area > 0.0f
        ? this->GetScene().Area(receiver.Cluster) / receiver.Data.Area
        : 1.0;
      double worst = 0.0;
      for (double r : this->TotalResidual[e])
      {
        worst = std::max(worst, std::abs(r));
      }
      redo = scale * worst > this->PartEpsilon && this->CanSubdivide(receiver);
      if (redo)
      {
        this->Subdivide(static_cast<std::int32_t>(e));
      }
    }
    if (redo && !this->Nodes[e].IsLeaf())
    {
      std::fill_n(this->Accepted.begin() + e * ne, ne, IrradianceVector{});
      const std::int32_t k0 = this->Nodes[e].Child[0], k1 = this->Nodes[e].Child[1];
      for (std::int32_t j : this->AcceptedFrom[e])
      {
        this->AddShooter(k0, j, pending);
        this->AddShooter(k1, j, pending);
      }
      any = true;
      // Kept otherwise: what the element accepts in a later round adds to
      // this sum, and a redo drops all of its light this iteration, so all
      // of it must be listed.
      this->AcceptedFrom[e].clear();
      this->TotalResidual[e].clear();
    }
  }
  return any;
}

void FaceClusterRadiosity::Transport()
{
  this->TotalResidual.clear();
  this->AcceptedFrom.clear();
  const std::size_t ne = static_cast<std::size_t>(this->IrradianceBasis.Size());
  this->Accepted.assign(this->Nodes.size() * ne, IrradianceVector{});
  this->AcceptedLights.clear();
  this->AcceptedPunctual.clear();
  std::vector<PendingTransfer> pending, next;
  for (std::int32_t i : this->Top)
  {
    for (std::int32_t j : this->Top)
    {
      this->AddShooter(i, j, pending);
    }
  }
  std::size_t visited = 0; // elements whose self-transfer was checked
  std::vector<char> leafWhenVisited; // and were leaves then
  std::vector<char> lightsChecked;
  const bool lights = this->Lights && this->Iteration == 0;
  for (;;)
  {
    // An element subdivided since its visit exchanges light between its
    // new children too (CheckSelfTransfer).
    for (std::size_t e = 0; e < visited; ++e)
    {
      if (leafWhenVisited[e] && !this->Nodes[e].IsLeaf())
      {
        leafWhenVisited[e] = 0;
        this->CheckSelfTransfer(static_cast<std::int32_t>(e), pending);
      }
    }
    for (; visited < this->Nodes.size(); ++visited)
    {
      this->CheckSelfTransfer(static_cast<std::int32_t>(visited), pending);
      leafWhenVisited.push_back(this->Nodes[visited].IsLeaf() ? 1 : 0);
    }
    this->Accepted.resize(this->Nodes.size() * ne, IrradianceVector{});
    if (lights)
    {
      this->AcceptedLights.resize(this->Nodes.size() * ne, IrradianceVector{});
      if (this->Lights->HasPunctualLights())
      {
        this->AcceptedPunctual.resize(this->Nodes.size() * ne, IrradianceVector{});
      }
    }
    if (!pending.empty())
    {
      next.clear();
      for (std::size_t first = 0; first < pending.size(); first += TransferBlock)
      {
        const std::size_t n = std::min(TransferBlock, pending.size() - first);
        const std::vector<Transfer> transfers = this->ComputeTransfers(&pending[first], n);
        for (std::size_t k = 0; k < n; ++k)
        {
          this->Resolve(pending[first + k], transfers[k], next); // pairs of elements made before the round
        }
      }
      pending.swap(next);
      continue;
    }
    if (visited < this->Nodes.size())
    {
      continue;
    }
    if (lights && this->ResolveLights(lightsChecked))
    {
      continue;
    }
    if (!this->BisectOnTotals(pending))
    {
      break;
    }
  }
  this->TotalResidual.clear();
  this->AcceptedFrom.clear();
  this->Accepted.resize(this->Nodes.size() * ne, IrradianceVector{});
  if (lights)
  {
    this->AcceptedLights.resize(this->Nodes.size() * ne, IrradianceVector{});
    this->AcceptedPunctual.resize(this->Lights->HasPunctualLights() ? this->Nodes.size() * ne : 0, IrradianceVector{});
  }
  this->NextPowerRGB = RGB(0.0);
  this->ReceivedPower = RGB(0.0);
  for (std::int32_t i : this->Top)
  {
    this->PushPull(i, nullptr, nullptr);
  }
  this->AcceptedLights.clear();
  this->AcceptedLights.shrink_to_fit();
  this->AcceptedPunctual.clear();
  this->AcceptedPunctual.shrink_to_fit();
  this->NextPower = Mean(this->NextPowerRGB);
}

void FaceClusterRadiosity::PushPull(std::int32_t i, const IrradianceVector* up, const IrradianceVector* upExact)
{
  const int ne = this->IrradianceBasis.Size(), nb = this->RadiosityBasis.Size();
  // In the first iteration, with lights or emitters shown exactly, the
  // part of dE that the output replaces by the exact light (ExactFit):
  // every transfer's (all from the emitters then) where the emitters are
  // shown exactly, and the punctual lights' fit.
  const bool exact = this->Iteration == 0 && this->ShowsExact();
  std::vector<IrradianceVector> dE(ne, IrradianceVector{}), dExact(exact ? ne : 0, IrradianceVector{});
  FaceClusterElement& e = this->Nodes[i];
  if (up)
  {
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
          if (exact)
          {
            dExact[b][c] += e.PushE[a * ne + b] * upExact[a][c];
          }
        }
      }
    }
  }
  const std::size_t at = static_cast<std::size_t>(i) * ne;
  const IrradianceVector* received = &this->Accepted[at];
  const IrradianceVector* lights = this->AcceptedLights.empty() ? nullptr : &this->AcceptedLights[at];
  const IrradianceVector* punctual = this->AcceptedPunctual.empty() ? nullptr : &this->AcceptedPunctual[at];
  for (int a = 0; a < ne; ++a)
  {
    for (int c = 0; c < 3; ++c)
    {
      dE[a][c] += received[a][c] + (lights ? lights[a][c] : Vec3(0.0));
      if (exact)
      {
        dExact[a][c] += (this->ExactEmitters ? received[a][c] : Vec3(0.0)) + (punctual ? punctual[a][c] : Vec3(0.0));
      }
    }
  }
  std::fill(e.Next.begin(), e.Next.end(), RGB(0.0));
  e.NextMin = std::numeric_limits<double>::infinity();
  e.NextMax = 0.0;
  if (e.IsLeaf())
  {
    // A non-convex leaf cluster lights itself: of the light it reflects, the
    // fraction F_ii lands on it again (3.3.3's estimate, the mean of the
    // bounds) and is reflected in turn, B = rho (n . dE + F_ii B), so
    // B = rho n . dE / (1 - rho F_ii), and that self-irradiance F_ii B is
    // part of what it receives. The paper's (1 - F_ii) rho n . dE drops it
    // instead, while the transfers from the cluster already send only the
    // part that leaves it (exact visibility over its nodes): a loss of
    // rho F_ii per bounce, amplified by 1 / (1 - rho) in a closed scene
    // (the inside of a sphere of 1280 facets: 0.4% low at rho 0.8, 8% at
    // 0.99 from this alone).
    const double self = 0.5 * (e.Data.SelfFormFactorLower() + e.Data.SelfFormFactorUpper());
    // The reflected radiosity at the element's nodes with each node's own
    // normal, fitted by the radiosity basis; the self-irradiance along the
    // nodes' normals, fitted by the irradiance basis.
    const SurfaceRule& rule = e.Rule;
    std::vector<IrradianceVector> selfLight(ne, IrradianceVector{});
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
        const double rho = e.Data.ReflectanceMean[c];
        const double b = rho * std::max(glm::dot(rule.Normals[q], atNode), 0.0) / (1.0 - rho * self);
        reflected[c] = b;
        this->ReceivedPower[c] += rule.Weights[q] * std::max(glm::dot(rule.Normals[q], atNode), 0.0);
        this->NextPowerRGB[c] += (1.0 - self) * rule.Weights[q] * b; // the part that leaves it
        for (int a = 0; a < nb; ++a)
        {
          e.Next[a][c] += e.RadiosityDual[q * nb + a] * b;
        }
        if (self > 0.0)
        {
          for (int a = 0; a < ne; ++a)
          {
            selfLight[a][c] += rule.Dual[q * ne + a] * (self * b) * rule.Normals[q];
          }
        }
      }
      e.NextMin = std::min(e.NextMin, Mean(reflected));
      e.NextMax = std::max(e.NextMax, Mean(reflected));
    }
    for (int a = 0; a < ne; ++a)
    {
      for (int c = 0; c < 3; ++c)
      {
        e.Irradiance[a][c] += dE[a][c] + selfLight[a][c];
        e.LastIncrement[a][c] = dE[a][c] + selfLight[a][c];
      }
    }
    if (exact)
    {
      e.ExactFit = std::move(dExact);
    }
    return;
  }
  const std::int32_t children[2] = { e.Child[0], e.Child[1] };
  for (std::int32_t k : children)
  {
    this->PushPull(k, dE.data(), exact ? dExact.data() : nullptr);
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
} // namespace radiosity
