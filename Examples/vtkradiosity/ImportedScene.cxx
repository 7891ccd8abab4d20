#include "ImportedScene.h"

#include "GltfFileCheck.h"
#include "SceneFileCheck.h"

#include "vtk3DSImporter.h"
#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkGLTFImporter.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLogger.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRadiosityRendererNode.h"
#include "vtkRadiositySceneConverter.h"
#include "vtkVRMLImporter.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace radiosity
{
namespace cli
{
namespace
{
std::string LowerExtension(const std::string& file)
{
  const auto slash = file.find_last_of('/');
  const auto dot = file.rfind('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return "";
  }
  std::string ext = file.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// VTK's error and warning messages during an import, collected instead of
// printed (the refusal is one line naming the file).
class ImportMessages : public vtkOutputWindow
{
public:
  static ImportMessages* New();
  vtkTypeMacro(ImportMessages, vtkOutputWindow);
  void DisplayErrorText(const char* text) override { this->Errors.push_back(Message(text)); }
  void DisplayWarningText(const char* text) override { this->Warnings.push_back(Message(text)); }
  void DisplayGenericWarningText(const char* text) override { this->DisplayWarningText(text); }
  void DisplayText(const char* text) override { this->Warnings.push_back(Message(text)); }
  void DisplayDebugText(const char*) override {}
  std::vector<std::string> Errors, Warnings;

private:
  // "ERROR: In file.cxx, line 12\nvtkGLTFImporter (0x55...): the message\n\n" -> the message.
  static std::string Message(const char* text)
  {
    std::string s = text ? text : "";
    const auto object = s.find("): ");
    if (object != std::string::npos)
    {
      s = s.substr(object + 3);
    }
    std::replace(s.begin(), s.end(), '\n', ' ');
    while (!s.empty() && s.back() == ' ')
    {
      s.pop_back();
    }
    return s;
  }
};
vtkStandardNewMacro(ImportMessages);

// VTK's importers trust their files further than the checks here reach:
// vtk3DSImporter reads chunks past their ends and segfaults on a truncated or
// bit-flipped .3ds, and the image decoders under vtkGLTFImporter crash on a
// corrupted PNG inside a .glb (both measured by mutating the corpus files).
// So the import runs first in a child process (fork: the same code on a copy
// of this one, before any solver thread exists); a child killed by a signal,
// or still reading after ImportSeconds, is a refusal here, and only a file
// the child read (and whose actors' pipelines it updated) is imported for real.
const unsigned int ImportSeconds = 120;

bool ImportSurvives(vtkImporter* importer, const std::string& file, const std::string& name, std::string& error)
{
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child < 0)
  {
    return true; // no child to try it in: import it here
  }
  if (child == 0)
  {
    const int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0)
    {
      ::dup2(null, 1);
      ::dup2(null, 2);
    }
    const struct rlimit noCore = { 0, 0 }; // a crash here is expected: no core file
    ::setrlimit(RLIMIT_CORE, &noCore);
    ::alarm(ImportSeconds);
    importer->Read();
    // The importers' pipelines run when a mapper updates (vtk3DSImporter's
    // normals and stripper index the file's faces there).
    vtkActorCollection* actors = importer->GetRenderer() ? importer->GetRenderer()->GetActors() : nullptr;
    if (actors)
    {
      actors->InitTraversal();
      while (vtkActor* actor = actors->GetNextActor())
      {
        if (actor->GetMapper())
        {
          actor->GetMapper()->Update();
        }
      }
    }
    ::_exit(0);
  }
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR)
  {
  }
  if (WIFSIGNALED(status))
  {
    const int signal = WTERMSIG(status);
    error = file + ": " + name +
      (signal == SIGALRM ? " did not finish reading it in " + std::to_string(ImportSeconds) + " s"
                         : " crashed reading it (signal " + std::to_string(signal) + ")") +
      ": the file is malformed";
    return false;
  }
  return true;
}

// Runs the importer with VTK's messages collected.
bool RunImporter(vtkImporter* importer, const std::string& file, ImportedScene& scene, std::string& error,
  std::vector<std::string>& warnings)
{
  scene.Window = vtkSmartPointer<vtkRenderWindow>::New();
  scene.Renderer = vtkSmartPointer<vtkRenderer>::New();
  scene.Window->AddRenderer(scene.Renderer);
  importer->SetRenderWindow(scene.Window);
  if (!ImportSurvives(importer, file, scene.Importer, error))
  {
    return false;
  }
  VtkMessages messages;
  importer->Read();
  for (const std::string& w : messages.Warnings())
  {
    warnings.push_back(file + ": " + scene.Importer + ": " + w);
  }
  // Textures are not read by the solve (a material's factors are): VTK's
  // complaint about a valid file's texture colour space ("The materialTex
  // texture is not in linear color space.", vtkProperty) is a warning here;
  // a malformed texture reference ("Invalid textureInfo.index value") is
  // still a refusal.
  std::string refusal;
  for (const std::string& e : messages.Errors())
  {
    std::string lower = e;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
    if (lower.find("texture") != std::string::npos && lower.find("color space") != std::string::npos)
    {
      warnings.push_back(file + ": " + scene.Importer + ": " + e + " (textures are not used by the solve)");
    }
    else if (refusal.empty())
    {
      refusal = e;
    }
  }
  if (!refusal.empty())
  {
    error = file + ": VTK's importer (" + scene.Importer + ") cannot read it: " + refusal;
    return false;
  }
  return true;
}

// Content checks of the formats without a checker of their own: what makes
// VTK's parsers read past the bytes they have.
bool Check3ds(const std::string& file, const std::string& bytes, std::string& error)
{
  // The main chunk: id 0x4D4D and a length no larger than the file.
  if (bytes.size() < 6 || static_cast<unsigned char>(bytes[0]) != 0x4D ||
    static_cast<unsigned char>(bytes[1]) != 0x4D)
  {
    error = file + ": not a 3D Studio file (it does not start with the main chunk 0x4D4D)";
    return false;
  }
  const auto* b = reinterpret_cast<const unsigned char*>(bytes.data());
  const unsigned long length = b[2] | b[3] << 8 | b[4] << 16 | static_cast<unsigned long>(b[5]) << 24;
  if (length > bytes.size() || length < 6)
  {
    error = file + ": the main chunk says " + std::to_string(length) + " bytes but the file holds " +
      std::to_string(bytes.size()) + (length > bytes.size() ? " (truncated)" : "");
    return false;
  }
  return true;
}

bool CheckVrml(const std::string& file, const std::string& bytes, std::string& error)
{
  // vtkVRMLImporter reads VRML 2.0 text (it refuses nothing itself: a file of
  // another kind parses to nothing or to an error).
  if (bytes.compare(0, 15, "#VRML V2.0 utf8") != 0)
  {
    error = file + ": not a VRML 2.0 file (it does not start with '#VRML V2.0 utf8'; VTK reads VRML 2.0)";
    return false;
  }
  return true;
}

void TakeCamera(vtkCamera* camera, ViewCamera& view)
{
  camera->GetPosition(view.Position);
  camera->GetFocalPoint(view.FocalPoint);
  camera->GetViewUp(view.ViewUp);
  view.ViewAngle = camera->GetViewAngle();
}

// The corrections to VTK 9.2's glTF lights (ImportedScene.h) and the lights a
// vtkLight cannot carry.
void FixGltfLights(const std::string& file, const GltfSummary& summary, ImportedScene& scene,
  std::vector<std::string>& warnings, std::vector<std::string>& notes)
{
  vtkLightCollection* lights = scene.Renderer->GetLights();
  std::vector<vtkLight*> imported;
  lights->InitTraversal();
  while (vtkLight* light = lights->GetNextItem())
  {
    imported.push_back(light);
  }
  if (imported.size() != summary.ImportedLightOrder.size())
  {
    warnings.push_back(file + ": VTK imported " + std::to_string(imported.size()) + " lights, the file places " +
      std::to_string(summary.ImportedLightOrder.size()) + ": the lights are taken as VTK imported them");
    return;
  }
  for (std::size_t k = 0; k < imported.size(); ++k)
  {
    vtkLight* light = imported[k];
    const GltfLight& defined = summary.Lights[summary.ImportedLightOrder[k]];
    scene.LightLabels[light] = "light " + std::to_string(summary.ImportedLightOrder[k]) +
      (defined.Name.empty() ? std::string() : " ('" + defined.Name + "')");
    light->SetPosition(0.0, 0.0, 0.0);
    light->SetFocalPoint(0.0, 0.0, -1.0);
    if (defined.Type == "spot" && defined.InnerConeAngle > 0.0)
    {
      double p[3], f[3];
      light->GetTransformedPosition(p);
      light->GetTransformedFocalPoint(f);
      Light spot;
      spot.Type = LightType::Spot;
      spot.Position = Vec3(p[0], p[1], p[2]);
      spot.Direction = Vec3(f[0] - p[0], f[1] - p[1], f[2] - p[2]);
      spot.Intensity = RGB(defined.Intensity * defined.Color[0], defined.Intensity * defined.Color[1],
        defined.Intensity * defined.Color[2]);
      spot.InnerConeAngle = defined.InnerConeAngle;
      spot.OuterConeAngle = defined.OuterConeAngle;
      spot.Name = defined.Name;
      scene.ExtraLights.Lights.push_back(spot);
      scene.Renderer->RemoveLight(light);
      notes.push_back(file + ": light " + std::to_string(summary.ImportedLightOrder[k]) +
        " (spot, innerConeAngle " + std::to_string(defined.InnerConeAngle) +
        ") is solved from the file's values: a vtkLight has no inner cone");
    }
  }
}

// A file's lights are data, not a contract the user wrote (SPEC "Lights and
// sky"): one the solver cannot take (a zero direction, as a .3ds light whose
// position equals its target; a NaN; a negative intensity) is left out with a
// warning naming it, and the rest of the scene is solved.
void DropDegenerateLights(const std::string& file, ImportedScene& scene, std::vector<std::string>& warnings)
{
  const auto check = [](Light& light, std::string& why) {
    LightSet one;
    one.Lights.push_back(light);
    try
    {
      ValidateLights(one);
    }
    catch (const std::exception& e)
    {
      why = e.what();
      const std::string prefix = "light 0 ";
      if (why.compare(0, prefix.size(), prefix) == 0)
      {
        why = why.substr(prefix.size()); // "(type, 'name'): field ..."
      }
      return false;
    }
    light = one.Lights[0];
    if (!(MaxComponent(light.Intensity) > 0.0))
    {
      why = std::string("(") + LightTypeName(light.Type) +
        (light.Name.empty() ? std::string() : ", '" + light.Name + "'") + "): its intensity is zero";
      return false;
    }
    return true;
  };
  std::vector<vtkLight*> lights;
  scene.Renderer->GetLights()->InitTraversal();
  while (vtkLight* light = scene.Renderer->GetLights()->GetNextItem())
  {
    lights.push_back(light);
  }
  for (std::size_t k = 0; k < lights.size(); ++k)
  {
    Light converted = vtkRadiositySceneConverter::ToLight(lights[k], scene.LightScale);
    std::string why;
    if (!check(converted, why))
    {
      const auto label = scene.LightLabels.find(lights[k]);
      warnings.push_back(file + ": " +
        (label != scene.LightLabels.end() ? label->second
                                          : "imported light " + std::to_string(k) + " of " + std::to_string(lights.size())) +
        " " + why + ": that light is left out");
      scene.Renderer->RemoveLight(lights[k]);
      ++scene.LightsLeftOut;
    }
  }
  std::vector<Light> kept;
  for (std::size_t k = 0; k < scene.ExtraLights.Lights.size(); ++k)
  {
    Light light = scene.ExtraLights.Lights[k];
    std::string why;
    if (check(light, why))
    {
      kept.push_back(scene.ExtraLights.Lights[k]);
      continue;
    }
    warnings.push_back(file + ": light " + why + ": that light is left out");
    ++scene.LightsLeftOut;
  }
  scene.ExtraLights.Lights = kept;
}

bool ImportGltf(const std::string& file, const std::string& bytes, ImportedScene& scene, std::string& error,
  std::vector<std::string>& warnings, std::vector<std::string>& notes)
{
  GltfSummary summary;
  if (!CheckGltf(file, bytes, summary, error, warnings))
  {
    return false;
  }
  scene.Importer = "vtkGLTFImporter";
  vtkNew<vtkGLTFImporter> importer;
  importer->SetFileName(file.c_str());
  if (summary.Cameras > 0)
  {
    importer->SetCamera(0); // SPEC: the first camera for --image
  }
  if (!RunImporter(importer, file, scene, error, warnings))
  {
    return false;
  }
  // glTF's doubleSided (VTK's importer culls the back faces of the other
  // materials): those actors are solved on both sides.
  std::size_t doubleSided = 0;
  vtkActorCollection* actors = scene.Renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* actor = actors->GetNextActor())
  {
    if (!actor->GetProperty()->GetBackfaceCulling())
    {
      vtkNew<vtkInformation> keys;
      if (actor->GetPropertyKeys())
      {
        keys->Copy(actor->GetPropertyKeys());
      }
      keys->Set(vtkRadiosityRendererNode::TWO_SIDED(), 1);
      actor->SetPropertyKeys(keys);
      ++doubleSided;
    }
  }
  if (doubleSided > 0)
  {
    notes.push_back(file + ": " + std::to_string(doubleSided) +
      " actors have a doubleSided material: they are solved on both sides");
  }
  scene.TwoSidedActors = doubleSided;
  scene.LightScale = 1.0; // the file's intensity one to one (ImportedScene.h)
  scene.FileLights = summary.ImportedLightOrder.size();
  FixGltfLights(file, summary, scene, warnings, notes);
  if (summary.Cameras > 0)
  {
    scene.HasCamera = true;
    TakeCamera(scene.Renderer->GetActiveCamera(), scene.Camera);
  }
  return true;
}
} // namespace

