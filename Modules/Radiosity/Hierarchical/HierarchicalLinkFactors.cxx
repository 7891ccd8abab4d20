// Hierarchical radiosity's link form factors (Hanrahan, Salzman and
// Aupperle 1991, section 4; the blockers of partial links for Hardt and
// Teller's backprojection) and the row normalisation that keeps a closed
// room's form factors summing to one; on MPI ranks each rank computes its
// share (WorkShare.h).
#include "Radiosity/Hierarchical/HierarchicalRadiosity.h"

#include "Radiosity/Common/FormFactor.h"
#include "Radiosity/Common/SceneAnalysis.h"
#include "Radiosity/Common/Visibility.h"
#include "Radiosity/FaceCluster/FaceClusterDescent.h"
#include "Radiosity/Hierarchical/ClusterLinks.h"
#include "Radiosity/Hierarchical/HierarchicalNodeRules.h"
#include "Radiosity/Hierarchical/Shaft.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <functional>

namespace radiosity
{
using hierarchical::At;
using hierarchical::RuleA;
using hierarchical::RuleB;

bool HierarchicalRadiosity::ComputeLinks(const std::vector<PendingLink>& pending,
  SolverStatistics& stats, const std::function<bool()>& keepGoing)
{
  struct Result
  {
    HierarchicalLink Link;
    std::vector<std::uint32_t> Blockers;
  };
  std::vector<Result> results(pending.size());
  const Scene& scene = this->SourceScene;
  // In blocks, so that an abort is seen between them (progress and abort go
  // through this thread, not the workers).
  // MPI ranks: each computes its share of every block, then every rank holds
  // every link (WorkShare.h); the blocks, and so the abort checks, are the same on every rank.
  WorkShare& share = ShareOrAlone(this->Settings.Share);
  constexpr std::size_t Block = 1 << 14;
  for (std::size_t begin = 0; begin < pending.size(); begin += Block)
  {
    if (!keepGoing())
    {
      return false;
    }
    const std::size_t blockSize = std::min(pending.size(), begin + Block) - begin;
    const auto mine = share.Range(blockSize);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(begin + mine.first, begin + mine.second, 16),
      [&](const tbb::blocked_range<std::size_t>& range) {
        std::vector<TriangleCorners> blockerCorners;
        std::vector<std::array<std::uint32_t, 3>> blockerIds;
        for (std::size_t i = range.begin(); i != range.end(); ++i)
        {
          Result& res = results[i];
          HierarchicalLink& link = res.Link;
          link.Receiver = pending[i].Receiver;
          link.Source = pending[i].Source;
          const TriangleCorners p = this->Corners(link.Receiver);
          const TriangleCorners q = this->Corners(link.Source);
          const Vec3& n = (*this->Elements)[link.Receiver].Normal;
          // Candidate blockers: occluders near the shaft (the BVH's boxes that
          // meet its bounding sphere), inside the shaft's hull planes and with a
          // vertex in front of both nodes. A superset is harmless:
          // backprojection is exact, and a candidate that hides nothing
          // subtracts nothing.
          const Element& pe = (*this->Elements)[link.Receiver];
          const Element& qe = (*this->Elements)[link.Source];
          if (!this->Rays->Empty())
          {
            const Vec3 centre = (p[0] + p[1] + p[2] + q[0] + q[1] + q[2]) / 6.0;
            double radius = 0.0;
            for (int k = 0; k < 3; ++k)
            {
              radius = std::max({ radius, glm::length(p[k] - centre), glm::length(q[k] - centre) });
            }
            const Shaft shaft(p, q);
            const std::function<bool(std::uint32_t)> blocks = [&](std::uint32_t b) {
              if (b == pe.Source || b == qe.Source ||
                shaft.Excludes({ scene.Vertex(b, 0), scene.Vertex(b, 1), scene.Vertex(b, 2) }))
              {
                return false;
              }
              bool frontP = false, frontQ = false;
              for (int k = 0; k < 3; ++k)
              {
                const Vec3 v = scene.Vertex(b, k);
                frontP = frontP || glm::dot(v - pe.Centroid, pe.Normal) > this->PlaneTolerance;
                frontQ = frontQ || glm::dot(v - qe.Centroid, qe.Normal) > this->PlaneTolerance;
              }
              return frontP && frontQ;
            };
            // Past MaxBlockersPerLink the list is cut to the rays' below, so
            // the query stops there: a shaft across a dense mesh would
            // otherwise list every triangle in its sphere.
            if (this->ClusterSolve)
            {
              // The boxes of the face cluster hierarchy against the shaft and
              // the two nodes' planes: a dense mesh beside the shaft is ruled
              // out a cluster at a time.
              const std::vector<unsigned char>& occludes = this->SceneInfo.CanOcclude;
              const auto mayBlock = [&](const FaceCluster& c) {
                // The boxes are single precision: grown to hold their triangles.
                const double grow = 1e-5 * glm::length(Vec3(c.HalfSize)) + this->PlaneTolerance;
                double outside = 0.0; // from the link's sphere's centre to the box
                for (int k = 0; k < 3; ++k)
                {
                  const double along = std::fabs(glm::dot(centre - Vec3(c.Centre), Vec3(c.Axis[k])));
                  const double beyond = std::max(0.0, along - (double(c.HalfSize[k]) + grow));
                  outside += beyond * beyond;
                }
                if (outside > radius * radius)
                {
                  return false;
                }
                Vec3 corner[8];
                GrownBoxCorners(c, 0.0, grow, corner);
                double frontP = -1e300, frontQ = -1e300;
                for (int k = 0; k < 8; ++k)
                {
                  frontP = std::max(frontP, glm::dot(corner[k] - pe.Centroid, pe.Normal));
                  frontQ = std::max(frontQ, glm::dot(corner[k] - qe.Centroid, qe.Normal));
                }
                return frontP > this->PlaneTolerance && frontQ > this->PlaneTolerance && !shaft.Excludes(corner, 8);
              };
              // At most MaxBlockersPerLink + 1 kept: past that the rays decide.
              DescendClusters(this->ClusterSolve->Hierarchy(), mayBlock, [&](std::uint32_t b) {
                if ((occludes.empty() || occludes[b]) && blocks(b))
                {
                  res.Blockers.push_back(b);
                }
                return res.Blockers.size() <= this->Settings.MaxBlockersPerLink;
              });
            }
            else
            {
              this->Rays->OccludersInSphere(centre, radius, blocks, this->Settings.MaxBlockersPerLink, res.Blockers);
            }
            std::sort(res.Blockers.begin(), res.Blockers.end());
          }
          if (res.Blockers.size() > this->Settings.MaxBlockersPerLink)
          {
            {
              // Too many candidates: keep those the rays between the nodes meet.
              std::vector<std::uint32_t> hit;
              Vec3 from[16], to[16];
              for (int a = 0; a < 4; ++a)
              {
                for (int b = 0; b < 4; ++b)
                {
                  from[4 * a + b] = At(p, RuleA[a]);
                  to[4 * a + b] = At(q, RuleA[b]);
                }
              }
              Vec3 f[32], t[32];
              for (int a = 0; a < 4; ++a)
              {
                for (int b = 0; b < 4; ++b)
                {
                  f[8 * a + 2 * b] = At(p, RuleA[a]);
                  t[8 * a + 2 * b] = At(q, RuleB[b]);
                  f[8 * a + 2 * b + 1] = At(p, RuleB[a]);
                  t[8 * a + 2 * b + 1] = At(q, RuleA[b]);
                }
              }
              this->Rays->CollectOccluders(from, to, 16, hit);
              this->Rays->CollectOccluders(f, t, 32, hit);
              unsigned char passes[48];
              this->Rays->TestSegments(from, to, 16, passes);
              this->Rays->TestSegments(f, t, 32, passes + 16);
              link.VisibleFraction = static_cast<float>(std::count(passes, passes + 48, 1)) / 48.0f;
              std::sort(hit.begin(), hit.end());
              hit.erase(std::unique(hit.begin(), hit.end()), hit.end());
              hit.erase(std::remove_if(hit.begin(), hit.end(),
                          [&](std::uint32_t b) { return b == pe.Source || b == qe.Source; }),
                hit.end());
              if (hit.size() > this->Settings.MaxBlockersPerLink)
              {
                hit.resize(this->Settings.MaxBlockersPerLink);
              }
              link.BlockersCut = true;
              res.Blockers.swap(hit);
            }
          }
          link.Kind = res.Blockers.empty() ? HierarchicalLink::Visible : HierarchicalLink::Partial;
          // The blockers to backproject through (none for a cut link, whose
          // rays' passing fraction stands for them), the two coplanar
          // triangles of a quad as one.
          blockerCorners.clear();
          blockerIds.clear();
          for (std::uint32_t b : link.BlockersCut ? std::vector<std::uint32_t>() : res.Blockers)
          {
            blockerCorners.push_back({ scene.Vertex(b, 0), scene.Vertex(b, 1), scene.Vertex(b, 2) });
            blockerIds.push_back(scene.Triangles[b].V);
          }
          const std::vector<BlockerPolygon> blockers = MergeCoplanarPairs(blockerCorners, blockerIds);
          // Receiver-area mean of the point form factor: the centroids of the
          // uniform midpoint subdivision, finer where the source is close (the
          // kernel varies fastest there, and the sums over a closed room must
          // stay 1 to 1e-4 for reflectance 0.999).
          const double distance = glm::length(
            (*this->Elements)[link.Source].Centroid - (*this->Elements)[link.Receiver].Centroid);
          const double size = this->Elements->LongestEdge(link.Receiver);
          const int splits = distance < 1.5 * size ? 8 : distance < 4 * size ? 4 : 2;
          double f = 0.0;
          int count = 0;
          auto accumulate = [&](double s, double t) {
            const double w[3] = { 1.0 - s - t, s, t };
            const Vec3 x = At(p, w);
            f += link.Kind == HierarchicalLink::Partial && !link.BlockersCut
              ? VisibleFormFactor(x, n, q, blockers.data(), blockers.size())
              : PointToPolygonFormFactor(x, n, q.data(), 3);
            ++count;
          };
          for (int i = 0; i < splits; ++i)
          {
            for (int j = 0; i + j < splits; ++j)
            {
              accumulate((i + 1.0 / 3) / splits, (j + 1.0 / 3) / splits);
              if (i + j < splits - 1)
              {
                accumulate((i + 2.0 / 3) / splits, (j + 2.0 / 3) / splits);
              }
            }
          }
          f /= count;
          link.Factor = link.BlockersCut ? link.VisibleFraction * f : f;
        }
      });
    share.CombineItems(
      blockSize,
      [&](std::size_t i, std::vector<char>& bytes) {
        const Result& res = results[begin + i];
        PutBytes(bytes, res.Link);
        PutBytes(bytes, static_cast<std::uint64_t>(res.Blockers.size()));
        for (std::uint32_t b : res.Blockers)
        {
          PutBytes(bytes, b);
        }
      },
      [&](std::size_t i, const char* data, std::size_t size) {
        Result& res = results[begin + i];
        std::size_t at = GetBytes(data, size, res.Link);
        std::uint64_t count = 0;
        at += GetBytes(data + at, size - at, count);
        if (count > (size - at) / sizeof(std::uint32_t))
        {
          ThrowShortShare(size - at, static_cast<std::size_t>(count) * sizeof(std::uint32_t));
        }
        res.Blockers.resize(static_cast<std::size_t>(count));
        for (std::uint32_t& b : res.Blockers)
        {
          at += GetBytes(data + at, size - at, b);
        }
        return at;
      });
  }
  for (Result& r : results)
  {
    r.Link.FirstBlocker = static_cast<std::uint32_t>(this->BlockerPool.size());
    r.Link.BlockerCount = static_cast<std::uint32_t>(r.Blockers.size());
    this->BlockerPool.insert(this->BlockerPool.end(), r.Blockers.begin(), r.Blockers.end());
    this->LinkList.push_back(r.Link);
    stats.PartialLinks += r.Link.Kind == HierarchicalLink::Partial;
    stats.HiddenLinks += r.Link.Kind == HierarchicalLink::Hidden;
  }
  return true;
}

