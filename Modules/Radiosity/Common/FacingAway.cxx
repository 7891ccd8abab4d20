#include "Radiosity/Common/FacingAway.h"

#include "Radiosity/Common/Visibility.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <mutex>
#include <set>
#include <vector>

namespace radiosity
{
namespace
{
// Whether the front of triangle t faces any source: a punctual light in
// front of its plane (any corner), the sun's reversed direction, the sky's
// hemisphere (unless the triangle faces straight down), or a corner of the
// emitters' bounding box (conservative: it only ever says "faces").
bool FacesASource(const Scene& scene, std::size_t t, const std::vector<Vec3>& emitterBox)
{
  const Vec3 n = scene.Normal(t);
  const LightSet& lighting = scene.Lighting;
  if (lighting.SkyLight.Enabled() && glm::dot(n, glm::normalize(lighting.SkyLight.Up)) > -0.999)
  {
    return true;
  }
  for (const Light& l : lighting.Lights)
  {
    if (l.Type == LightType::Directional)
    {
      if (glm::dot(-l.Direction, n) > 0.0)
      {
        return true;
      }
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      if (glm::dot(l.Position - scene.Vertex(t, k), n) > 0.0)
      {
        return true;
      }
    }
  }
  for (const Vec3& corner : emitterBox)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (glm::dot(corner - scene.Vertex(t, k), n) > 0.0)
      {
        return true;
      }
    }
  }
  return false;
}
}

FacingAway FindFacingAway(const Scene& scene)
{
  FacingAway result;
  const std::size_t nt = scene.Triangles.size();
  for (std::size_t t = 0; t < nt; ++t)
  {
    result.TotalArea += scene.Area(t);
  }
  std::vector<const Light*> punctual;
  for (const Light& l : scene.Lighting.Lights)
  {
    // Lamps only: the back of a one-sided room's walls (outside) sees the sun.
    if (punctual.size() < FacingAwayLights && l.Type != LightType::Directional && MaxComponent(l.Intensity) > 0.0)
    {
      punctual.push_back(&l);
    }
  }
  if (nt == 0 || punctual.empty())
  {
    return result;
  }
  std::vector<Vec3> emitterBox;
  {
    Vec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    bool any = false;
    for (std::size_t t = 0; t < nt; ++t)
    {
      if (MaxComponent(scene.Materials[t].Emission) > 0.0)
      {
        any = true;
        for (int k = 0; k < 3; ++k)
        {
          lo = glm::min(lo, scene.Vertex(t, k));
          hi = glm::max(hi, scene.Vertex(t, k));
        }
      }
    }
    for (int c = 0; any && c < 8; ++c)
    {
      emitterBox.emplace_back(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z);
    }
  }
  // A two-sided surface is two triangles on the same points, one reversed
  // (SPEC TwoSided): neither faces away from anything the pair does not.
  std::set<std::array<std::uint32_t, 3>> seen, twins;
  for (const Triangle& t : scene.Triangles)
  {
    std::array<std::uint32_t, 3> key{ t.V[0], t.V[1], t.V[2] };
    std::sort(key.begin(), key.end());
    if (!seen.insert(key).second)
    {
      twins.insert(key);
    }
  }
  const auto twoSided = [&](std::size_t t) {
    if (twins.empty())
    {
      return false;
    }
    std::array<std::uint32_t, 3> key{ scene.Triangles[t].V[0], scene.Triangles[t].V[1], scene.Triangles[t].V[2] };
    std::sort(key.begin(), key.end());
    return twins.count(key) > 0;
  };
  const Visibility rays(scene, Visibility::AllTriangles(scene));
  std::mutex merge;
  std::map<int, double> byObject;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nt), [&](const tbb::blocked_range<std::size_t>& range) {
    std::vector<Vec3> from, to;
    std::vector<std::size_t> owner;
    for (std::size_t t = range.begin(); t != range.end(); ++t)
    {
      if (FacesASource(scene, t, emitterBox) || twoSided(t))
      {
        continue;
      }
      // The back side's view: from just behind the centre towards each light.
      const Vec3 n = scene.Normal(t);
      const Vec3 behind = scene.Centroid(t) - 2.0 * rays.Offset() * n;
      for (const Light* l : punctual)
      {
        from.push_back(behind);
        to.push_back(l->Position);
        owner.push_back(t);
      }
    }
    std::vector<unsigned char> visible(from.size(), 0);
    if (!from.empty())
    {
      rays.TestSegments(from.data(), to.data(), from.size(), visible.data());
    }
    std::size_t triangles = 0;
    double area = 0.0;
    std::map<int, double> objects;
    // Each triangle's rays are consecutive: it counts once if any is visible.
    for (std::size_t i = 0; i < from.size();)
    {
      const std::size_t t = owner[i];
      bool seen = false;
      for (; i < from.size() && owner[i] == t; ++i)
      {
        seen = seen || visible[i] != 0;
      }
      if (seen)
      {
        ++triangles;
        area += scene.Area(t);
        objects[scene.ObjectIds.empty() ? 0 : scene.ObjectIds[t]] += scene.Area(t);
      }
    }
    const std::lock_guard<std::mutex> lock(merge);
    result.Triangles += triangles;
    result.Area += area;
    for (const auto& o : objects)
    {
      byObject[o.first] += o.second;
    }
  });
  double most = 0.0;
  for (const auto& o : byObject)
  {
    if (o.second > most)
    {
      most = o.second;
      result.Object = o.first;
    }
  }
  return result;
}

std::string FacingAwayWarning(const Scene& scene)
{
  const FacingAway away = FindFacingAway(scene);
  if (!(away.TotalArea > 0.0) || away.Area <= FacingAwayShare * away.TotalArea)
  {
    return std::string();
  }
  char share[32];
  std::snprintf(share, sizeof share, "%.1f%%", 100.0 * away.Area / away.TotalArea);
  std::string object;
  if (away.Object >= 0 && static_cast<std::size_t>(away.Object) < scene.ObjectNames.size() &&
    !scene.ObjectNames[away.Object].empty())
  {
    object = ", most of them in '" + scene.ObjectNames[away.Object] + "'";
  }
  return std::to_string(away.Triangles) + " triangles (" + share + " of the surface area" + object +
    ") face away from every light, emitter and the sky while their back side sees a light directly: "
    "surfaces are one-sided, so they get no direct light and are drawn dark from that side. If they "
    "were modelled the wrong way round, solve both sides (the TwoSided array, vtkRadiosityPass::TwoSided, "
    "--two-sided)";
}
} // namespace radiosity
