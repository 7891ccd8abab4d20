#include "Radiosity/Progressive/ProgressiveMethod.h"

namespace radiosity
{
ProgressiveMethod::ProgressiveMethod(std::shared_ptr<const Scene> scene, const ProgressiveOptions& options)
  : RadiositySolver(std::move(scene))
  , Solver(*this->SceneRef, options)
{
}

SolverStatistics ProgressiveMethod::Solve(const ProgressCallback& progress)
{
  return this->Solver.Solve(progress);
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
