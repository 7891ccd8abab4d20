#include "vtkIrradianceSamplesRepresentation.h"

#include "vtkIrradianceSamplesMapper.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkIrradianceSamplesRepresentation);

vtkIrradianceSamplesRepresentation::vtkIrradianceSamplesRepresentation()
  : vtkRadiosityRepresentation(vtkIrradianceSamplesMapper::New())
{
}

vtkIrradianceSamplesRepresentation::~vtkIrradianceSamplesRepresentation() = default;

void vtkIrradianceSamplesRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
