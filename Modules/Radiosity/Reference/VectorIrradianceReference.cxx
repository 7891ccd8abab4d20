#include "Radiosity/Reference/VectorIrradianceReference.h"

#include "Radiosity/Common/FormFactor.h"
#include "Radiosity/Common/Visibility.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace radiosity
{
namespace
{
// The m x m congruent parts of triangle (a, b, c), all oriented as it is:
// the grid of barycentric steps 1/m, "upward" parts then "downward" ones.
void VecRefSplitTriangle(const std::array<Vec3, 3>& t, int m, std::vector<std::array<Vec3, 3>>& parts)
{
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

// The four probe points of a source triangle: its centroid and three points
// just inside its corners (barycentric 0.8, 0.1, 0.1).
void VecRefProbePoints(const std::array<Vec3, 3>& t, Vec3* out)
{
  out[0] = (t[0] + t[1] + t[2]) / 3.0;
  for (int k = 0; k < 3; ++k)
  {
    out[k + 1] = 0.8 * t[k] + 0.1 * t[(k + 1) % 3] + 0.1 * t[(k + 2) % 3];
  }
}
}

std::vector<std::array<Vec3, 3>> GatherVectorIrradiance(const Scene& occluders,
  const std::vector<RadiantTriangle>& sources, const std::vector<Vec3>& points,
  const std::vector<Vec3>& normals, const VectorGatherOptions& options)
{
  std::vector<std::array<Vec3, 3>> out(points.size(), { Vec3(0.0), Vec3(0.0), Vec3(0.0) });
  const Visibility rays(occluders, Visibility::AllTriangles(occluders));
  const int m = std::max(1, options.MaxStrataPerEdge);
  std::vector<Vec3> areaVectors(sources.size());
  for (std::size_t s = 0; s < sources.size(); ++s)
  {
    const auto& c = sources[s].Corners;
    areaVectors[s] = glm::cross(c[1] - c[0], c[2] - c[0]);
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 8),
    [&](const tbb::blocked_range<std::size_t>& range) {
      std::vector<std::uint32_t> facing;
      std::vector<Vec3> vectors, from, to;
      std::vector<unsigned char> visible;
      std::vector<std::array<Vec3, 3>> parts;
      for (std::size_t i = range.begin(); i != range.end(); ++i)
      {
        const Vec3& p = points[i];
        const Vec3& n = normals[i];
        // The sources in front of which p lies and that reach above its
        // horizon, with their exact (horizon-clipped) vector form factors.
        facing.clear();
        vectors.clear();
        for (std::size_t s = 0; s < sources.size(); ++s)
        {
          const auto& c = sources[s].Corners;
          // Behind the source, or in its plane (a neighbour on the same
          // flat face, seen edge on: nothing arrives, and the contour
          // integral of a polygon seen edge on is rounding noise).
          const double twiceArea = glm::length(areaVectors[s]);
          if (glm::dot(p - c[0], areaVectors[s]) <= 1e-9 * twiceArea * std::sqrt(twiceArea))
          {
            continue;
          }
          const Vec3 f = PointToPolygonVectorFormFactor(p, c.data(), 3, &n);
          if (glm::dot(f, f) > 0.0)
          {
            facing.push_back(static_cast<std::uint32_t>(s));
            vectors.push_back(f);
          }
        }
        std::array<Vec3, 3>& e = out[i];
        if (rays.Empty())
        {
          for (std::size_t k = 0; k < facing.size(); ++k)
          {
            for (int ch = 0; ch < 3; ++ch)
            {
              e[ch] += sources[facing[k]].Radiosity[ch] * vectors[k];
            }
          }
          continue;
        }
        const Vec3 origin = p + rays.Offset() * n;
        from.assign(4 * facing.size(), origin);
        to.resize(4 * facing.size());
        visible.resize(4 * facing.size());
        for (std::size_t k = 0; k < facing.size(); ++k)
        {
          VecRefProbePoints(sources[facing[k]].Corners, &to[4 * k]);
        }
        rays.TestSegments(from.data(), to.data(), to.size(), visible.data());
        for (std::size_t k = 0; k < facing.size(); ++k)
        {
          const RadiantTriangle& source = sources[facing[k]];
          const int seen = visible[4 * k] + visible[4 * k + 1] + visible[4 * k + 2] + visible[4 * k + 3];
          Vec3 f(0.0);
          if (seen == 4)
          {
            f = vectors[k];
          }
          else if (seen > 0)
          {
            // Partly hidden: the strata, each by its own ray.
            VecRefSplitTriangle(source.Corners, m, parts);
            std::vector<Vec3> partFrom(parts.size(), origin), partTo(parts.size());
            std::vector<unsigned char> partVisible(parts.size());
            for (std::size_t q = 0; q < parts.size(); ++q)
            {
              partTo[q] = (parts[q][0] + parts[q][1] + parts[q][2]) / 3.0;
            }
            rays.TestSegments(partFrom.data(), partTo.data(), parts.size(), partVisible.data());
            for (std::size_t q = 0; q < parts.size(); ++q)
            {
              if (partVisible[q])
              {
                f += PointToPolygonVectorFormFactor(p, parts[q].data(), 3, &n);
              }
            }
          }
          for (int ch = 0; ch < 3; ++ch)
          {
            e[ch] += source.Radiosity[ch] * f;
          }
        }
      }
    });
  return out;
}

std::vector<RadiantTriangle> RadiantTrianglesOf(
  const Scene& scene, const SolutionMesh& solution, int strataPerEdge)
{
  const int m = std::max(1, strataPerEdge);
  std::vector<RadiantTriangle> out;
  std::vector<std::array<Vec3, 3>> parts;
  for (std::size_t e = 0; e < solution.Triangles.size(); ++e)
  {
    const Material& material = scene.Materials[solution.SourceTriangle[e]];
    std::array<Vec3, 3> corners;
    for (int k = 0; k < 3; ++k)
    {
      corners[k] = solution.Points[solution.Triangles[e].V[k]];
    }
    const Vec3 u = corners[1] - corners[0], v = corners[2] - corners[0];
    const double uv = glm::dot(u, v), uu = glm::dot(u, u), vv = glm::dot(v, v);
    const double det = uu * vv - uv * uv;
    VecRefSplitTriangle(corners, m, parts);
    for (const auto& part : parts)
    {
      // The part's centroid in the element's barycentric coordinates.
      const Vec3 d = (part[0] + part[1] + part[2]) / 3.0 - corners[0];
      const double du = glm::dot(d, u), dv = glm::dot(d, v);
      const double b1 = det > 0.0 ? (vv * du - uv * dv) / det : 1.0 / 3.0;
      const double b2 = det > 0.0 ? (uu * dv - uv * du) / det : 1.0 / 3.0;
      // Irradiance is not negative: the quadratic through a halved
      // triangle's samples can dip below zero between them.
      const RGB irradiance = NonNegative(InterpolateSamples(solution.Samples[e], 1.0 - b1 - b2, b1, b2));
      const RGB b = material.Emission + material.Reflectance * irradiance;
      if (b[0] > 0.0 || b[1] > 0.0 || b[2] > 0.0)
      {
        out.push_back({ part, b });
      }
    }
  }
  return out;
}
} // namespace radiosity
