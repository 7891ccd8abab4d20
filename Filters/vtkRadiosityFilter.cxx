#include "vtkRadiosityFilter.h"

#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFaceClusterHierarchy.h"
#include "vtkFaceClusterHierarchyFilter.h"
#include "vtkHierarchicalRadiositySolution.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseKey.h"
#include "vtkInformationVector.h"
#include "vtkMeshlessRadiositySolution.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRadiositySceneConverter.h"
#include "vtkRadiosityRequestGuard.h"
#include "vtkVersion.h"

#include "Radiosity/FaceCluster/FaceClusterRadiosity.h"
#include "Radiosity/Hierarchical/HierarchicalRadiosity.h"
#include "Radiosity/Meshless/MeshlessRadiosity.h"
#include "Radiosity/Progressive/ProgressiveRadiosity.h"
#include "Radiosity/Common/SolutionMesh.h"

#include <algorithm>
#include <chrono>

vtkStandardNewMacro(vtkRadiosityFilter);
vtkInformationKeyMacro(vtkRadiosityFilter, HIERARCHICAL_SOLUTION, ObjectBase);
vtkInformationKeyMacro(vtkRadiosityFilter, MESHLESS_SOLUTION, ObjectBase);

vtkRadiosityFilter* vtkRadiosityFilter::FindUpstream(vtkAlgorithm* producer)
{
  for (int hop = 0; producer && hop < 4; ++hop)
  {
    if (auto* solver = vtkRadiosityFilter::SafeDownCast(producer))
    {
      return solver;
    }
    if (!producer->IsA("vtkPVPostFilter") || producer->GetNumberOfInputConnections(0) < 1)
    {
      return nullptr;
    }
    producer = producer->GetInputAlgorithm(0, 0);
  }
  return nullptr;
}

namespace
{
/// A solver together with the scene it references, so that the solver
/// handed out (an aliasing shared_ptr) keeps the scene alive.
template <typename Solver, typename Options>
struct SolverHolder
{
  std::shared_ptr<const radiosity::Scene> SceneRef;
  Solver Instance;
  SolverHolder(std::shared_ptr<const radiosity::Scene> scene, const Options& options)
    : SceneRef(std::move(scene))
    , Instance(*this->SceneRef, options)
  {
  }
};
using HierarchicalHolder = SolverHolder<radiosity::HierarchicalRadiosity, radiosity::HierarchicalOptions>;
using MeshlessHolder = SolverHolder<radiosity::MeshlessRadiosity, radiosity::MeshlessOptions>;

/// The face cluster solver with its scene.
struct FaceClusterHolder
{
  std::shared_ptr<const radiosity::Scene> SceneRef;
  radiosity::FaceClusterRadiosity Instance;
  FaceClusterHolder(std::shared_ptr<const radiosity::Scene> scene,
    const radiosity::FaceClusterSettings& settings,
    std::shared_ptr<const radiosity::FaceClusterHierarchy> hierarchy)
    : SceneRef(std::move(scene))
    , Instance(*this->SceneRef, settings,
        // Built on the shared scene itself: no copy of it.
        hierarchy ? std::move(hierarchy)
                  : radiosity::FaceClusterHierarchy::Shared(this->SceneRef, settings.Clustering))
  {
  }
};

constexpr radiosity::BasisKind BasisKinds[5] = { radiosity::BasisKind::Constant,
  radiosity::BasisKind::Linear, radiosity::BasisKind::Bilinear, radiosity::BasisKind::Quadratic,
  radiosity::BasisKind::Cubic };
}

vtkRadiosityFilter::vtkRadiosityFilter()
  : LastScene(std::make_shared<radiosity::Scene>())
{
}
vtkRadiosityFilter::~vtkRadiosityFilter() = default;

const char* vtkRadiosityFilter::GetMethodName(int method)
{
  switch (method)
  {
    case Auto:
      return "auto";
    case Progressive:
      return "progressive";
    case Hierarchical:
      return "hierarchical";
    case Meshless:
      return "meshless";
    case FaceCluster:
      return "facecluster";
    default:
      return "unknown";
  }
}

const char* vtkRadiosityFilter::GetBasisName(int basis)
{
  return basis >= ConstantBasis && basis <= CubicBasis ? radiosity::BasisName(BasisKinds[basis]) : "unknown";
}

