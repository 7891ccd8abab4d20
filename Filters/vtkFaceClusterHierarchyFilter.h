/**
 * @class   vtkFaceClusterHierarchyFilter
 * @brief   builds the face cluster hierarchy of a scene (Gobbetti, Spano &
 *          Agus 2003, section 3.1; Garland, Willmott & Heckbert 2001)
 *
 * Input: a scene as vtkRadiosityFilter takes it (polydata or multiblock with
 * the SPEC.md cell arrays). Per object, the triangles are clustered by greedy
 * contraction of the dual graph (planarity, orientation and compactness
 * costs) into a binary tree whose leaves are the triangles; every cluster
 * gets an oriented box, its area samples, a convexity flag and material
 * bounds (radiosity::FaceClusterHierarchy).
 *
 * Output: for polydata input, the input with the cell arrays `ClusterId0`,
 * `ClusterId1`, ... `ClusterId<NumberOfLevels - 1>`: the cluster containing
 * the cell at that depth of the tree (0: the object's root; a leaf shallower
 * than the level keeps its own id; -1 for a cell that is not a triangle of
 * the scene, such as a line or a zero-area triangle; a polygon gets the
 * cluster of its first triangle). For multiblock input, the scene's
 * triangles as polydata with the same arrays. The hierarchy itself
 * (GetHierarchy()) is shared while this filter holds it: a second execution,
 * or a downstream vtkRadiosityFilter with Method FaceCluster, on the same
 * geometry, materials and ShapeWeight reuses it rather than building it
 * again (GetReused(); radiosity::FaceClusterHierarchy::Shared).
 *
 * Bad input gets an error naming the array, cell or value and an empty
 * output. Progress is reported while clustering; AbortExecute stops it.
 */
#ifndef vtkFaceClusterHierarchyFilter_h
#define vtkFaceClusterHierarchyFilter_h

#include "RadiosityFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <memory> // for std::shared_ptr
#include <string> // for std::string


namespace radiosity
{
class FaceClusterHierarchy;
}

class RADIOSITYFILTERS_EXPORT vtkFaceClusterHierarchyFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkFaceClusterHierarchyFilter* New();
  vtkTypeMacro(vtkFaceClusterHierarchyFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Number of `ClusterId<L>` arrays written (default 8), clamped to [1, 64].
  vtkSetClampMacro(NumberOfLevels, int, 1, 64);
  vtkGetMacro(NumberOfLevels, int);
  ///@}

  ///@{
  /// Weight of the compactness bias against planarity (default 0.5),
  /// clamped to [0, 100].
  vtkSetClampMacro(ShapeWeight, double, 0.0, 100.0);
  vtkGetMacro(ShapeWeight, double);
  ///@}


  /// The hierarchy of the last execution (null after a failure).
  std::shared_ptr<const radiosity::FaceClusterHierarchy> GetHierarchy() const
  {
    return this->Hierarchy;
  }
  /// Whether the last execution reused a hierarchy built before.
  bool GetReused() const { return this->Reused; }
  /// Why the last execution failed ("" when it did not).
  const std::string& GetLastError() const { return this->LastError; }

protected:
  vtkFaceClusterHierarchyFilter();
  ~vtkFaceClusterHierarchyFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NumberOfLevels = 8;
  double ShapeWeight = 0.5;

private:
  vtkFaceClusterHierarchyFilter(const vtkFaceClusterHierarchyFilter&) = delete;
  void operator=(const vtkFaceClusterHierarchyFilter&) = delete;

  /// Records and reports `message`; returns 0 (a failed request).
  int Fail(const std::string& message);
  /// RequestData inside vtkRadiosityGuardedRequest.
  int ExecuteRequest(vtkInformationVector** inputVector, vtkInformationVector* outputVector);

  std::shared_ptr<const radiosity::FaceClusterHierarchy> Hierarchy;
  bool Reused = false;
  std::string LastError;
};

#endif
