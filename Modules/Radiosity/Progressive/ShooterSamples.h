// Fixed, stratified sample points on a shooting triangle for visibility rays:
// the centroids of its level-k uniform subdivision (1, 4 or 16 points).
#ifndef Radiosity_ShooterSamples_h
#define Radiosity_ShooterSamples_h

#include "Radiosity/Common/Types.h"

#include <vector>

namespace radiosity
{
inline void AppendSubtriangleCentroids(
  const Vec3& a, const Vec3& b, const Vec3& c, int levels, std::vector<Vec3>& out)
{
  if (levels <= 0)
  {
    out.push_back((a + b + c) / 3.0);
    return;
  }
  const Vec3 ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
  AppendSubtriangleCentroids(a, ab, ca, levels - 1, out);
  AppendSubtriangleCentroids(ab, b, bc, levels - 1, out);
  AppendSubtriangleCentroids(ca, bc, c, levels - 1, out);
  AppendSubtriangleCentroids(ab, bc, ca, levels - 1, out);
}

/// 1 -> centroid, 4 -> 4 points, 16 -> 16 points (other counts round down).
inline std::vector<Vec3> ShooterSamplePoints(const Vec3& a, const Vec3& b, const Vec3& c, int count)
{
  const int levels = count >= 16 ? 2 : (count >= 4 ? 1 : 0);
  std::vector<Vec3> pts;
  AppendSubtriangleCentroids(a, b, c, levels, pts);
  return pts;
}
} // namespace radiosity

#endif
