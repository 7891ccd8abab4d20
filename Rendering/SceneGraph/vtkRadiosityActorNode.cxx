#include "vtkRadiosityActorNode.h"

#include "vtkActor.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkProperty.h"
#include "vtkRadiosityPolyDataMapperNode.h"

vtkStandardNewMacro(vtkRadiosityActorNode);

vtkRadiosityActorNode::vtkRadiosityActorNode() = default;
vtkRadiosityActorNode::~vtkRadiosityActorNode() = default;

void vtkRadiosityActorNode::Synchronize(bool prepass)
{
  if (!prepass)
  {
    return;
  }
  this->Solvable = false;
  auto* actor = vtkActor::SafeDownCast(this->GetRenderable());
  if (!actor)
  {
    this->Reason = "not an actor";
    return;
  }
  vtkProperty* property = actor->GetProperty();
  if (!actor->GetVisibility())
  {
    this->Reason = "not visible";
  }
  else if (!this->AssemblyVisible)
  {
    this->Reason = "part of an assembly that is not visible";
  }
  else if (!actor->GetMapper())
  {
    this->Reason = "no mapper";
  }
  else if (property->GetRepresentation() != VTK_SURFACE)
  {
    this->Reason = "wireframe or points representation (drawn, not solved)";
  }
  else if (property->GetOpacity() < 1.0 || actor->GetForceTranslucent())
  {
    this->Reason = "translucent (drawn, not solved)";
  }
  else
  {
    this->Reason.clear();
    this->Solvable = true;
  }
}

vtkRadiosityPolyDataMapperNode* vtkRadiosityActorNode::GetMapperNode()
{
  auto* actor = vtkActor::SafeDownCast(this->GetRenderable());
  if (!actor || !actor->GetMapper())
  {
    return nullptr;
  }
  return vtkRadiosityPolyDataMapperNode::SafeDownCast(this->GetViewNodeFor(actor->GetMapper()));
}

void vtkRadiosityActorNode::SetAssemblyPath(vtkMatrix4x4* matrix, bool visible)
{
  this->InAssembly = matrix != nullptr;
  this->AssemblyVisible = !matrix || visible;
  if (!matrix)
  {
    return;
  }
  bool same = true;
  for (int i = 0; i < 16; ++i)
  {
    same &= this->AssemblyMatrix->GetData()[i] == matrix->GetData()[i];
  }
  if (!same)
  {
    this->AssemblyMatrix->DeepCopy(matrix);
  }
}

vtkMTimeType vtkRadiosityActorNode::GetAssemblyMTime() const
{
  return this->InAssembly ? this->AssemblyMatrix->GetMTime() : 0;
}

vtkMatrix4x4* vtkRadiosityActorNode::GetWorldMatrix()
{
  if (this->InAssembly)
  {
    return this->AssemblyMatrix;
  }
  auto* actor = vtkActor::SafeDownCast(this->GetRenderable());
  return actor ? actor->GetMatrix() : nullptr;
}

void vtkRadiosityActorNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Label: " << this->Label << "\n";
  os << indent << "Solvable: " << (this->Solvable ? "true" : this->Reason.c_str()) << "\n";
  os << indent << "InAssembly: " << (this->InAssembly ? "true" : "false") << "\n";
  if (this->InAssembly)
  {
    os << indent << "AssemblyVisible: " << (this->AssemblyVisible ? "true" : "false") << "\n";
    os << indent << "AssemblyMatrix:\n";
    this->AssemblyMatrix->PrintSelf(os, indent.GetNextIndent());
  }
}
