/**
 * @class   vtkQuadraticInterpolantRepresentation
 * @brief   ParaView's "Radiosity Quadratic Interpolants" surface representation
 *
 * Draws Hardt & Teller's quadratic irradiance interpolants, evaluated per
 * pixel: the Product output of Radiosity with Method Hierarchical (cell array
 * QuadraticInterpolant, 18 components), with vtkQuadraticInterpolantMapper.
 * The display parameters and the
 * handling of ParaView's delivered geometry are vtkRadiosityRepresentation's;
 * input the mapper refuses is reported by the mapper (an error naming the
 * array or cell) and nothing is drawn.
 *
 * @sa vtkQuadraticInterpolantMapper, vtkRadiosityRepresentation
 */

#ifndef vtkQuadraticInterpolantRepresentation_h
#define vtkQuadraticInterpolantRepresentation_h

#include "RadiosityParaViewRepresentationsModule.h" // For export macro
#include "vtkRadiosityRepresentation.h"

class RADIOSITYPARAVIEWREPRESENTATIONS_EXPORT vtkQuadraticInterpolantRepresentation
  : public vtkRadiosityRepresentation
{
public:
  static vtkQuadraticInterpolantRepresentation* New();
  vtkTypeMacro(vtkQuadraticInterpolantRepresentation, vtkRadiosityRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkQuadraticInterpolantRepresentation();
  ~vtkQuadraticInterpolantRepresentation() override;

private:
  vtkQuadraticInterpolantRepresentation(const vtkQuadraticInterpolantRepresentation&) = delete;
  void operator=(const vtkQuadraticInterpolantRepresentation&) = delete;
};

#endif
