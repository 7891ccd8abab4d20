// Progressive refinement radiosity on the GPU: Coombe, Harris & Lastra 2004,
// "Radiosity on Graphics Hardware", section 3 (README.md in this folder maps
// the sections to the code). The radiosity and the residual live in texture
// atlases, one texel per element; each shot draws a hemicube item buffer
// from the shooter and one fragment per element texel back-projects itself
// onto it and adds eq. 1 with eq. 2's disc form factor (the exact contour
// formula where the shooter is close); the next shooter is the node of
// largest unshot power, found by the z-buffer maximum of section 3.4. The
// CPU holds the bookkeeping only: one pixel of totals and one of the chosen
// node come back per shot, and the solution once at the end.
//
// The elements are the CPU progressive solver's uniform initial mesh
// (ElementMesh: the same element and shooter sizes), so the two methods
// solve the same discrete problem and their answers compare directly.
#ifndef Radiosity_ProgressiveGPUMethod_h
#define Radiosity_ProgressiveGPUMethod_h

#include "RadiosityRenderingGPUModule.h" // For export macro
#include "Radiosity/Common/RadiositySolver.h"
#include "Radiosity/Progressive/ProgressiveRadiosity.h"

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace radiosity
{
class DirectLighting;
class Visibility;
class ElementMesh;
class ProgressiveGPUPasses;

struct ProgressiveGPUOptions : ProgressiveOptions
{
  /// Pixels along a hemicube face's edge (section 3.2's item buffer).
  int HemicubeResolution = 256;
};

class RADIOSITYRENDERINGGPU_EXPORT ProgressiveGPUMethod final : public RadiositySolver
{
public:
  /// Builds the element mesh (SceneError when it exceeds the memory budget
  /// or the 2^24 elements a float texel can index).
  ProgressiveGPUMethod(std::shared_ptr<const Scene> scene, const ProgressiveGPUOptions& options);
  ~ProgressiveGPUMethod() override;
  const char* MethodName() const override { return "progressive-gpu"; }
  /// Opens the OpenGL context (SceneError when none can be opened), uploads
  /// the atlases and shoots to a stop condition; can be called once.
  SolverStatistics Solve(const ProgressCallback& progress) override;
  SolutionMesh Surface() const override;
  SolverProduct Product(const ProgressCallback& progress) const override;
  /// The OpenGL renderer that solved ("llvmpipe ...", a GPU's name); empty before Solve.
  const std::string& Renderer() const { return this->RendererName; }
  const ElementMesh& Mesh() const { return *this->Elements; }

private:
  void ShootLights(SolverStatistics& stats);
  /// The lights' and the sky's exact irradiance at the elements' samples.
  void LightElements(const std::vector<std::uint32_t>& elements);
  /// Subdivision levels of a shooter's parts (0: one part).
  int PartsDepth(std::uint32_t node, double initialEdge, bool occluders) const;
  /// A split's children: what every earlier shooter (index in Shooters(),
  /// total radiosity shot) sent them, added to their irradiance samples.
  void GatherHistory(const std::vector<std::uint32_t>& children,
    const std::vector<std::pair<std::size_t, RGB>>& active, const Visibility& rays, double initialEdge, bool convex);

  ProgressiveGPUOptions Settings;
  std::unique_ptr<ElementMesh> Elements;
  std::unique_ptr<DirectLighting> Lights; ///< null without lights and sky
  std::vector<std::uint16_t> MaxLevel; ///< per input triangle: the deepest an element may split to
  std::size_t ElementCapacity = 0;     ///< elements the memory budget holds
  std::string RendererName;
};
} // namespace radiosity

#endif
