// Progressive refinement radiosity (Coombe et al. 2004 after Cohen et al.
// 1988) behind the common solver interface: its product is the surface
// itself, so Product() is empty.
#ifndef Radiosity_ProgressiveMethod_h
#define Radiosity_ProgressiveMethod_h

#include "Radiosity/Common/RadiositySolver.h"
#include "Radiosity/Progressive/ProgressiveRadiosity.h"

namespace radiosity
{
class ProgressiveMethod final : public MethodSolver<ProgressiveRadiosity>
{
public:
  ProgressiveMethod(std::shared_ptr<const Scene> scene, const ProgressiveOptions& options);
  const char* MethodName() const override { return "progressive"; }
  SolutionMesh Surface() const override;
  SolverProduct Product(const ProgressCallback& progress) const override;
};
} // namespace radiosity

#endif