int vtkRadiosityFilter::FillInputPortInformation(int, vtkInformation* info)
{
  // What vtkRadiositySceneConverter::ToScene accepts: any dataset (polydata,
  // or the outer surface of another dataset) and composite data, which arrive
  // whole (each leaf one object of the scene; a composite that is not a tree
  // is refused by ToScene with its message, as before).
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

int vtkRadiosityFilter::Fail(const std::string& message)
{
  this->LastError = message;
  vtkErrorMacro(<< message);
  return 0;
}

int vtkRadiosityFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return vtkRadiosityGuardedRequest(
    vtkPolyData::GetData(outputVector, 0),
    [&] { return this->ExecuteRequest(inputVector, outputVector); },
    [this](const std::string& message) { return this->Fail(message); });
}

int vtkRadiosityFilter::ExecuteRequest(
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  this->LastError.clear();
  this->Warnings.clear();
  this->Solution.reset();
  this->HierarchicalSolution.reset();
  this->MeshlessSolution.reset();
  this->FaceClusterSolution.reset();
  this->Statistics = radiosity::SolverStatistics();
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  // The data object's information outlives executions: drop a solution of
  // an earlier hierarchical run before anything can fail.
  output->GetInformation()->Remove(HIERARCHICAL_SOLUTION());
  output->GetInformation()->Remove(MESHLESS_SOLUTION());

  radiosity::Scene scene;
  std::string error;
  if (!vtkRadiositySceneConverter::ToScene(input, scene, error, this->Warnings))
  {
    return this->Fail("bad input: " + error);
  }
  for (const std::string& w : this->Warnings)
  {
    vtkWarningMacro(<< w);
  }
  radiosity::ValidateScene(scene); // a SceneError is bad input (vtkRadiosityGuardedRequest)
  this->Cleanup = radiosity::DropDegenerateTriangles(scene);
  if (this->Cleanup.DegenerateTrianglesDropped > 0)
  {
    const std::string w = "dropped " + std::to_string(this->Cleanup.DegenerateTrianglesDropped) +
      " degenerate (zero-area) triangles";
    this->Warnings.push_back(w);
    vtkWarningMacro(<< w);
  }
  if (scene.Triangles.empty())
  {
    return this->Fail("bad input: the scene has no triangle of non-zero area");
  }
  if (!scene.HasEmitters())
  {
    const std::string w = "the scene has no emitter: the solution is zero";
    this->Warnings.push_back(w);
    vtkWarningMacro(<< w);
  }
  auto sharedScene = std::make_shared<const radiosity::Scene>(std::move(scene));
  this->LastScene = sharedScene;
  const double budget = this->MaxMemory * 1e9; // 0: the core's default (75% of physical memory)

  auto last = Clock::now();
  // The solvers' fractions are estimates from the residual, which can dip;
  // a progress bar (ParaView's) must not run backwards.
  double shown = 0.0;
  auto progress = [this, &last, &shown](const radiosity::ProgressStatus& status)
  {
    const auto now = Clock::now();
    if (std::chrono::duration<double>(now - last).count() > 0.05)
    {
      last = now;
      shown = std::max(shown, status.Fraction);
      this->UpdateProgress(shown);
    }
    if (this->StatusCallback && !this->StatusCallback(status))
    {
      return false;
    }
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 0)
    return !this->CheckAbort();
#else
    return !this->GetAbortExecute();
#endif
  };

  if (this->Method == Hierarchical)
  {
    radiosity::HierarchicalOptions options;
    options.Tolerance = this->Tolerance;
    options.MaxIterations = this->MaxIterations;
    options.MaxTimeSeconds = this->MaxTime;
    options.Threads = this->NumberOfThreads;
    options.RelativeLinkTolerance = this->LinkTolerance;
    options.MinElementSize = this->MinElementSize;
    options.MaxRefinementRounds = this->MaxRefinementRounds;
    options.ErrorProbes = this->ErrorProbes;
    options.ErrorReference = this->ErrorReference;
    options.MemoryBudgetBytes = budget;
    auto holder = std::make_shared<HierarchicalHolder>(sharedScene, options);
    this->PreprocessSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    last = Clock::now();
    this->Statistics = holder->Instance.Solve(progress);
    this->HierarchicalSolution =
      std::shared_ptr<const radiosity::HierarchicalRadiosity>(holder, &holder->Instance);
    this->Solution =
      std::make_unique<radiosity::SolutionMesh>(radiosity::ExtractSolution(holder->Instance.Mesh()));
  }
  else if (this->Method == Meshless)
  {
    radiosity::MeshlessOptions options;
    options.Tolerance = this->Tolerance;
    options.MaxBounces = static_cast<int>(std::min<vtkIdType>(this->MaxIterations, 1000000));
    options.MaxTimeSeconds = this->MaxTime;
    options.Threads = this->NumberOfThreads;
    options.Placement.InitialRadius = this->PointRadius;
    options.Placement.Levels = this->PointLevels;
    options.GatherRays = this->GatherRays;
    options.VariationThreshold = this->VariationThreshold;
    options.SolidAngleThreshold = this->SolidAngleThreshold;
    options.ErrorProbes = this->ErrorProbes;
    options.ErrorReference = this->ErrorReference;
    options.MemoryBudgetBytes = budget;
    auto holder = std::make_shared<MeshlessHolder>(sharedScene, options);
    this->PreprocessSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    last = Clock::now();
    this->Statistics = holder->Instance.Solve(progress);
    this->MeshlessSolution =
      std::shared_ptr<const radiosity::MeshlessRadiosity>(holder, &holder->Instance);
    this->Solution = std::make_unique<radiosity::SolutionMesh>(holder->Instance.Surface());
  }
  else if (this->Method == FaceCluster)
  {
    radiosity::FaceClusterSettings settings;
    settings.IrradianceBasis = BasisKinds[this->IrradianceBasis];
    settings.RadiosityBasis = BasisKinds[std::min(this->RadiosityBasis, this->IrradianceBasis)];
    settings.TransferTolerance = this->TransferTolerance;
    settings.MaxBisections = this->MaxBisections;
    settings.Tolerance = this->Tolerance;
    settings.MaxIterations = static_cast<int>(std::min<vtkIdType>(this->MaxIterations, 1000000));
    settings.MaxTimeSeconds = this->MaxTime;
    settings.Threads = this->NumberOfThreads;
    settings.MemoryBudgetBytes = budget;
    // A hierarchy from vtkFaceClusterHierarchyFilter upstream, when it was
    // built for this very scene; otherwise the shared one (built once).
    std::shared_ptr<const radiosity::FaceClusterHierarchy> hierarchy;
    if (auto* carrier = vtkFaceClusterHierarchy::SafeDownCast(
          input->GetInformation()->Get(vtkFaceClusterHierarchyFilter::FACE_CLUSTER_HIERARCHY())))
    {
      hierarchy = carrier->GetHierarchy();
      if (hierarchy &&
        hierarchy->Fingerprint() != radiosity::FaceClusterHierarchy::FingerprintOf(*sharedScene, settings.Clustering))
      {
        hierarchy.reset();
      }
    }
    auto holder = std::make_shared<FaceClusterHolder>(sharedScene, settings, hierarchy);
    this->PreprocessSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    last = Clock::now();
    this->Statistics = holder->Instance.Solve(progress);
    this->FaceClusterSolution =
      std::shared_ptr<const radiosity::FaceClusterRadiosity>(holder, &holder->Instance);
    this->Solution = std::make_unique<radiosity::SolutionMesh>(holder->Instance.Surface());
  }
  else
  {
    this->PreprocessSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    this->SolveProgressive(progress);
  }
  this->UpdateProgress(1.0);
  if (this->Statistics.LinksWithBlockersCut > 0)
  {
    const std::string w = std::to_string(this->Statistics.LinksWithBlockersCut) +
      " links had more candidate blockers than the 64 kept per link: their visibility comes from "
      "the blockers the rays between the nodes meet (approximate there)";
    this->Warnings.push_back(w);
    vtkWarningMacro(<< w);
  }
  if (this->Statistics.Stop == radiosity::StopReason::Aborted)
  {
    vtkWarningMacro(<< "aborted after " << this->Statistics.Iterations << " iterations");
  }
  output->ShallowCopy(vtkRadiositySceneConverter::FromSolution(*this->Solution, *this->LastScene));
  output->GetFieldData()->AddArray(vtkRadiositySceneConverter::FromHistory(this->Statistics.History));
  if (this->FaceClusterSolution && output->GetNumberOfPoints() == static_cast<vtkIdType>(this->Solution->Points.size()))
  {
    // The irradiance vectors at the points, for vtkVectorIrradianceMapper.
    const auto vectors = this->FaceClusterSolution->VertexIrradianceVectors();
    auto array = vtkRadiositySceneConverter::NewDoubleArray(
      "IrradianceVector", 9, static_cast<vtkIdType>(vectors.size()));
    for (std::size_t p = 0; p < vectors.size(); ++p)
    {
      array->SetTypedTuple(static_cast<vtkIdType>(p), vectors[p].data());
    }
    output->GetPointData()->AddArray(array);
  }
  // An aborted solve is not a solution to mesh downstream (VTK empties the
  // output; GetHierarchicalSolution() still gives the partial one).
  if (this->HierarchicalSolution && this->Statistics.Stop != radiosity::StopReason::Aborted)
  {
    vtkNew<vtkHierarchicalRadiositySolution> carrier;
    carrier->SetSolution(this->HierarchicalSolution);
    output->GetInformation()->Set(HIERARCHICAL_SOLUTION(), carrier);
  }
  if (this->MeshlessSolution && this->Statistics.Stop != radiosity::StopReason::Aborted)
  {
    vtkNew<vtkMeshlessRadiositySolution> carrier;
    carrier->SetSolution(this->MeshlessSolution);
    output->GetInformation()->Set(MESHLESS_SOLUTION(), carrier);
  }
  return 1;
}

