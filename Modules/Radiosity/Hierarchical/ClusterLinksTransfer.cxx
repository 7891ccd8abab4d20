// Clustered hierarchical radiosity's transfers: the links' form factors from
// sample points with sampled visibility, the gather with first-order vector
// irradiance pushed down the face cluster tree, and the row-sum normalisation
// where a triangle's hemisphere is closed (ClusterLinks.h has the method).
#include "Radiosity/Hierarchical/ClusterLinks.h"

#include "Radiosity/Common/Enclosure.h"
#include "Radiosity/Common/Visibility.h"
#include "Radiosity/FaceCluster/FaceClusterHierarchy.h"
#include "Radiosity/Hierarchical/ClusterExpansion.h"
#include "Radiosity/Hierarchical/HierarchicalNodeRules.h"

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>

namespace radiosity
{
void ClusterLinks::SamplesOf(std::uint32_t node, SamplePoints& s) const
{
  const FaceClusterHierarchy& h = *this->Clusters;
  s.Count = 0;
  auto add = [&](const Vec3& x, const Vec3& n, double w) {
    s.Point[s.Count] = x;
    s.Normal[s.Count] = n;
    s.Weight[s.Count] = w;
    ++s.Count;
  };
  if (IsElement(node))
  {
    const std::uint32_t e = ElementOf(node);
    const TriangleCorners p = { this->Mesh.Corner(e, 0), this->Mesh.Corner(e, 1), this->Mesh.Corner(e, 2) };
    for (const auto& w : hierarchical::RuleA)
    {
      add(hierarchical::At(p, w), this->Mesh[e].Normal, 0.25 * this->Mesh[e].Area);
    }
    return;
  }
  const std::vector<double>& cumulative = h.CumulativeArea();
  const std::vector<std::uint32_t>& order = h.TriangleOrder();
  const FaceCluster& f = *h.InternalCluster(node);
  if (f.Count <= SamplePoints::Most)
  {
    for (std::uint32_t k = f.First; k < f.First + f.Count; ++k)
    {
      const TriangleFrame& frame = this->Frames[order[k]];
      add(frame.Centroid, frame.Normal, frame.Area);
    }
    return;
  }
  const double begin = cumulative[f.First], area = cumulative[f.First + f.Count] - begin;
  for (int k = 0; k < SamplePoints::Most; ++k)
  {
    const double target = begin + (k + 0.5) / SamplePoints::Most * area;
    const auto it = std::upper_bound(cumulative.begin() + f.First + 1, cumulative.begin() + f.First + f.Count + 1, target);
    const std::uint32_t t = order[static_cast<std::size_t>(it - cumulative.begin()) - 1];
    add(this->Frames[t].Centroid, this->Frames[t].Normal, area / SamplePoints::Most);
  }
}

bool ClusterLinks::Compute(const std::vector<Pair>& pending, const std::function<bool()>& keepGoing)
{
  constexpr int Most = SamplePoints::Most;
  std::vector<ScalarLink> scalars(pending.size());
  std::vector<VectorLink> vectors(pending.size());
  constexpr std::size_t Block = 1 << 14;
  for (std::size_t begin = 0; begin < pending.size(); begin += Block)
  {
    if (!keepGoing())
    {
      return false;
    }
    const std::size_t end = std::min(pending.size(), begin + Block);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end, 16), [&](const tbb::blocked_range<std::size_t>& range) {
      SamplePoints rs, qs;
      Vec3 from[Most * Most], to[Most * Most];
      unsigned char visible[Most * Most];
      double seen[Most];
      for (std::size_t i = range.begin(); i != range.end(); ++i)
      {
        const Pair& p = pending[i];
        this->SamplesOf(p.Receiver, rs);
        this->SamplesOf(p.Source, qs);
        const std::size_t pairs = static_cast<std::size_t>(rs.Count) * static_cast<std::size_t>(qs.Count);
        // Closer than sampling is good for (two nodes neither of which can be
        // split): each source point as a disc of its area facing the receiver
        // point, w / (pi r^2 + w) (Wallace, Elmquist & Haines 1989), not the
        // point kernel, which grows without bound as r -> 0.
        const Bounds rb = this->BoundsOf(p.Receiver), qb = this->BoundsOf(p.Source);
        const bool near = rb.Radius + qb.Radius > SampledOpening * glm::length(qb.Centre - rb.Centre);
        const auto disc = [near](double w, double r2) { return near ? Pi * r2 / (Pi * r2 + w) : 1.0; };
        if (this->Rays.Empty())
        {
          std::fill(visible, visible + pairs, static_cast<unsigned char>(1));
        }
        else
        {
          // Sampled visibility in two rounds for a distant pair: a stratified
          // quarter of the rays first (every point in two of them), and the
          // rest only where the quarter disagrees; a quarter that all agree
          // stands for the whole (a pair wholly seen or wholly hidden, most
          // of a large scene's links). A near pair takes every ray.
          std::size_t first = 0, rest = pairs;
          std::size_t index[Most * Most];
          for (int a = 0; a < rs.Count; ++a)
          {
            for (int b = 0; b < qs.Count; ++b)
            {
              const std::size_t k = near || pairs <= QuarterRays || (a - b) % 4 != 0 ? --rest : first++;
              index[k] = static_cast<std::size_t>(a * qs.Count + b);
              from[k] = rs.Point[a];
              to[k] = qs.Point[b];
            }
          }
          unsigned char tested[Most * Most];
          this->Rays.TestSegments(from, to, first, tested);
          const bool agree = first > 0 && std::all_of(tested, tested + first, [&](unsigned char v) { return v == tested[0]; });
          if (agree)
          {
            std::fill(tested + first, tested + pairs, tested[0]);
          }
          else
          {
            this->Rays.TestSegments(from + first, to + first, pairs - first, tested + first);
          }
          for (std::size_t k = 0; k < pairs; ++k)
          {
            visible[index[k]] = tested[k];
          }
        }
        if (IsElement(p.Receiver))
        {
          // The mean over the element's points, each in its own half-space.
          double f = 0.0;
          for (int a = 0; a < rs.Count; ++a)
          {
            for (int b = 0; b < qs.Count; ++b)
            {
              const Vec3 d = qs.Point[b] - rs.Point[a];
              const double r2 = glm::dot(d, d);
              if (visible[a * qs.Count + b] && r2 > 0)
              {
                const double r = std::sqrt(r2);
                f += qs.Weight[b] * disc(qs.Weight[b], r2) * std::max(0.0, -glm::dot(qs.Normal[b], d) / r) *
                  std::max(0.0, glm::dot(rs.Normal[a], d) / r) / (Pi * r2);
              }
            }
          }
          scalars[i] = { ElementOf(p.Receiver), p.Source, static_cast<float>(f / rs.Count) };
          continue;
        }
        // A cluster: the vector irradiance per unit radiosity at its centroid
        // and its gradient, each source point weighted by the fraction of the
        // receiver's points that see it. A point source y of area w and
        // normal m gives at x, with d = x - y and r = |d|:
        //   E(x) = -w (m . d) d / (pi r^4),
        //   dE_j/dx_k = -w (m_k d_j + (m . d) delta_jk - 4 (m . d) d_j d_k / r^2) / (pi r^4).
        // Only the receiver's points that face a source point judge its
        // visibility: the others' rays start into their own surface (a leaf
        // cluster's cone may be wide).
        for (int b = 0; b < qs.Count; ++b)
        {
          int count = 0, facing = 0;
          for (int a = 0; a < rs.Count; ++a)
          {
            if (glm::dot(rs.Normal[a], qs.Point[b] - rs.Point[a]) > 0)
            {
              ++facing;
              count += visible[a * qs.Count + b] != 0;
            }
          }
          seen[b] = facing > 0 ? static_cast<double>(count) / facing : 0.0;
        }
        const Vec3 c(this->Clusters->InternalCluster(p.Receiver)->Centroid);
        // A nearly flat receiver's plane (Refine); a leaf of a wider cone has
        // each triangle clamp its own share (Descend).
        const bool clip = rb.ConeAngle <= NearlyFlatCone;
        const Vec3 axis = rb.Axis;
        Vec3 e(0.0);
        double g[9] = { 0, 0, 0, 0, 0, 0, 0, 0, 0 };
        for (int b = 0; b < qs.Count; ++b)
        {
          const Vec3 d = c - qs.Point[b];
          const double r2 = glm::dot(d, d);
          const double md = glm::dot(qs.Normal[b], d);
          // Behind the receiver's plane (a nearly flat receiver that the
          // source straddles; Refine) or facing away: no light.
          if (!(seen[b] > 0) || !(r2 > 0) || md <= 0 || (clip && glm::dot(axis, d) >= 0))
          {
            continue;
          }
          const double w = seen[b] * qs.Weight[b] * disc(qs.Weight[b], r2) / (Pi * r2 * r2);
          e -= w * md * d;
          for (int k = 0; k < 3; ++k)
          {
            for (int j = 0; j < 3; ++j)
            {
              g[3 * k + j] -= w * (qs.Normal[b][k] * d[j] + (j == k ? md : 0.0) - 4.0 * md * d[j] * d[k] / r2);
            }
          }
        }
        VectorLink& l = vectors[i];
        l.Receiver = p.Receiver;
        l.Source = p.Source;
        l.Factor = glm::vec3(e);
        for (int k = 0; k < 9; ++k)
        {
          l.Gradient[k] = static_cast<float>(g[k]);
        }
        // A curved leaf: the links that some of its triangles face away from
        // are clamped per triangle (Descend); one that none faces is dropped.
        const Facing facing = clip || !rb.Leaf ? Facing::All : FacingOf(l, c, rb);
        l.Straddles = facing == Facing::Some;
        if (facing == Facing::None)
        {
          l.Factor = glm::vec3(0.0f);
        }
      }
    });
  }
  for (std::size_t i = 0; i < pending.size(); ++i)
  {
    if (IsElement(pending[i].Receiver))
    {
      if (scalars[i].Factor > 0)
      {
        this->ToElements.push_back(scalars[i]);
      }
    }
    else if (vectors[i].Factor != glm::vec3(0.0f))
    {
      this->ToClusters.push_back(vectors[i]);
    }
  }
  this->Index();
  return true;
}

