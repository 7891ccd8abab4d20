#include "InterpolantSolution.h"

namespace radiosity
{
namespace cli
{
SolutionMesh InterpolantSolution(const DiscontinuityMesh& mesh, const Scene& scene, int n)
{
  SolutionMesh out;
  const std::size_t perTriangle = static_cast<std::size_t>((n + 1) * (n + 2) / 2);
  out.Points.reserve(mesh.Triangles.size() * perTriangle);
  out.Triangles.reserve(mesh.Triangles.size() * n * n);
  for (std::size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    const auto& v = mesh.Triangles[t].V;
    const Vec3 &p0 = mesh.Points[v[0]], &p1 = mesh.Points[v[1]], &p2 = mesh.Points[v[2]];
    const Material& material = scene.Materials[mesh.SourceTriangle[t]];
    const QuadraticInterpolant& q = mesh.Interpolants[t];
    const auto first = static_cast<std::uint32_t>(out.Points.size());
    // Sub-vertex (i, j): s = i / n, t = j / n. Positions are the weighted sum
    // of the corners, so that a point on a shared edge is computed from the
    // same two terms in both triangles and the ray caster sees no crack.
    for (int j = 0; j <= n; ++j)
    {
      for (int i = 0; i + j <= n; ++i)
      {
        const double k = n - i - j;
        out.Points.push_back((k * p0 + static_cast<double>(i) * p1 + static_cast<double>(j) * p2) /
          static_cast<double>(n));
        const RGB e = q.Evaluate(static_cast<double>(i) / n, static_cast<double>(j) / n);
        out.PointIrradiance.push_back(e);
        out.PointRadiosity.push_back(material.Emission + material.Reflectance * e);
      }
    }
    const auto index = [first, n](int i, int j)
    {
      // Rows j = 0..n hold n + 1 - j vertices each.
      return first + static_cast<std::uint32_t>(j * (n + 1) - j * (j - 1) / 2 + i);
    };
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i + j < n; ++i)
      {
        out.Triangles.push_back(Triangle{ { index(i, j), index(i + 1, j), index(i, j + 1) } });
        if (i + j + 1 < n)
        {
          out.Triangles.push_back(
            Triangle{ { index(i + 1, j), index(i + 1, j + 1), index(i, j + 1) } });
        }
      }
    }
  }
  return out;
}
}
}
