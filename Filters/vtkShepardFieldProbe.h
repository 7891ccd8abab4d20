/**
 * @class   vtkShepardFieldProbe
 * @brief   evaluates a meshless multilevel Shepard field on any dataset's points
 *
 * Input 0: the dataset to probe (any vtkDataSet; a solution can be moved onto
 * a finer or a different mesh with no remeshing). Input 1 (SetSourceConnection):
 * a field as port 1 of vtkRadiosityFilter (Method Meshless) writes it (vertices with `Level`, `Radius`,
 * `Normal`, `Group`, `Coefficient`).
 *
 * At each point (x, n) the irradiance is Lehtinen et al.'s eq. 9: per level
 * the normalised Shepard sum of the coefficients with the weights
 * K(|x - x_j| / r_j) max(0, n . n_j) (eqs. 12, 13), summed over the levels.
 * Point normals come from the point array `Normals`, or for polydata from
 * vtkPolyDataNormals (no splitting, orientation kept). The group of a point is
 * the point array `ObjectId` when present, else the cell array `ObjectId` of a
 * cell using it, else the group of the nearest facing field point. Output: the input with the point arrays
 * `Irradiance` and, when the input has the cell arrays `Reflectance` and
 * `Emission`, `Radiosity` = E + rho H (materials of a cell using the point).
 */
#ifndef vtkShepardFieldProbe_h
#define vtkShepardFieldProbe_h

#include "RadiosityFiltersModule.h" // for export macro
#include "vtkDataSetAlgorithm.h"

#include <string> // for std::string

class RADIOSITYFILTERS_EXPORT vtkShepardFieldProbe : public vtkDataSetAlgorithm
{
public:
  static vtkShepardFieldProbe* New();
  vtkTypeMacro(vtkShepardFieldProbe, vtkDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The field to evaluate (input port 1).
  void SetSourceConnection(vtkAlgorithmOutput* field) { this->SetInputConnection(1, field); }
  void SetSourceData(vtkDataObject* field) { this->SetInputData(1, field); }

  ///@{
  /// Evaluate levels 0..MaxLevel only (-1: all), to show partial reconstructions.
  vtkSetClampMacro(MaxLevel, int, -1, 64);
  vtkGetMacro(MaxLevel, int);
  ///@}

  const std::string& GetLastError() const { return this->LastError; }

protected:
  vtkShepardFieldProbe();
  ~vtkShepardFieldProbe() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int MaxLevel = -1;

private:
  vtkShepardFieldProbe(const vtkShepardFieldProbe&) = delete;
  void operator=(const vtkShepardFieldProbe&) = delete;

  /// Records and reports `message`; returns 0 (a failed request).
  int Fail(const std::string& message);
  /// RequestData inside vtkRadiosityGuardedRequest.
  int ExecuteRequest(vtkInformationVector** inputVector, vtkInformationVector* outputVector);
  std::string LastError;
};

#endif
