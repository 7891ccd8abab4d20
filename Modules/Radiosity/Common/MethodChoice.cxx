#include "Radiosity/Common/MethodChoice.h"

#include <algorithm>

namespace radiosity
{
const char* SolutionMethodName(SolutionMethod method)
{
  switch (method)
  {
    case SolutionMethod::Progressive:
      return "progressive";
    case SolutionMethod::Hierarchical:
      return "hierarchical";
    case SolutionMethod::Meshless:
      return "meshless";
    case SolutionMethod::FaceCluster:
      return "facecluster";
  }
  return "unknown";
}

MethodChoice ChooseMethod(const Scene& scene)
{
  MethodChoice choice;
  const std::size_t triangles = scene.Triangles.size();
  const std::size_t glossy = static_cast<std::size_t>(std::count_if(scene.Materials.begin(),
    scene.Materials.end(), [](const Material& m) { return MaxComponent(m.Specular) > 0.0; }));
  if (glossy > 0)
  {
    choice.Method = SolutionMethod::FaceCluster;
    choice.Rule = "glossy";
    choice.Why = std::to_string(glossy) + " of the " + std::to_string(triangles) +
      " triangles have a glossy part (Specular > 0): face cluster radiosity's vector irradiance is "
      "the only solution the glossy display is drawn from";
  }
  else if (!scene.HasEmitters() && scene.Lighting.SkyLight.Enabled())
  {
    choice.Method = SolutionMethod::Meshless;
    choice.Rule = "sky";
    choice.Why = std::to_string(triangles) +
      " triangles lit by a sky and no emitting triangle: meshless radiosity gathers the sky where it shows; "
      "on the built-in office (738 triangles, CIE overcast sky through a window) it was within 0.19% RMS "
      "and 0.41% worst of the peak of the path tracer in 2.5 s all in, hierarchical radiosity as close in "
      "24 s (bench/results/real-interiors.md)";
  }
  else if (triangles <= AutoHierarchicalMaxTriangles)
  {
    choice.Method = SolutionMethod::Hierarchical;
    choice.Rule = "small";
    choice.Clustered = true;
    choice.Why = std::to_string(triangles) + " triangles, at most " +
      std::to_string(AutoHierarchicalMaxTriangles) +
      ": clustered hierarchical radiosity with discontinuity meshing was within 1.5x of the lowest "
      "error at equal run time on every standard scene of this size (bench/results/error-vs-time)";
  }
  else
  {
    choice.Method = SolutionMethod::Meshless;
    choice.Rule = "large";
    choice.Why = std::to_string(triangles) + " triangles, more than " +
      std::to_string(AutoHierarchicalMaxTriangles) +
      ": meshless radiosity's cost follows the lighting, not the tessellation, and it had the "
      "lowest error at equal run time on the bunny rooms of 3,868 and 235,330 triangles "
      "(bench/results/error-vs-time)";
  }
  return choice;
}
} // namespace radiosity
