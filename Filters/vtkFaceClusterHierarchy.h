/**
 * @class   vtkFaceClusterHierarchy
 * @brief   a face cluster hierarchy carried by a data object
 *
 * vtkFaceClusterHierarchyFilter stores one of these in its output's
 * information under vtkFaceClusterHierarchyFilter::FACE_CLUSTER_HIERARCHY(),
 * so that a face cluster solve downstream takes the hierarchy instead of
 * building it. The hierarchy is shared (radiosity::FaceClusterHierarchy::
 * Shared): a second build on the same geometry returns it.
 */
#ifndef vtkFaceClusterHierarchy_h
#define vtkFaceClusterHierarchy_h

#include "RadiosityFiltersModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::shared_ptr

namespace radiosity
{
class FaceClusterHierarchy;
}

class RADIOSITYFILTERS_EXPORT vtkFaceClusterHierarchy : public vtkObject
{
public:
  static vtkFaceClusterHierarchy* New();
  vtkTypeMacro(vtkFaceClusterHierarchy, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The hierarchy (null when none was set).
  void SetHierarchy(std::shared_ptr<const radiosity::FaceClusterHierarchy> hierarchy);
  std::shared_ptr<const radiosity::FaceClusterHierarchy> GetHierarchy() const
  {
    return this->Hierarchy;
  }
  ///@}

protected:
  vtkFaceClusterHierarchy();
  ~vtkFaceClusterHierarchy() override;

private:
  vtkFaceClusterHierarchy(const vtkFaceClusterHierarchy&) = delete;
  void operator=(const vtkFaceClusterHierarchy&) = delete;

  std::shared_ptr<const radiosity::FaceClusterHierarchy> Hierarchy;
};

#endif
