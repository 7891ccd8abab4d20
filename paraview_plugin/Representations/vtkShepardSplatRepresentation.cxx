#include "vtkShepardSplatRepresentation.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPVView.h"
#include "vtkPolyData.h"
#include "vtkRadiositySceneConverter.h"
#include "vtkShepardSplatMapper.h"

vtkStandardNewMacro(vtkShepardSplatRepresentation);

vtkShepardSplatRepresentation::vtkShepardSplatRepresentation()
  : vtkRadiosityRepresentation(vtkShepardSplatMapper::New())
{
}

vtkShepardSplatRepresentation::~vtkShepardSplatRepresentation() = default;

int vtkShepardSplatRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->Field->Initialize();
  // No input: the client side of a client-server session, which receives
  // the field through the view's delivery.
  if (inputVector[0]->GetNumberOfInformationObjects() == 1)
  {
    // The Radiosity filter (Method Meshless) puts its Shepard field into the
    // surface's field data too: the input itself carries it.
    auto field = vtkRadiositySceneConverter::AttachedPointProduct(
      vtkPolyData::GetData(inputVector[0], 0), "ShepardField");
    if (!field)
    {
      vtkErrorMacro(<< "Meshless Field Splats draws a meshless radiosity solution: the input is "
                       "not the Surface output of a Radiosity filter with Method Meshless.");
    }
    else
    {
      this->Field->ShallowCopy(field);
    }
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

int vtkShepardSplatRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request_type, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo))
  {
    return 0;
  }
  if (request_type == vtkPVView::REQUEST_UPDATE())
  {
    vtkPVView::SetPiece(inInfo, this, this->Field, 0, 1);
  }
  else if (request_type == vtkPVView::REQUEST_RENDER())
  {
    auto* mapper = static_cast<vtkShepardSplatMapper*>(this->GetRadiosityMapper());
    auto* field = vtkPolyData::SafeDownCast(vtkPVView::GetDeliveredPiece(inInfo, this, 1));
    if (field && field->GetNumberOfPoints() > 0)
    {
      mapper->SetFieldData(field);
    }
    else
    {
      // Already reported by RequestData: the mapper draws nothing, quietly.
      mapper->SetFieldData(this->Empty);
      mapper->SetInputDataObject(this->Empty);
    }
  }
  return 1;
}

void vtkShepardSplatRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Field: " << this->Field->GetNumberOfPoints() << " basis functions\n";
}
