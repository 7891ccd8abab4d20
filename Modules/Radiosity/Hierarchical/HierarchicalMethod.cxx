#include "Radiosity/Hierarchical/HierarchicalMethod.h"

#include <cmath>
#include <limits>
#include <string>

namespace radiosity
{
HierarchicalMethod::HierarchicalMethod(std::shared_ptr<const Scene> scene,
  const HierarchicalOptions& options, const DiscontinuityMeshOptions& meshing)
  : MethodSolver(std::move(scene), options)
  , Meshing(meshing)
{
}

SolutionMesh HierarchicalMethod::Surface() const
{
  return ExtractSolution(this->Solver.Mesh());
}

std::vector<RGB> HierarchicalMethod::EvaluateProbes(const std::vector<Probe>& probes, std::size_t* gathered) const
{
  std::vector<RGB> values(probes.size(), RGB(std::numeric_limits<double>::quiet_NaN()));
  if (this->Meshing.Discontinuities)
  {
    if (this->Mesh.Triangles.empty())
    {
      this->Mesh = BuildDiscontinuityMesh(this->Solver, this->Meshing);
    }
    values = EvaluateInterpolants(
      this->Mesh, probes, 1e-6 * this->Solver.Analysis().Diagonal, this->Solver.GetDirectLighting());
  }
  // The probes on no interpolant's triangle: from the leaves.
  std::vector<Probe> rest;
  std::vector<std::size_t> restIndex;
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    if (!std::isfinite(Luminance(values[i])))
    {
      rest.push_back(probes[i]);
      restIndex.push_back(i);
    }
  }
  if (gathered)
  {
    *gathered = 0;
  }
  if (!rest.empty())
  {
    const SolutionMesh leaves = this->Surface();
    const ProbeEvaluator evaluator(leaves, this->GetScene());
    const std::vector<RGB> fromLeaves = evaluator.Evaluate(rest);
    for (std::size_t i = 0; i < rest.size(); ++i)
    {
      values[restIndex[i]] = fromLeaves[i];
    }
    if (gathered)
    {
      *gathered = evaluator.GatheredCount();
    }
  }
  return values;
}

SolverProduct HierarchicalMethod::Product(const ProgressCallback& progress) const
{
  bool aborted = false;
  this->Mesh = BuildDiscontinuityMesh(this->Solver, this->Meshing,
    [&](const ProgressStatus& status)
    {
      aborted = progress && !progress(status);
      return !aborted;
    });
  if (aborted || this->Mesh.Interpolants.size() != this->Mesh.Triangles.size() ||
    this->Mesh.PointIrradiance.size() != this->Mesh.Points.size())
  {
    SolverProduct none;
    none.Kind = "DiscontinuityMesh";
    none.Complete = false;
    none.Warnings.push_back("discontinuity meshing aborted");
    return none;
  }
  SolverProduct product = DiscontinuityMeshProduct(this->Mesh, *this->SceneRef);
  if (this->Mesh.LeavesPastTimeLimit > 0 || this->Mesh.LeavesSampledPastTimeLimit > 0)
  {
    product.Warnings.push_back("discontinuity meshing reached its time limit (" +
      std::to_string(this->Meshing.MaxSeconds) + " s): " + std::to_string(this->Mesh.LeavesPastTimeLimit) +
      " leaves were meshed without their discontinuities (one interpolant each), " +
      std::to_string(this->Mesh.LeavesSampledPastTimeLimit) +
      " sampled with their partially visible links' means (not through the blockers)");
  }
  if (this->Mesh.LeavesTriangulationFailed > 0)
  {
    product.Warnings.push_back(std::to_string(this->Mesh.LeavesTriangulationFailed) +
      " leaves could not be triangulated with their discontinuities (CGAL refused the "
      "constraints) and are meshed as the leaf alone");
  }
  return product;
}

SolverProduct DiscontinuityMeshProduct(const DiscontinuityMesh& mesh, const Scene& scene)
{
  using Type = ProductArray::ValueType;
  SolverProduct product;
  product.Kind = "DiscontinuityMesh";
  product.Points = mesh.Points;
  product.Triangles = mesh.Triangles;
  const std::size_t nc = mesh.Triangles.size(), np = mesh.Points.size();
  ProductArray interpolant("QuadraticInterpolant", 18, nc), irradiance("Irradiance", 3, nc),
    radiosity("Radiosity", 3, nc), reflectance("Reflectance", 3, nc), emission("Emission", 3, nc),
    elementId("ElementId", 1, nc, Type::IdType), level("Level", 1, nc, Type::Int),
    objects("ObjectId", 1, nc, Type::Int);
  ProductArray pointIrradiance("Irradiance", 3, np), pointRadiosity("Radiosity", 3, np);
  for (std::size_t p = 0; p < np; ++p)
  {
    pointIrradiance.SetRGB(p, mesh.PointIrradiance[p]);
  }
  for (std::size_t t = 0; t < nc; ++t)
  {
    const QuadraticInterpolant& q = mesh.Interpolants[t];
    double* k = interpolant.Tuple(t);
    for (int c = 0; c < 3; ++c)
    {
      for (int j = 0; j < 6; ++j)
      {
        k[6 * c + j] = q.Coefficients[j][c];
      }
    }
    const Material& m = scene.Materials[mesh.SourceTriangle[t]];
    const RGB h = NonNegative(q.Mean()); // samples >= 0; the mean from the coefficients a rounding off
    irradiance.SetRGB(t, h);
    radiosity.SetRGB(t, m.Emission + m.Reflectance * h);
    reflectance.SetRGB(t, m.Reflectance);
    emission.SetRGB(t, m.Emission);
    elementId.Values[t] = mesh.Leaf[t];
    level.Values[t] = mesh.Level[t];
    objects.Values[t] = scene.ObjectIds[mesh.SourceTriangle[t]];
    // Points are not shared between leaves, so every triangle using a point
    // has the same material.
    for (std::uint32_t p : mesh.Triangles[t].V)
    {
      pointRadiosity.SetRGB(p, m.Emission + m.Reflectance * mesh.PointIrradiance[p]);
    }
  }
  product.CellArrays = { std::move(interpolant), std::move(irradiance), std::move(radiosity),
    std::move(reflectance), std::move(emission), std::move(elementId), std::move(level),
    std::move(objects) };
  product.PointArrays = { std::move(pointIrradiance), std::move(pointRadiosity) };
  return product;
}
} // namespace radiosity
