// Clustered hierarchical radiosity's first-order vector irradiance (the
// detail shared by ClusterLinksTransfer.cxx and ClusterLinksCurvedLeaves.cxx;
// ClusterLinks.h has the method): the expansion a cluster passes down, and a
// link's share on one normal.
#ifndef Radiosity_ClusterExpansion_h
#define Radiosity_ClusterExpansion_h

#include "Radiosity/Common/Types.h"

#include <glm/vec3.hpp>

namespace radiosity
{
namespace cluster_detail
{
/// Irradiance about a centre to first order: per colour channel, the vector
/// E (x, y, z) and its gradient G[3 k + j] = dE_j / dx_k.
struct Expansion
{
  Vec3 Centre{ 0.0 };
  RGB E[3] = { RGB(0.0), RGB(0.0), RGB(0.0) };
  RGB G[9] = { RGB(0.0), RGB(0.0), RGB(0.0), RGB(0.0), RGB(0.0), RGB(0.0), RGB(0.0), RGB(0.0), RGB(0.0) };

  /// The vector at x (first order).
  void At(const Vec3& x, RGB (&out)[3]) const
  {
    const Vec3 d = x - this->Centre;
    for (int j = 0; j < 3; ++j)
    {
      out[j] = this->E[j] + d.x * this->G[j] + d.y * this->G[3 + j] + d.z * this->G[6 + j];
    }
  }
  /// Adds a link's vector factor `factor` and gradient `gradient` (about this
  /// centre) times the source's radiosity `b`.
  void Add(const Vec3& factor, const float (&gradient)[9], const RGB& b)
  {
    for (int j = 0; j < 3; ++j)
    {
      this->E[j] += factor[j] * b;
    }
    for (int j = 0; j < 9; ++j)
    {
      this->G[j] += double(gradient[j]) * b;
    }
  }
};

/// A link's vector factor moved by d from its centre (first order).
inline Vec3 FactorAt(const glm::vec3& factor, const float (&gradient)[9], const Vec3& d)
{
  Vec3 e;
  for (int j = 0; j < 3; ++j)
  {
    e[j] = factor[j] + d.x * gradient[j] + d.y * gradient[3 + j] + d.z * gradient[6 + j];
  }
  return e;
}
} // namespace cluster_detail
} // namespace radiosity

#endif
