#include "vtkRadiosityRepresentation.h"

#include "vtkAppendPolyData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkInformation.h"
#include "vtkPVView.h"
#include "vtkRadiosityCellTexelMapper.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <vector>

vtkRadiosityRepresentation::vtkRadiosityRepresentation(vtkRadiosityCellTexelMapper* mapper)
{
  this->Mapper->Delete();
  this->LODMapper->Delete();
  this->Mapper = mapper;
  this->LODMapper = mapper->NewInstance();
  this->SuppressLOD = true;
  // The actors must be given the new mappers.
  this->SetupDefaults();
}

vtkRadiosityRepresentation::~vtkRadiosityRepresentation() = default;

vtkRadiosityCellTexelMapper* vtkRadiosityRepresentation::GetRadiosityMapper()
{
  return static_cast<vtkRadiosityCellTexelMapper*>(this->Mapper);
}

void vtkRadiosityRepresentation::SetExposure(double exposure)
{
  this->GetRadiosityMapper()->SetExposure(exposure);
  static_cast<vtkRadiosityCellTexelMapper*>(this->LODMapper)->SetExposure(exposure);
}

double vtkRadiosityRepresentation::GetExposure()
{
  return this->GetRadiosityMapper()->GetExposure();
}

void vtkRadiosityRepresentation::SetToneMapping(int toneMapping)
{
  this->GetRadiosityMapper()->SetToneMapping(toneMapping);
  static_cast<vtkRadiosityCellTexelMapper*>(this->LODMapper)->SetToneMapping(toneMapping);
}

int vtkRadiosityRepresentation::GetToneMapping()
{
  return this->GetRadiosityMapper()->GetToneMapping();
}

void vtkRadiosityRepresentation::SetGamma(double gamma)
{
  this->GetRadiosityMapper()->SetGamma(gamma);
  static_cast<vtkRadiosityCellTexelMapper*>(this->LODMapper)->SetGamma(gamma);
}

double vtkRadiosityRepresentation::GetGamma()
{
  return this->GetRadiosityMapper()->GetGamma();
}

vtkPolyData* vtkRadiosityRepresentation::DeliveredSurface(vtkDataObject* piece)
{
  if (auto* surface = vtkPolyData::SafeDownCast(piece))
  {
    return surface;
  }
  std::vector<vtkPolyData*> blocks;
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(piece))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      auto* block = vtkPolyData::SafeDownCast(it->GetCurrentDataObject());
      if (block && block->GetNumberOfCells() > 0)
      {
        blocks.push_back(block);
      }
    }
  }
  if (blocks.empty())
  {
    return this->Empty;
  }
  if (blocks.size() == 1)
  {
    return blocks.front();
  }
  // Appended again only when a block changed since the last append.
  vtkMTimeType newest = 0;
  for (vtkPolyData* block : blocks)
  {
    newest = std::max(newest, block->GetMTime());
  }
  if (newest > this->Appended->GetMTime())
  {
    vtkNew<vtkAppendPolyData> append;
    for (vtkPolyData* block : blocks)
    {
      append->AddInputData(block);
    }
    append->Update();
    this->Appended->ShallowCopy(append->GetOutput());
  }
  return this->Appended;
}

int vtkRadiosityRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request_type, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo))
  {
    return 0;
  }
  if (request_type == vtkPVView::REQUEST_RENDER())
  {
    // The superclass handed the mappers the delivered multiblock.
    vtkDataObject* piece = vtkPVView::GetDeliveredPiece(inInfo, this);
    this->Mapper->SetInputDataObject(this->DeliveredSurface(piece));
    this->LODMapper->SetInputDataObject(this->Empty);
  }
  return 1;
}

void vtkRadiosityRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mapper: " << this->Mapper->GetClassName() << "\n";
  os << indent << "Exposure: " << this->GetExposure() << "\n";
  os << indent << "ToneMapping: " << this->GetToneMapping() << "\n";
  os << indent << "Gamma: " << this->GetGamma() << "\n";
}