struct VtkMessages::Internals
{
  vtkSmartPointer<vtkOutputWindow> Previous;
  vtkNew<ImportMessages> Collector;
  vtkLogger::Verbosity Stderr;
};

VtkMessages::VtkMessages()
  : Data(new Internals)
{
  this->Data->Previous = vtkOutputWindow::GetInstance();
  vtkOutputWindow::SetInstance(this->Data->Collector);
  // VTK also logs every error and warning to stderr through vtkLogger.
  this->Data->Stderr = vtkLogger::GetCurrentVerbosityCutoff();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
}

VtkMessages::~VtkMessages()
{
  vtkLogger::SetStderrVerbosity(this->Data->Stderr);
  vtkOutputWindow::SetInstance(this->Data->Previous);
  delete this->Data;
}

const std::vector<std::string>& VtkMessages::Errors() const
{
  return this->Data->Collector->Errors;
}

const std::vector<std::string>& VtkMessages::Warnings() const
{
  return this->Data->Collector->Warnings;
}

bool IsImporterFile(const std::string& file)
{
  const std::string ext = LowerExtension(file);
  return ext == "gltf" || ext == "glb" || ext == "3ds" || ext == "wrl" || ext == "vrml";
}

bool ImportScene(const std::string& file, ImportedScene& scene, std::string& error,
  std::vector<std::string>& warnings, std::vector<std::string>& notes)
{
  scene = ImportedScene();
  scene.File = file;
  std::string bytes;
  if (!ReadFileBytes(file, bytes, error))
  {
    return false;
  }
  if (bytes.empty())
  {
    error = file + ": the file is empty";
    return false;
  }
  const std::string ext = LowerExtension(file);
  if (ext == "gltf" || ext == "glb")
  {
    if (!ImportGltf(file, bytes, scene, error, warnings, notes))
    {
      return false;
    }
  }
  else if (ext == "3ds")
  {
    if (!Check3ds(file, bytes, error))
    {
      return false;
    }
    scene.Importer = "vtk3DSImporter";
    vtkNew<vtk3DSImporter> importer;
    importer->SetFileName(file.c_str());
    if (!RunImporter(importer, file, scene, error, warnings))
    {
      return false;
    }
  }
  else if (ext == "wrl" || ext == "vrml")
  {
    if (!CheckVrml(file, bytes, error))
    {
      return false;
    }
    scene.Importer = "vtkVRMLImporter";
    vtkNew<vtkVRMLImporter> importer;
    importer->SetFileName(file.c_str());
    if (!RunImporter(importer, file, scene, error, warnings))
    {
      return false;
    }
  }
  else
  {
    error = file + ": not a file VTK's importers read (.gltf, .glb, .3ds, .wrl)";
    return false;
  }
  if (scene.Importer != "vtkGLTFImporter")
  {
    scene.FileLights = static_cast<std::size_t>(scene.Renderer->GetLights()->GetNumberOfItems());
    // An importer that set a camera made the renderer's active camera.
    if (scene.Renderer->IsActiveCameraCreated())
    {
      scene.HasCamera = true;
      TakeCamera(scene.Renderer->GetActiveCamera(), scene.Camera);
    }
  }
  DropDegenerateLights(file, scene, warnings);
  // What was imported: the surface actors and their polygons.
  vtkActorCollection* actors = scene.Renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* actor = actors->GetNextActor())
  {
    vtkMapper* mapper = actor->GetMapper();
    if (!mapper)
    {
      continue;
    }
    mapper->Update();
    auto* pd = vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0));
    if (pd && pd->GetNumberOfPolys() + pd->GetNumberOfStrips() > 0)
    {
      ++scene.Actors;
      scene.Polygons += static_cast<std::size_t>(pd->GetNumberOfPolys() + pd->GetNumberOfStrips());
    }
  }
  if (scene.Actors == 0)
  {
    error = file + ": no surfaces: " + scene.Importer + " imported " +
      std::to_string(actors->GetNumberOfItems()) + " actors and none holds polygons";
    return false;
  }
  notes.push_back("imported " + file + " with " + scene.Importer + ": " + std::to_string(scene.Actors) +
    " surface actors, " + std::to_string(scene.Polygons) + " polygons, " + std::to_string(scene.FileLights) +
    " lights" + (scene.LightsLeftOut ? " (" + std::to_string(scene.LightsLeftOut) + " left out)" : std::string()) + ", " + (scene.HasCamera ? "the file's camera" : "no camera"));
  return true;
}
}
}
