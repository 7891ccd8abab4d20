/**
 * @class   vtkIrradianceSamplesRepresentation
 * @brief   ParaView's "Radiosity Element Samples" surface representation
 *
 * Draws every solution element from its own irradiance samples, per pixel
 * (Coombe et al.'s texel display): the output of Radiosity with Method
 * Progressive, Progressive (GPU) or Hierarchical (cell array
 * IrradianceSamples, 12 components), with vtkIrradianceSamplesMapper. The
 * display parameters and the handling of ParaView's delivered geometry are
 * vtkRadiosityRepresentation's; input the mapper refuses is reported by the
 * mapper (an error naming the array or cell) and nothing is drawn.
 *
 * @sa vtkIrradianceSamplesMapper, vtkRadiosityRepresentation
 */

#ifndef vtkIrradianceSamplesRepresentation_h
#define vtkIrradianceSamplesRepresentation_h

#include "RadiosityParaViewRepresentationsModule.h" // For export macro
#include "vtkRadiosityRepresentation.h"

class RADIOSITYPARAVIEWREPRESENTATIONS_EXPORT vtkIrradianceSamplesRepresentation
  : public vtkRadiosityRepresentation
{
public:
  static vtkIrradianceSamplesRepresentation* New();
  vtkTypeMacro(vtkIrradianceSamplesRepresentation, vtkRadiosityRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkIrradianceSamplesRepresentation();
  ~vtkIrradianceSamplesRepresentation() override;

private:
  vtkIrradianceSamplesRepresentation(const vtkIrradianceSamplesRepresentation&) = delete;
  void operator=(const vtkIrradianceSamplesRepresentation&) = delete;
};

#endif
