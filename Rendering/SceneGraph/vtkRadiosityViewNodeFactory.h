/**
 * @class   vtkRadiosityViewNodeFactory
 * @brief   the scene-graph nodes of vtkRadiosityPass
 *
 * Registers vtkRadiosityRendererNode for vtkRenderer, vtkRadiosityActorNode
 * for vtkActor (vtkOpenGLActor, ParaView's vtkPVLODActor: the factory takes
 * the nearest registered superclass), vtkRadiosityPolyDataMapperNode for
 * vtkPolyDataMapper, vtkRadiosityCompositePolyDataMapperNode for
 * vtkCompositePolyDataMapper2 and vtkCompositePolyDataMapper, and
 * vtkRadiosityLightNode for vtkLight. Cameras, volumes and other props get
 * no node: they are not part of the solve.
 */
#ifndef vtkRadiosityViewNodeFactory_h
#define vtkRadiosityViewNodeFactory_h

#include "RadiosityRenderingSceneGraphModule.h" // for export macro
#include "vtkViewNodeFactory.h"

class RADIOSITYRENDERINGSCENEGRAPH_EXPORT vtkRadiosityViewNodeFactory : public vtkViewNodeFactory
{
public:
  static vtkRadiosityViewNodeFactory* New();
  vtkTypeMacro(vtkRadiosityViewNodeFactory, vtkViewNodeFactory);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkRadiosityViewNodeFactory();
  ~vtkRadiosityViewNodeFactory() override;

private:
  vtkRadiosityViewNodeFactory(const vtkRadiosityViewNodeFactory&) = delete;
  void operator=(const vtkRadiosityViewNodeFactory&) = delete;
};

#endif
