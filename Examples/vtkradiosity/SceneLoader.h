// Loads a scene file or a built-in scene into VTK data (SPEC: .vtp, .vtk,
// .ply, .stl, .obj with .mtl, and composite .vtm; `cornell` and the
// procedural test scenes `shadow`, `contact`, `sphere`, `closed-room-0.99`,
// `closed-room-0.999`). A file's content is checked before a VTK reader sees
// it (SceneFileCheck.h): bad input is refused, never a crash.
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
struct LoadOptions
{
  /// Display colours (.mtl Kd) at or above it are clamped to it, with one
  /// warning counting the materials (SPEC, Scenes); in (0, 1).
  double MaxReflectance = 0.95;
};

/**
 * Null with `error` set when the file is missing, unreadable, of an unknown
 * type or bad: "FILE: what, where, the value" (without a "bad input: "
 * prefix). `warnings` get what was defaulted, clamped or ignored, among them
 * cell arrays that are not scene arrays (a typo such as `Reflectence`).
 */
vtkSmartPointer<vtkDataObject> LoadScene(const std::string& scene, std::string& error,
  std::vector<std::string>& warnings, const LoadOptions& options = {});

/// Same, and `notes` gets one line per file read: "read FILE: N points, M
/// polygons; cell arrays: Reflectance (3), Emission (3); point arrays: ...".
vtkSmartPointer<vtkDataObject> LoadScene(const std::string& scene, std::string& error,
  std::vector<std::string>& warnings, std::vector<std::string>& notes,
  const LoadOptions& options);
}
}

#endif
