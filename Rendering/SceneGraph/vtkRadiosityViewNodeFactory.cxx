#include "vtkRadiosityViewNodeFactory.h"

#include "vtkObjectFactory.h"
#include "vtkRadiosityActorNode.h"
#include "vtkRadiosityCompositePolyDataMapperNode.h"
#include "vtkRadiosityLightNode.h"
#include "vtkRadiosityPolyDataMapperNode.h"
#include "vtkRadiosityRendererNode.h"

vtkStandardNewMacro(vtkRadiosityViewNodeFactory);

namespace
{
template <typename Node>
vtkViewNode* Make()
{
  return Node::New();
}
}

vtkRadiosityViewNodeFactory::vtkRadiosityViewNodeFactory()
{
  this->RegisterOverride("vtkRenderer", Make<vtkRadiosityRendererNode>);
  this->RegisterOverride("vtkActor", Make<vtkRadiosityActorNode>);
  this->RegisterOverride("vtkPolyDataMapper", Make<vtkRadiosityPolyDataMapperNode>);
  this->RegisterOverride("vtkCompositePolyDataMapper2", Make<vtkRadiosityCompositePolyDataMapperNode>);
  this->RegisterOverride("vtkCompositePolyDataMapper", Make<vtkRadiosityCompositePolyDataMapperNode>);
  this->RegisterOverride("vtkLight", Make<vtkRadiosityLightNode>);
}

vtkRadiosityViewNodeFactory::~vtkRadiosityViewNodeFactory() = default;

void vtkRadiosityViewNodeFactory::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Nodes: vtkRenderer, vtkActor, vtkPolyDataMapper, vtkCompositePolyDataMapper2, "
                  "vtkCompositePolyDataMapper, vtkLight\n";
}
