/**
 * @class   vtkVectorIrradianceRepresentation
 * @brief   ParaView's "Vector Irradiance (glossy)" surface representation
 *
 * Draws the face cluster solution's vector irradiance lighting a modified
 * Phong BRDF per pixel (Gobbetti et al. 2003, eq. 10): the output of the
 * Radiosity filter with Method Face Cluster (point array IrradianceVector, 9
 * components; optional Specular and Shininess cell arrays), with
 * vtkVectorIrradianceMapper. The display parameters and the
 * handling of ParaView's delivered geometry are vtkRadiosityRepresentation's;
 * input the mapper refuses is reported by the mapper (an error naming the
 * array or cell) and nothing is drawn.
 *
 * @sa vtkVectorIrradianceMapper, vtkRadiosityRepresentation
 */

#ifndef vtkVectorIrradianceRepresentation_h
#define vtkVectorIrradianceRepresentation_h

#include "RadiosityParaViewRepresentationsModule.h" // For export macro
#include "vtkRadiosityRepresentation.h"

class RADIOSITYPARAVIEWREPRESENTATIONS_EXPORT vtkVectorIrradianceRepresentation
  : public vtkRadiosityRepresentation
{
public:
  static vtkVectorIrradianceRepresentation* New();
  vtkTypeMacro(vtkVectorIrradianceRepresentation, vtkRadiosityRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkVectorIrradianceRepresentation();
  ~vtkVectorIrradianceRepresentation() override;

private:
  vtkVectorIrradianceRepresentation(const vtkVectorIrradianceRepresentation&) = delete;
  void operator=(const vtkVectorIrradianceRepresentation&) = delete;
};

#endif
