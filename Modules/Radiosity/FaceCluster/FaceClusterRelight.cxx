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
// cost rays.
#include "Radiosity/FaceCluster/FaceClusterRadiosity.h"

#include <sstream>

namespace radiosity
{
namespace
{
std::string Text(const RGB& c)
{
  std::ostringstream s;
  s << "(" << c.r << ", " << c.g << ", " << c.b << ")";
  return s.str();
}
}

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
  for (std::size_t t = 0; t < own.Triangles.size(); ++t)
  {
    if (own.Materials[t].Emission != scene->Materials[t].Emission)
    {
      throw SceneError("face cluster relighting: the emission of triangle " + std::to_string(t) + " changed from " +
        Text(own.Materials[t].Emission) + " to " + Text(scene->Materials[t].Emission) +
        ": the face clusters carry their triangles' emission, so only lights and the sky may change (solve again; "
        "meshless relighting takes new emission)");
    }
  }
  this->Lighting = scene->Lighting;
  return this->Solve(progress);
}
} // namespace radiosity
