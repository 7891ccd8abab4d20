// Scenes from VTK's importers (SPEC "Scenes from VTK's scene graph and
// importers"): a .gltf/.glb (vtkGLTFImporter), .3ds (vtk3DSImporter) or
// .wrl/.vrml (vtkVRMLImporter) file is imported into a vtkRenderer, actors,
// lights and camera, which the command line then solves through
// vtkRadiosityPass::UpdateSolution like any VTK application's renderer.
// Nothing is rendered here: the importer's render window is created (VTK's
// importers always make one) but never shown, so no display is needed.
// VTK's importers crash on some malformed files (a truncated .3ds, a corrupted
// PNG inside a .glb): each import is tried first in a child process, and a
// crash or a hang there is a refusal naming the file (ImportedScene.cxx).
//
// A .obj keeps the scene loader's own reader (ObjMtlReader.h): VTK 9.2's
// vtkOBJImporter reads Ka, Kd, Ks, Ns, d, illum and map_Kd but not Ke (the
// emission SPEC asks for), gives faces without a material white instead of
// SPEC's 0.5 grey, and keeps neither the o/g objects nor line numbers in its
// errors.
//
// glTF (SPEC): baseColorFactor is the reflectance (the pass takes a PBR
// property's base colour x (1 - metallic); glTF's metallicFactor defaults to
// 1), emissiveFactor the emission in W/m^2, and KHR_lights_punctual lights
// keep the file's numbers one to one as radiometric ones: vtkGLTFImporter
// sets a vtkLight's Intensity to the glTF intensity and its colour to the
// glTF colour, so the filter's LightScale is 1 for a glTF file (W/sr, or W/m^2
// for a directional light, per unit of Intensity x colour). Two corrections
// are made to the lights VTK 9.2 imports: a light's Position and FocalPoint
// are set to the node's origin and -z axis, (0, 0, 0) and (0, 0, -1), under
// the node's TransformMatrix (VTK leaves vtkLight's defaults (0, 0, 1) and
// (0, 0, 0), which puts a point light one unit along its node's z axis); and
// a spot with an innerConeAngle > 0 (a vtkLight has one cone only) is taken
// out of the renderer and handed to the filter as a SPEC light with both
// cones. A light's range is ignored (SPEC: inverse-square, no cut-off).
// .3ds and .wrl lights are display lights as VTK imports them (vtk3DSImporter
// leaves its omni and spot lights non-positional, hence directional), with
// the filter's default LightScale (pi, VTK's on-screen brightness).
#ifndef vtkradiosity_ImportedScene_h
#define vtkradiosity_ImportedScene_h

#include "vtkLight.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include "Radiosity/Common/Lights.h"

#include <map>
#include <string>
#include <vector>

namespace radiosity
{
namespace cli
{
/// A view: position, focal point, view up and vertical view angle in degrees.
struct ViewCamera
{
  double Position[3] = { 0, 0, 1 };
  double FocalPoint[3] = { 0, 0, 0 };
  double ViewUp[3] = { 0, 1, 0 };
  double ViewAngle = 30.0;
};

struct ImportedScene
{
  std::string File;     ///< as given
  std::string Importer; ///< VTK's class: "vtkGLTFImporter", "vtk3DSImporter", "vtkVRMLImporter"
  vtkSmartPointer<vtkRenderWindow> Window; ///< the importer's, never rendered
  vtkSmartPointer<vtkRenderer> Renderer;   ///< the imported actors, lights and camera
  bool HasCamera = false; ///< the file's first camera is `Camera`
  ViewCamera Camera;
  /// The filter's LightScale for the renderer's vtkLights (1 for glTF).
  double LightScale = 3.14159265358979323846;
  /// Lights a vtkLight cannot carry (glTF spots with an inner cone), in SI units.
  LightSet ExtraLights;
  std::size_t Actors = 0;      ///< surface actors imported
  std::size_t Polygons = 0;    ///< their polygons and strips
  std::size_t FileLights = 0;  ///< lights the file defines (glTF) or VTK imported
  std::size_t TwoSidedActors = 0; ///< glTF doubleSided: solved on both sides
  std::size_t LightsLeftOut = 0; ///< of those, left out as degenerate (a warning each)
  /// How a warning names each imported vtkLight: the file's light index and
  /// name (glTF), else its place among the lights VTK imported.
  std::map<vtkLight*, std::string> LightLabels;
};

/// VTK's error and warning messages (vtkErrorMacro, vtkWarningMacro) while
/// it lives, collected instead of printed: "the message" without VTK's file,
/// line and object prefix.
class VtkMessages
{
public:
  VtkMessages();
  ~VtkMessages();
  VtkMessages(const VtkMessages&) = delete;
  VtkMessages& operator=(const VtkMessages&) = delete;
  const std::vector<std::string>& Errors() const;
  const std::vector<std::string>& Warnings() const;

private:
  struct Internals;
  Internals* Data;
};

/// True for the extensions read by VTK's importers: .gltf, .glb, .3ds, .wrl, .vrml.
bool IsImporterFile(const std::string& file);

/**
 * Imports `file` into `scene` (a new renderer). False with `error` = "FILE:
 * what" when the file is missing, malformed (a glTF is checked first,
 * GltfFileCheck.h), the importer reports an error, or it holds no surface.
 * `warnings` get what is read but not used and the importer's warnings;
 * `notes` one line on what was imported.
 */
bool ImportScene(const std::string& file, ImportedScene& scene, std::string& error,
  std::vector<std::string>& warnings, std::vector<std::string>& notes);
}
}

#endif
