// Meshless radiosity (Lehtinen et al. 2007) behind the common solver
// interface; its product is the Shepard field: one vertex per basis function
// (section 3.2) with its support radius, normal, group, level and
// coefficients, which vtkShepardSplatMapper and vtkShepardFieldProbe read.
#ifndef Radiosity_MeshlessMethod_h
#define Radiosity_MeshlessMethod_h

#include "Radiosity/Common/RadiositySolver.h"
#include "Radiosity/Meshless/MeshlessRadiosity.h"

namespace radiosity
{
class MeshlessMethod final : public MethodSolver<MeshlessRadiosity>
{
public:
  MeshlessMethod(std::shared_ptr<const Scene> scene, const MeshlessOptions& options);
  const char* MethodName() const override { return "meshless"; }
  SolutionMesh Surface() const override;
  /// Only the kept triangles' elements evaluated (the field's evaluation is
  /// the output's cost).
  SolutionMesh SurfaceOf(const std::vector<char>& keep, std::vector<std::uint32_t>* pointSource) const override;
  /// From the Shepard field (MeshlessRadiosity::Evaluate).
  std::vector<RGB> EvaluateProbes(const std::vector<Probe>& probes, std::size_t* gathered = nullptr) const override;
  /// Kind "ShepardField": vertices with `Level`, `Radius`, `Normal`,
  /// `Group`, `Coefficient` (total irradiance), `DirectCoefficient`,
  /// `Irradiance` (the field evaluated at the point) and `Gathered`.
  SolverProduct Product(const ProgressCallback& progress) const override;

  /// Section 6.5: MeshlessRadiosity::PrecomputeTransfer and Relight.
  bool SupportsRelighting() const override { return true; }
  bool HasRelighting() const override { return this->Solver.HasTransfer(); }
  bool PrecomputeRelighting(const ProgressCallback& progress) override;
  SolverStatistics Relight(std::shared_ptr<const Scene> scene, const ProgressCallback& progress) override;
  void SetRelightGatherSeconds(double seconds) override { this->Solver.SetRelightGatherSeconds(seconds); }
};
} // namespace radiosity

#endif
