// Culled depth-first descent of the face cluster hierarchy (Willmott,
// Heckbert & Garland 1999): shaft culling of candidate blockers (Haines &
// Wallace 1991) a cluster box at a time, shared by face cluster radiosity's
// exact visibility (FaceClusterVisibility::ShaftBlockers) and the
// hierarchical solver's blocker search (HierarchicalLinkFactors.cxx).
#ifndef Radiosity_FaceClusterDescent_h
#define Radiosity_FaceClusterDescent_h

#include "Radiosity/FaceCluster/FaceClusterHierarchy.h"

#include <cstdint>
#include <vector>

namespace radiosity
{
/// The eight corners of a cluster's oriented box, each half size grown to
/// HalfSize (1 + relative) + absolute: the boxes are single precision, and a
/// flat one has no thickness. Corner k is on the + side of axis j when bit j
/// of k is set.
inline void GrownBoxCorners(const FaceCluster& c, double relative, double absolute, Vec3 (&corners)[8])
{
  Vec3 half[3];
  for (int j = 0; j < 3; ++j)
  {
    half[j] = (double(c.HalfSize[j]) * (1.0 + relative) + absolute) * Vec3(c.Axis[j]);
  }
  for (int k = 0; k < 8; ++k)
  {
    corners[k] = Vec3(c.Centre) + (k & 1 ? half[0] : -half[0]) + (k & 2 ? half[1] : -half[1]) +
      (k & 4 ? half[2] : -half[2]);
  }
}

/// Visits `h` from its roots, depth first: an internal cluster is opened only
/// when `open(cluster)` is true, and `take(triangle)` is called for every
/// triangle reached. Stops, returning false, as soon as `take` returns false.
template <typename Open, typename Take>
bool DescendClusters(const FaceClusterHierarchy& h, Open&& open, Take&& take)
{
  thread_local std::vector<std::uint32_t> stack;
  stack.assign(h.Roots().begin(), h.Roots().end());
  while (!stack.empty())
  {
    const std::uint32_t id = stack.back();
    stack.pop_back();
    const FaceCluster* c = h.InternalCluster(id);
    if (!c)
    {
      if (!take(id))
      {
        return false;
      }
    }
    else if (open(*c))
    {
      stack.push_back(c->Child[0]);
      stack.push_back(c->Child[1]);
    }
  }
  return true;
}
} // namespace radiosity

#endif
