#include "vtkRadiosityFilter.h"

#include "vtkCommunicator.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLight.h"
#include "vtkIdTypeArray.h"
#include "vtkLightCollection.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRadiositySceneConverter.h"
#include "vtkRadiosityRankExchange.h"
#include "vtkRadiosityRequestGuard.h"
#include "vtkStringArray.h"
#include "vtkVersion.h"

#include "Radiosity/FaceCluster/FaceClusterMethod.h"
#include "Radiosity/Common/FacingAway.h"
#include "Radiosity/Common/MethodChoice.h"
#include "Radiosity/Hierarchical/HierarchicalMethod.h"
#include "Radiosity/Meshless/MeshlessMethod.h"
#include "Radiosity/Progressive/ProgressiveMethod.h"
#include "ProgressiveGPUMethod.h"
#include "Radiosity/Common/Lights.h"
#include "Radiosity/Common/MemoryBudget.h"
#include "Radiosity/Common/ScenePieces.h"
#include "Radiosity/Common/SolutionMesh.h"
#include "Radiosity/Common/WorkShare.h"

#include <algorithm>
#include <chrono>
#include <sstream>

vtkStandardNewMacro(vtkRadiosityFilter);
vtkCxxSetObjectMacro(vtkRadiosityFilter, Controller, vtkMultiProcessController);


namespace
{
constexpr radiosity::BasisKind BasisKinds[5] = { radiosity::BasisKind::Constant,
  radiosity::BasisKind::Linear, radiosity::BasisKind::Bilinear, radiosity::BasisKind::Quadratic,
  radiosity::BasisKind::Cubic };
}

vtkRadiosityFilter::vtkRadiosityFilter()
  : LastScene(std::make_shared<radiosity::Scene>())
  , Lights(vtkSmartPointer<vtkLightCollection>::New())
  , SceneLights(std::make_unique<radiosity::LightSet>())
{
  // Port 0: the surface solution; port 1: the method's own product.
  this->SetNumberOfOutputPorts(2);
  this->SetController(vtkMultiProcessController::GetGlobalController());
}
vtkRadiosityFilter::~vtkRadiosityFilter()
{
  this->SetLightsFileName(nullptr);
  this->SetController(nullptr);
}

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
    case ProgressiveGPU:
      return "progressive-gpu";
    default:
      return "unknown";
  }
}

const char* vtkRadiosityFilter::GetBasisName(int basis)
{
  return basis >= ConstantBasis && basis <= CubicBasis ? radiosity::BasisName(BasisKinds[basis]) : "unknown";
}

