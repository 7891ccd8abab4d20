/**
 * @class   vtkRadiositySceneConverter
 * @brief   converts VTK data to the radiosity core's scene and solutions back
 *
 * The only place where VTK data and the core's types meet (DESIGN.md: filters
 * convert once in each direction). Input: vtkPolyData, or any composite
 * dataset whose leaves are datasets (each leaf one object, SPEC "Scenes");
 * polygons are triangulated, vertices, lines and strips ignored with a
 * warning; non-polygonal datasets contribute their outer surface. Cell arrays
 * `Reflectance`, `Emission`, `Specular`, `Shininess` and `TwoSided` as SPEC.md.
 */
#ifndef vtkRadiositySceneConverter_h
#define vtkRadiositySceneConverter_h

#include "vtkObject.h"
#include "RadiosityFiltersModule.h" // for export macro
#include "vtkSmartPointer.h"           // for return values

#include "Radiosity/Common/ConvergenceHistory.h" // for radiosity::ConvergenceHistory
#include "Radiosity/Common/Scene.h"              // for radiosity::Scene
#include "Radiosity/Common/ScenePieces.h"        // for radiosity::PieceGlobalIds
#include "Radiosity/Common/SolutionMesh.h"       // for radiosity::SolutionMesh
#include "Radiosity/Common/RadiositySolver.h"    // for radiosity::SolverProduct

#include <string> // for std::string
#include <vector> // for std::vector

class vtkDataObject;
class vtkDataArray;
class vtkLight;
class vtkDoubleArray;
class vtkPolyData;

class RADIOSITYFILTERS_EXPORT vtkRadiositySceneConverter : public vtkObject
{
public:
  static vtkRadiositySceneConverter* New();
  vtkTypeMacro(vtkRadiositySceneConverter, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Builds the core scene. On bad input returns false with `error` naming the
   * array, cell or block and the value; `warnings` collects what was ignored
   * or defaulted. Material values themselves are validated by the core
   * (radiosity::ValidateScene).
   *
   * `ids`, when given, receives the global ids of the scene's points and of
   * each triangle's input cell (vtkPointData/vtkCellData GetGlobalIds, what
   * ParaView's distributed pipelines carry), or nothing when some block
   * lacks them (radiosity::AssembleScenePieces uses them).
   */
  static bool ToScene(vtkDataObject* input, radiosity::Scene& scene, std::string& error,
    std::vector<std::string>& warnings, radiosity::PieceGlobalIds* ids = nullptr);

  /**
   * A vtkLight as a SPEC light (SPEC.md "Scenes from VTK's scene graph"):
   * positional with ConeAngle < 90 degrees a spot, positional otherwise a
   * point, non-positional a directional light travelling along
   * FocalPoint - Position. Positions are the world ones
   * (GetTransformedPosition, GetTransformedFocalPoint). The intensity is
   * `lightScale` x Intensity x DiffuseColor per channel (W/sr for point and
   * spot, W/m^2 for directional; vtkRadiosityFilter::LightScale documents
   * the default). Spot cones: VTK's ConeAngle is the half angle of its hard
   * cone, so outerConeAngle = ConeAngle in radians; innerConeAngle is 0,
   * glTF's default, whatever the Exponent: VTK's cos^Exponent falloff has
   * no inner cone of full intensity, and glTF's ramp from the axis to the
   * outer cone is the nearest of glTF's shapes to it (Exponent 1). VTK's
   * AttenuationValues are not used: a SPEC point light falls off with the
   * inverse square, physically. Not validated here (see
   * radiosity::ValidateLights): a zero direction or a NaN is kept as it is.
   */
  static radiosity::Light ToLight(vtkLight* light, double lightScale);

  /// The scene as polydata with its material cell arrays, `ObjectId` and the
  /// field data string array `ObjectNames`.
  static vtkSmartPointer<vtkPolyData> FromScene(const radiosity::Scene& scene);

  /// A solution as polydata with the SPEC output arrays (points and cells).
  static vtkSmartPointer<vtkPolyData> FromSolution(
    const radiosity::SolutionMesh& solution, const radiosity::Scene& scene);

  /**
   * A method's product (radiosity::RadiositySolver::Product) as polydata:
   * its points, its triangles (or one vertex cell per point when it has
   * none) and its named arrays; an empty polydata for an empty product. The
   * field data string array `ProductKind` names the kind.
   */
  static vtkSmartPointer<vtkPolyData> FromProduct(const radiosity::SolverProduct& product);

  /**
   * Puts a product of points (no cells but vertices: the Shepard field)
   * into the field data of `surface`, sharing the arrays (no copy):
   * `<Kind>.Points` and `<Kind>.<array>` for every point array, so that a
   * consumer of the surface alone (a ParaView representation) has it too.
   */
  static void AttachPointProduct(vtkPolyData* product, vtkPolyData* surface);

  /// The product of points of kind `kind` that AttachPointProduct put into
  /// `surface`'s field data; null when it has none.
  static vtkSmartPointer<vtkPolyData> AttachedPointProduct(vtkPolyData* surface, const std::string& kind);

  /// A product's or a surface's named array as the VTK array its type says.
  static vtkSmartPointer<vtkDataArray> FromProductArray(const radiosity::ProductArray& array);

  /// A double array named `name` with `components` components and `tuples` tuples.
  static vtkSmartPointer<vtkDoubleArray> NewDoubleArray(
    const char* name, int components, vtkIdType tuples);

  /// `ConvergenceHistory`: one tuple per row, one named component per SPEC column.
  static vtkSmartPointer<vtkDoubleArray> FromHistory(const radiosity::ConvergenceHistory& history);

protected:
  vtkRadiositySceneConverter() = default;
  ~vtkRadiositySceneConverter() override = default;

private:
  vtkRadiositySceneConverter(const vtkRadiositySceneConverter&) = delete;
  void operator=(const vtkRadiositySceneConverter&) = delete;
};

#endif