void vtkRadiosityFilter::SolveProgressive(const radiosity::ProgressCallback& progress)
{
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  radiosity::ProgressiveOptions options;
  options.Tolerance = this->Tolerance;
  options.MaxIterations = this->MaxIterations;
  options.MaxTimeSeconds = this->MaxTime;
  options.Threads = this->NumberOfThreads;
  options.Overshooting = this->Overshooting;
  options.ShooterElementSize = this->ShooterElementSize;
  options.InitialElementSize = this->InitialElementSize;
  options.MaxSubdivisionLevels = this->MaxSubdivisionLevels;
  options.SubdivisionThreshold = this->SubdivisionThreshold;
  options.FormFactorTolerance = this->FormFactorTolerance;
  options.VisibilitySamples = this->VisibilitySamples;
  options.IndirectVisibilitySamples = this->IndirectVisibilitySamples;
  options.ErrorProbes = this->ErrorProbes;
  options.ErrorReference = this->ErrorReference;
  options.MemoryBudgetBytes = this->MaxMemory * 1e9;
  radiosity::ProgressiveRadiosity solver(*this->LastScene, options);
  this->PreprocessSeconds += std::chrono::duration<double>(Clock::now() - start).count();

  this->Statistics = solver.Solve(progress);
  this->Solution = std::make_unique<radiosity::SolutionMesh>(radiosity::ExtractSolution(solver.Mesh()));
}

void vtkRadiosityFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Method: " << GetMethodName(this->Method) << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MaxIterations: " << this->MaxIterations << "\n";
  os << indent << "MaxTime: " << this->MaxTime << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "Overshooting: " << (this->Overshooting ? "On" : "Off") << "\n";
  os << indent << "ShooterElementSize: " << this->ShooterElementSize << "\n";
  os << indent << "InitialElementSize: " << this->InitialElementSize << "\n";
  os << indent << "MaxSubdivisionLevels: " << this->MaxSubdivisionLevels << "\n";
  os << indent << "SubdivisionThreshold: " << this->SubdivisionThreshold << "\n";
  os << indent << "FormFactorTolerance: " << this->FormFactorTolerance << "\n";
  os << indent << "VisibilitySamples: " << this->VisibilitySamples << "\n";
  os << indent << "IndirectVisibilitySamples: " << this->IndirectVisibilitySamples << "\n";
  os << indent << "LinkTolerance: " << this->LinkTolerance << "\n";
  os << indent << "MinElementSize: " << this->MinElementSize << "\n";
  os << indent << "MaxRefinementRounds: " << this->MaxRefinementRounds << "\n";
  os << indent << "PointRadius: " << this->PointRadius << "\n";
  os << indent << "PointLevels: " << this->PointLevels << "\n";
  os << indent << "GatherRays: " << this->GatherRays << "\n";
  os << indent << "VariationThreshold: " << this->VariationThreshold << "\n";
  os << indent << "SolidAngleThreshold: " << this->SolidAngleThreshold << "\n";
  os << indent << "IrradianceBasis: " << GetBasisName(this->IrradianceBasis) << "\n";
  os << indent << "RadiosityBasis: " << GetBasisName(this->RadiosityBasis) << "\n";
  os << indent << "TransferTolerance: " << this->TransferTolerance << "\n";
  os << indent << "MaxBisections: " << this->MaxBisections << "\n";
  os << indent << "MaxMemory: " << this->MaxMemory << " GB\n";
  os << indent << "FaceClusterSolution: " << (this->FaceClusterSolution ? "yes" : "none") << "\n";
  os << indent << "HierarchicalSolution: " << (this->HierarchicalSolution ? "yes" : "none") << "\n";
  os << indent << "ErrorReference: " << this->ErrorReference.size() << " probes\n";
  os << indent << "StatusCallback: " << (this->StatusCallback ? "set" : "(none)") << "\n";
  os << indent << "LastError: " << this->LastError << "\n";
}
