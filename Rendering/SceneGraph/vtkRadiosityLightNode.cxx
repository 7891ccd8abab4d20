#include "vtkRadiosityLightNode.h"

#include "vtkLight.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"

#include <algorithm>

vtkStandardNewMacro(vtkRadiosityLightNode);

vtkRadiosityLightNode::vtkRadiosityLightNode() = default;
vtkRadiosityLightNode::~vtkRadiosityLightNode() = default;

vtkLight* vtkRadiosityLightNode::GetLight()
{
  return vtkLight::SafeDownCast(this->GetRenderable());
}

bool vtkRadiosityLightNode::GetSolved()
{
  vtkLight* light = this->GetLight();
  return light && light->LightTypeIsSceneLight();
}

vtkMTimeType vtkRadiosityLightNode::GetSceneMTime()
{
  vtkLight* light = this->GetLight();
  if (!light)
  {
    return 0;
  }
  vtkMTimeType time = light->GetMTime();
  if (vtkMatrix4x4* m = light->GetTransformMatrix())
  {
    time = std::max(time, m->GetMTime());
  }
  return time;
}

void vtkRadiosityLightNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Solved: " << (this->GetSolved() ? "true" : "false (not a scene light)") << "\n";
}
