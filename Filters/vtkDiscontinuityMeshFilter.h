/**
 * @class   vtkDiscontinuityMeshFilter
 * @brief   Hardt & Teller's discontinuity mesh and quadratic interpolants
 *
 * Input: the output of vtkRadiosityFilter run with Method Hierarchical, whose
 * information carries the solver (vtkRadiosityFilter::HIERARCHICAL_SOLUTION()).
 * Per quadtree leaf, the strongest EV/VE discontinuities of its partially
 * visible links constrain a Delaunay triangulation of the leaf, and every
 * triangle gets a quadratic irradiance interpolant through accurate point
 * irradiance at its corners and edge midpoints (radiosity::BuildDiscontinuityMesh).
 *
 * Output polydata (points are not shared between leaves):
 * - cell data `QuadraticInterpolant` (18 components, channel-major: component
 *   6c+k is coefficient k of (A, 2B, 2C, D, 2E, F) for channel c of R, G, B;
 *   vtkQuadraticInterpolantMapper and vtkRadiosityView draw it per pixel),
 *   `Irradiance` (the interpolant's area mean), `Radiosity` (E + rho H),
 *   `Reflectance`, `Emission`, `ElementId` (the quadtree leaf), `Level`,
 *   `ObjectId`;
 * - point data `Irradiance` (the accurate sample at the point) and `Radiosity`
 *   (E + rho H with the material of the triangle using the point);
 * - field data `ConvergenceHistory` copied from the input when present.
 *
 * An input without a hierarchical solution gives an error (GetLastError()
 * keeps it) and an empty output. Progress events while meshing;
 * AbortExecute stops it.
 */
#ifndef vtkDiscontinuityMeshFilter_h
#define vtkDiscontinuityMeshFilter_h

#include "RadiosityFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include "Radiosity/Hierarchical/DiscontinuityMesher.h" // for radiosity::DiscontinuityMesh

#include <memory> // for std::shared_ptr
#include <string> // for std::string

class RADIOSITYFILTERS_EXPORT vtkDiscontinuityMeshFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkDiscontinuityMeshFilter* New();
  vtkTypeMacro(vtkDiscontinuityMeshFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Mesh the discontinuities; off gives one triangle and interpolant per
  /// quadtree leaf. Default on.
  vtkSetMacro(Discontinuities, bool);
  vtkGetMacro(Discontinuities, bool);
  vtkBooleanMacro(Discontinuities, bool);
  ///@}

  ///@{
  /// k: the strongest discontinuities kept per leaf (0 meshes none). Default 10.
  vtkSetClampMacro(MaxDiscontinuitiesPerLeaf, int, 0, 1000);
  vtkGetMacro(MaxDiscontinuitiesPerLeaf, int);
  ///@}

  ///@{
  /// w_min: the smallest weight of a kept discontinuity, relative to the
  /// largest emitted exitance of the scene (one channel). Default 0.05.
  vtkSetClampMacro(MinDiscontinuityWeight, double, 0.0, 1e6);
  vtkGetMacro(MinDiscontinuityWeight, double);
  ///@}

  ///@{
  /// Insert into every leaf the vertices of its neighbours that lie on its
  /// edges, so that the mesh has no T-junction and the per-pixel rendering no
  /// crack. Off: the paper's hybrid mesh as it is (a leaf without
  /// discontinuities stays one triangle). Default on.
  vtkSetMacro(ConformingBoundaries, bool);
  vtkGetMacro(ConformingBoundaries, bool);
  vtkBooleanMacro(ConformingBoundaries, bool);
  ///@}

  ///@{
  /// Worker threads; 0 uses every core. Default 0.
  vtkSetClampMacro(NumberOfThreads, int, 0, 4096);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  /// Why the last execution failed ("" when it did not).
  const std::string& GetLastError() const { return this->LastError; }

  /// The last mesh in the core's form, with its statistics (LeavesMeshed,
  /// SegmentsFound, SegmentsKept, PointSamples, Seconds); empty before a run.
  const radiosity::DiscontinuityMesh& GetMesh() const { return this->Mesh; }

protected:
  vtkDiscontinuityMeshFilter();
  ~vtkDiscontinuityMeshFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool Discontinuities = true;
  int MaxDiscontinuitiesPerLeaf = 10;
  bool ConformingBoundaries = true;
  double MinDiscontinuityWeight = 0.05;
  int NumberOfThreads = 0;

private:
  vtkDiscontinuityMeshFilter(const vtkDiscontinuityMeshFilter&) = delete;
  void operator=(const vtkDiscontinuityMeshFilter&) = delete;

  /// Records and reports `message`; returns 0 (a failed request).
  int Fail(const std::string& message);
  /// RequestData inside vtkRadiosityGuardedRequest.
  int ExecuteRequest(vtkInformationVector** inputVector, vtkInformationVector* outputVector);
  std::string LastError;
  radiosity::DiscontinuityMesh Mesh;
};

#endif
