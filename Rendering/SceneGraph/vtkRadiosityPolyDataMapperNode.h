/**
 * @class   vtkRadiosityPolyDataMapperNode
 * @brief   the scene-graph node of a polydata mapper for vtkRadiosityPass:
 *          converts its actor's surface to a radiosity object
 *
 * Synchronize (prepass) converts the mapper's input, when the actor node
 * solves its actor (vtkRadiosityActorNode::GetSolvable) and what it reads
 * changed since the last conversion (GetSceneMTime: actor, property,
 * mapper, lookup table, input, transform): polygons and strips
 * triangulated (vertices and lines left out), points in world coordinates
 * (the actor's matrix; a mirroring matrix keeps the front sides), and the
 * SPEC.md cell arrays `Reflectance`, `Emission`, `Specular`, `Shininess`
 * and `TwoSided` from the property and the mapped scalar colours (see
 * vtkRadiosityPass for the mapping). Bad values give an error naming the
 * actor and the property or array (GetError).
 */
#ifndef vtkRadiosityPolyDataMapperNode_h
#define vtkRadiosityPolyDataMapperNode_h

#include "RadiosityRenderingSceneGraphModule.h" // for export macro
#include "vtkPolyDataMapperNode.h"
#include "vtkSmartPointer.h" // for members
#include "vtkTimeStamp.h"    // for members

#include <string> // for std::string
#include <vector> // for std::vector

class vtkActor;
class vtkMapper;
class vtkPolyData;
class vtkRadiosityRendererNode;

class RADIOSITYRENDERINGSCENEGRAPH_EXPORT vtkRadiosityPolyDataMapperNode
  : public vtkPolyDataMapperNode
{
public:
  static vtkRadiosityPolyDataMapperNode* New();
  vtkTypeMacro(vtkRadiosityPolyDataMapperNode, vtkPolyDataMapperNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Prepass: updates the mapper's input and converts it when it changed.
  void Synchronize(bool prepass) override;

  /// One object of the scene: world-space triangles with the material arrays.
  struct Object
  {
    vtkSmartPointer<vtkPolyData> Data;
    std::string Name;
  };
  /// The objects of the last conversion (none when the actor is not solved).
  const std::vector<Object>& GetObjects() const { return this->Objects; }
  /// The error of the last conversion ("" when none).
  const std::string& GetError() const { return this->Error; }
  const std::vector<std::string>& GetWarnings() const { return this->Warnings; }

  /// The largest MTime of what the conversion reads, now.
  virtual vtkMTimeType GetSceneMTime();
  /// GetSceneMTime() after the last conversion.
  vtkMTimeType GetConvertedMTime() const { return this->ConvertedMTime; }
  /// When the objects last changed (a global VTK time: it moves at every
  /// conversion that gave other objects, points, triangles or material
  /// arrays, also one for a changed MaxReflectance or LightScale; a moved
  /// MTime that changes none of it leaves it, so nothing is solved again).
  vtkMTimeType GetConversionTime() const { return this->ConversionTime.GetMTime(); }

protected:
  vtkRadiosityPolyDataMapperNode();
  ~vtkRadiosityPolyDataMapperNode() override;

  /// Converts the mapper's input into Objects; false with Error set on bad input.
  virtual bool Convert(vtkActor* actor, vtkMapper* mapper, const std::string& label);

  /**
   * Converts one polydata: appends an object named `name` (none when it has
   * no polygon). `blockColor`, when not null, replaces DiffuseColor.
   */
  bool ConvertPolyData(vtkPolyData* input, vtkActor* actor, vtkMapper* mapper,
    const double* blockColor, const std::string& name);

  vtkActor* GetActor();
  vtkRadiosityRendererNode* GetRendererNode();

  std::vector<Object> Objects;
  std::string Error;
  std::vector<std::string> Warnings;
  int ClampedColours = 0;

private:
  vtkRadiosityPolyDataMapperNode(const vtkRadiosityPolyDataMapperNode&) = delete;
  void operator=(const vtkRadiosityPolyDataMapperNode&) = delete;

  vtkMTimeType ConvertedMTime = 0;
  vtkTimeStamp ConversionTime;
  // The settings of the last conversion: a change converts again.
  double ConvertedMaxReflectance = -1.0;
  double ConvertedLightScale = -1.0;
  int ConvertedTwoSided = -1;
  bool ConvertedSolvable = false;
};

#endif
