/**
 * @class   vtkHierarchicalRadiositySolution
 * @brief   a solved hierarchical radiosity solution carried by a data object
 *
 * vtkRadiosityFilter with Method Hierarchical stores one of these in its
 * output's information under vtkRadiosityFilter::HIERARCHICAL_SOLUTION(), so
 * that a downstream filter (vtkDiscontinuityMeshFilter) finds the quadtrees,
 * links and blockers that the polydata alone cannot carry. It shares the
 * solver, which keeps the scene it references alive.
 */
#ifndef vtkHierarchicalRadiositySolution_h
#define vtkHierarchicalRadiositySolution_h

#include "RadiosityFiltersModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::shared_ptr

namespace radiosity
{
class HierarchicalRadiosity;
}

class RADIOSITYFILTERS_EXPORT vtkHierarchicalRadiositySolution : public vtkObject
{
public:
  static vtkHierarchicalRadiositySolution* New();
  vtkTypeMacro(vtkHierarchicalRadiositySolution, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The solved solver (null when none was set).
  void SetSolution(std::shared_ptr<const radiosity::HierarchicalRadiosity> solution);
  std::shared_ptr<const radiosity::HierarchicalRadiosity> GetSolution() const
  {
    return this->Solution;
  }
  ///@}

protected:
  vtkHierarchicalRadiositySolution();
  ~vtkHierarchicalRadiositySolution() override;

private:
  vtkHierarchicalRadiositySolution(const vtkHierarchicalRadiositySolution&) = delete;
  void operator=(const vtkHierarchicalRadiositySolution&) = delete;

  std::shared_ptr<const radiosity::HierarchicalRadiosity> Solution;
};

#endif
