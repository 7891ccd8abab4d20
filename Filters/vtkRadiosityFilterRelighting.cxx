// vtkRadiosityFilter's Relighting mode (Lehtinen et al. 2007, section 6.5):
// whether a kept transfer serves a request, the relight, and the
// precomputation after a solve.
#include "vtkRadiosityFilter.h"

#include "vtkMultiProcessController.h"

#include "Radiosity/Common/RadiositySolver.h"
#include "Radiosity/FaceCluster/FaceClusterRadiosity.h"
#include "Radiosity/Meshless/MeshlessRadiosity.h"

#include <chrono>
#include <sstream>
#include <string>

namespace
{
bool StartsWith(const std::string& text, const char* prefix)
{
  return text.compare(0, std::char_traits<char>::length(prefix), prefix) == 0;
}
}

bool vtkRadiosityFilter::RelightWith(std::shared_ptr<radiosity::RadiositySolver> previous,
  const std::shared_ptr<const radiosity::Scene>& scene, const radiosity::ProgressCallback& progress,
  bool distributed)
{
  this->RelightingStatus = this->Relighting ? "pending" : "off";
  if (!this->Relighting || !previous || !previous->HasRelighting())
  {
    return false;
  }
  // The kept transfer applies when the settings are those it was
  // precomputed with and the surfaces are the same (the solver checks them
  // and refuses, naming the difference, before changing anything).
  if (distributed || this->RelightingSettingsKey() != this->RelightingSettings)
  {
    const std::string why = distributed ? "the request runs on MPI ranks"
                                        : "the method's settings changed since the precomputation";
    this->Warn("relighting invalidated: " + why + "; solving and precomputing again");
    this->RelightingStatus = "invalidated: " + why;
    return false;
  }
  try
  {
    previous->SetRelightGatherSeconds(this->MaxRelightGatherTime);
    this->Statistics = previous->Relight(scene, progress);
  }
  catch (const radiosity::SceneError& e)
  {
    this->Warn(std::string("relighting invalidated: ") + e.what());
    this->RelightingStatus = std::string("invalidated: ") + e.what();
    return false;
  }
  this->Solver = std::move(previous);
  if (const auto meshless = this->GetMeshlessSolution())
  {
    const radiosity::MeshlessStatistics& m = meshless->Statistics();
    std::ostringstream status;
    status << "relit: direct light " << m.RelightDirectSeconds << " s, transfer " << m.RelightIndirectSeconds
           << " s, " << m.RelightBounces << " bounces";
    if (m.RelightRowsAdded > 0)
    {
      status << ", " << m.RelightRowsAdded << " receivers added to the transfer";
    }
    if (m.RelightRowsDeferred > 0)
    {
      status << ", " << m.RelightRowsDeferred << " receivers deferred to the next relights";
    }
    this->RelightingStatus = status.str();
  }
  else if (const auto faceCluster = this->GetFaceClusterSolution())
  {
    const radiosity::FaceClusterStatistics& f = faceCluster->Statistics();
    std::ostringstream status;
    status << "relit: " << f.CouplingsReused << " transfers from kept couplings, " << f.CouplingsComputed
           << " computed anew, " << this->Statistics.Iterations << " iterations, " << this->Statistics.SolveSeconds
           << " s";
    this->RelightingStatus = status.str();
  }
  return true;
}

std::string vtkRadiosityFilter::RelightingSettingsKey() const
{
  std::ostringstream key;
  key.precision(17);
  key << this->Method << ' ' << this->Tolerance << ' ' << this->MaxIterations << ' ' << this->MaxTime << ' '
      << this->NumberOfThreads << ' ' << this->MaxMemory << ' ' << this->PointRadius << ' ' << this->PointLevels
      << ' ' << this->GatherRays << ' ' << this->VariationThreshold << ' ' << this->SolidAngleThreshold << ' '
      << this->IrradianceBasis << ' ' << this->RadiosityBasis << ' ' << this->TransferTolerance << ' '
      << this->MaxBisections << ' ' << this->ExactEmitters;
  return key.str();
}

void vtkRadiosityFilter::PrecomputeRelighting(const radiosity::ProgressCallback& progress)
{
  // An invalidated transfer's status keeps why, before the new one's.
  const std::string invalidated =
    StartsWith(this->RelightingStatus, "invalidated: ") ? this->RelightingStatus + "; " : std::string();
  this->PrecomputeRelightingAnew(progress);
  this->RelightingStatus = invalidated + this->RelightingStatus;
}

void vtkRadiosityFilter::PrecomputeRelightingAnew(const radiosity::ProgressCallback& progress)
{
  this->RelightingSettings.clear();
  if (this->Controller && this->Controller->GetNumberOfProcesses() > 1)
  {
    this->RelightingStatus = "unavailable: relighting runs on one process (this request runs on MPI ranks)";
    return;
  }
  if (!this->Solver->SupportsRelighting())
  {
    this->RelightingStatus = std::string("unavailable: method ") + this->Solver->MethodName() +
      " has no relighting (Methods Meshless and FaceCluster have)";
    this->Warn("Relighting is on, but " + this->RelightingStatus.substr(13));
    return;
  }
  if (this->Statistics.Stop == radiosity::StopReason::Aborted ||
    this->Statistics.Stop == radiosity::StopReason::NoEmitters)
  {
    this->RelightingStatus = "unavailable: the solve was aborted or had no light; nothing precomputed";
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  if (!this->Solver->PrecomputeRelighting(progress))
  {
    this->RelightingStatus = "unavailable: the precomputation was aborted";
    return;
  }
  this->RelightingPrecomputeSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  this->RelightingSettings = this->RelightingSettingsKey();
  std::ostringstream status;
  status << "precomputed: ";
  if (const auto meshless = this->GetMeshlessSolution())
  {
    const radiosity::MeshlessStatistics& m = meshless->Statistics();
    status << m.TransferReceivers << " receivers, " << m.TransferEntries << " entries, "
           << static_cast<double>(m.TransferBytes) / 1048576.0 << " MiB, ";
  }
  else if (const auto faceCluster = this->GetFaceClusterSolution())
  {
    const radiosity::FaceClusterStatistics& f = faceCluster->Statistics();
    // Kept as the solve computed them (KeepTransfers): the time is the solve's.
    status << f.KeptCouplings << " transfer couplings kept, " << static_cast<double>(f.KeptBytes) / 1048576.0
           << " MiB (by the solve), ";
  }
  status << this->RelightingPrecomputeSeconds << " s";
  this->RelightingStatus = status.str();
}
