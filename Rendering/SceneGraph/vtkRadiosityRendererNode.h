/**
 * @class   vtkRadiosityRendererNode
 * @brief   the scene-graph node of a renderer for vtkRadiosityPass
 *
 * Build adds the nodes of the renderer's lights and actors (and camera)
 * through the pass's factory (vtkRendererNode). Synchronize names every
 * actor node (its index among the renderer's actors and its class, the name
 * errors use), lets the children convert their actors and lights, and then
 * gathers: the objects of the solved actors as one vtkMultiBlockDataSet
 * (a block per object, named after its actor), the renderer's scene lights
 * as a vtkLightCollection, and the signature of all of it (each solved
 * actor's identity and the time its mapper node last converted it, each
 * scene light's identity and MTime). The node also keeps the cached
 * solution (the filter's outputs of the last successful solve) and the
 * signature it was solved for, so that vtkRadiosityPass solves again only
 * when the signature moved.
 *
 * The settings the solution was solved and drawn with are readable from
 * the renderer's information, as vtkOSPRayRendererNode keeps OSPRay's:
 * vtkRadiosityPass writes them at every UpdateSolution and Render (keys
 * METHOD, TOLERANCE, LIGHT_SCALE, SKY_MODEL, MAX_REFLECTANCE, TWO_SIDED,
 * EXPOSURE, TONE_MAPPING, NUMBER_OF_SOLVES), and the static getters read
 * them from any renderer (the pass's default where a key is absent, so
 * code that holds only the renderer, such as a view or an annotation, can
 * say what it shows).
 */
#ifndef vtkRadiosityRendererNode_h
#define vtkRadiosityRendererNode_h

#include "RadiosityRenderingSceneGraphModule.h" // for export macro
#include "vtkRendererNode.h"
#include "vtkSmartPointer.h" // for members

#include <set>     // for std::set
#include <string>  // for std::string
#include <utility> // for std::pair
#include <vector>  // for std::vector

class vtkActor;
class vtkInformationDoubleKey;
class vtkInformationIntegerKey;
class vtkLightCollection;
class vtkMultiBlockDataSet;
class vtkPolyData;
class vtkProp;
class vtkRenderer;

class RADIOSITYRENDERINGSCENEGRAPH_EXPORT vtkRadiosityRendererNode : public vtkRendererNode
{
public:
  static vtkRadiosityRendererNode* New();
  vtkTypeMacro(vtkRadiosityRendererNode, vtkRendererNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The keys of the pass's settings in the renderer's information (see the class doc).
  static vtkInformationIntegerKey* METHOD();
  static vtkInformationDoubleKey* TOLERANCE();
  static vtkInformationDoubleKey* LIGHT_SCALE();
  static vtkInformationIntegerKey* SKY_MODEL();
  static vtkInformationDoubleKey* MAX_REFLECTANCE();
  static vtkInformationIntegerKey* TWO_SIDED();
  static vtkInformationDoubleKey* EXPOSURE();
  static vtkInformationIntegerKey* TONE_MAPPING();
  static vtkInformationIntegerKey* NUMBER_OF_SOLVES();
  ///@}

  ///@{
  /**
   * The settings a renderer's pass last wrote (vtkRadiosityFilter's method
   * constants, the sky model's, ...); the pass's defaults when the renderer
   * has none (a null renderer too).
   */
  static int GetMethod(vtkRenderer* renderer);
  static double GetTolerance(vtkRenderer* renderer);
  static double GetLightScale(vtkRenderer* renderer);
  static int GetSkyModel(vtkRenderer* renderer);
  static double GetMaxReflectance(vtkRenderer* renderer);
  static bool GetTwoSided(vtkRenderer* renderer);
  static double GetExposure(vtkRenderer* renderer);
  static int GetToneMapping(vtkRenderer* renderer);
  static int GetNumberOfSolves(vtkRenderer* renderer);
  ///@}

  /// Prepass: names the actor nodes; postpass: gathers what the children converted.
  void Synchronize(bool prepass) override;

  ///@{
  /// What the mapper nodes convert with (set by the pass before a traversal).
  vtkSetMacro(MaxReflectance, double);
  vtkGetMacro(MaxReflectance, double);
  vtkSetMacro(LightScale, double);
  vtkGetMacro(LightScale, double);
  ///@}

  /// Whether every surface is solved on both sides (vtkRadiosityPass::TwoSided).
  vtkSetMacro(TwoSided, bool);
  vtkGetMacro(TwoSided, bool);

  /// The scene gathered by the last Synchronize: one block per object.
  vtkMultiBlockDataSet* GetSceneInput();
  /// The renderer's scene lights, in its order.
  vtkLightCollection* GetSceneLights();
  /// The first conversion error of the last Synchronize ("" when none).
  const std::string& GetGatherError() const { return this->GatherError; }
  /// Warnings of the last conversion (colours clamped, ...).
  const std::vector<std::string>& GetGatherWarnings() const { return this->GatherWarnings; }
  /// How many triangles the gathered objects have.
  vtkIdType GetNumberOfTriangles() const { return this->NumberOfTriangles; }

  /// Whether `prop` is one of the actors the last Synchronize gathered for the solve.
  bool IsGathered(vtkProp* prop) const;

  /**
   * Identity and MTime of everything gathered, in order: a solve is needed
   * when this differs from the signature of the cached solution.
   */
  using Signature = std::vector<std::pair<const void*, vtkMTimeType>>;
  const Signature& GetSignature() const { return this->CurrentSignature; }

  ///@{
  /**
   * The cached solution: the filter's surface (port 0) and product (port 1)
   * of the last solve, and the signature and filter MTime it was solved
   * for. ClearSolution keeps the signature (a failed solve is not retried
   * until the scene changes) but no data.
   */
  void SetSolution(vtkPolyData* surface, vtkPolyData* product, const Signature& signature,
    vtkMTimeType filterTime);
  void ClearSolution(const Signature& signature, vtkMTimeType filterTime);
  vtkPolyData* GetSolutionSurface();
  vtkPolyData* GetSolutionProduct();
  bool HasSolution() const { return this->SolutionSurface != nullptr; }
  bool IsSolvedFor(const Signature& signature, vtkMTimeType filterTime) const;
  ///@}

protected:
  vtkRadiosityRendererNode();
  ~vtkRadiosityRendererNode() override;

  double MaxReflectance = 0.95;
  double LightScale = 3.14159265358979323846;
  bool TwoSided = false;

private:
  vtkRadiosityRendererNode(const vtkRadiosityRendererNode&) = delete;
  void operator=(const vtkRadiosityRendererNode&) = delete;

  void Gather();

  vtkSmartPointer<vtkMultiBlockDataSet> SceneInput;
  vtkSmartPointer<vtkLightCollection> SceneLights;
  std::string GatherError;
  std::vector<std::string> GatherWarnings;
  vtkIdType NumberOfTriangles = 0;
  std::set<vtkProp*> Gathered;
  Signature CurrentSignature;
  Signature SolvedSignature;
  vtkMTimeType SolvedFilterTime = 0;
  bool Solved = false;
  vtkSmartPointer<vtkPolyData> SolutionSurface;
  vtkSmartPointer<vtkPolyData> SolutionProduct;
};

#endif
