#include "SceneLoader.h"

#include "ObjMtlReader.h"

#include "vtkCornellBoxSource.h"
#include "vtkRadiositySceneConverter.h"
#include "vtkDataSetReader.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkPLYReader.h"
#include "vtkPolyData.h"
#include "vtkSTLReader.h"
#include "vtkXMLGenericDataObjectReader.h"

#include "Radiosity/BunnyScene.h"
#include "Radiosity/SceneGenerators.h"

#include <algorithm>
#include <functional>
#include <map>
#include <fstream>

namespace radiosity
{
namespace cli
{
namespace
{
std::string Extension(const std::string& file)
{
  const auto dot = file.rfind('.');
  std::string ext = dot == std::string::npos ? "" : file.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

/// Runs a reader; VTK readers report failures through error codes and output.
vtkSmartPointer<vtkDataObject> Run(vtkAlgorithm* reader, const std::string& file, std::string& error)
{
  reader->Update();
  vtkDataObject* out = reader->GetOutputDataObject(0);
  if (reader->GetErrorCode() != 0 || !out)
  {
    error = "cannot read scene file " + file;
    return nullptr;
  }
  vtkSmartPointer<vtkDataObject> copy;
  copy.TakeReference(out->NewInstance());
  copy->ShallowCopy(out);
  return copy;
}

template <typename Reader>
vtkSmartPointer<vtkDataObject> ReadWith(const std::string& file, std::string& error)
{
  vtkNew<Reader> reader;
  reader->SetFileName(file.c_str());
  return Run(reader, file, error);
}
}

vtkSmartPointer<vtkDataObject> LoadScene(
  const std::string& scene, std::string& error, std::vector<std::string>& warnings)
{
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
  if (!std::ifstream(scene).good())
  {
    error = "scene file " + scene + " does not exist or cannot be opened";
    return nullptr;
  }
  const std::string ext = Extension(scene);
  if (ext == "obj")
  {
    vtkSmartPointer<vtkPolyData> pd = ReadObjWithMaterials(scene, error, warnings);
    return pd;
  }
  if (ext == "vtp" || ext == "vtm" || ext == "vtu" || ext == "vtpc" || ext == "vtpd")
  {
    return ReadWith<vtkXMLGenericDataObjectReader>(scene, error);
  }
  if (ext == "vtk")
  {
    return ReadWith<vtkDataSetReader>(scene, error);
  }
  if (ext == "ply")
  {
    return ReadWith<vtkPLYReader>(scene, error);
  }
  if (ext == "stl")
  {
    return ReadWith<vtkSTLReader>(scene, error);
  }
  error = "unknown scene file type '." + ext + "' (" + scene +
    "): use .vtp, .vtm, .vtk, .ply, .stl or .obj, or a built-in scene: cornell, shadow, contact, "
    "sphere, closed-room-0.99, closed-room-0.999, bunny-235k, bunny-940k";
  return nullptr;
}
}
}
