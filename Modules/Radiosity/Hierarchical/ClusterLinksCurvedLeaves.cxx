// Clustered hierarchical radiosity's curved leaves: a leaf cluster (no larger
// than the smallest element) is never split, whatever its normal cone, so it
// receives from sources that some of its triangles face away from. Its
// triangles take n_t . E, and a sum of links from opposite sides cancels on
// a triangle facing across them (a triangle facing sideways under a bright
// source went to 0 on the bunny), so such links are clamped per triangle:
// each triangle receives sum_l max(0, n_t . E_l(x_t)) over them. Rather than
// every link at every triangle, each link descends the leaf's subtree
// (ClusterLinks::Descend) only where its terminator (n . E_l = 0) passes: a subtree whose normal cone
// faces it takes it into the expansion it passes down, one that faces away
// drops it, and a nearly flat subtree decides by its plane, as a nearly flat
// receiver does (ClusterLinks.h has the method and its papers). The cost per
// link is then the few wide nodes its terminator crosses, not the leaf's
// triangles: on the 400k bunny room a leaf held 365 triangles on average.
#include "Radiosity/Hierarchical/ClusterLinks.h"

#include "Radiosity/Hierarchical/ClusterExpansion.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace radiosity
{
using cluster_detail::FactorAt;

ClusterLinks::Facing ClusterLinks::FacingOf(const VectorLink& link, const Vec3& origin, const Bounds& b)
{
  const Vec3 e = FactorAt(link.Factor, link.Gradient, b.Centre - origin);
  const double length = glm::length(e);
  const double cosA = length > 0 ? std::clamp(glm::dot(e, b.Axis) / length, -1.0, 1.0) : 0.0;
  if (b.ConeAngle <= NearlyFlatCone)
  {
    // Nearly flat: its plane decides, as it does for a source straddling a
    // nearly flat receiver (Compute), off by at most sin(cone) of the link.
    return cosA > 0 ? Facing::All : Facing::None;
  }
  // A normal within the cone (half angle beta about the axis) makes an angle
  // between |a - beta| and a + beta with the vector at the node's centre:
  // every one faces it when a + beta < pi/2, none when a - beta > pi/2 (a and
  // beta in [0, pi]: the cosine alone would take a + beta near 2 pi, or
  // beta - a past pi/2, for those).
  const double sinA = std::sqrt(1.0 - cosA * cosA);
  if (b.CosCone > 0 && cosA * b.CosCone - sinA * b.SinCone > 0)
  {
    return Facing::All;
  }
  if (cosA < b.CosCone && cosA * b.CosCone + sinA * b.SinCone < 0)
  {
    return Facing::None;
  }
  return Facing::Some;
}

} // namespace radiosity
