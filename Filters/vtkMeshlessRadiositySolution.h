/**
 * @class   vtkMeshlessRadiositySolution
 * @brief   a solved meshless radiosity solution carried by a data object
 *
 * vtkRadiosityFilter with Method Meshless stores one of these in its output's
 * information under vtkRadiosityFilter::MESHLESS_SOLUTION(), so that
 * vtkMeshlessFieldFilter finds the point hierarchy and the Shepard
 * coefficients. It shares the solver, which keeps its scene alive.
 */
#ifndef vtkMeshlessRadiositySolution_h
#define vtkMeshlessRadiositySolution_h

#include "RadiosityFiltersModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::shared_ptr

namespace radiosity
{
class MeshlessRadiosity;
}

class RADIOSITYFILTERS_EXPORT vtkMeshlessRadiositySolution : public vtkObject
{
public:
  static vtkMeshlessRadiositySolution* New();
  vtkTypeMacro(vtkMeshlessRadiositySolution, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The solved solver (null when none was set).
  void SetSolution(std::shared_ptr<const radiosity::MeshlessRadiosity> solution);
  std::shared_ptr<const radiosity::MeshlessRadiosity> GetSolution() const
  {
    return this->Solution;
  }
  ///@}

protected:
  vtkMeshlessRadiositySolution();
  ~vtkMeshlessRadiositySolution() override;

private:
  vtkMeshlessRadiositySolution(const vtkMeshlessRadiositySolution&) = delete;
  void operator=(const vtkMeshlessRadiositySolution&) = delete;

  std::shared_ptr<const radiosity::MeshlessRadiosity> Solution;
};

#endif