void HierarchicalRadiosity::Normalize()
{
  const ElementMesh& mesh = *this->Elements;
  const std::size_t n = mesh.Elements().size();
  WorkShare& share = ShareOrAlone(this->Settings.Share); // MPI ranks: a share of the leaves each
  const auto mine = share.Range(n);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(mine.first, mine.second, 64),
    [&](const tbb::blocked_range<std::size_t>& range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i)
      {
        const auto e = static_cast<std::uint32_t>(i);
        if (!mesh[e].IsLeaf())
        {
          continue;
        }
        const TriangleCorners p = this->Corners(e);
        Vec3 points[4];
        for (int k = 0; k < 4; ++k)
        {
          points[k] = At(p, RuleA[k]);
        }
        double approximate = 0.0, exact = 0.0;
        for (std::int32_t a = static_cast<std::int32_t>(e); a >= 0; a = mesh[static_cast<std::uint32_t>(a)].Parent)
        {
          const auto node = static_cast<std::uint32_t>(a);
          for (std::uint32_t l = this->LinkOffsets[node]; l < this->LinkOffsets[node + 1]; ++l)
          {
            const HierarchicalLink& link = this->LinkList[l];
            if (link.Kind != HierarchicalLink::Visible)
            {
              continue;
            }
            approximate += link.Factor;
            const TriangleCorners q = this->Corners(link.Source);
            for (const Vec3& x : points)
            {
              exact += 0.25 * PointToPolygonFormFactor(x, mesh[e].Normal, q.data(), 3);
            }
          }
        }
        this->Normalization[e] = approximate > 0 ? exact / approximate : 1.0;
      }
    });
  share.Combine(this->Normalization.data(), n);
  this->NormalizeClusters();
}
} // namespace radiosity
