// Basic numeric types of the core. Double precision everywhere a value is
// accumulated or compared with a reference (DESIGN.md, principles).
#ifndef Radiosity_Types_h
#define Radiosity_Types_h

#include <glm/vec3.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cstdint>

namespace radiosity
{
/// One constant for every file (the core builds as unity translation units:
/// a per-file Pi would be defined twice in one of them).
constexpr double Pi = 3.14159265358979323846;

using Vec3 = glm::dvec3;
/// A colour triple, linear RGB. Same type as Vec3 so that glm's arithmetic applies.
using RGB = glm::dvec3;

inline double Luminance(const RGB& c)
{
  return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}
inline double MaxComponent(const RGB& c)
{
  return c.r > c.g ? (c.r > c.b ? c.r : c.b) : (c.g > c.b ? c.g : c.b);
}
inline double Mean(const RGB& c)
{
  return (c.x + c.y + c.z) / 3.0;
}

/// `c` with its negative components set to 0 (a NaN stays NaN): irradiance
/// handed out from a representation that can undershoot zero where the
/// light is cut off (a multilevel Shepard field's residual levels, an
/// extrapolated iteration, sums of signed contour integrals in an umbra).
inline RGB NonNegative(const RGB& c)
{
  return RGB(c.r < 0.0 ? 0.0 : c.r, c.g < 0.0 ? 0.0 : c.g, c.b < 0.0 ? 0.0 : c.b);
}

inline double SumComponents(const RGB& c)
{
  return c.r + c.g + c.b;
}

/// Lexicographic order of points (x, then y, then z): a key for sorting
/// and merging equal points.
inline bool LexLess(const Vec3& a, const Vec3& b)
{
  if (a.x != b.x)
  {
    return a.x < b.x;
  }
  if (a.y != b.y)
  {
    return a.y < b.y;
  }
  return a.z < b.z;
}

struct Triangle
{
  std::array<std::uint32_t, 3> V;
};

/// Area vector (normal times area) of a triangle.
inline Vec3 AreaVector(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return 0.5 * glm::cross(b - a, c - a);
}

/// Distance from p to the segment from a to b.
inline double DistanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double length2 = glm::dot(ab, ab);
  const double s = length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + s * ab));
}
} // namespace radiosity

#endif
