// GATHER of Lehtinen et al. 2007, section 6.3, as weights on the senders'
// coefficients: the one place that casts a receiver's hemisphere rays and
// picks the sender level, shared by the bounce (MeshlessRadiosity::Gather:
// the weights times the previous bounce's coefficients) and the precomputed
// transfer of section 6.5 (MeshlessTransfer: the weights kept as a row of
// the one-bounce operator), so that the two are the same linear map.
//
// A fixed Hammersley pattern of cosine-distributed rays (Malley's method),
// rotated about the normal by a pseudo-random angle per receiver; at each
// hit on a front face the sender's normalised basis functions (eq. 8) from
// the coarsest level down to the first whose supports subtend, on average,
// less than epsilon_Omega seen from the receiver (after Bekaert et al.
// 1998), times the reflectance there, over the number of rays: the
// cosine-weighted estimator of E = int B/pi cos dw.
#ifndef Radiosity_MeshlessGather_h
#define Radiosity_MeshlessGather_h

#include "Radiosity/Common/Scene.h"
#include "Radiosity/Common/Visibility.h"
#include "Radiosity/Meshless/MeshlessRadiosity.h"
#include "Radiosity/Meshless/ShepardField.h"

#include <cmath>
#include <utility>
#include <vector>

namespace radiosity
{
namespace meshless_detail
{
inline double RadicalInverse2(std::uint32_t i)
{
  i = (i << 16u) | (i >> 16u);
  i = ((i & 0x55555555u) << 1u) | ((i & 0xAAAAAAAAu) >> 1u);
  i = ((i & 0x33333333u) << 2u) | ((i & 0xCCCCCCCCu) >> 2u);
  i = ((i & 0x0F0F0F0Fu) << 4u) | ((i & 0xF0F0F0F0u) >> 4u);
  i = ((i & 0x00FF00FFu) << 8u) | ((i & 0xFF00FF00u) >> 8u);
  return static_cast<double>(i) * 2.3283064365386963e-10;
}

/// A per-receiver pseudo-random rotation in [0, 1): splitmix64 of (seed, index).
inline double Rotation(std::uint64_t seed, std::uint64_t index)
{
  std::uint64_t z = seed * 0x9E3779B97F4A7C15ull + index + 0x632BE59BD9B4E019ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * (1.0 / 9007199254740992.0);
}
} // namespace meshless_detail

/**
 * Calls add(j, weight, reflectance) for every sender basis function j the
 * gather at `receiver` reaches: the receiver's irradiance from a field of
 * coefficients alpha is sum(weight * reflectance * alpha_j). `basis` gives
 * the basis functions (its coefficients are not read).
 */
template <typename Add>
void GatherWeights(const Scene& scene, const PointHierarchy& points, const ShepardField& basis,
  const Visibility& rays, const MeshlessOptions& options, std::uint32_t receiver, Add&& add)
{
  const MeshlessPoint& p = points.Points()[receiver];
  const Vec3 origin = p.Position + rays.Offset() * p.Normal;
  const Vec3 a = std::fabs(p.Normal.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  const Vec3 tangent = glm::normalize(glm::cross(a, p.Normal));
  const Vec3 bitangent = glm::cross(p.Normal, tangent);
  const double turn = 2.0 * Pi * meshless_detail::Rotation(options.Seed, receiver);
  const int n = std::max(1, options.GatherRays);
  const double perRay = 1.0 / static_cast<double>(n);
  const int levels = points.NumberOfLevels();
  thread_local std::vector<std::pair<std::uint32_t, double>> found;
  for (int i = 0; i < n; ++i)
  {
    const double u1 = (i + 0.5) / n, u2 = meshless_detail::RadicalInverse2(static_cast<std::uint32_t>(i));
    const double r = std::sqrt(u1), phi = 2.0 * Pi * u2 + turn;
    const Vec3 dir = r * std::cos(phi) * tangent + r * std::sin(phi) * bitangent +
      std::sqrt(std::max(0.0, 1.0 - u1)) * p.Normal;
    double t = 0, hu = 0, hv = 0;
    unsigned tri = 0;
    if (!rays.Intersect(origin, dir, t, tri, hu, hv))
    {
      continue; // escapes
    }
    const Vec3 nh = scene.Normal(tri);
    if (glm::dot(nh, dir) >= 0)
    {
      continue; // the back of a one-sided surface sends nothing
    }
    const Vec3 x = origin + t * dir;
    const auto group = static_cast<std::uint32_t>(scene.ObjectIds[tri]);
    const RGB& reflectance = scene.Materials[tri].Reflectance;
    // Sender level: down to the first level whose supports look small.
    for (int level = 0; level < levels; ++level)
    {
      found.clear();
      basis.Basis(level, group, x, nh, found);
      if (found.empty())
      {
        continue;
      }
      double r2 = 0.0;
      for (const auto& [j, w] : found)
      {
        add(j, w * perRay, reflectance);
        const double rj = points.Points()[j].Radius;
        r2 += rj * rj;
      }
      const double solidAngle = Pi * r2 / static_cast<double>(found.size()) / std::max(t * t, 1e-300);
      if (solidAngle < options.SolidAngleThreshold)
      {
        break;
      }
    }
  }
}
} // namespace radiosity

#endif
