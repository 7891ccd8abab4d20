#include "Radiosity/FaceCluster/MinimumRectangle.h"

// CGAL in a translation unit of its own (DESIGN.md: compile time).
#include <CGAL/Polygon_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/min_quadrilateral_2.h>

#include <glm/geometric.hpp>

#include <iterator>

namespace radiosity
{
namespace
{
// Exact predicates: the hull of nearly collinear points stays convex.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;
}

PlanarHullRectangle MinimumAreaRectangle(const std::vector<glm::dvec2>& points)
{
  PlanarHullRectangle out;
  std::vector<Point> in;
  in.reserve(points.size());
  for (const glm::dvec2& p : points)
  {
    in.emplace_back(p.x, p.y);
  }
  std::vector<Point> hull;
  CGAL::convex_hull_2(in.begin(), in.end(), std::back_inserter(hull));
  for (const Point& p : hull)
  {
    out.Hull.emplace_back(p.x(), p.y());
  }
  if (hull.size() < 3)
  {
    if (hull.size() == 2)
    {
      const glm::dvec2 d = out.Hull[1] - out.Hull[0];
      if (glm::length(d) > 0.0)
      {
        out.Axis = glm::normalize(d);
      }
    }
    return out;
  }
  CGAL::Polygon_2<Kernel> rectangle;
  try
  {
    CGAL::min_rectangle_2(hull.begin(), hull.end(), std::back_inserter(rectangle));
  }
  catch (const CGAL::Failure_exception&)
  {
    // Inexact constructions on a sliver hull: keep its longest edge's
    // direction, which a minimum rectangle of a sliver has too.
    rectangle.clear();
    double longest = -1.0;
    for (std::size_t i = 0; i < out.Hull.size(); ++i)
    {
      const glm::dvec2 d = out.Hull[(i + 1) % out.Hull.size()] - out.Hull[i];
      if (glm::length(d) > longest)
      {
        longest = glm::length(d);
        out.Axis = glm::normalize(d);
      }
    }
  }
  if (rectangle.size() == 4)
  {
    const glm::dvec2 a(rectangle[0].x(), rectangle[0].y());
    const glm::dvec2 b(rectangle[1].x(), rectangle[1].y());
    if (glm::length(b - a) > 0.0)
    {
      out.Axis = glm::normalize(b - a);
    }
  }
  return out;
}
} // namespace radiosity