using cluster_detail::Expansion;

void ClusterLinks::Descend(std::uint32_t position, const void* aboveExpansion, const std::vector<Carried>& carried,
  std::vector<RGB>& out) const
{
  const Expansion& above = *static_cast<const Expansion*>(aboveExpansion);
  const DescentNode& node = this->Preorder[position];
  const std::uint32_t c = node.Id;
  if (c < this->Triangles)
  {
    const Vec3& x = node.Point;
    const Vec3& n = node.Normal;
    RGB v[3];
    above.At(x, v);
    RGB sum = glm::max(n.x * v[0] + n.y * v[1] + n.z * v[2], RGB(0.0));
    // The carried links, each clamped to the triangle's own half-space.
    for (const Carried& l : carried)
    {
      const double e = glm::dot(n, cluster_detail::FactorAt(l.Link->Factor, l.Link->Gradient, x - l.Origin));
      if (e > 0)
      {
        sum += e * l.B;
      }
    }
    out[c] = sum;
    return;
  }
  const std::size_t i = c - this->Triangles;
  Expansion here;
  here.Centre = node.Point;
  above.At(here.Centre, here.E);
  std::copy(std::begin(above.G), std::end(above.G), std::begin(here.G));
  // Links carried from a curved leaf above (ClusterLinksCurvedLeaves.cxx):
  // summed where every triangle below faces them, dropped where none does.
  std::vector<Carried> down;
  for (const Carried& l : carried)
  {
    switch (this->FacingAt(l, i))
    {
      case Facing::All:
        here.Add(cluster_detail::FactorAt(l.Link->Factor, l.Link->Gradient, here.Centre - l.Origin), l.Link->Gradient,
          l.B);
        break;
      case Facing::Some:
        down.push_back(l);
        break;
      case Facing::None:
        break;
    }
  }
  // Its own links; those that some of its triangles face away from (a
  // curved leaf's) are carried down to be clamped per triangle.
  for (std::uint32_t k = this->ClusterOffsets[i]; k < this->ClusterOffsets[i + 1]; ++k)
  {
    const VectorLink& l = this->ToClusters[k];
    if (l.Straddles)
    {
      down.push_back({ &l, this->RadiosityOf(l.Source), here.Centre });
    }
    else
    {
      here.Add(Vec3(l.Factor), l.Gradient, this->RadiosityOf(l.Source));
    }
  }
  // In parallel only without carried links: a link's subtree is walked by
  // one thread, in the order its recorded decisions replay (FacingAt).
  this->VisitChildren(
    position, down.empty(), [&](std::uint32_t child) { this->Descend(child, &here, down, out); });
}

