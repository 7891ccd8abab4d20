// Bounds of a punctual light's direct light over a face cluster, the test
// that decides whether a leaf cluster must be opened for the lights (in the
// manner of 3.3.2's transfer bounds, Gobbetti et al. 2003, with the light as
// a point emitter): the most unshadowed power the light could put on the
// cluster anywhere in its oriented box, against what its rule nodes see.
//
// Why a bound and not the nodes alone: a spot's cone, or a light close to a
// large cluster, can fall between the nodes, which then see nothing or too
// little. Why not open every cluster to its triangles (the solver's rule
// before): the solution then grew with the input (a 940k-triangle bunny
// room with one point light: 949,638 elements and 8.6 GB), which a face
// cluster solution must not (the paper's figure 4).
#ifndef Radiosity_FaceClusterLightBounds_h
#define Radiosity_FaceClusterLightBounds_h

#include "Radiosity/Common/Lights.h"
#include "Radiosity/FaceCluster/FaceClusterHierarchy.h"

#include <vector>

namespace radiosity
{
/**
 * How much more power (W, the mean of the channels) the unshadowed light of a
 * point or spot light can bring to `cluster` than its nodes show:
 *   I (f_box / d_min^2 - max_q f_q / d_q^2)_+ A_max,
 * with d_min the distance from the light to the cluster's oriented box, f
 * the spot falloff (1 for a point light), f_box its largest value over the
 * directions towards the box, f_q and d_q those at the nodes, and A_max the
 * cluster's largest projected area towards the light (Willmott's
 * directional samples, widened by the box's angular radius), at most its
 * area. Infinite when the light is inside the box's bounding sphere. 0 for a directional
 * light: it is the same at every point, and the nodes see its shadows as
 * they see an emitter's (the paper's sampled visibility).
 */
double PunctualLightExcess(const FaceCluster& cluster, const Light& light, const std::vector<Vec3>& nodes);

/**
 * The most power (W, mean of the channels) the light can bring to `cluster`
 * unshadowed: I f_box A_max / d_min^2 (a directional light: E A). What a
 * shadow edge inside the cluster can misplace, when its visibility samples
 * disagree. Infinite when the light is inside the box's bounding sphere.
 */
double PunctualLightMost(const FaceCluster& cluster, const Light& light);
} // namespace radiosity

#endif
