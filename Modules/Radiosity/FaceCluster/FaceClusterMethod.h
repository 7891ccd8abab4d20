// Face cluster radiosity (Gobbetti et al. 2003) behind the common solver
// interface. The surface's points carry the irradiance vectors (section 3.5,
// what vtkVectorIrradianceMapper shades per pixel); the product is the input
// triangles labelled with their leaf cluster and its vector irradiance.
#ifndef Radiosity_FaceClusterMethod_h
#define Radiosity_FaceClusterMethod_h

#include "Radiosity/Common/RadiositySolver.h"
#include "Radiosity/FaceCluster/FaceClusterRadiosity.h"

namespace radiosity
{
class FaceClusterMethod final : public MethodSolver<FaceClusterRadiosity>
{
public:
  /// `hierarchy`: one built for this scene (vtkFaceClusterHierarchyFilter);
  /// null: the shared one, built once per scene.
  FaceClusterMethod(std::shared_ptr<const Scene> scene, const FaceClusterSettings& settings,
    std::shared_ptr<const FaceClusterHierarchy> hierarchy = nullptr);
  const char* MethodName() const override { return "facecluster"; }
  SolutionMesh Surface() const override;
  /// From the vector irradiance bases (FaceClusterRadiosity::Evaluate).
  std::vector<RGB> EvaluateProbes(const std::vector<Probe>& probes, std::size_t* gathered = nullptr) const override;
  /// `IrradianceVector` (9 values: the R, G, B vectors) at every scene point.
  std::vector<ProductArray> SurfacePointArrays() const override;
  /// Kind "LeafClusters": the input triangles with `LeafElement` (the leaf
  /// element's index), `LeafCluster` (its cluster), `Level` (the cluster's
  /// depth, as the surface's) and
  /// `IrradianceVector` at the triangle's centroid.
  SolverProduct Product(const ProgressCallback& progress) const override;
  /// Relighting of lights and sky over the kept transfers
  /// (FaceClusterRadiosity::PrecomputeTransfer and Relight).
  bool SupportsRelighting() const override { return true; }
  bool HasRelighting() const override { return this->Solver.HasTransfer(); }
  bool PrecomputeRelighting(const ProgressCallback& progress) override;
  SolverStatistics Relight(std::shared_ptr<const Scene> scene, const ProgressCallback& progress) override;
};
} // namespace radiosity

#endif
