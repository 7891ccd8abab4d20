// The hard-shadow boundaries of punctual lights on a receiver polygon: the
// D0 discontinuities of the radiance function (Heckbert 1992, "Discontinuity
// meshing for radiosity"; Hardt & Teller 1996 section 4.1 rank them above
// every other kind), the projections from the light of the blockers'
// silhouette edges onto the receiver's plane, clipped to the receiver.
//
// A point or spot light projects centrally from its position, a directional
// light in parallel along its direction. An edge is a silhouette edge seen
// from the light when it bounds one triangle only or when the triangles
// sharing it face the light differently. Blockers are the occluders inside
// the volume between the receiver and the light (an Embree point query over
// the BVH, then the volume's planes).
#ifndef Radiosity_HardShadowEdges_h
#define Radiosity_HardShadowEdges_h

#include "Radiosity/Common/Lights.h"
#include "Radiosity/Common/Scene.h"
#include "Radiosity/Hierarchical/Backprojection.h"

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace radiosity
{
class Visibility;

class HardShadowEdges
{
public:
  /// `occluders` holds every triangle (DirectLighting's BVH); `farDistance` a length beyond the scene.
  HardShadowEdges(const Scene& scene, const Visibility& occluders, double farDistance);

  /**
   * The shadow boundary segments that `light` casts onto the triangle
   * `receiver` (unit normal `normal`), each at least `minLength` long,
   * appended to `segments`. A boundary along one of the receiver's edges is
   * included (within a relative 1e-7): the samples there need both sides.
   */
  void Find(const Light& light, const TriangleCorners& receiver, const Vec3& normal, double minLength,
    std::vector<std::array<Vec3, 2>>& segments) const;

private:
  bool Silhouette(std::uint32_t triangle, int edge, const Light& light) const;

  const Scene& SourceScene;
  const Visibility& Occluders;
  double Far;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> EdgeTriangles;
};
} // namespace radiosity

#endif
