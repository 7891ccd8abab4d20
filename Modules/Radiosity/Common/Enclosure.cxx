#include "Radiosity/Common/Enclosure.h"

#include "Radiosity/Common/Visibility.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace radiosity
{
std::vector<unsigned char> EnclosedTriangles(const Scene& scene, const Visibility& visibility,
  const std::vector<std::uint32_t>& triangles, double reach, int rays)
{
  std::vector<unsigned char> enclosed(triangles.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, triangles.size(), 64),
    [&](const tbb::blocked_range<std::size_t>& range) {
      std::vector<Vec3> from(rays), to(rays);
      std::vector<unsigned char> open(rays);
      for (std::size_t i = range.begin(); i != range.end(); ++i)
      {
        const std::uint32_t t = triangles[i];
        const Vec3 z = scene.Normal(t);
        if (!(glm::length(z) > 0.5))
        {
          continue; // degenerate: no hemisphere
        }
        const Vec3 x = glm::normalize(std::fabs(z.x) < 0.9 ? glm::cross(z, Vec3(1, 0, 0)) : glm::cross(z, Vec3(0, 1, 0)));
        const Vec3 y = glm::cross(z, x);
        const Vec3 c = scene.Centroid(t);
        for (int k = 0; k < rays; ++k)
        {
          const double u = (k + 0.5) / rays;
          const double phi = 2.39996322972865332 * k + 0.618 * static_cast<double>(t % 97);
          const double r = std::sqrt(u);
          const Vec3 d = r * std::cos(phi) * x + r * std::sin(phi) * y + std::sqrt(1.0 - u) * z;
          from[k] = c;
          to[k] = c + reach * d;
        }
        visibility.TestSegments(from.data(), to.data(), static_cast<std::size_t>(rays), open.data());
        enclosed[i] = std::none_of(open.begin(), open.end(), [](unsigned char v) { return v != 0; });
      }
    });
  return enclosed;
}

bool SceneIsEnclosed(const Scene& scene, std::size_t samples)
{
  const std::size_t n = scene.Triangles.size();
  if (n == 0)
  {
    return false;
  }
  std::vector<std::uint32_t> chosen;
  if (n <= samples)
  {
    for (std::size_t t = 0; t < n; ++t)
    {
      chosen.push_back(static_cast<std::uint32_t>(t));
    }
  }
  else
  {
    // The triangles at the area quantiles (k + 0.5) / samples.
    double total = 0.0;
    for (std::size_t t = 0; t < n; ++t)
    {
      total += scene.Area(t);
    }
    double below = 0.0;
    std::size_t k = 0;
    for (std::size_t t = 0; t < n && k < samples; ++t)
    {
      below += scene.Area(t);
      if (below >= (static_cast<double>(k) + 0.5) / static_cast<double>(samples) * total)
      {
        chosen.push_back(static_cast<std::uint32_t>(t));
        while (k < samples && below >= (static_cast<double>(k) + 0.5) / static_cast<double>(samples) * total)
        {
          ++k;
        }
      }
    }
  }
  const double reach = 2.0 * scene.Diagonal();
  if (!(reach > 0.0))
  {
    return false;
  }
  const Visibility all(scene, Visibility::AllTriangles(scene));
  const std::vector<unsigned char> enclosed = EnclosedTriangles(scene, all, chosen, reach);
  return std::all_of(enclosed.begin(), enclosed.end(), [](unsigned char v) { return v != 0; });
}
} // namespace radiosity
