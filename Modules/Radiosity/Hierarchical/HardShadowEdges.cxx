#include "Radiosity/Hierarchical/HardShadowEdges.h"

#include "Radiosity/Common/Visibility.h"

#include <algorithm>
#include <cmath>

namespace radiosity
{
namespace
{
std::uint64_t ShadowEdgeKey(std::uint32_t a, std::uint32_t b)
{
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
}

/// Which side of the light a triangle faces: +1 towards it, -1 away, 0 edge-on.
int Facing(const Scene& scene, std::uint32_t t, const Light& light, const Vec3& onEdge)
{
  const Vec3 n = scene.Normal(t);
  const double d = light.Type == LightType::Directional ? -glm::dot(n, light.Direction)
                                                        : glm::dot(n, light.Position - onEdge);
  return d > 0 ? 1 : (d < 0 ? -1 : 0);
}
}

HardShadowEdges::HardShadowEdges(const Scene& scene, const Visibility& occluders, double farDistance)
  : SourceScene(scene)
  , Occluders(occluders)
  , Far(farDistance)
{
  for (std::uint32_t t = 0; t < scene.Triangles.size(); ++t)
  {
    const auto& v = scene.Triangles[t].V;
    for (int k = 0; k < 3; ++k)
    {
      this->EdgeTriangles[ShadowEdgeKey(v[k], v[(k + 1) % 3])].push_back(t);
    }
  }
}

bool HardShadowEdges::Silhouette(std::uint32_t t, int k, const Light& light) const
{
  const Scene& scene = this->SourceScene;
  const auto& v = scene.Triangles[t].V;
  const auto& sharing = this->EdgeTriangles.at(ShadowEdgeKey(v[k], v[(k + 1) % 3]));
  if (sharing.size() != 2)
  {
    return true; // a boundary edge, or a non-manifold one
  }
  const Vec3& p = scene.Points[v[k]];
  return Facing(scene, sharing[0], light, p) != Facing(scene, sharing[1], light, p);
}

void HardShadowEdges::Find(const Light& light, const TriangleCorners& receiver, const Vec3& normal,
  double minLength, std::vector<std::array<Vec3, 2>>& segments) const
{
  const Scene& scene = this->SourceScene;
  const bool parallel = light.Type == LightType::Directional;
  const Vec3 c0 = receiver[0];
  const double lightHeight = parallel ? 0.0 : glm::dot(light.Position - c0, normal);
  if (parallel ? !(glm::dot(light.Direction, normal) < 0.0) : !(lightHeight > 0.0))
  {
    return; // the receiver faces away: it receives nothing, casts nothing on itself
  }
  // The volume between the receiver and the light, bounded by the receiver's
  // plane and three planes through its edges and the light (or its direction).
  const Vec3 centroid = (receiver[0] + receiver[1] + receiver[2]) / 3.0;
  const Vec3 apex = parallel ? centroid - this->Far * light.Direction : light.Position;
  std::array<Vec3, 3> sideNormal;
  std::array<Vec3, 3> sidePoint;
  for (int k = 0; k < 3; ++k)
  {
    const Vec3& a = receiver[k];
    const Vec3& b = receiver[(k + 1) % 3];
    const Vec3 towardsLight = parallel ? -light.Direction : light.Position - a;
    Vec3 m = glm::cross(b - a, towardsLight);
    if (glm::dot(m, centroid - a) < 0)
    {
      m = -m;
    }
    sideNormal[k] = m;
    sidePoint[k] = a;
  }
  double radius = 0.0;
  const Vec3 centre = 0.5 * (centroid + apex);
  for (const Vec3& c : receiver)
  {
    radius = std::max(radius, glm::length(c - centre));
  }
  radius = std::max(radius, glm::length(apex - centre));
  std::vector<std::uint32_t> candidates;
  this->Occluders.OccludersInSphere(centre, radius * (1.0 + 1e-9), candidates);
  const double size = std::max({ glm::length(receiver[1] - receiver[0]),
    glm::length(receiver[2] - receiver[1]), glm::length(receiver[0] - receiver[2]) });
  const double above = 1e-9 * size; // strictly above the receiver's plane
  for (std::uint32_t b : candidates)
  {
    const TriangleCorners v = { scene.Vertex(b, 0), scene.Vertex(b, 1), scene.Vertex(b, 2) };
    bool outside = false;
    for (int k = 0; k < 3 && !outside; ++k)
    {
      outside = glm::dot(v[0] - sidePoint[k], sideNormal[k]) < 0 &&
        glm::dot(v[1] - sidePoint[k], sideNormal[k]) < 0 && glm::dot(v[2] - sidePoint[k], sideNormal[k]) < 0;
    }
    const auto height = [&](const Vec3& x) { return glm::dot(x - c0, normal); };
    if (outside || std::max({ height(v[0]), height(v[1]), height(v[2]) }) <= above)
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      if (!this->Silhouette(b, k, light))
      {
        continue;
      }
      // The part of the edge strictly between the receiver's plane and the light.
      Vec3 p = v[k], q = v[(k + 1) % 3];
      double hp = height(p), hq = height(q);
      const double top = parallel ? std::numeric_limits<double>::infinity() : lightHeight * (1.0 - 1e-9);
      double s0 = 0.0, s1 = 1.0;
      const auto clip = [&](double f0, double f1) { // keep f(s) >= 0, f linear
        if (f0 < 0 && f1 < 0)
        {
          s0 = 1.0;
          s1 = 0.0;
          return;
        }
        if (f0 < 0)
        {
          s0 = std::max(s0, f0 / (f0 - f1));
        }
        else if (f1 < 0)
        {
          s1 = std::min(s1, f0 / (f0 - f1));
        }
      };
      clip(hp - above, hq - above);
      if (std::isfinite(top))
      {
        clip(top - hp, top - hq);
      }
      if (!(s0 < s1))
      {
        continue;
      }
      const Vec3 a = p + s0 * (q - p), bEnd = p + s1 * (q - p);
      const auto project = [&](const Vec3& x) {
        if (parallel)
        {
          return x - height(x) / glm::dot(light.Direction, normal) * light.Direction;
        }
        const double t = lightHeight / (lightHeight - height(x));
        return light.Position + t * (x - light.Position);
      };
      const Vec3 A = project(a), B = project(bEnd);
      // Clip the projected segment to the receiver triangle (three half-planes),
      // grown by a rounding margin: a shadow edge along the receiver's own
      // edge (a blocker edge whose projection is a leaf's boundary) is kept.
      double t0 = 0.0, t1 = 1.0;
      for (int e = 0; e < 3 && t0 < t1; ++e)
      {
        const Vec3& ea = receiver[e];
        const Vec3& eb = receiver[(e + 1) % 3];
        const Vec3 inward = glm::cross(normal, eb - ea);
        const double margin = 1e-7 * size * glm::length(inward);
        const double fa = glm::dot(A - ea, inward) + margin, fb = glm::dot(B - ea, inward) + margin;
        if (fa < 0 && fb < 0)
        {
          t0 = 1.0;
          t1 = 0.0;
        }
        else if (fa < 0)
        {
          t0 = std::max(t0, fa / (fa - fb));
        }
        else if (fb < 0)
        {
          t1 = std::min(t1, fa / (fa - fb));
        }
      }
      if (!(t0 < t1))
      {
        continue;
      }
      const Vec3 s = A + t0 * (B - A), e = A + t1 * (B - A);
      if (glm::length(e - s) >= minLength)
      {
        segments.push_back({ s, e });
      }
    }
  }
}
} // namespace radiosity
