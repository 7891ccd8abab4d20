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
 *
 * A part of a vtkAssembly (the renderer's actors include every assembly's
 * parts, vtkAssembly::GetActors) is placed by its assembly path's matrix,
 * the concatenation of the assembly's, every intermediate part's and its
 * own (vtkAssemblyNode::GetMatrix, what vtkAssembly pokes into the part when
 * it renders it): the renderer node sets it (SetAssemblyPath), and the part
 * is solved only while its assembly is visible. GetWorldMatrix is what the
 * mapper node transforms the points by.
 */
#ifndef vtkRadiosityActorNode_h
#define vtkRadiosityActorNode_h

#include "RadiosityRenderingSceneGraphModule.h" // for export macro
#include "vtkActorNode.h"
#include "vtkNew.h" // for members

#include <string> // for std::string

class vtkMatrix4x4;
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

  ///@{
  /**
   * The part of an assembly: `matrix` is its path's concatenated matrix and
   * `visible` whether the top assembly is visible; a null `matrix` makes the
   * actor a top-level one again (its own matrix). The renderer node calls it
   * before the actor's Synchronize. The stored matrix's MTime moves only
   * when its values change (GetAssemblyMTime), so that an assembly drawn
   * without the pass, which pokes its parts' matrices at every render,
   * does not make the scene look changed.
   */
  void SetAssemblyPath(vtkMatrix4x4* matrix, bool visible);
  bool GetInAssembly() const { return this->InAssembly; }
  vtkMTimeType GetAssemblyMTime() const;
  ///@}

  /// The matrix from the actor's model coordinates to world coordinates:
  /// the assembly path's for a part, else the actor's GetMatrix().
  vtkMatrix4x4* GetWorldMatrix();

protected:
  vtkRadiosityActorNode();
  ~vtkRadiosityActorNode() override;

private:
  vtkRadiosityActorNode(const vtkRadiosityActorNode&) = delete;
  void operator=(const vtkRadiosityActorNode&) = delete;

  bool Solvable = false;
  std::string Reason;
  std::string Label;
  bool InAssembly = false;
  bool AssemblyVisible = true;
  vtkNew<vtkMatrix4x4> AssemblyMatrix;
};

#endif
