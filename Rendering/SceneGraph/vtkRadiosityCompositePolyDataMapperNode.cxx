#include "vtkRadiosityCompositePolyDataMapperNode.h"

#include "vtkActor.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositePolyDataMapper.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkMapper.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkSmartPointer.h"

#include <algorithm>

vtkStandardNewMacro(vtkRadiosityCompositePolyDataMapperNode);

vtkRadiosityCompositePolyDataMapperNode::vtkRadiosityCompositePolyDataMapperNode() = default;
vtkRadiosityCompositePolyDataMapperNode::~vtkRadiosityCompositePolyDataMapperNode() = default;

vtkCompositeDataDisplayAttributes* vtkRadiosityCompositePolyDataMapperNode::GetAttributes()
{
  if (auto* m2 = vtkCompositePolyDataMapper2::SafeDownCast(this->GetRenderable()))
  {
    return m2->GetCompositeDataDisplayAttributes();
  }
  return nullptr;
}

vtkMTimeType vtkRadiosityCompositePolyDataMapperNode::GetSceneMTime()
{
  vtkMTimeType time = this->Superclass::GetSceneMTime();
  if (vtkCompositeDataDisplayAttributes* attributes = this->GetAttributes())
  {
    time = std::max(time, attributes->GetMTime());
  }
  auto* mapper = vtkMapper::SafeDownCast(this->GetRenderable());
  auto* tree = mapper ? vtkDataObjectTree::SafeDownCast(mapper->GetInputDataObject(0, 0)) : nullptr;
  if (tree)
  {
    // A block changed in place does not move the composite's MTime.
    vtkSmartPointer<vtkDataObjectTreeIterator> it;
    it.TakeReference(tree->NewTreeIterator());
    it->VisitOnlyLeavesOn();
    it->SkipEmptyNodesOn();
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      time = std::max(time, it->GetCurrentDataObject()->GetMTime());
    }
  }
  return time;
}

bool vtkRadiosityCompositePolyDataMapperNode::Convert(
  vtkActor* actor, vtkMapper* mapper, const std::string& label)
{
  vtkDataObject* input = mapper->GetInputDataObject(0, 0);
  if (!vtkDataObjectTree::SafeDownCast(input))
  {
    return this->Superclass::Convert(actor, mapper, label);
  }
  this->LeftOutTranslucent = 0;
  unsigned int flatIndex = 0;
  const bool ok = this->ConvertBlock(input, actor, mapper, this->GetAttributes(), true, nullptr,
    actor->GetProperty()->GetOpacity(), flatIndex, label);
  if (this->LeftOutTranslucent > 0)
  {
    this->Warnings.push_back(label + ": " + std::to_string(this->LeftOutTranslucent) +
      " blocks with an opacity below 1 left out of the solve (and not drawn)");
  }
  return ok;
}

bool vtkRadiosityCompositePolyDataMapperNode::ConvertBlock(vtkDataObject* block, vtkActor* actor,
  vtkMapper* mapper, vtkCompositeDataDisplayAttributes* attributes, bool visible,
  const double* colour, double opacity, unsigned int& flatIndex, const std::string& label)
{
  const unsigned int index = flatIndex++;
  double own[3];
  if (attributes && block)
  {
    if (attributes->HasBlockVisibility(block))
    {
      visible = attributes->GetBlockVisibility(block);
    }
    if (attributes->HasBlockColor(block))
    {
      attributes->GetBlockColor(block, own);
      colour = own;
    }
    if (attributes->HasBlockOpacity(block))
    {
      opacity = attributes->GetBlockOpacity(block);
    }
  }
  if (auto* tree = vtkDataObjectTree::SafeDownCast(block))
  {
    vtkSmartPointer<vtkDataObjectTreeIterator> it;
    it.TakeReference(tree->NewTreeIterator());
    it->VisitOnlyLeavesOff();
    it->TraverseSubTreeOff();
    it->SkipEmptyNodesOff();
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      if (!this->ConvertBlock(it->GetCurrentDataObject(), actor, mapper, attributes, visible,
            colour, opacity, flatIndex, label))
      {
        return false;
      }
    }
    return true;
  }
  auto* poly = vtkPolyData::SafeDownCast(block);
  if (!poly || !visible)
  {
    return true;
  }
  if (opacity < 1.0)
  {
    ++this->LeftOutTranslucent;
    return true;
  }
  return this->ConvertPolyData(
    poly, actor, mapper, colour, label + " block " + std::to_string(index));
}

void vtkRadiosityCompositePolyDataMapperNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LeftOutTranslucent: " << this->LeftOutTranslucent << "\n";
}