ClusterLinks::Facing ClusterLinks::FacingAt(const Carried& l, std::size_t internal) const
{
  std::vector<Facing>& decisions = this->FacingDecisions[l.Link->Straddling];
  if (this->FacingRecorded)
  {
    return decisions[this->FacingCursor[l.Link->Straddling]++];
  }
  decisions.push_back(FacingOf(*l.Link, l.Origin, this->InternalBounds[internal]));
  return decisions.back();
}

void ClusterLinks::Gather(std::vector<RGB>& triangleIrradiance, std::vector<RGB>& elementIrradiance) const
{
  const std::size_t elements = this->Mesh.Elements().size();
  triangleIrradiance.assign(this->Triangles, RGB(0.0));
  elementIrradiance.assign(elements, RGB(0.0));
  if (!this->ToClusters.empty())
  {
    const Expansion none;
    std::fill(this->FacingCursor.begin(), this->FacingCursor.end(), 0u);
    tbb::parallel_for(std::size_t(0), this->RootPositions.size(),
      [&](std::size_t r) { this->Descend(this->RootPositions[r], &none, {}, triangleIrradiance); });
    this->FacingRecorded = true;
  }
  const std::size_t indexed = std::min(elements, this->ElementOffsets.empty() ? 0 : this->ElementOffsets.size() - 1);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, indexed, 256), [&](const tbb::blocked_range<std::size_t>& range) {
    for (std::size_t e = range.begin(); e != range.end(); ++e)
    {
      RGB sum(0.0);
      for (std::uint32_t k = this->ElementOffsets[e]; k < this->ElementOffsets[e + 1]; ++k)
      {
        sum += double(this->ToElements[k].Factor) * this->RadiosityOf(this->ToElements[k].Source);
      }
      elementIrradiance[e] = sum;
    }
  });
}

