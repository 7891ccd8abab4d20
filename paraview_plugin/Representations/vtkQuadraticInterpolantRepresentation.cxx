#include "vtkQuadraticInterpolantRepresentation.h"

#include "vtkQuadraticInterpolantMapper.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkQuadraticInterpolantRepresentation);

vtkQuadraticInterpolantRepresentation::vtkQuadraticInterpolantRepresentation()
  : vtkRadiosityRepresentation(vtkQuadraticInterpolantMapper::New())
{
}

vtkQuadraticInterpolantRepresentation::~vtkQuadraticInterpolantRepresentation() = default;

void vtkQuadraticInterpolantRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