const char* vtkRadiosityFilter::GetClusteringName(int clustering)
{
  switch (clustering)
  {
    case ClusteringOff:
      return "off";
    case ClusteringOn:
      return "on";
    case ClusteringAuto:
      return "auto";
    default:
      return "unknown";
  }
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

template <typename Options>
void vtkRadiosityFilter::FillCommonOptions(Options& options) const
{
  options.Tolerance = this->Tolerance;
  options.MaxTimeSeconds = this->MaxTime;
  options.Threads = this->NumberOfThreads;
  // 0: the core's default (75% of physical memory); on MPI ranks the
  // smallest rank's, agreed before the solve.
  options.MemoryBudgetBytes = this->AgreedMemoryBudget > 0 ? this->AgreedMemoryBudget : this->MaxMemory * 1e9;
  options.Share = this->Share; // MPI ranks: the split loops (null on one process)
}

template <typename Options>
void vtkRadiosityFilter::FillErrorReference(Options& options) const
{
  options.ErrorProbes = this->ErrorProbes;
  options.ErrorReference = this->ErrorReference;
}

std::shared_ptr<radiosity::RadiositySolver> vtkRadiosityFilter::MakeSolver(
  const std::shared_ptr<const radiosity::Scene>& scene) const
{
  switch (this->ResolvedMethod)
  {
    case Hierarchical:
    {
      radiosity::HierarchicalOptions options;
      this->FillCommonOptions(options);
      this->FillErrorReference(options);
      options.MaxIterations = this->MaxIterations;
      options.RelativeLinkTolerance = this->LinkTolerance;
      options.MinElementSize = this->MinElementSize;
      options.MaxRefinementRounds = this->MaxRefinementRounds;
      // Method Auto chose clustered hierarchical radiosity (MethodChoice.h):
      // ClusteringAuto then clusters at any size; Off still turns it off.
      const bool clusterAlways = this->Method == Auto;
      options.Clustering = this->Clustering == ClusteringOn ? radiosity::HierarchicalClustering::On
        : this->Clustering == ClusteringOff                 ? radiosity::HierarchicalClustering::Off
        : clusterAlways                                     ? radiosity::HierarchicalClustering::On
                                                            : radiosity::HierarchicalClustering::Auto;
      radiosity::DiscontinuityMeshOptions meshing;
      meshing.Discontinuities = this->DiscontinuityMeshing;
      meshing.MaxPerLeaf = this->MaxDiscontinuitiesPerLeaf;
      meshing.MinWeight = this->MinDiscontinuityWeight;
      meshing.Conforming = this->ConformingBoundaries;
      meshing.Threads = this->NumberOfThreads;
      meshing.MaxSeconds = this->MaxTime; // the search for discontinuities gets the solve's limit again
      return std::make_shared<radiosity::HierarchicalMethod>(scene, options, meshing);
    }
    case Meshless:
    {
      radiosity::MeshlessOptions options;
      this->FillCommonOptions(options);
      this->FillErrorReference(options);
      options.MaxBounces = static_cast<int>(std::min<vtkIdType>(this->MaxIterations, 1000000));
      options.Placement.InitialRadius = this->PointRadius;
      options.Placement.Levels = this->PointLevels;
      options.GatherRays = this->GatherRays;
      options.VariationThreshold = this->VariationThreshold;
      options.SolidAngleThreshold = this->SolidAngleThreshold;
      options.RelightGatherSeconds = this->MaxRelightGatherTime;
      return std::make_shared<radiosity::MeshlessMethod>(scene, options);
    }
    case FaceCluster:
    {
      radiosity::FaceClusterSettings settings;
      this->FillCommonOptions(settings);
      settings.IrradianceBasis = BasisKinds[this->IrradianceBasis];
      settings.RadiosityBasis = BasisKinds[std::min(this->RadiosityBasis, this->IrradianceBasis)];
      settings.TransferTolerance = this->TransferTolerance;
      settings.MaxBisections = this->MaxBisections;
      if (!this->ExactEmitters)
      {
        settings.ExactEmitterTriangles = 0;
      }
      settings.MaxIterations = static_cast<int>(std::min<vtkIdType>(this->MaxIterations, 1000000));
      // Relighting: the solve keeps its transfers' couplings (one process).
      settings.KeepTransfers = this->Relighting && !(settings.Share && settings.Share->Ranks() > 1);
      // The hierarchy shared by every user of this scene (FaceClusterHierarchy::
      // Shared): one that vtkFaceClusterHierarchyFilter built upstream for
      // the same geometry, materials and options is reused, not rebuilt.
      // Built (or found) here, where it is timed: FaceClusterMethod would
      // build it before FaceClusterRadiosity's own clock starts.
      const auto start = std::chrono::steady_clock::now();
      auto hierarchy = radiosity::FaceClusterHierarchy::Shared(scene, settings.Clustering);
      this->HierarchySeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return std::make_shared<radiosity::FaceClusterMethod>(scene, settings, std::move(hierarchy));
    }
    case ProgressiveGPU:
    {
      radiosity::ProgressiveGPUOptions options;
      this->FillProgressiveOptions(options);
      options.HemicubeResolution = this->HemicubeResolution;
      return std::make_shared<radiosity::ProgressiveGPUMethod>(scene, options);
    }
    case Progressive:
    default:
    {
      radiosity::ProgressiveOptions options;
      this->FillProgressiveOptions(options);
      return std::make_shared<radiosity::ProgressiveMethod>(scene, options);
    }
  }
}

void vtkRadiosityFilter::FillProgressiveOptions(radiosity::ProgressiveOptions& options) const
{
  this->FillCommonOptions(options);
  this->FillErrorReference(options);
  options.MaxIterations = this->MaxIterations;
  options.Overshooting = this->Overshooting;
  options.ShooterElementSize = this->ShooterElementSize;
  options.InitialElementSize = this->InitialElementSize;
  options.MaxSubdivisionLevels = this->MaxSubdivisionLevels;
  options.SubdivisionThreshold = this->SubdivisionThreshold;
  options.FormFactorTolerance = this->FormFactorTolerance;
  options.VisibilitySamples = this->VisibilitySamples;
  options.IndirectVisibilitySamples = this->IndirectVisibilitySamples;
}

void vtkRadiosityFilter::ResolveMethod(const radiosity::Scene& scene)
{
  this->MethodChoiceWhy.clear();
  this->ResolvedMethod = this->Method;
  if (this->Method == Auto)
  {
    // The whole scene (on MPI ranks the gathered one): every rank chooses the same.
    const radiosity::MethodChoice choice = radiosity::ChooseMethod(scene);
    static_assert(Progressive == 1 + static_cast<int>(radiosity::SolutionMethod::Progressive) &&
        FaceCluster == 1 + static_cast<int>(radiosity::SolutionMethod::FaceCluster),
      "vtkRadiosityFilter::Methods follow radiosity::SolutionMethod");
    this->ResolvedMethod = 1 + static_cast<int>(choice.Method);
    this->MethodChoiceWhy = choice.Why;
    vtkDebugMacro(<< "Method Auto: " << GetMethodName(this->ResolvedMethod) << ": " << choice.Why);
  }
}

const radiosity::SolutionMesh* vtkRadiosityFilter::GetSolution() const
{
  if (this->SolutionPending && this->Solver)
  {
    this->Solution = std::make_unique<radiosity::SolutionMesh>(this->Solver->Surface());
    this->SolutionPending = false;
  }
  return this->Solution.get();
}

void vtkRadiosityFilter::Warn(const std::string& warning)
{
  this->Warnings.push_back(warning);
  vtkWarningMacro(<< warning);
}

bool vtkRadiosityFilter::LocalScene(vtkDataObject* input, radiosity::Scene& scene)
{
  std::string error;
  std::vector<std::string> conversionWarnings;
  if (!vtkRadiositySceneConverter::ToScene(input, scene, error, conversionWarnings))
  {
    return this->Fail("bad input: " + error) != 0;
  }
  // Lights go into the scene before the solver is made (a SceneError, a bad
  // light, fails the request as bad input: vtkRadiosityGuardedRequest).
  scene.Lighting = this->GatherLights();
  for (const std::string& w : conversionWarnings)
  {
    this->Warn(w);
  }
  radiosity::ValidateScene(scene); // a SceneError is bad input (vtkRadiosityGuardedRequest)
  this->Cleanup = radiosity::DropDegenerateTriangles(scene);
  this->WarnDropped();
  if (scene.Triangles.empty())
  {
    return this->Fail("bad input: the scene has no triangle of non-zero area") != 0;
  }
  return true;
}

bool vtkRadiosityFilter::GatheredScene(
  vtkDataObject* input, radiosity::Scene& scene, std::vector<char>& mine)
{
  vtkMultiProcessController* controller = this->Controller;
  const int rank = controller->GetLocalProcessId();
  // This rank's piece, checked here; then every rank learns whether any
  // failed before anything else is exchanged.
  radiosity::Scene piece;
  radiosity::PieceGlobalIds ids;
  std::vector<std::string> conversionWarnings;
  std::string localError;
  vtkRadiosityGuardedRequest(
    nullptr,
    [&]
    {
      std::string error;
      if (!vtkRadiositySceneConverter::ToScene(input, piece, error, conversionWarnings, &ids))
      {
        throw radiosity::SceneError(error);
      }
      piece.Lighting = this->GatherLights();
      if (!piece.Triangles.empty()) // an empty piece is normal
      {
        radiosity::ValidateScene(piece);
      }
      return 1;
    },
    [&localError](const std::string& message)
    {
      localError = message;
      return 0;
    });
  const std::string error = vtkRadiosityRankExchange::AgreeOnError(controller, localError);
  if (!error.empty())
  {
    return this->Fail(error) != 0;
  }
  for (const std::string& w : conversionWarnings)
  {
    this->Warn(w);
  }
  const auto pieces = vtkRadiosityRankExchange::AllGatherBytes(
    controller, radiosity::PackScenePiece(piece, ids), this->RankBytesReceived);
  // The same bytes on every rank: the same scene, or the same SceneError.
  radiosity::AssembledScene assembled = radiosity::AssembleScenePieces(pieces);
  scene = std::move(assembled.Whole);
  scene.Lighting = piece.Lighting;
  this->RankTriangles.assign(assembled.RankTriangles.begin(), assembled.RankTriangles.end());
  // Dropped from the whole scene, as on one process (the threshold is
  // relative to the scene's size).
  std::vector<std::uint32_t> kept;
  this->Cleanup = radiosity::DropDegenerateTriangles(scene, &kept);
  this->WarnDropped();
  mine.assign(scene.Triangles.size(), 0);
  for (std::size_t t = 0; t < kept.size(); ++t)
  {
    mine[t] = assembled.Owner[kept[t]] == static_cast<std::uint32_t>(rank);
  }
  if (scene.Triangles.empty())
  {
    return this->Fail("bad input: the scene has no triangle of non-zero area on any of the " +
             std::to_string(controller->GetNumberOfProcesses()) + " ranks") != 0;
  }
  return true;
}

void vtkRadiosityFilter::WarnDropped()
{
  if (this->Cleanup.DegenerateTrianglesDropped > 0)
  {
    this->Warn("dropped " + std::to_string(this->Cleanup.DegenerateTrianglesDropped) +
      " degenerate (zero-area) triangles");
  }
}

int vtkRadiosityFilter::ExecuteRequest(
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  this->LastError.clear();
  this->Warnings.clear();
  // A kept transfer may serve this request (Relighting); otherwise dropped below.
  std::shared_ptr<radiosity::RadiositySolver> previous = std::move(this->Solver);
  this->Solver.reset();
  this->RelightingPrecomputeSeconds = 0.0;
  this->Solution.reset();
  this->SolutionPending = false;
  this->Statistics = radiosity::SolverStatistics();
  this->PreprocessSeconds = this->SolveWallSeconds = this->OutputSeconds = this->ProductSeconds = 0.0;
  this->HierarchySeconds = 0.0;
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* productOutput = vtkPolyData::GetData(outputVector, 1);
  productOutput->Initialize();

  radiosity::Scene scene;
  // Distributed: this rank's triangles of the gathered scene.
  std::vector<char> mine;
  const bool distributed = this->Controller && this->Controller->GetNumberOfProcesses() > 1;
  this->RankTriangles.clear();
  this->RankBytesReceived.clear();
  this->RankWorkItems.clear();
  this->RankSolveBytesReceived.clear();
  this->Share = distributed ? vtkRadiosityRankExchange::MakeWorkShare(this->Controller) : nullptr;
  // Ranks on machines of different memory would check the solver's budget
  // against different limits, and a rank that refused alone would leave the
  // others waiting in the solve's exchanges: every rank takes the smallest.
  this->AgreedMemoryBudget = 0.0;
  if (distributed)
  {
    const double mine = radiosity::ResolveMemoryBudget(this->MaxMemory * 1e9);
    this->Controller->AllReduce(&mine, &this->AgreedMemoryBudget, 1, vtkCommunicator::MIN_OP);
  }
  if (!(distributed ? this->GatheredScene(input, scene, mine) : this->LocalScene(input, scene)))
  {
    return 0;
  }
  if (!scene.IsLit())
  {
    this->Warn("the scene has no emitter: the solution is zero (no emitting triangle, no light)");
  }
  const std::string facingAway = radiosity::FacingAwayWarning(scene);
  if (!facingAway.empty())
  {
    this->Warn(facingAway);
  }
  auto sharedScene = std::make_shared<const radiosity::Scene>(std::move(scene));
  this->LastScene = sharedScene;
  this->ResolveMethod(*sharedScene);

  auto last = Clock::now();
  // The solvers' fractions are estimates from the residual, which can dip;
  // a progress bar (ParaView's) must not run backwards. The product (the
  // discontinuity mesh) takes the last tenth of the bar.
  double shown = 0.0, offset = 0.0, scale = 1.0;
  auto local = [this, &last, &shown, &offset, &scale](const radiosity::ProgressStatus& status)
  {
    const auto now = Clock::now();
    if (std::chrono::duration<double>(now - last).count() > 0.05)
    {
      last = now;
      shown = std::max(shown, offset + scale * status.Fraction);
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
  // During a distributed solve every progress call is made on every rank at
  // the same point: an abort on one rank stops every rank there.
  bool collective = false;
  auto progress = [this, &local, &collective](const radiosity::ProgressStatus& status)
  {
    const bool go = local(status);
    return collective ? !this->Share->AnyRank(!go) : go;
  };

  // Relighting: the kept transfer, when it still applies, instead of a solve.
  this->PreprocessSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  last = Clock::now();
  const auto relighting = last;
  const bool relit = this->RelightWith(std::move(previous), sharedScene, progress, distributed);
  if (relit)
  {
    this->SolveWallSeconds = std::chrono::duration<double>(Clock::now() - relighting).count();
  }
  if (!relit)
  {
    // One path for every method: build its solver, solve, output the surface
    // (port 0) and the method's own product (port 1).
    this->Solver = this->MakeSolver(sharedScene);
    this->PreprocessSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    last = Clock::now();
    const auto solving = last;
    scale = 0.9;
    collective = distributed;
    this->Statistics = this->Solver->Solve(progress);
    collective = false;
    this->SolveWallSeconds = std::chrono::duration<double>(Clock::now() - solving).count();
    if (this->Relighting)
    {
      this->PrecomputeRelighting(progress);
    }
  }
  if (this->Statistics.Stop == radiosity::StopReason::Diverged)
  {
    // Never a plausible wrong answer: no output, an error saying what grew.
    return this->Fail(std::string(GetMethodName(this->ResolvedMethod)) + " radiosity diverged after " +
      std::to_string(this->Statistics.Iterations) + " iterations: " + this->Statistics.StopDetail);
  }
  const auto solved = Clock::now();
  if (distributed)
  {
    // Each rank's share of the split loops, for the report (one all-gather).
    const radiosity::WorkShareStatistics& mine = this->Share->Statistics();
    std::vector<char> bytes;
    radiosity::PutBytes(bytes, static_cast<std::uint64_t>(mine.Items));
    radiosity::PutBytes(bytes, static_cast<std::uint64_t>(mine.BytesReceived));
    std::vector<vtkIdType> ignored;
    for (const std::vector<char>& theirs : vtkRadiosityRankExchange::AllGatherBytes(this->Controller, bytes, ignored))
    {
      std::uint64_t items = 0, received = 0;
      const std::size_t at = radiosity::GetBytes(theirs.data(), theirs.size(), items);
      radiosity::GetBytes(theirs.data() + at, theirs.size() - at, received);
      this->RankWorkItems.push_back(static_cast<vtkIdType>(items));
      this->RankSolveBytesReceived.push_back(static_cast<vtkIdType>(received));
    }
  }
  // Without SurfaceOutput the surface is evaluated when first asked for.
  const bool surface = distributed || this->SurfaceOutput;
  if (!distributed && surface)
  {
    this->Solution = std::make_unique<radiosity::SolutionMesh>(this->Solver->Surface());
  }
  this->SolutionPending = distributed || !surface;
  if (this->Statistics.LinksWithBlockersCut > 0)
  {
    this->Warn(std::to_string(this->Statistics.LinksWithBlockersCut) +
      " links had more candidate blockers than the 64 kept per link: their visibility comes from "
      "the fraction of 48 rays between the nodes that pass (sampled there, not exact)");
  }
  const bool aborted = this->Statistics.Stop == radiosity::StopReason::Aborted;
  if (aborted)
  {
    vtkWarningMacro(<< "aborted after " << this->Statistics.Iterations << " iterations");
  }
  // Distributed: this rank's elements only, the only ones evaluated where
  // the output costs (meshless); GetSolution() gives the whole solution on
  // demand, for probes and images.
  std::vector<std::uint32_t> pointSource;
  const radiosity::SolutionMesh own =
    distributed ? this->Solver->SurfaceOf(mine, &pointSource) : radiosity::SolutionMesh();
  output->ShallowCopy(vtkRadiositySceneConverter::FromSolution(
    distributed ? own : surface ? *this->Solution : radiosity::SolutionMesh(), *this->LastScene));
  // Not on a distributed rank's empty output: VTK sends an empty data set
  // between ranks as legacy ASCII, which cannot read back the history's NaN
  // (ParaView's Fetch failed with "Unrecognized keyword").
  if (!distributed || !own.Triangles.empty())
  {
    output->GetFieldData()->AddArray(vtkRadiositySceneConverter::FromHistory(this->Statistics.History));
    vtkNew<vtkStringArray> relighting;
    relighting->SetName("Relighting");
    relighting->InsertNextValue(this->RelightingStatus);
    output->GetFieldData()->AddArray(relighting);
    // The method solved with, and for Auto why (ParaView shows it among the field data, in the spreadsheet view).
    vtkNew<vtkStringArray> method;
    method->SetName("MethodChoice");
    method->InsertNextValue(std::string(GetMethodName(this->ResolvedMethod)) +
      (this->MethodChoiceWhy.empty() ? std::string(": asked for by name") : ": " + this->MethodChoiceWhy));
    output->GetFieldData()->AddArray(method);
  }
  for (radiosity::ProductArray a :
    surface ? this->Solver->SurfacePointArrays() : std::vector<radiosity::ProductArray>())
  {
    const bool onSurface = distributed
      ? std::all_of(pointSource.begin(), pointSource.end(), [&a](std::uint32_t p) { return p < a.Tuples(); })
      : a.Tuples() == this->Solution->Points.size();
    if (!onSurface)
    {
      continue;
    }
    if (distributed)
    {
      radiosity::ProductArray subset(a.Name, a.Components, pointSource.size(), a.Type);
      for (std::size_t p = 0; p < pointSource.size(); ++p)
      {
        std::copy_n(a.Tuple(pointSource[p]), a.Components, subset.Tuple(p));
      }
      a = std::move(subset);
    }
    output->GetPointData()->AddArray(vtkRadiositySceneConverter::FromProductArray(a));
  }
  if (distributed)
  {
    for (const auto& values : { std::make_pair("RankTriangles", &this->RankTriangles),
           std::make_pair("RankBytesReceived", &this->RankBytesReceived),
           std::make_pair("RankWorkItems", &this->RankWorkItems),
           std::make_pair("RankSolveBytesReceived", &this->RankSolveBytesReceived) })
    {
      vtkNew<vtkIdTypeArray> a;
      a->SetName(values.first);
      for (vtkIdType v : *values.second)
      {
        a->InsertNextValue(v);
      }
      output->GetFieldData()->AddArray(a);
    }
  }
  // An aborted solve is not a solution to mesh downstream: the product
  // stays empty (GetSolver() still gives the partial solution). The product
  // of a distributed solve is the whole scene's: on rank 0 only.
  const auto evaluated = Clock::now();
  this->OutputSeconds = std::chrono::duration<double>(evaluated - solved).count();
  if (!aborted && (distributed ? this->Controller->GetLocalProcessId() == 0 : this->ProductOutput))
  {
    offset = 0.9;
    scale = 0.1;
    const radiosity::SolverProduct product = this->Solver->Product(progress);
    for (const std::string& w : product.Warnings)
    {
      this->Warn(w);
    }
    productOutput->ShallowCopy(vtkRadiositySceneConverter::FromProduct(product));
    for (const char* name : { "ConvergenceHistory", "ObjectNames" })
    {
      if (vtkAbstractArray* a = output->GetFieldData()->GetAbstractArray(name))
      {
        productOutput->GetFieldData()->AddArray(a);
      }
    }
    if (product.Triangles.empty() && !product.Points.empty())
    {
      // A product of points (the Shepard field) travels with the surface
      // too, in its field data (the same arrays, no copy), so that a
      // representation of port 0 (ParaView's Meshless Field Splats) reads
      // it from its own input.
      vtkRadiositySceneConverter::AttachPointProduct(productOutput, output);
    }
  }
  this->ProductSeconds = std::chrono::duration<double>(Clock::now() - evaluated).count();
  this->UpdateProgress(1.0);
  return 1;
}

void vtkRadiosityFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Method: " << GetMethodName(this->Method) << "\n";
  os << indent << "ResolvedMethod: " << GetMethodName(this->ResolvedMethod) << "\n";
  os << indent << "MethodChoice: " << (this->MethodChoiceWhy.empty() ? "(none)" : this->MethodChoiceWhy) << "\n";
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
  os << indent << "HemicubeResolution: " << this->HemicubeResolution << "\n";
  os << indent << "VisibilitySamples: " << this->VisibilitySamples << "\n";
  os << indent << "IndirectVisibilitySamples: " << this->IndirectVisibilitySamples << "\n";
  os << indent << "LinkTolerance: " << this->LinkTolerance << "\n";
  os << indent << "MinElementSize: " << this->MinElementSize << "\n";
  os << indent << "MaxRefinementRounds: " << this->MaxRefinementRounds << "\n";
  os << indent << "Clustering: " << GetClusteringName(this->Clustering) << "\n";
  os << indent << "PointRadius: " << this->PointRadius << "\n";
  os << indent << "PointLevels: " << this->PointLevels << "\n";
  os << indent << "GatherRays: " << this->GatherRays << "\n";
  os << indent << "VariationThreshold: " << this->VariationThreshold << "\n";
  os << indent << "SolidAngleThreshold: " << this->SolidAngleThreshold << "\n";
  os << indent << "IrradianceBasis: " << GetBasisName(this->IrradianceBasis) << "\n";
  os << indent << "RadiosityBasis: " << GetBasisName(this->RadiosityBasis) << "\n";
  os << indent << "TransferTolerance: " << this->TransferTolerance << "\n";
  os << indent << "MaxBisections: " << this->MaxBisections << "\n";
  os << indent << "ExactEmitters: " << (this->ExactEmitters ? "On" : "Off") << "\n";
  os << indent << "MaxMemory: " << this->MaxMemory << " GB\n";
  os << indent << "DiscontinuityMeshing: " << (this->DiscontinuityMeshing ? "On" : "Off") << "\n";
  os << indent << "MaxDiscontinuitiesPerLeaf: " << this->MaxDiscontinuitiesPerLeaf << "\n";
  os << indent << "MinDiscontinuityWeight: " << this->MinDiscontinuityWeight << "\n";
  os << indent << "SurfaceOutput: " << (this->SurfaceOutput ? "On" : "Off") << "\n";
  os << indent << "ProductOutput: " << (this->ProductOutput ? "On" : "Off") << "\n";
  os << indent << "Relighting: " << (this->Relighting ? "On" : "Off") << "\n";
  os << indent << "MaxRelightGatherTime: " << this->MaxRelightGatherTime << "\n";
  os << indent << "RelightingStatus: " << this->RelightingStatus << "\n";
  os << indent << "RelightingPrecomputeSeconds: " << this->RelightingPrecomputeSeconds << "\n";
  os << indent << "ConformingBoundaries: " << (this->ConformingBoundaries ? "On" : "Off") << "\n";
  os << indent << "Lights: " << this->Lights->GetNumberOfItems() << " vtkLights\n";
  {
    vtkCollectionSimpleIterator it;
    this->Lights->InitTraversal(it);
    while (vtkLight* light = this->Lights->GetNextLight(it))
    {
      light->PrintSelf(os, indent.GetNextIndent());
    }
  }
  os << indent << "LightScale: " << this->LightScale << "\n";
  os << indent << "SkyModel: " << GetSkyModelName(this->SkyModel) << "\n";
  os << indent << "SkyRadiance: (" << this->SkyRadiance[0] << ", " << this->SkyRadiance[1] << ", "
     << this->SkyRadiance[2] << ")\n";
  os << indent << "SkyUp: (" << this->SkyUp[0] << ", " << this->SkyUp[1] << ", " << this->SkyUp[2]
     << ")\n";
  os << indent << "LightsFileName: " << (this->LightsFileName ? this->LightsFileName : "(none)") << "\n";
  os << indent << "SceneLights: " << this->SceneLights->Lights.size() << " lights, sky "
     << radiosity::SkyModelName(this->SceneLights->SkyLight.Model) << "\n";
  os << indent << "LastLighting: " << this->LastScene->Lighting.Lights.size() << " lights, sky "
     << radiosity::SkyModelName(this->LastScene->Lighting.SkyLight.Model) << "\n";
  os << indent << "Solver: " << (this->Solver ? this->Solver->MethodName() : "(none)") << "\n";
  os << indent << "ErrorReference: " << this->ErrorReference.size() << " probes\n";
  os << indent << "StatusCallback: " << (this->StatusCallback ? "set" : "(none)") << "\n";
  os << indent << "Controller: " << this->Controller << " ("
     << (this->Controller ? this->Controller->GetNumberOfProcesses() : 1) << " processes)\n";
  os << indent << "LastError: " << this->LastError << "\n";
}

namespace
{
/// The method-specific solver inside `solver` when it is of method `Method`
/// (sharing its ownership), else null.
template <typename Method, typename Instance>
std::shared_ptr<const Instance> InstanceOf(const std::shared_ptr<radiosity::RadiositySolver>& solver)
{
  auto method = std::dynamic_pointer_cast<const Method>(solver);
  return method ? std::shared_ptr<const Instance>(method, &method->GetInstance()) : nullptr;
}
}

std::shared_ptr<const radiosity::FaceClusterRadiosity> vtkRadiosityFilter::GetFaceClusterSolution() const
{
  return InstanceOf<radiosity::FaceClusterMethod, radiosity::FaceClusterRadiosity>(this->Solver);
}

std::shared_ptr<const radiosity::MeshlessRadiosity> vtkRadiosityFilter::GetMeshlessSolution() const
{
  return InstanceOf<radiosity::MeshlessMethod, radiosity::MeshlessRadiosity>(this->Solver);
}

std::shared_ptr<const radiosity::HierarchicalRadiosity> vtkRadiosityFilter::GetHierarchicalSolution() const
{
  return InstanceOf<radiosity::HierarchicalMethod, radiosity::HierarchicalRadiosity>(this->Solver);
}
