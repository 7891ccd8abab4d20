/**
 * @class   vtkRadiosityCompositePolyDataMapperNode
 * @brief   the scene-graph node of a composite polydata mapper for
 *          vtkRadiosityPass: one radiosity object per visible block
 *
 * For vtkCompositePolyDataMapper2 and vtkCompositePolyDataMapper: every
 * polydata leaf of the composite input is an object (named after its actor
 * and its flat index), converted as vtkRadiosityPolyDataMapperNode does,
 * with the composite display attributes inherited down the tree: blocks
 * hidden (block visibility) are left out, a block colour replaces the
 * property's DiffuseColor, and blocks with an opacity below 1 are left out
 * of the solve (documented in vtkRadiosityPass). The scene MTime also
 * covers every leaf and the display attributes.
 */
#ifndef vtkRadiosityCompositePolyDataMapperNode_h
#define vtkRadiosityCompositePolyDataMapperNode_h

#include "RadiosityRenderingSceneGraphModule.h" // for export macro
#include "vtkRadiosityPolyDataMapperNode.h"

class vtkCompositeDataDisplayAttributes;
class vtkDataObject;

class RADIOSITYRENDERINGSCENEGRAPH_EXPORT vtkRadiosityCompositePolyDataMapperNode
  : public vtkRadiosityPolyDataMapperNode
{
public:
  static vtkRadiosityCompositePolyDataMapperNode* New();
  vtkTypeMacro(vtkRadiosityCompositePolyDataMapperNode, vtkRadiosityPolyDataMapperNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The superclass's, and every block's and the display attributes' MTime.
  vtkMTimeType GetSceneMTime() override;

protected:
  vtkRadiosityCompositePolyDataMapperNode();
  ~vtkRadiosityCompositePolyDataMapperNode() override;

  bool Convert(vtkActor* actor, vtkMapper* mapper, const std::string& label) override;

private:
  vtkRadiosityCompositePolyDataMapperNode(const vtkRadiosityCompositePolyDataMapperNode&) = delete;
  void operator=(const vtkRadiosityCompositePolyDataMapperNode&) = delete;

  /// The mapper's display attributes, or null.
  vtkCompositeDataDisplayAttributes* GetAttributes();
  /// Converts `block` and its children with the attributes inherited from its parents.
  bool ConvertBlock(vtkDataObject* block, vtkActor* actor, vtkMapper* mapper,
    vtkCompositeDataDisplayAttributes* attributes, bool visible, const double* colour,
    double opacity, unsigned int& flatIndex, const std::string& label);

  int LeftOutTranslucent = 0;
};

#endif
