// What `--method auto` (vtkRadiosityFilter::Auto, the default of the filter,
// the scene-graph pass, the command line and ParaView) solves a scene with:
// rules measured on the error-against-run-time benches, not guessed, and a
// sentence saying which rule chose and why, for the report and the log.
//
// The rules, first match wins (bench/results/error-vs-time, its last table):
//  1. A glossy part (some triangle with Specular > 0): face cluster
//     radiosity (Gobbetti et al. 2003). Its vector irradiance is the only
//     solution the glossy display can be drawn from (vtkVectorIrradianceMapper);
//     every other method's output would show the scene matte.
//  2. Lit by a sky, no emitting triangle (a daylit interior): meshless
//     radiosity. On the built-in office (daylight only, 20 working-plane
//     sensors, bench/results/real-interiors.md) every method was within
//     0.41% of the peak of the path tracer, meshless in 2.5 s all in,
//     progressive 9.4 s, face clusters 14 s, hierarchical 24 s.
//  3. At most AutoHierarchicalMaxTriangles triangles: hierarchical radiosity
//     with discontinuity meshing (Hanrahan et al. 1991, Hardt & Teller 1996),
//     its links started from the face cluster roots at any size (Smits et
//     al. 1994: on the Cornell box at link tolerance 0.05 the interpolants'
//     error is 8.0e-3 clustered, 1.4e-2 not). On every standard scene of
//     that size (Cornell box, shadow, contact, sphere, closed rooms) it is
//     within 1.5x of the lowest error any method reaches in the same time.
//  4. More: meshless radiosity (Lehtinen et al. 2007), whose cost follows
//     the lighting, not the tessellation. On the bunny room of 3,868
//     triangles it reaches RMS 3.5e-2 in 8.6 s, where clustered hierarchical
//     radiosity reaches 4.5e-2 (constant leaves, 9.5 s; 14.0 s meshed) and
//     progressive refinement 5.3e-2 in 27.5 s; on the 235k-triangle room
//     2.8e-2 in 8.0 s against progressive's 7.1e-2 after 60 s (clustered
//     hierarchical radiosity takes minutes there).
#ifndef Radiosity_MethodChoice_h
#define Radiosity_MethodChoice_h

#include "Radiosity/Common/Scene.h"

#include <cstddef>
#include <string>

namespace radiosity
{
/// The four solution methods, one per paper.
enum class SolutionMethod
{
  Progressive,
  Hierarchical,
  Meshless,
  FaceCluster
};

/// "progressive", "hierarchical", "meshless", "facecluster" (the command line's names).
const char* SolutionMethodName(SolutionMethod method);

/// Rule 2's bound: the largest scene hierarchical radiosity is chosen for.
constexpr std::size_t AutoHierarchicalMaxTriangles = 2048;

struct MethodChoice
{
  SolutionMethod Method = SolutionMethod::Hierarchical;
  std::string Rule; ///< "glossy", "sky", "small" or "large"
  std::string Why;  ///< one sentence: the scene's figure and the rule's measurement
  /// Hierarchical: links from the cluster roots at any size (HierarchicalClustering::On).
  bool Clustered = false;
};

/// The method for `scene` (validated, degenerate triangles dropped).
MethodChoice ChooseMethod(const Scene& scene);
} // namespace radiosity

#endif
