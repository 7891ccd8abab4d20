#include "Radiosity/Common/FormFactor.h"

#include <cmath>
#include <vector>

namespace radiosity
{
namespace
{
constexpr std::size_t MaxClipped = 16;

// Sutherland-Hodgman clip of a polygon against the half-space (x - p).n >= 0.
std::size_t ClipToHemisphere(
  const Vec3& p, const Vec3& n, const Vec3* in, std::size_t count, Vec3* out)
{
  std::size_t k = 0;
  for (std::size_t i = 0; i < count; ++i)
  {
    const Vec3& a = in[i];
    const Vec3& b = in[(i + 1) % count];
    const double da = glm::dot(a - p, n);
    const double db = glm::dot(b - p, n);
    if (da >= 0)
    {
      out[k++] = a;
    }
    if ((da >= 0) != (db >= 0))
    {
      const double t = da / (da - db);
      out[k++] = a + t * (b - a);
    }
  }
  return k;
}

/// Room for the clipped polygon: the stack for the usual triangles and
/// quads, the heap for larger polygons (Sutherland-Hodgman emits at most two
/// vertices per input vertex).
class ClipBuffer
{
public:
  explicit ClipBuffer(std::size_t count)
  {
    if (2 * count > MaxClipped)
    {
      this->Heap.resize(2 * count);
    }
  }
  Vec3* data() { return this->Heap.empty() ? this->Stack : this->Heap.data(); }

private:
  Vec3 Stack[MaxClipped];
  std::vector<Vec3> Heap;
};
}

Vec3 PointToPolygonVectorFormFactor(const Vec3& p, const Vec3* poly, std::size_t count, const Vec3* horizon)
{
  if (horizon && count >= 3)
  {
    Vec3 areaVector(0.0);
    for (std::size_t i = 1; i + 1 < count; ++i)
    {
      areaVector += glm::cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
    }
    if (glm::dot(p - poly[0], areaVector) <= 0)
    {
      return Vec3(0.0);
    }
    ClipBuffer clipped(count);
    const std::size_t m = ClipToHemisphere(p, *horizon, poly, count, clipped.data());
    return m < 3 ? Vec3(0.0) : PointToPolygonVectorFormFactor(p, clipped.data(), m, nullptr);
  }
  Vec3 areaVector(0.0), centroid(0.0);
  for (std::size_t i = 1; i + 1 < count; ++i)
  {
    areaVector += glm::cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
  }
  for (std::size_t i = 0; i < count; ++i)
  {
    centroid += poly[i] / static_cast<double>(count);
  }
  if (count < 3 || glm::dot(p - poly[0], areaVector) <= 0)
  {
    return Vec3(0.0);
  }
  Vec3 sum(0.0);
  for (std::size_t i = 0; i < count; ++i)
  {
    const Vec3 a = poly[i] - p;
    const Vec3 b = poly[(i + 1) % count] - p;
    const Vec3 c = glm::cross(a, b);
    const double cl = glm::length(c);
    if (cl > 0.0)
    {
      sum += std::atan2(cl, glm::dot(a, b)) * c / cl;
    }
  }
  sum /= 2.0 * Pi;
  return glm::dot(sum, centroid - p) < 0.0 ? -sum : sum;
}

double PointToPolygonFormFactor(const Vec3& p, const Vec3& n, const Vec3* poly, std::size_t count)
{
  if (count < 3)
  {
    return 0.0;
  }
  // One-sided emitter: the receiver must be in front of the polygon's plane.
  Vec3 areaVector(0.0);
  for (std::size_t i = 1; i + 1 < count; ++i)
  {
    areaVector += glm::cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
  }
  if (glm::dot(p - poly[0], areaVector) <= 0)
  {
    return 0.0;
  }
  // A polygon wholly above the receiver's horizon is its own clip (the
  // mesher's samples see hundreds of such sources each): no copy then.
  bool above = true;
  for (std::size_t i = 0; i < count && above; ++i)
  {
    above = glm::dot(poly[i] - p, n) >= 0;
  }
  ClipBuffer buffer(above ? 0 : count);
  const Vec3* clipped = poly;
  std::size_t m = count;
  if (!above)
  {
    m = ClipToHemisphere(p, n, poly, count, buffer.data());
    clipped = buffer.data();
  }
  if (m < 3)
  {
    return 0.0;
  }
  // Lambert's contour integral: F = 1/(2 pi) sum_i theta_i n . unit(R_i x R_i+1).
  double sum = 0.0;
  Vec3 a = clipped[0] - p;
  const Vec3 first = a;
  for (std::size_t i = 0; i < m; ++i)
  {
    const Vec3 b = i + 1 < m ? clipped[i + 1] - p : first;
    const Vec3 c = glm::cross(a, b);
    const double cl = glm::length(c);
    if (cl > 0.0)
    {
      const double theta = std::atan2(cl, glm::dot(a, b));
      sum += theta * glm::dot(n, c) / cl;
    }
    // else: the receiver lies on this edge's line; approached from the
    // receiver's side the edge's plane contains n, so it contributes nothing.
    a = b;
  }
  return std::fabs(sum) / (2.0 * Pi);
}

double DiscFormFactor(const Vec3& p, const Vec3& n, const Vec3& q, const Vec3& m, double area)
{
  const Vec3 d = q - p;
  const double r2 = glm::dot(d, d);
  if (r2 <= 0.0)
  {
    return 0.0;
  }
  const double r = std::sqrt(r2);
  const double cosR = glm::dot(n, d) / r;
  const double cosS = -glm::dot(m, d) / r;
  if (cosR <= 0.0 || cosS <= 0.0)
  {
    return 0.0;
  }
  return area * cosR * cosS / (Pi * r2 + area);
}
} // namespace radiosity
