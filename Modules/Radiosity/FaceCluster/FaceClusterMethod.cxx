#include "Radiosity/FaceCluster/FaceClusterMethod.h"

namespace radiosity
{
FaceClusterMethod::FaceClusterMethod(std::shared_ptr<const Scene> scene,
  const FaceClusterSettings& settings, std::shared_ptr<const FaceClusterHierarchy> hierarchy)
  // Built on the shared scene itself: no copy of it.
  : MethodSolver(scene, settings,
      hierarchy ? std::move(hierarchy) : FaceClusterHierarchy::Shared(scene, settings.Clustering))
{
}

SolutionMesh FaceClusterMethod::Surface() const
{
  return this->Solver.Surface();
}

std::vector<ProductArray> FaceClusterMethod::SurfacePointArrays() const
{
  const auto vectors = this->Solver.VertexIrradianceVectors();
  ProductArray array("IrradianceVector", 9, vectors.size());
  for (std::size_t p = 0; p < vectors.size(); ++p)
  {
    std::copy(vectors[p].begin(), vectors[p].end(), array.Tuple(p));
  }
  return { std::move(array) };
}

std::vector<RGB> FaceClusterMethod::EvaluateProbes(const std::vector<Probe>& probes, std::size_t* gathered) const
{
  return EvaluateSensorsOnInputTriangles([this]() { return this->Surface(); }, *this->SceneRef, probes,
    [this](const std::vector<Probe>& onSurface) { return this->Solver.Evaluate(onSurface); }, gathered);
}

SolverProduct FaceClusterMethod::Product(const ProgressCallback&) const
{
  using Type = ProductArray::ValueType;
  const Scene& scene = *this->SceneRef;
  SolverProduct product;
  product.Kind = "LeafClusters";
  product.Points = scene.Points;
  product.Triangles = scene.Triangles;
  const std::size_t n = scene.Triangles.size();
  ProductArray leaf("LeafElement", 1, n, Type::IdType), cluster("LeafCluster", 1, n, Type::IdType),
    level("Level", 1, n, Type::Int), vector("IrradianceVector", 9, n);
  const auto& elements = this->Solver.Elements();
  for (std::size_t t = 0; t < n; ++t)
  {
    const Vec3 centroid = scene.Centroid(t);
    const auto ti = static_cast<std::uint32_t>(t);
    const std::int32_t e = this->Solver.LeafAt(ti, centroid);
    leaf.Values[t] = e;
    // The leaf's cluster and its depth in the cluster tree, as the surface's
    // ElementId and Level (FaceClusterRadiosity::Surface).
    const FaceClusterElement* element = e >= 0 ? &elements[static_cast<std::size_t>(e)] : nullptr;
    cluster.Values[t] = element ? element->Cluster : -1.0;
    level.Values[t] = element ? element->Data.Depth : 0.0;
    const IrradianceVector v = this->Solver.IrradianceVectorAt(ti, centroid);
    double* out = vector.Tuple(t);
    for (int c = 0; c < 3; ++c)
    {
      out[3 * c] = v[c].x;
      out[3 * c + 1] = v[c].y;
      out[3 * c + 2] = v[c].z;
    }
  }
  product.CellArrays = { std::move(leaf), std::move(cluster), std::move(level), std::move(vector) };
  return product;
}
bool FaceClusterMethod::PrecomputeRelighting(const ProgressCallback& progress)
{
  return this->Solver.PrecomputeTransfer(progress);
}

SolverStatistics FaceClusterMethod::Relight(std::shared_ptr<const Scene> scene, const ProgressCallback& progress)
{
  // The solver checks the scene and takes its lights, sky and emission;
  // the surfaces it reads are the hierarchy's, the same (SameSurfaces).
  SolverStatistics stats = this->Solver.Relight(scene, progress);
  this->SceneRef = std::move(scene);
  return stats;
}
} // namespace radiosity
