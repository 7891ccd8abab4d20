// Fixed, stratified sample points on a shooting triangle for visibility rays:
// the centroids of its level-k uniform subdivision (1, 4 or 16 points); the
// GPU solver shoots from the subdivision's triangles themselves.
#ifndef Radiosity_ShooterSamples_h
#define Radiosity_ShooterSamples_h

#include "Radiosity/Common/Types.h"

#include <array>
#include <vector>

namespace radiosity
{
/// The level-k uniform subdivision of triangle (a, b, c) at its edge
/// midpoints: 4^k triangles, corner children first, then the centre one.
inline void AppendSubtriangles(
  const Vec3& a, const Vec3& b, const Vec3& c, int levels, std::vector<std::array<Vec3, 3>>& out)
{
  if (levels <= 0)
  {
    out.push_back({ a, b, c });
    return;
  }
  const Vec3 ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
  AppendSubtriangles(a, ab, ca, levels - 1, out);
  AppendSubtriangles(ab, b, bc, levels - 1, out);
  AppendSubtriangles(ca, bc, c, levels - 1, out);
  AppendSubtriangles(ab, bc, ca, levels - 1, out);
}

/// The centroids of AppendSubtriangles' triangles.
inline void AppendSubtriangleCentroids(
  const Vec3& a, const Vec3& b, const Vec3& c, int levels, std::vector<Vec3>& out)
{
  std::vector<std::array<Vec3, 3>> parts;
  AppendSubtriangles(a, b, c, levels, parts);
  for (const auto& t : parts)
  {
    out.push_back((t[0] + t[1] + t[2]) / 3.0);
  }
}

/// 1, 4 or 16 samples as subdivision levels 0, 1 or 2 (other counts round down).
inline int SubdivisionLevelsOfSamples(int count)
{
  return count >= 16 ? 2 : (count >= 4 ? 1 : 0);
}

/// 1 -> centroid, 4 -> 4 points, 16 -> 16 points (other counts round down).
inline std::vector<Vec3> ShooterSamplePoints(const Vec3& a, const Vec3& b, const Vec3& c, int count)
{
  std::vector<Vec3> pts;
  AppendSubtriangleCentroids(a, b, c, SubdivisionLevelsOfSamples(count), pts);
  return pts;
}
} // namespace radiosity

#endif
