// Scene analysis that leaves out what a scene does not need (DESIGN.md,
// principles): which triangles can ever occlude a transfer, and the counts
// the report states.
#ifndef Radiosity_SceneAnalysis_h
#define Radiosity_SceneAnalysis_h

#include "Radiosity/Common/Scene.h"

#include <vector>

namespace radiosity
{
struct SceneAnalysis
{
  std::size_t Triangles = 0;
  std::size_t Emitters = 0;
  /// Per triangle: can it block a segment between two scene points? A
  /// triangle with every scene point on or in front of its plane cannot: a
  /// segment with both ends in that closed half-space never crosses the plane.
  std::vector<unsigned char> CanOcclude;
  std::size_t Occluders = 0;
  double Diagonal = 0.0;
};

/// Classifies every triangle (parallel; early exit per triangle).
SceneAnalysis AnalyzeScene(const Scene& scene);
} // namespace radiosity

#endif
