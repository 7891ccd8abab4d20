/**
 * @class   vtkShepardSplatRepresentation
 * @brief   ParaView's "Meshless Field Splats" surface representation
 *
 * Draws a meshless multilevel Shepard irradiance field by splatting its
 * basis functions per pixel (Lehtinen et al. 2007, section 6.2) with
 * vtkShepardSplatMapper, on the output of the Radiosity filter with Method
 * Meshless.
 *
 * The mapper needs the field beside the surface. The Radiosity filter puts
 * the field (its Product output) into the Surface output's field data too
 * (vtkRadiositySceneConverter::AttachPointProduct, sharing the arrays); the
 * representation reads it from its own input when that changes, and hands
 * it to the view as a second piece (port 1), which the view delivers to
 * where the rendering happens as it does the surface. An input without a
 * field is reported with an error naming what is missing, and nothing is
 * drawn.
 *
 * @sa vtkShepardSplatMapper, vtkRadiosityFilter, vtkRadiosityRepresentation
 */

#ifndef vtkShepardSplatRepresentation_h
#define vtkShepardSplatRepresentation_h

#include "RadiosityParaViewRepresentationsModule.h" // For export macro
#include "vtkRadiosityRepresentation.h"

class RADIOSITYPARAVIEWREPRESENTATIONS_EXPORT vtkShepardSplatRepresentation
  : public vtkRadiosityRepresentation
{
public:
  static vtkShepardSplatRepresentation* New();
  vtkTypeMacro(vtkShepardSplatRepresentation, vtkRadiosityRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Hands the view the field (REQUEST_UPDATE) and the mapper the delivered
   * field (REQUEST_RENDER).
   */
  int ProcessViewRequest(vtkInformationRequestKey* request_type, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

protected:
  vtkShepardSplatRepresentation();
  ~vtkShepardSplatRepresentation() override;

  /**
   * Builds the field from the upstream solution, then the surface as the
   * superclass does.
   */
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkShepardSplatRepresentation(const vtkShepardSplatRepresentation&) = delete;
  void operator=(const vtkShepardSplatRepresentation&) = delete;

  vtkNew<vtkPolyData> Field;
};

#endif
