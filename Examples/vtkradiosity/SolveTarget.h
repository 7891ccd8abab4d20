// What a solve of the command line runs on: a loaded scene (vtkDataObject,
// the scene loader's) through its own vtkRadiosityFilter, or an imported
// one (a renderer filled by VTK's importers, ImportedScene.h) through
// vtkRadiosityPass::UpdateSolution, the scene-graph path a VTK application
// takes (no OpenGL: a solve without --image needs no display). Either way
// the filter that solved holds the settings and the result.
#ifndef vtkradiosity_SolveTarget_h
#define vtkradiosity_SolveTarget_h

#include "ImportedScene.h"

#include "vtkSmartPointer.h"

#include "Radiosity/Common/Lights.h"

#include <nlohmann/json.hpp>

class vtkDataObject;
class vtkRadiosityFilter;
class vtkRadiosityPass;

namespace solve
{
class SolveTarget
{
public:
  /// A loaded scene: the filter's input.
  explicit SolveTarget(vtkDataObject* input);
  /// An imported scene, solved through a vtkRadiosityPass with the scene's
  /// LightScale and `maxReflectance` for its display colours.
  SolveTarget(radiosity::cli::ImportedScene& imported, double maxReflectance);
  ~SolveTarget();

  /// The filter that solves (the pass's for an imported scene).
  vtkRadiosityFilter* Filter() const;
  /// The method, on the filter (and the pass).
  void SetMethod(int method);
  /// An imported scene's surfaces solved on both sides (vtkRadiosityPass::TwoSided).
  void SetTwoSided();
  /// Solves: filter->Update(), or pass->UpdateSolution(renderer). A failure
  /// leaves the message in the filter's LastError; a failure of the pass
  /// before the filter ran (a NaN point, a bad colour or light of an actor)
  /// is BadInput naming the file and the pass's message.
  void Update();
  /// The pass's warnings of the last Update (colours clamped, ...), "FILE: ...".
  const std::vector<std::string>& PassWarnings() const { return this->Warnings; }

  bool IsImported() const { return this->Imported != nullptr; }
  /// The file's camera for --image; null when it has none (or for a loaded scene).
  const radiosity::cli::ViewCamera* Camera() const;
  /// `lights` (--lights) and the lights the import could not leave on the
  /// renderer (ImportedScene::ExtraLights).
  radiosity::LightSet SceneLights(const radiosity::LightSet& lights) const;
  /// The report's "import" section: the importer, actors, polygons, lights,
  /// LightScale, the camera; null for a loaded scene.
  nlohmann::json ImportReport() const;

private:
  vtkSmartPointer<vtkRadiosityFilter> OwnFilter;
  vtkSmartPointer<vtkRadiosityPass> Pass;
  radiosity::cli::ImportedScene* Imported = nullptr;
  std::vector<std::string> Warnings;
};
}

#endif
