#include "Radiosity/Common/MemoryBudget.h"

#include "Radiosity/Common/SystemInfo.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace radiosity
{
double DefaultMemoryBudgetBytes()
{
  return 0.75 * PhysicalMemoryBytes();
}

double ResolveMemoryBudget(double budget)
{
  return budget > 0 ? budget : DefaultMemoryBudgetBytes();
}

namespace
{
/// `value` in steps of 1000 named by `names` (names[0] for below 1000),
/// three significant digits past the first step.
std::string InThousands(double value, const char* const* names, int count)
{
  int u = 0;
  while (value >= 1000.0 && u + 1 < count)
  {
    value /= 1000.0;
    ++u;
  }
  char text[64];
  std::snprintf(text, sizeof text, u == 0 ? "%.0f%s" : "%.3g%s", value, names[u]);
  return text;
}
}

std::string FormatBytes(double bytes)
{
  const char* units[] = { " bytes", " kB", " MB", " GB", " TB", " PB", " EB" };
  return InThousands(bytes, units, 7);
}

std::string FormatCount(double count)
{
  const char* words[] = { "", " thousand", " million", " billion", " trillion" };
  return InThousands(count, words, 5);
}

void CheckMemoryBudget(
  double bytes, double budget, const std::string& what, const std::string& advice)
{
  if (budget > 0 && !(bytes <= budget))
  {
    throw MemoryBudgetExceeded(what + " need about " + FormatBytes(bytes) + ", over the memory budget of " +
      FormatBytes(budget) + " (--max-memory, MaxMemory; default 75% of physical memory): " + advice);
  }
}

namespace
{
bool InFrontOf(const Scene& scene, std::size_t a, std::size_t b, double tolerance)
{
  const Vec3 c = scene.Centroid(b);
  const Vec3 n = scene.Normal(b);
  for (int k = 0; k < 3; ++k)
  {
    if (glm::dot(scene.Vertex(a, k) - c, n) > tolerance)
    {
      return true;
    }
  }
  return false;
}
}

double FacingTrianglePairs(const Scene& scene)
{
  const std::size_t n = scene.Triangles.size();
  if (n < 2)
  {
    return 0.0;
  }
  const double tolerance = 1e-9 * scene.Diagonal(); // HierarchicalRadiosity's plane tolerance
  auto facing = [&](std::size_t p, std::size_t q) {
    return InFrontOf(scene, p, q, tolerance) && InFrontOf(scene, q, p, tolerance);
  };
  const double pairs = static_cast<double>(n) * static_cast<double>(n - 1);
  if (n <= 2000)
  {
    std::size_t count = 0;
    for (std::size_t p = 0; p < n; ++p)
    {
      for (std::size_t q = p + 1; q < n; ++q)
      {
        count += facing(p, q);
      }
    }
    return 2.0 * static_cast<double>(count);
  }
  // A fixed sample (the same scene gives the same estimate): SplitMix64.
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  auto next = [&state]() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  };
  const std::size_t samples = 4000000;
  std::size_t count = 0;
  for (std::size_t s = 0; s < samples; ++s)
  {
    const std::size_t p = next() % n;
    std::size_t q = next() % (n - 1);
    q += q >= p;
    count += facing(p, q);
  }
  return pairs * static_cast<double>(count) / static_cast<double>(samples);
}

double UniformQuadtreeLeaves(const Scene& scene, double edge, int maxLevel)
{
  double leaves = 0.0;
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    const Vec3 a = scene.Vertex(t, 0), b = scene.Vertex(t, 1), c = scene.Vertex(t, 2);
    const double longest =
      std::max({ glm::length(b - a), glm::length(c - b), glm::length(a - c) });
    // Each split halves every edge: levels until the longest is at most `edge`.
    int levels = 0;
    if (edge > 0 && longest > edge)
    {
      levels = static_cast<int>(std::ceil(std::log2(longest / edge)));
    }
    else if (!(edge > 0))
    {
      levels = maxLevel;
    }
    leaves += std::pow(4.0, std::min(levels, maxLevel));
  }
  return leaves;
}
} // namespace radiosity
