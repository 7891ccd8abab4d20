/**
 * @class   vtkRadiosityActorNode
 * @brief   the scene-graph node of an actor for vtkRadiosityPass
 *
 * Build adds the node of the actor's mapper, GetMapper(): for ParaView's
 * LOD actor the full-resolution one, so that the solve never follows the
 * decimated geometry shown while interacting. Synchronize (prepass) decides
 * whether the actor is solved (GetSolvable): visible, a mapper, the Surface
 * representation, Opacity 1 and not ForceTranslucent; the mapper node then
 * converts it. GetLabel is the name errors and objects carry: the actor's
 * index among the renderer's actors and its class.
 */
#ifndef vtkRadiosityActorNode_h
#define vtkRadiosityActorNode_h

#include "RadiosityRenderingSceneGraphModule.h" // for export macro
#include "vtkActorNode.h"

#include <string> // for std::string

class vtkRadiosityPolyDataMapperNode;

class RADIOSITYRENDERINGSCENEGRAPH_EXPORT vtkRadiosityActorNode : public vtkActorNode
{
public:
  static vtkRadiosityActorNode* New();
  vtkTypeMacro(vtkRadiosityActorNode, vtkActorNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Prepass: whether the actor is solved.
  void Synchronize(bool prepass) override;

  /// Whether the last Synchronize found the actor solvable (see the class doc).
  bool GetSolvable() const { return this->Solvable; }
  /// Why it is not ("" when it is).
  const std::string& GetReason() const { return this->Reason; }

  ///@{
  /// The actor's name in errors and objects ("actor 2 (vtkOpenGLActor)").
  void SetLabel(const std::string& label) { this->Label = label; }
  const std::string& GetLabel() const { return this->Label; }
  ///@}

  /// The node of the actor's mapper (null when it has none we know).
  vtkRadiosityPolyDataMapperNode* GetMapperNode();

protected:
  vtkRadiosityActorNode();
  ~vtkRadiosityActorNode() override;

private:
  vtkRadiosityActorNode(const vtkRadiosityActorNode&) = delete;
  void operator=(const vtkRadiosityActorNode&) = delete;

  bool Solvable = false;
  std::string Reason;
  std::string Label;
};

#endif
