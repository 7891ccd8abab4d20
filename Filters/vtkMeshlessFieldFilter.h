/**
 * @class   vtkMeshlessFieldFilter
 * @brief   the point hierarchy and Shepard coefficients of a meshless solution
 *
 * Input: the output of vtkRadiosityFilter run with Method Meshless (the
 * solution travels in the output's information, see
 * vtkRadiosityFilter::MESHLESS_SOLUTION()). Output: one vertex per basis
 * function (Lehtinen et al. 2007, sections 4 and 6.1) with the point arrays
 * `Level` (0 = coarsest), `Radius` (support radius r_j), `Normal` (n_j),
 * `Group` (reconstruction group: the scene object), `Coefficient` (RGB
 * coefficient alpha_j of the irradiance field, W/m^2), `DirectCoefficient`
 * (the direct light's alone), `Irradiance` (the field's value at the point)
 * and `Gathered` (1 where the solver computed a coefficient at least once).
 * vtkShepardFieldProbe evaluates such a field on any dataset, and
 * vtkShepardSplatMapper draws it. Without a meshless solution on the input the
 * filter reports an error and produces an empty output.
 */
#ifndef vtkMeshlessFieldFilter_h
#define vtkMeshlessFieldFilter_h

#include "RadiosityFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // for std::string

class RADIOSITYFILTERS_EXPORT vtkMeshlessFieldFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkMeshlessFieldFilter* New();
  vtkTypeMacro(vtkMeshlessFieldFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Why the last execution failed ("" when it did not).
  const std::string& GetLastError() const { return this->LastError; }

protected:
  vtkMeshlessFieldFilter();
  ~vtkMeshlessFieldFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkMeshlessFieldFilter(const vtkMeshlessFieldFilter&) = delete;
  void operator=(const vtkMeshlessFieldFilter&) = delete;

  /// Records and reports `message`; returns 0 (a failed request).
  int Fail(const std::string& message);
  /// RequestData inside vtkRadiosityGuardedRequest.
  int ExecuteRequest(vtkInformationVector** inputVector, vtkInformationVector* outputVector);
  std::string LastError;
};

#endif
