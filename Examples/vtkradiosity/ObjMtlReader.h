// Wavefront .obj with its .mtl materials (SPEC, Scenes): vtkOBJReader keeps
// neither the materials nor the objects, and both are the scene's meaning here.
// Kept rather than VTK's vtkOBJImporter (which the other importer formats go
// through, ImportedScene.h): VTK 9.2's importer reads Ka, Kd, Ks, Ns, d,
// illum and map_Kd but not Ke, the emission SPEC asks for; it gives faces
// without a material white instead of SPEC's 0.5 grey, keeps no o/g objects
// (the clustering and reconstruction groups) and names no line in its errors.
#ifndef vtkradiosity_ObjMtlReader_h
#define vtkradiosity_ObjMtlReader_h

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

namespace radiosity
{
namespace cli
{
/**
 * Reads `objFile` and the .mtl files it names (`mtllib`, relative to the obj's
 * directory). Output: double points (every `v`, in file order), triangles
 * (polygons fan-triangulated), cell data `Reflectance` (Kd), `Emission` (Ke),
 * `Specular` (Ks) with 3 double components, `Shininess` (Ns, 1), `ObjectId`
 * (int, index into the field data string array `ObjectNames`: one object per
 * distinct `o`/`g` name that has faces; faces before any `o`/`g` belong to an
 * object named after the file).
 *
 * Warnings (the data is still usable): a missing .mtl file, a face with no
 * `usemtl` or with an undefined material (SPEC default: reflectance 0.5 grey),
 * ignored `l`/`p` elements and unknown statements, counted once each.
 * Errors (returns nullptr, `error` = "file:line: reason: 'text'"): an unreadable
 * .obj, bad or non-finite numbers, face indices out of range or zero, faces
 * with fewer than 3 vertices, malformed .mtl lines.
 * Material values are passed through unchecked (the scene loader validates
 * them) except that a Kd component in [maxReflectance, 1] is clamped to
 * `maxReflectance` (SPEC: .mtl colours are display colours, white is common),
 * with one warning counting the materials clamped; 1 (the default) clamps nothing.
 */
vtkSmartPointer<vtkPolyData> ReadObjWithMaterials(const std::string& objFile, std::string& error,
  std::vector<std::string>& warnings, double maxReflectance = 1.0);
} // namespace cli
} // namespace radiosity

#endif
