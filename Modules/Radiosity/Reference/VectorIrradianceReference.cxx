#include "Radiosity/Reference/VectorIrradianceReference.h"

#include "Radiosity/Common/FormFactor.h"
#include "Radiosity/Common/TriangleGather.h"
#include "Radiosity/Common/Visibility.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace radiosity
{
std::vector<std::array<Vec3, 3>> GatherVectorIrradiance(const Scene& occluders,
  const std::vector<RadiantTriangle>& sources, const std::vector<Vec3>& points,
  const std::vector<Vec3>& normals, const VectorGatherOptions& options)
{
  std::vector<std::array<Vec3, 3>> out(points.size(), { Vec3(0.0), Vec3(0.0), Vec3(0.0) });
  const Visibility rays(occluders, Visibility::AllTriangles(occluders));
  const TriangleGather gather(sources, &rays, options.MaxStrataPerEdge);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 8),
    [&](const tbb::blocked_range<std::size_t>& range) {
      TriangleGather::Scratch scratch;
      for (std::size_t i = range.begin(); i != range.end(); ++i)
      {
        out[i] = gather.At(points[i], normals[i], points[i] + rays.Offset() * normals[i], scratch);
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
    SplitTriangle(corners, m, parts);
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