std::size_t ClusterLinks::Normalize(const std::vector<double>& polygonFactors, std::vector<double>& scale)
{
  const Scene& scene = this->SourceScene;
  const std::size_t n = this->Triangles;
  if (this->Closed.empty())
  {
    const Visibility all(scene, Visibility::AllTriangles(scene));
    std::vector<std::uint32_t> every(n);
    for (std::size_t t = 0; t < n; ++t)
    {
      every[t] = static_cast<std::uint32_t>(t);
    }
    this->Closed = EnclosedTriangles(scene, all, every, 2.0 * this->Diagonal);
  }
  // The cluster links' form factor sums: a gather of radiosity 1, then per
  // leaf what its chain receives.
  const std::vector<RGB>* radiosity = this->ElementRadiosity;
  const std::size_t elements = this->Mesh.Elements().size();
  const std::vector<RGB> ones(elements, RGB(1.0));
  this->ElementRadiosity = &ones;
  this->PullRadiosity();
  std::vector<RGB> perTriangle, perElement;
  this->Gather(perTriangle, perElement);
  this->ElementRadiosity = radiosity;
  scale.assign(elements, 1.0);
  std::vector<unsigned char> scaled(elements, 0);
  tbb::parallel_for(std::size_t(0), elements, [&](std::size_t i) {
    const auto e = static_cast<std::uint32_t>(i);
    const Element& el = this->Mesh[e];
    if (!el.IsLeaf() || !this->Closed[el.Source])
    {
      return;
    }
    double clustered = perTriangle[el.Source].x;
    for (std::int32_t a = static_cast<std::int32_t>(e); a >= 0; a = this->Mesh[static_cast<std::uint32_t>(a)].Parent)
    {
      clustered += perElement[static_cast<std::size_t>(a)].x;
    }
    const double wanted = 1.0 - polygonFactors[i];
    // Far from 1 the links, not the quadrature, are wrong: left alone.
    if (clustered > 0 && wanted > 0.5 * clustered && wanted < 2.0 * clustered)
    {
      scale[i] = wanted / clustered;
      scaled[i] = 1;
    }
  });
  return static_cast<std::size_t>(std::count(scaled.begin(), scaled.end(), 1));
}
} // namespace radiosity
