#include "vtkShepardSplatRepresentation.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMeshlessFieldFilter.h"
#include "vtkMeshlessRadiositySolution.h"
#include "vtkObjectFactory.h"
#include "vtkPVView.h"
#include "vtkRadiosityFilter.h"
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
  if (inputVector[0]->GetNumberOfInformationObjects() == 1 &&
    this->GetNumberOfInputConnections(0) > 0)
  {
    // ParaView's copy of the input has lost the solution key: the solver
    // upstream holds the solution.
    vtkRadiosityFilter* solver = vtkRadiosityFilter::FindUpstream(this->GetInputAlgorithm(0, 0));
    auto solution = solver ? solver->GetMeshlessSolution() : nullptr;
    if (!solution)
    {
      vtkErrorMacro(<< "Meshless Field Splats draws a meshless radiosity solution: the input is "
                       "not the output of a Radiosity filter with Method Meshless.");
    }
    else
    {
      vtkNew<vtkMeshlessRadiositySolution> carrier;
      carrier->SetSolution(solution);
      vtkNew<vtkPolyData> carried;
      carried->GetInformation()->Set(vtkRadiosityFilter::MESHLESS_SOLUTION(), carrier);
      vtkNew<vtkMeshlessFieldFilter> field;
      field->SetInputData(carried);
      field->Update();
      this->Field->ShallowCopy(field->GetOutput());
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
