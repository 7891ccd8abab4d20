// Loads a scene file or a built-in scene into VTK data (SPEC: .vtp, .vtk,
// .ply, .stl, .obj with .mtl, and composite .vtm; `cornell` and the
// procedural test scenes `shadow`, `contact`, `sphere`, `closed-room-0.99`,
// `closed-room-0.999`).
#ifndef vtkradiosity_SceneLoader_h
#define vtkradiosity_SceneLoader_h

#include "vtkDataObject.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

namespace radiosity
{
namespace cli
{
/// Null with `error` set when the file is missing, unreadable or of an unknown type.
vtkSmartPointer<vtkDataObject> LoadScene(
  const std::string& scene, std::string& error, std::vector<std::string>& warnings);
}
}

#endif
