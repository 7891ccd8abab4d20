#include "Radiosity/Common/TriangleGather.h"

#include "Radiosity/Common/FormFactor.h"
#include "Radiosity/Common/Visibility.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace radiosity
{
namespace
{
// The four probe points of a source triangle: its centroid and three points
// just inside its corners (barycentric 0.998, 0.001, 0.001). A shadow edge
// across the source (a half-plane's) leaves at least one corner on each
// side, so the rays disagree wherever such an edge crosses it; at 0.8,
// 0.1, 0.1 a shadow over a corner's tenth went unseen, 10% of the exact
// penumbra's peak.
void ProbePoints(const std::array<Vec3, 3>& t, Vec3* out)
{
  out[0] = (t[0] + t[1] + t[2]) / 3.0;
  for (int k = 0; k < 3; ++k)
  {
    out[k + 1] = 0.998 * t[k] + 0.001 * t[(k + 1) % 3] + 0.001 * t[(k + 2) % 3];
  }
}
}

void SplitTriangle(const std::array<Vec3, 3>& t, int m, std::vector<std::array<Vec3, 3>>& parts)
{
  // The grid of barycentric steps 1/m, "upward" parts then "downward" ones.
  parts.clear();
  const Vec3 du = (t[1] - t[0]) / static_cast<double>(m), dv = (t[2] - t[0]) / static_cast<double>(m);
  auto at = [&](int i, int j) { return t[0] + static_cast<double>(i) * du + static_cast<double>(j) * dv; };
  for (int i = 0; i < m; ++i)
  {
    for (int j = 0; i + j < m; ++j)
    {
      parts.push_back({ at(i, j), at(i + 1, j), at(i, j + 1) });
      if (i + j + 2 <= m)
      {
        parts.push_back({ at(i + 1, j), at(i + 1, j + 1), at(i, j + 1) });
      }
    }
  }
}

TriangleGather::TriangleGather(std::vector<RadiantTriangle> sources, const Visibility* rays, int strataPerEdge)
  : Sources(std::move(sources))
  , Rays(rays && !rays->Empty() ? rays : nullptr)
  , Strata(std::max(1, strataPerEdge))
{
  this->AreaVectors.reserve(this->Sources.size());
  for (const RadiantTriangle& s : this->Sources)
  {
    const auto& c = s.Corners;
    this->AreaVectors.push_back(glm::cross(c[1] - c[0], c[2] - c[0]));
  }
}

std::array<Vec3, 3> TriangleGather::At(
  const Vec3& p, const Vec3& n, const Vec3& rayOrigin, Scratch& s) const
{
  std::array<Vec3, 3> e{ Vec3(0.0), Vec3(0.0), Vec3(0.0) };
  // The sources in front of which p lies and that reach above its
  // horizon, with their exact (horizon-clipped) vector form factors.
  s.Facing.clear();
  s.Vectors.clear();
  for (std::size_t k = 0; k < this->Sources.size(); ++k)
  {
    const auto& c = this->Sources[k].Corners;
    // Behind the source, or in its plane (a neighbour on the same flat
    // face, seen edge on: nothing arrives, and the contour integral of a
    // polygon seen edge on is rounding noise).
    const double twiceArea = glm::length(this->AreaVectors[k]);
    if (glm::dot(p - c[0], this->AreaVectors[k]) <= 1e-9 * twiceArea * std::sqrt(twiceArea))
    {
      continue;
    }
    const Vec3 f = PointToPolygonVectorFormFactor(p, c.data(), 3, &n);
    if (glm::dot(f, f) > 0.0)
    {
      s.Facing.push_back(static_cast<std::uint32_t>(k));
      s.Vectors.push_back(f);
    }
  }
  if (!this->Rays)
  {
    for (std::size_t k = 0; k < s.Facing.size(); ++k)
    {
      for (int ch = 0; ch < 3; ++ch)
      {
        e[ch] += this->Sources[s.Facing[k]].Radiosity[ch] * s.Vectors[k];
      }
    }
    return e;
  }
  s.From.assign(4 * s.Facing.size(), rayOrigin);
  s.To.resize(4 * s.Facing.size());
  s.Visible.resize(4 * s.Facing.size());
  for (std::size_t k = 0; k < s.Facing.size(); ++k)
  {
    ProbePoints(this->Sources[s.Facing[k]].Corners, &s.To[4 * k]);
  }
  this->Rays->TestSegments(s.From.data(), s.To.data(), s.To.size(), s.Visible.data());
  for (std::size_t k = 0; k < s.Facing.size(); ++k)
  {
    const RadiantTriangle& source = this->Sources[s.Facing[k]];
    const int seen = s.Visible[4 * k] + s.Visible[4 * k + 1] + s.Visible[4 * k + 2] + s.Visible[4 * k + 3];
    Vec3 f(0.0);
    if (seen == 4)
    {
      f = s.Vectors[k];
    }
    else if (seen > 0)
    {
      // Partly hidden: the strata, each by its own ray (after the four
      // above, so the scratch's rays are reused).
      SplitTriangle(source.Corners, this->Strata, s.Parts);
      s.From.assign(s.Parts.size(), rayOrigin);
      s.To.resize(s.Parts.size());
      s.PartVisible.resize(s.Parts.size());
      for (std::size_t q = 0; q < s.Parts.size(); ++q)
      {
        s.To[q] = (s.Parts[q][0] + s.Parts[q][1] + s.Parts[q][2]) / 3.0;
      }
      this->Rays->TestSegments(s.From.data(), s.To.data(), s.Parts.size(), s.PartVisible.data());
      for (std::size_t q = 0; q < s.Parts.size(); ++q)
      {
        if (s.PartVisible[q])
        {
          f += PointToPolygonVectorFormFactor(p, s.Parts[q].data(), 3, &n);
        }
      }
    }
    for (int ch = 0; ch < 3; ++ch)
    {
      e[ch] += source.Radiosity[ch] * f;
    }
  }
  return e;
}
} // namespace radiosity
