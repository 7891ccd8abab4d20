// The minimum-area enclosing rectangle of a planar point set, by rotating
// calipers over its convex hull (Toussaint 1983, "Solving geometric problems
// with the rotating calipers"), as CGAL's min_rectangle_2 implements it: the
// x/y axes of a face cluster's oriented box (Gobbetti et al. 2003, 3.1).
#ifndef Radiosity_MinimumRectangle_h
#define Radiosity_MinimumRectangle_h

#include <glm/vec2.hpp>

#include <vector>

namespace radiosity
{
struct PlanarHullRectangle
{
  std::vector<glm::dvec2> Hull; ///< convex hull, counter-clockwise
  glm::dvec2 Axis{ 1.0, 0.0 };  ///< unit direction of one side; the other is its normal
};

/// Convex hull and minimum-area rectangle of `points`. Fewer than three
/// distinct points, or collinear ones, give the direction of the longest
/// extent (or (1, 0)).
PlanarHullRectangle MinimumAreaRectangle(const std::vector<glm::dvec2>& points);
} // namespace radiosity

#endif
