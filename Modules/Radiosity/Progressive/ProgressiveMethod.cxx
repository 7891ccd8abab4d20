#include "Radiosity/Progressive/ProgressiveMethod.h"

namespace radiosity
{
ProgressiveMethod::ProgressiveMethod(std::shared_ptr<const Scene> scene, const ProgressiveOptions& options)
  : MethodSolver(std::move(scene), options)
{
}

SolutionMesh ProgressiveMethod::Surface() const
{
  return ExtractSolution(this->Solver.Mesh());
}

SolverProduct ProgressiveMethod::Product(const ProgressCallback&) const
{
  return {};
}
} // namespace radiosity
