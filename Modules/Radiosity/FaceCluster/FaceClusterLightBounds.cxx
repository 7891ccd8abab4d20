#include "Radiosity/FaceCluster/FaceClusterLightBounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace radiosity
{
namespace
{
/// The light's falloff towards unit direction `towards` (from the light).
double Falloff(const Light& light, const Vec3& towards)
{
  return light.Type == LightType::Spot ? SpotFalloff(light, glm::dot(towards, light.Direction)) : 1.0;
}

/// The light's reach over a cluster's box: the squared distance to it, the
/// largest falloff towards it and the largest projected area towards the
/// light; Inside when the light is within the box's bounding sphere.
struct BoxReach
{
  bool Inside = false;
  double Nearest2 = 0.0, Falloff = 1.0, Facing = 0.0;
};

BoxReach ReachOf(const FaceCluster& cluster, const Light& light)
{
  BoxReach reach;
  // The light in the box's frame; the nearest point of the box.
  const Vec3 centre(cluster.Centre);
  const Vec3 offset = light.Position - centre;
  for (int k = 0; k < 3; ++k)
  {
    const double along = glm::dot(offset, Vec3(cluster.Axis[k]));
    const double outside = std::abs(along) - double(cluster.HalfSize[k]);
    reach.Nearest2 += outside > 0.0 ? outside * outside : 0.0;
  }
  const double radius = glm::length(Vec3(cluster.HalfSize));
  const double distance = glm::length(offset);
  if (!(reach.Nearest2 > 0.0) || !(distance > radius))
  {
    reach.Inside = true;
    return reach;
  }
  // The directions from the light towards the box lie within `angle` of
  // the one towards its centre.
  const double angle = std::asin(std::min(1.0, radius / distance));
  if (light.Type == LightType::Spot)
  {
    const double toAxis = std::acos(std::clamp(-glm::dot(offset, light.Direction) / distance, -1.0, 1.0));
    reach.Falloff = SpotFalloff(light, std::cos(std::max(0.0, toAxis - angle)));
  }
  // |r - r_c| <= angle for every direction r from the box to the light, and
  // each of the six samples changes by at most that much per unit of D.
  double spread = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    spread += double(cluster.DPlus[k]) + double(cluster.DMinus[k]);
  }
  reach.Facing = std::min(double(cluster.Area), cluster.MaxProjectedArea(offset / distance) + angle * spread);
  return reach;
}
} // namespace

double PunctualLightMost(const FaceCluster& cluster, const Light& light)
{
  if (light.Type == LightType::Directional)
  {
    return Mean(light.Intensity) * double(cluster.Area);
  }
  const BoxReach reach = ReachOf(cluster, light);
  if (reach.Inside)
  {
    return std::numeric_limits<double>::infinity();
  }
  return Mean(light.Intensity) * reach.Falloff / reach.Nearest2 * reach.Facing;
}

double PunctualLightExcess(const FaceCluster& cluster, const Light& light, const std::vector<Vec3>& nodes)
{
  if (light.Type == LightType::Directional || !(Mean(light.Intensity) > 0.0))
  {
    return 0.0;
  }
  const BoxReach reach = ReachOf(cluster, light);
  if (reach.Inside)
  {
    return std::numeric_limits<double>::infinity();
  }
  double seen = 0.0;
  for (const Vec3& x : nodes)
  {
    const Vec3 d = x - light.Position;
    const double d2 = glm::dot(d, d);
    if (d2 > 0.0)
    {
      seen = std::max(seen, Falloff(light, d / std::sqrt(d2)) / d2);
    }
  }
  const double excess = reach.Falloff / reach.Nearest2 - seen;
  return excess > 0.0 ? Mean(light.Intensity) * excess * reach.Facing : 0.0;
}
} // namespace radiosity
