#include "vtkFaceClusterHierarchyFilter.h"
#include "vtkRadiosityRequestGuard.h"

#include "vtkCellData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkRadiositySceneConverter.h"
#include "vtkVersion.h"

#include "Radiosity/FaceCluster/FaceClusterHierarchy.h"

#include <string>
#include <vector>

vtkStandardNewMacro(vtkFaceClusterHierarchyFilter);

vtkFaceClusterHierarchyFilter::vtkFaceClusterHierarchyFilter() = default;
vtkFaceClusterHierarchyFilter::~vtkFaceClusterHierarchyFilter() = default;

int vtkFaceClusterHierarchyFilter::FillInputPortInformation(int, vtkInformation* info)
{
  // What vtkRadiositySceneConverter::ToScene accepts: any dataset (polydata,
  // or the outer surface of another dataset) and composite data, which arrive
  // whole (each leaf one object of the scene; a composite that is not a tree
  // is refused by ToScene with its message, as before).
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

int vtkFaceClusterHierarchyFilter::Fail(const std::string& message)
{
  this->LastError = message;
  this->Hierarchy.reset();
  vtkErrorMacro(<< message);
  return 0;
}

int vtkFaceClusterHierarchyFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return vtkRadiosityGuardedRequest(
    vtkPolyData::GetData(outputVector, 0),
    [&] { return this->ExecuteRequest(inputVector, outputVector); },
    [this](const std::string& message) { return this->Fail(message); });
}

int vtkFaceClusterHierarchyFilter::ExecuteRequest(vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->LastError.clear();
  this->Reused = false;
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);

  radiosity::Scene scene;
  std::string error;
  std::vector<std::string> warnings;
  if (!vtkRadiositySceneConverter::ToScene(input, scene, error, warnings))
  {
    return this->Fail("bad input: " + error);
  }
  for (const std::string& w : warnings)
  {
    vtkWarningMacro(<< w);
  }
  try
  {
    radiosity::ValidateScene(scene);
  }
  catch (const radiosity::SceneError& e)
  {
    return this->Fail(std::string("bad input: ") + e.what());
  }
  radiosity::DropDegenerateTriangles(scene);
  if (scene.Triangles.empty())
  {
    return this->Fail("bad input: the scene has no triangle of non-zero area");
  }

  radiosity::FaceClusterOptions options;
  options.ShapeWeight = this->ShapeWeight;
  auto progress = [this](const radiosity::ProgressStatus& status) {
    this->UpdateProgress(0.95 * status.Fraction);
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 0)
    return !this->CheckAbort();
#else
    return !this->GetAbortExecute();
#endif
  };
  // The hierarchy keeps its scene: handed over, not copied.
  const auto shared = std::make_shared<const radiosity::Scene>(std::move(scene));
  try
  {
    this->Hierarchy =
      radiosity::FaceClusterHierarchy::Shared(shared, options, progress, &this->Reused);
  }
  catch (const radiosity::FaceClusterBuildAborted&)
  {
    return this->Fail("aborted while building the face cluster hierarchy");
  }
  catch (const radiosity::SceneError& e)
  {
    return this->Fail(std::string("bad input: ") + e.what());
  }
  const radiosity::FaceClusterHierarchy& h = *this->Hierarchy;

  // One tuple per output cell: the input's cells for polydata input (a cell
  // gets the clusters of its first triangle), the triangles otherwise.
  vtkPolyData* polyInput = vtkPolyData::SafeDownCast(input);
  if (polyInput)
  {
    output->ShallowCopy(polyInput);
  }
  else
  {
    output->ShallowCopy(vtkRadiositySceneConverter::FromScene(*shared));
  }
  const vtkIdType cells = output->GetNumberOfCells();
  std::vector<vtkIdType> leafOfCell(static_cast<std::size_t>(cells), -1);
  for (std::size_t t = 0; t < shared->Triangles.size(); ++t)
  {
    const vtkIdType cell = polyInput ? static_cast<vtkIdType>(shared->SourceCells[t])
                                     : static_cast<vtkIdType>(t);
    if (cell >= 0 && cell < cells && leafOfCell[cell] < 0)
    {
      leafOfCell[cell] = static_cast<vtkIdType>(t);
    }
  }
  for (int level = 0; level < this->NumberOfLevels; ++level)
  {
    vtkNew<vtkIdTypeArray> ids;
    ids->SetName(("ClusterId" + std::to_string(level)).c_str());
    ids->SetNumberOfTuples(cells);
    for (vtkIdType c = 0; c < cells; ++c)
    {
      const vtkIdType leaf = leafOfCell[c];
      ids->SetValue(c, leaf < 0 ? -1
                                : static_cast<vtkIdType>(h.AncestorAtDepth(
                                    static_cast<std::uint32_t>(leaf), static_cast<std::uint32_t>(level))));
    }
    output->GetCellData()->AddArray(ids);
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkFaceClusterHierarchyFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfLevels: " << this->NumberOfLevels << "\n";
  os << indent << "ShapeWeight: " << this->ShapeWeight << "\n";
  os << indent << "Reused: " << (this->Reused ? "true" : "false") << "\n";
  os << indent << "LastError: " << (this->LastError.empty() ? "(none)" : this->LastError) << "\n";
  if (this->Hierarchy)
  {
    os << indent << "Hierarchy: " << this->Hierarchy->NumberOfClusters() << " clusters, "
       << this->Hierarchy->Roots().size() << " roots, depth " << this->Hierarchy->MaximumDepth()
       << ", built in " << this->Hierarchy->BuildSeconds() << " s\n";
  }
  else
  {
    os << indent << "Hierarchy: (none)\n";
  }
}
