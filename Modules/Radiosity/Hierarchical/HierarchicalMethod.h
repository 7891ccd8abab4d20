// Hierarchical radiosity (Hanrahan, Salzman & Aupperle 1991, with the
// blockers of every partial link) behind the common solver interface; its
// product is Hardt & Teller's discontinuity mesh with the quadratic
// irradiance interpolants (BuildDiscontinuityMesh).
#ifndef Radiosity_HierarchicalMethod_h
#define Radiosity_HierarchicalMethod_h

#include "Radiosity/Common/RadiositySolver.h"
#include "Radiosity/Hierarchical/DiscontinuityMesher.h"
#include "Radiosity/Hierarchical/HierarchicalRadiosity.h"

namespace radiosity
{
class HierarchicalMethod final : public MethodSolver<HierarchicalRadiosity>
{
public:
  HierarchicalMethod(std::shared_ptr<const Scene> scene, const HierarchicalOptions& options,
    const DiscontinuityMeshOptions& meshing);
  const char* MethodName() const override { return "hierarchical"; }
  SolutionMesh Surface() const override;
  /// From the quadratic interpolants of the discontinuity mesh (built here
  /// if Product() has not been), the probes on no mesh triangle from the
  /// leaves; with discontinuity meshing off, from the leaves.
  std::vector<RGB> EvaluateProbes(const std::vector<Probe>& probes, std::size_t* gathered = nullptr) const override;
  /// Kind "DiscontinuityMesh": the triangles with `QuadraticInterpolant`
  /// (18 values: six coefficients per channel), the SPEC fields, `ElementId`
  /// (quadtree leaf), `Level` and `ObjectId`; point `Irradiance` and `Radiosity`.
  SolverProduct Product(const ProgressCallback& progress) const override;
  /// The mesh behind the last Product() (its statistics, for reports).
  const DiscontinuityMesh& LastMesh() const { return this->Mesh; }

private:
  DiscontinuityMeshOptions Meshing;
  mutable DiscontinuityMesh Mesh;
};

/// The discontinuity mesh as a product (what HierarchicalMethod::Product gives).
SolverProduct DiscontinuityMeshProduct(const DiscontinuityMesh& mesh, const Scene& scene);
} // namespace radiosity

#endif
