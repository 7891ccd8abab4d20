#include "SceneLoader.h"

#include "ObjMtlReader.h"
#include "SceneFileCheck.h"

#include "vtkCellData.h"
#include "vtkCompositeDataSet.h"
#include "vtkCornellBoxSource.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkDataSet.h"
#include "vtkDataSetReader.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRadiositySceneConverter.h"
#include "vtkSTLReader.h"
#include "vtkXMLGenericDataObjectReader.h"

#include "Radiosity/Scenes/BunnyScene.h"
#include "Radiosity/Scenes/OfficeScene.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <algorithm>
#include <functional>
#include <map>
#include <set>

namespace radiosity
{
namespace cli
{
namespace
{
std::string Extension(const std::string& file)
{
  const auto slash = file.find_last_of('/');
  const auto dot = file.rfind('.');
  std::string ext =
    dot == std::string::npos || (slash != std::string::npos && dot < slash) ? "" : file.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// Collects what VTK's readers report (vtkErrorMacro and vtkWarningMacro go to
// the output window) so that a refusal is one line naming the file.
class CollectingOutputWindow : public vtkOutputWindow
{
public:
  static CollectingOutputWindow* New();
  vtkTypeMacro(CollectingOutputWindow, vtkOutputWindow);
  void DisplayErrorText(const char* text) override { this->Errors.push_back(Message(text)); }
  void DisplayWarningText(const char* text) override { this->Warnings.push_back(Message(text)); }
  void DisplayGenericWarningText(const char* text) override { this->DisplayWarningText(text); }
  void DisplayText(const char* text) override { this->Warnings.push_back(Message(text)); }
  void DisplayDebugText(const char*) override {}
  std::vector<std::string> Errors, Warnings;

private:
  // "ERROR: In file.cxx, line 12\nvtkPLYReader (0x55...): the message\n\n" -> the message.
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
vtkStandardNewMacro(CollectingOutputWindow);

// Runs a reader with VTK's messages collected; VTK readers report failures
// through error codes, messages and a missing output.
vtkSmartPointer<vtkDataObject> Run(vtkAlgorithm* reader, const std::string& file,
  const char* readerName, std::string& error, std::vector<std::string>& warnings)
{
  vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
  vtkNew<CollectingOutputWindow> collect;
  vtkOutputWindow::SetInstance(collect);
  reader->Update();
  vtkOutputWindow::SetInstance(previous);
  vtkDataObject* out = reader->GetOutputDataObject(0);
  for (const std::string& w : collect->Warnings)
  {
    warnings.push_back(file + ": " + readerName + ": " + w);
  }
  if (!collect->Errors.empty() || reader->GetErrorCode() != 0 || !out)
  {
    error = file + ": " + readerName + " cannot read it" +
      (collect->Errors.empty() ? std::string() : ": " + collect->Errors.front());
    return nullptr;
  }
  vtkSmartPointer<vtkDataObject> copy;
  copy.TakeReference(out->NewInstance());
  copy->ShallowCopy(out);
  return copy;
}

// The arrays the loader and the filter know on a scene's cells: the SPEC's
// materials, the OBJ reader's objects and the arrays of a written solution
// (a solution is itself a scene).
bool KnownCellArray(const std::string& name)
{
  static const std::set<std::string> known = { "Reflectance", "Emission", "Specular", "Shininess",
    "TwoSided", "ObjectId", "Irradiance", "Radiosity", "IrradianceVector", "QuadraticInterpolant",
    "ElementId", "Level" };
  return known.count(name) > 0;
}

std::string ArrayList(vtkFieldData* data)
{
  std::string list;
  for (int i = 0; data && i < data->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* a = data->GetAbstractArray(i);
    list += std::string(list.empty() ? "" : ", ") + (a->GetName() ? a->GetName() : "(unnamed)") +
      " (" + std::to_string(a->GetNumberOfComponents()) + ")";
  }
  return list.empty() ? "none" : list;
}

// The note naming what was read, and a warning per cell array that is not a
// scene array and per material array given on the points (ignored there).
void Describe(vtkDataObject* data, const std::string& file, std::vector<std::string>& warnings,
  std::vector<std::string>& notes)
{
  std::vector<vtkDataSet*> pieces;
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      if (auto* ds = vtkDataSet::SafeDownCast(it->GetCurrentDataObject()))
      {
        pieces.push_back(ds);
      }
    }
  }
  else if (auto* ds = vtkDataSet::SafeDownCast(data))
  {
    pieces.push_back(ds);
  }
  vtkIdType points = 0, cells = 0;
  std::set<std::string> unknown, onPoints;
  std::string cellArrays, pointArrays;
  for (vtkDataSet* ds : pieces)
  {
    points += ds->GetNumberOfPoints();
    cells += ds->GetNumberOfCells();
    vtkCellData* cd = ds->GetCellData();
    for (int i = 0; i < cd->GetNumberOfArrays(); ++i)
    {
      const char* name = cd->GetAbstractArray(i)->GetName();
      if (!KnownCellArray(name ? name : ""))
      {
        unknown.insert(name ? name : "(unnamed)");
      }
    }
    vtkPointData* pd = ds->GetPointData();
    for (int i = 0; i < pd->GetNumberOfArrays(); ++i)
    {
      const char* name = pd->GetAbstractArray(i)->GetName();
      if (name && (std::string(name) == "Reflectance" || std::string(name) == "Emission" ||
                    std::string(name) == "Specular" || std::string(name) == "Shininess"))
      {
        onPoints.insert(name);
      }
    }
  }
  if (pieces.size() == 1)
  {
    cellArrays = ArrayList(pieces[0]->GetCellData());
    pointArrays = ArrayList(pieces[0]->GetPointData());
  }
  std::string note = "read " + file + ": " + std::to_string(points) + " points, " +
    std::to_string(cells) + (vtkPolyData::SafeDownCast(data) ? " polygons" : " cells");
  if (pieces.size() != 1)
  {
    note += " in " + std::to_string(pieces.size()) + " blocks";
  }
  else
  {
    note += "; cell arrays: " + cellArrays + "; point arrays: " + pointArrays;
  }
  notes.push_back(note);
  for (const std::string& name : unknown)
  {
    warnings.push_back(file + ": cell array '" + name +
      "' is not a scene array (Reflectance, Emission, Specular, Shininess, TwoSided): ignored");
  }
  for (const std::string& name : onPoints)
  {
    warnings.push_back(file + ": point array '" + name +
      "' ignored: materials are cell arrays (one value per triangle)");
  }
}

vtkSmartPointer<vtkDataObject> ReadFile(const std::string& scene, const std::string& ext,
  std::string& bytes, std::string& error, std::vector<std::string>& warnings,
  const LoadOptions& options)
{
  if (ext == "obj")
  {
    if (!CheckObjText(scene, bytes, error))
    {
      return nullptr;
    }
    vtkSmartPointer<vtkPolyData> pd =
      ReadObjWithMaterials(scene, error, warnings, options.MaxReflectance);
    return pd;
  }
  if (ext == "vtp" || ext == "vtm" || ext == "vtu" || ext == "vtpc" || ext == "vtpd")
  {
    if (!CheckXmlVtk(scene, bytes, error))
    {
      return nullptr;
    }
    vtkNew<vtkXMLGenericDataObjectReader> reader;
    reader->SetFileName(scene.c_str()); // every array is read by default
    return Run(reader, scene, "VTK's XML reader", error, warnings);
  }
  if (ext == "vtk")
  {
    if (!CheckLegacyVtk(scene, bytes, error))
    {
      return nullptr;
    }
    vtkNew<vtkDataSetReader> reader;
    reader->SetFileName(scene.c_str());
    // Without these only the first SCALARS (VECTORS...) array is kept: an
    // Emission after a Reflectance would be lost.
    reader->ReadAllScalarsOn();
    reader->ReadAllVectorsOn();
    reader->ReadAllNormalsOn();
    reader->ReadAllTensorsOn();
    reader->ReadAllColorScalarsOn();
    reader->ReadAllTCoordsOn();
    reader->ReadAllFieldsOn();
    return Run(reader, scene, "VTK's legacy reader", error, warnings);
  }
  if (ext == "ply")
  {
    if (!CheckPly(scene, bytes, error))
    {
      return nullptr;
    }
    // The checked bytes (a final line end added where VTK needs it), not the file again.
    vtkNew<vtkPLYReader> reader;
    reader->SetFileName(scene.c_str());
    reader->SetInputString(bytes);
    reader->ReadFromInputStringOn();
    return Run(reader, scene, "VTK's PLY reader", error, warnings);
  }
  if (ext == "stl")
  {
    if (!CheckStl(scene, bytes, error))
    {
      return nullptr;
    }
    vtkNew<vtkSTLReader> reader;
    reader->SetFileName(scene.c_str());
    return Run(reader, scene, "VTK's STL reader", error, warnings);
  }
  error = scene + ": unknown scene file type '" + (ext.empty() ? "" : "." + ext) + "'" +
    (ext == "gltf" || ext == "glb" || ext == "3ds" || ext == "wrl"
        ? " (glTF, .3ds and .wrl are read by VTK's importers into a renderer: vtkradiosity solve "
          "imports them, ImportedScene.h)"
        : "") +
    ": use .vtp, .vtm, .vtk, .ply, .stl or .obj, an importer format (.gltf, .glb, .3ds, .wrl), or a "
    "built-in scene: cornell, office, shadow, contact, sphere, closed-room-0.99, closed-room-0.999, "
    "bunny-235k, bunny-940k";
  return nullptr;
}
} // namespace

vtkSmartPointer<vtkDataObject> LoadScene(const std::string& scene, std::string& error,
  std::vector<std::string>& warnings, const LoadOptions& options)
{
  std::vector<std::string> notes;
  return LoadScene(scene, error, warnings, notes, options);
}

vtkSmartPointer<vtkDataObject> LoadScene(const std::string& scene, std::string& error,
  std::vector<std::string>& warnings, std::vector<std::string>& notes, const LoadOptions& options)
{
  if (!(options.MaxReflectance > 0 && options.MaxReflectance < 1))
  {
    error = "--max-reflectance " + std::to_string(options.MaxReflectance) + " is outside (0, 1)";
    return nullptr;
  }
  if (scene == "cornell")
  {
    vtkNew<vtkCornellBoxSource> box;
    box->Update();
    vtkSmartPointer<vtkDataObject> out = box->GetOutput();
    return out;
  }
  // The procedural test scenes with exact answers (SceneGenerators.h).
  const std::map<std::string, std::function<Scene()>> builtIn = {
    { "shadow", [] { return MakeShadowScene(4, 10.0); } },
    { "contact", [] { return MakeContactScene(4, 0.0, 10.0); } },
    { "sphere", [] { return MakeSphereInterior(1.0, 3, 0.9, RGB(10.0)); } },
    { "closed-room-0.99", [] { return MakeClosedCube(1.0, 2, 0.99, 1.0); } },
    { "closed-room-0.999", [] { return MakeClosedCube(1.0, 2, 0.999, 1.0); } },
    // Lit by its lamp and the sky (its lights come through ReadLights).
    { "office", [] { return MakeOfficeScene(); } },
#ifdef RADIOSITY_BUNNY_JS
    { "bunny-235k", [] { return MakeBunnyRoom(ReadNpmBunny(RADIOSITY_BUNNY_JS), 3); } },
    { "bunny-940k", [] { return MakeBunnyRoom(ReadNpmBunny(RADIOSITY_BUNNY_JS), 4); } },
#endif
  };
  const auto found = builtIn.find(scene);
  if (found != builtIn.end())
  {
    vtkSmartPointer<vtkDataObject> out = vtkRadiositySceneConverter::FromScene(found->second());
    return out;
  }
  std::string bytes;
  if (!ReadFileBytes(scene, bytes, error))
  {
    return nullptr;
  }
  vtkSmartPointer<vtkDataObject> out =
    ReadFile(scene, Extension(scene), bytes, error, warnings, options);
  if (!out)
  {
    return nullptr;
  }
  Describe(out, scene, warnings, notes);
  // A file without surfaces is refused here, where its name is known.
  auto* pd = vtkPolyData::SafeDownCast(out);
  if (pd && pd->GetNumberOfPolys() + pd->GetNumberOfStrips() == 0)
  {
    error = scene + ": no polygons (" + std::to_string(pd->GetNumberOfPoints()) + " points, " +
      std::to_string(pd->GetNumberOfVerts()) + " vertex and " +
      std::to_string(pd->GetNumberOfLines()) + " line cells, which are not surfaces)";
    return nullptr;
  }
  return out;
}
}
}
