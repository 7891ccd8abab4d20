#include "vtkVectorIrradianceRepresentation.h"

#include "vtkVectorIrradianceMapper.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkVectorIrradianceRepresentation);

vtkVectorIrradianceRepresentation::vtkVectorIrradianceRepresentation()
  : vtkRadiosityRepresentation(vtkVectorIrradianceMapper::New())
{
}

vtkVectorIrradianceRepresentation::~vtkVectorIrradianceRepresentation() = default;

void vtkVectorIrradianceRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
