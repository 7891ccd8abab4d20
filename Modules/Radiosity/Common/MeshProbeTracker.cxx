#include "Radiosity/Common/MeshProbeTracker.h"

#include "Radiosity/Common/SolutionMesh.h"

#include <cmath>
#include <limits>

namespace radiosity
{
bool ProjectOnTriangle(
  const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, double& u, double& v, double& w)
{
  const Vec3 e0 = b - a, e1 = c - a, d = p - a;
  const double d00 = glm::dot(e0, e0), d01 = glm::dot(e0, e1), d11 = glm::dot(e1, e1);
  const double d20 = glm::dot(d, e0), d21 = glm::dot(d, e1);
  const double den = d00 * d11 - d01 * d01;
  if (!(den > 0))
  {
    return false;
  }
  v = (d11 * d20 - d01 * d21) / den;
  w = (d00 * d21 - d01 * d20) / den;
  u = 1.0 - v - w;
  return true;
}

MeshProbeTracker::MeshProbeTracker(
  const ElementMesh& mesh, const std::vector<Probe>& probes, double tolerance)
  : Mesh(mesh)
{
  constexpr double edge = 1e-6;
  const auto leaves = mesh.Leaves();
  for (const Probe& probe : probes)
  {
    Location loc;
    loc.Point = probe.Position;
    const Vec3 n = glm::normalize(probe.Normal);
    double best = std::numeric_limits<double>::infinity();
    for (std::uint32_t e : leaves)
    {
      const Element& el = mesh[e];
      if (glm::dot(el.Normal, n) < 0.9)
      {
        continue;
      }
      const double dist = std::fabs(glm::dot(probe.Position - mesh.Corner(e, 0), el.Normal));
      double u, v, w;
      if (dist <= tolerance && dist < best &&
        ProjectOnTriangle(probe.Position, mesh.Corner(e, 0), mesh.Corner(e, 1), mesh.Corner(e, 2),
          u, v, w) &&
        u >= -edge && v >= -edge && w >= -edge)
      {
        best = dist;
        loc.Element = e;
      }
    }
    this->Locations.push_back(loc);
  }
}

std::size_t MeshProbeTracker::Tracked() const
{
  std::size_t n = 0;
  for (const Location& l : this->Locations)
  {
    n += l.Element >= 0 ? 1 : 0;
  }
  return n;
}

std::vector<RGB> MeshProbeTracker::Evaluate()
{
  std::vector<RGB> values;
  values.reserve(this->Locations.size());
  for (Location& loc : this->Locations)
  {
    if (loc.Element < 0)
    {
      values.emplace_back(std::numeric_limits<double>::quiet_NaN());
      continue;
    }
    // Descend to the leaf that now contains the point: the four children
    // partition their parent, so the child with the largest smallest
    // barycentric coordinate holds it.
    auto e = static_cast<std::uint32_t>(loc.Element);
    while (!this->Mesh[e].IsLeaf())
    {
      const auto first = static_cast<std::uint32_t>(this->Mesh[e].FirstChild);
      std::uint32_t bestChild = first;
      double bestMin = -std::numeric_limits<double>::infinity();
      for (std::uint32_t c = first; c < first + 4; ++c)
      {
        double u, v, w;
        ProjectOnTriangle(loc.Point, this->Mesh.Corner(c, 0), this->Mesh.Corner(c, 1),
          this->Mesh.Corner(c, 2), u, v, w);
        const double m = std::min(u, std::min(v, w));
        if (m > bestMin)
        {
          bestMin = m;
          bestChild = c;
        }
      }
      e = bestChild;
    }
    loc.Element = e;
    double u, v, w;
    ProjectOnTriangle(loc.Point, this->Mesh.Corner(e, 0), this->Mesh.Corner(e, 1),
      this->Mesh.Corner(e, 2), u, v, w);
    values.push_back(InterpolateSamples(this->Mesh[e].Irradiance, u, v, w));
  }
  return values;
}
} // namespace radiosity
