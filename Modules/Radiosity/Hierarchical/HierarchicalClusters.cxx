// Hierarchical radiosity with clustering: the links start between the roots
// of the face cluster hierarchy and reach the polygon solver's quadtrees only
// where two input triangles meet (ClusterLinks.h has the method and its
// papers: Smits, Arvo & Greenberg 1994; Sillion 1995; Willmott et al. 1999).
#include "Radiosity/Hierarchical/HierarchicalRadiosity.h"

#include "Radiosity/Common/MemoryBudget.h"
#include "Radiosity/FaceCluster/FaceClusterHierarchy.h"
#include "Radiosity/Hierarchical/ClusterLinks.h"

#include <tbb/parallel_for.h>

#include <string>

namespace radiosity
{
namespace
{
// A cluster link: the pending pair and the link kept (receiver, source, a
// float vector), the kept list growing by doubling.
constexpr double BytesPerClusterLink = 8.0 + 1.5 * 20.0;
} // namespace

RGB HierarchicalRadiosity::ClusterIrradiance(std::uint32_t leaf) const
{
  if (!this->ClusterSolve)
  {
    return RGB(0.0);
  }
  const ElementMesh& mesh = *this->Elements;
  RGB sum = this->ClusterDown[mesh[leaf].Source];
  for (std::int32_t a = static_cast<std::int32_t>(leaf); a >= 0; a = mesh[static_cast<std::uint32_t>(a)].Parent)
  {
    if (static_cast<std::size_t>(a) < this->ElementDown.size())
    {
      sum += this->ElementDown[static_cast<std::size_t>(a)];
    }
  }
  return (leaf < this->ClusterScale.size() ? this->ClusterScale[leaf] : 1.0) * sum;
}

std::size_t HierarchicalRadiosity::NumberOfClusterLinks() const
{
  return this->ClusterSolve ? this->ClusterSolve->NumberOfLinks() : 0;
}

bool HierarchicalRadiosity::InitialClusterLinks(
  std::vector<PendingLink>& out, const std::function<bool()>& keepGoing, const ProgressCallback& progress)
{
  std::shared_ptr<const FaceClusterHierarchy> hierarchy;
  try
  {
    FaceClusterOptions options;
    options.Threads = this->Settings.Threads;
    hierarchy = FaceClusterHierarchy::Shared(this->SourceScene, options,
      [&](const ProgressStatus& status) {
        ProgressStatus s = status;
        s.Phase = "clustering";
        return !progress || progress(s);
      });
  }
  catch (const FaceClusterBuildAborted&)
  {
    return false;
  }
  this->ClusterSolve = std::make_unique<ClusterLinks>(this->SourceScene, hierarchy, *this->Rays,
    this->SceneInfo.Diagonal > 0 ? this->SceneInfo.Diagonal : 1.0, this->PlaneTolerance, *this->Elements,
    [this](std::uint32_t e) { return this->Children(e); }, this->MinEdge,
    this->NodeRadiosity);
  ClusterLinks& clusters = *this->ClusterSolve;
  const double nodes = static_cast<double>(this->Elements->Elements().size()) * BytesPerNode();
  const double rootPairs = static_cast<double>(clusters.NumberOfRootPairs());
  CheckMemoryBudget(nodes + static_cast<double>(clusters.MemoryBytes()) + rootPairs * BytesPerClusterLink, this->Budget,
    "clustered hierarchical radiosity: the first links between the " +
      std::to_string(hierarchy->Roots().size()) + " objects' cluster roots",
    "join objects (fewer object ids) or use --method meshless");
  const double budgetLinks = this->Budget > 0 ? (this->Budget - nodes) / BytesPerClusterLink : 1e300;
  clusters.BeforeLink = [this, budgetLinks](std::size_t links) {
    if (static_cast<double>(links) + 1 > budgetLinks)
    {
      CheckMemoryBudget(static_cast<double>(links + 1) * BytesPerClusterLink +
          static_cast<double>(this->Elements->Elements().size()) * BytesPerNode(),
        this->Budget, "clustered hierarchical radiosity: refining to " + std::to_string(links + 1) + " cluster links",
        "raise --link-tolerance (LinkTolerance)");
    }
  };
  std::vector<ClusterLinks::Pair> pending;
  clusters.PullRadiosity();
  const auto elements = [&](std::uint32_t p, std::uint32_t q) { this->Refine(p, q, out); };
  return clusters.LinkRoots(this->Epsilon, pending, elements, keepGoing) && clusters.Compute(pending, keepGoing);
}

std::size_t HierarchicalRadiosity::RefineClusterLinks(std::vector<PendingLink>& out, bool deferredOnly)
{
  if (!this->ClusterSolve)
  {
    return 0;
  }
  ClusterLinks& clusters = *this->ClusterSolve;
  clusters.PullRadiosity();
  std::vector<ClusterLinks::Pair> pending;
  const auto elements = [&](std::uint32_t p, std::uint32_t q) { this->Refine(p, q, out); };
  const std::size_t changed = deferredOnly ? clusters.LinkDeferred(this->Epsilon, pending, elements)
                                           : clusters.RefineAgain(this->Epsilon, pending, elements);
  clusters.Compute(pending, []() { return true; });
  return changed;
}

void HierarchicalRadiosity::NormalizeClusters()
{
  if (!this->ClusterSolve)
  {
    return;
  }
  // Each leaf's polygon links: the sum of the factors of its chain, the
  // unoccluded ones as Normalize scaled them.
  const ElementMesh& mesh = *this->Elements;
  const std::size_t n = mesh.Elements().size();
  std::vector<double> polygon(n, 0.0);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    const auto e = static_cast<std::uint32_t>(i);
    if (!mesh[e].IsLeaf())
    {
      return;
    }
    double f = 0.0;
    for (std::int32_t a = static_cast<std::int32_t>(e); a >= 0; a = mesh[static_cast<std::uint32_t>(a)].Parent)
    {
      const auto node = static_cast<std::uint32_t>(a);
      for (std::uint32_t l = this->LinkOffsets[node]; l < this->LinkOffsets[node + 1]; ++l)
      {
        const HierarchicalLink& link = this->LinkList[l];
        f += link.Kind == HierarchicalLink::Visible ? this->Normalization[e] * link.Factor : link.Factor;
      }
    }
    polygon[i] = f;
  });
  this->ClusterSolve->Normalize(polygon, this->ClusterScale);
}

void HierarchicalRadiosity::GatherClusters()
{
  if (!this->ClusterSolve)
  {
    return;
  }
  this->ClusterSolve->PullRadiosity();
  this->ClusterSolve->Gather(this->ClusterDown, this->ElementDown);
}
} // namespace radiosity
