/**
 * @class   vtkRadiosityLightNode
 * @brief   the scene-graph node of a light for vtkRadiosityPass
 *
 * A light is solved when it is a scene light (vtkLight::LightTypeIsSceneLight):
 * headlights and camera lights move with the camera and are not part of the
 * solve (a camera move would otherwise solve again). A light switched off is
 * still handed to the filter, which checks it and leaves it out.
 * GetSceneMTime covers the light and its transform matrix.
 */
#ifndef vtkRadiosityLightNode_h
#define vtkRadiosityLightNode_h

#include "RadiosityRenderingSceneGraphModule.h" // for export macro
#include "vtkLightNode.h"

class vtkLight;

class RADIOSITYRENDERINGSCENEGRAPH_EXPORT vtkRadiosityLightNode : public vtkLightNode
{
public:
  static vtkRadiosityLightNode* New();
  vtkTypeMacro(vtkRadiosityLightNode, vtkLightNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The light, or null.
  vtkLight* GetLight();
  /// Whether the light is part of the solve (a scene light).
  bool GetSolved();
  /// The light's MTime and its transform matrix's.
  vtkMTimeType GetSceneMTime();

protected:
  vtkRadiosityLightNode();
  ~vtkRadiosityLightNode() override;

private:
  vtkRadiosityLightNode(const vtkRadiosityLightNode&) = delete;
  void operator=(const vtkRadiosityLightNode&) = delete;
};

#endif
