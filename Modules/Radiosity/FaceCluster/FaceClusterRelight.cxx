// FaceClusterRadiosity's relighting (Lehtinen et al. 2007, section 6.5,
// carried over to this method): the transfers' couplings kept by a solve
// (KeepTransfers, FaceClusterTransport.cxx) and the relight that solves new
// lights and sky over them.
//
// Why a kept coupling and not the paper's precomputed operator: this method
// keeps no links. Each iteration refines afresh on the light it shoots
// (3.4.1), so which transfers a solve makes depends on the lighting, and a
// fixed operator built for one lighting would be too coarse where a moved
// light brightens what was dark. What does not depend on the lighting is a
// transfer's coupling (its K, the irradiance per unit radiosity at the
// receiver's points, the bounds of 3.3.2 per unit radiosity: rays and form
// factors, nearly all of the solve's time). Keyed by its two elements, a
// coupling serves every later solve that makes the same pair, and the
// oracle still decides with the new light: the relit answer is the fresh
// solve's, and only pairs the new light wants that no solve made before
// cost rays. New emission is the elements' own (SetEmission: the
// hierarchy's clusters carry the emission of the scene they were built on).
#include "Radiosity/FaceCluster/FaceClusterRadiosity.h"
#include "Radiosity/FaceCluster/FaceClusterGeometry.h"

#include <algorithm>

namespace radiosity
{
bool FaceClusterRadiosity::PrecomputeTransfer(const ProgressCallback& progress)
{
  if (this->Settings.Share && this->Settings.Share->Ranks() > 1)
  {
    throw SceneError("face cluster relighting runs on one process (this solve runs on MPI ranks)");
  }
  if (this->HasTransfer())
  {
    return true; // kept by the solve (KeepTransfers)
  }
  this->Couplings = std::make_unique<std::unordered_map<PairKey, TransferCoupling, PairKeyHash>>();
  this->Stats.KeptCouplings = this->Stats.KeptBytes = 0;
  const SolverStatistics stats = this->Solve(progress);
  if (stats.Stop == StopReason::Aborted)
  {
    this->Couplings.reset();
    return false;
  }
  return true;
}

SolverStatistics FaceClusterRadiosity::Relight(std::shared_ptr<const Scene> scene, const ProgressCallback& progress)
{
  if (!scene)
  {
    throw SceneError("face cluster relighting: no scene");
  }
  if (!this->Couplings)
  {
    throw SceneError("face cluster relighting: no transfers kept (PrecomputeTransfer, or KeepTransfers before the "
                     "solve)");
  }
  const Scene& own = this->GetScene();
  std::string why;
  if (!SameSurfaces(own, *scene, &why))
  {
    throw SceneError("face cluster relighting: " + why);
  }
  this->SetEmission(*scene);
  this->Lighting = scene->Lighting;
  return this->Solve(progress);
}

FaceClusterRadiosity::PairKey FaceClusterRadiosity::KeyOf(std::int32_t i, std::int32_t j) const
{
  const FaceClusterElement& emitter = this->Nodes[j];
  const glm::vec3& most = emitter.Data.EmissionMax;
  const bool emits = std::max({ most.x, most.y, most.z }) > 0.0f;
  return { this->Nodes[i].Key, emitter.Key | (emits ? std::uint64_t(1) << 63 : 0) };
}

void FaceClusterRadiosity::SetEmission(const Scene& scene)
{
  const Scene& own = this->GetScene();
  bool same = true;
  for (std::size_t t = 0; t < own.Triangles.size() && same; ++t)
  {
    same = own.Materials[t].Emission == scene.Materials[t].Emission;
  }
  this->OwnEmission.clear();
  this->InternalEmission.clear();
  if (same)
  {
    return;
  }
  // Bottom up, one height at a time, as the hierarchy merged its clusters.
  const FaceClusterHierarchy& h = *this->Clusters;
  const std::size_t n = h.NumberOfTriangles();
  this->OwnEmission.resize(n);
  for (std::size_t t = 0; t < n; ++t)
  {
    this->OwnEmission[t] = scene.Materials[t].Emission;
  }
  this->InternalEmission.resize(h.NumberOfClusters() - n);
  auto withEmission = [&](std::uint32_t id) {
    FaceCluster c;
    if (id < n)
    {
      // A leaf's area as TriangleCluster stores it, without fitting its box.
      c.Area = static_cast<float>(this->GetScene().Area(id));
      c.EmissionMin = c.EmissionMax = c.EmissionMean = glm::vec3(this->OwnEmission[id]);
    }
    else
    {
      const EmissionBounds& e = this->InternalEmission[id - n];
      c.Area = h.InternalCluster(id)->Area;
      c.EmissionMin = e.Min;
      c.EmissionMax = e.Max;
      c.EmissionMean = e.Mean;
    }
    return c;
  };
  for (std::uint32_t i : h.HeightOrder())
  {
    const FaceCluster& c = *h.InternalCluster(static_cast<std::uint32_t>(n) + i);
    FaceCluster merged;
    MergeClusterAttributes(withEmission(c.Child[0]), withEmission(c.Child[1]), merged);
    this->InternalEmission[i] = { merged.EmissionMin, merged.EmissionMax, merged.EmissionMean };
  }
}
} // namespace radiosity
