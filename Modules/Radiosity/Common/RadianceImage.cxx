#include "Radiosity/Common/RadianceImage.h"

#include "Radiosity/Common/Visibility.h"

#include <tbb/parallel_for.h>

#include <cmath>

namespace radiosity
{
RadianceImage RenderRadiance(
  const SolutionMesh& solution, const PinholeCamera& camera, int width, int height)
{
  constexpr double Pi = 3.14159265358979323846;
  Scene geometry;
  geometry.Points = solution.Points;
  geometry.Triangles = solution.Triangles;
  geometry.Materials.resize(solution.Triangles.size());
  geometry.ObjectIds.assign(solution.Triangles.size(), 0);
  const Visibility rays(geometry, Visibility::AllTriangles(geometry));

  RadianceImage image;
  image.Width = width;
  image.Height = height;
  image.RGB.assign(static_cast<std::size_t>(width) * height * 3, 0.f);
  const Vec3 forward = glm::normalize(camera.FocalPoint - camera.Position);
  const Vec3 right = glm::normalize(glm::cross(forward, camera.ViewUp));
  const Vec3 up = glm::cross(right, forward);
  const double halfHeight = std::tan(0.5 * camera.ViewAngleDegrees * Pi / 180.0);
  const double halfWidth = halfHeight * width / static_cast<double>(height);
  tbb::parallel_for(0, height,
    [&](int row)
    {
      for (int col = 0; col < width; ++col)
      {
        const double x = (2.0 * (col + 0.5) / width - 1.0) * halfWidth;
        const double y = (1.0 - 2.0 * (row + 0.5) / height) * halfHeight;
        const Vec3 dir = forward + x * right + y * up;
        double t, u, v;
        unsigned tri;
        if (!rays.Intersect(camera.Position, dir, t, tri, u, v))
        {
          continue;
        }
        const auto& idx = solution.Triangles[tri].V;
        // Embree's (u, v) weight vertices 1 and 2.
        const RGB b = (1.0 - u - v) * solution.PointRadiosity[idx[0]] +
          u * solution.PointRadiosity[idx[1]] + v * solution.PointRadiosity[idx[2]];
        float* px = &image.RGB[(static_cast<std::size_t>(row) * width + col) * 3];
        for (int c = 0; c < 3; ++c)
        {
          px[c] = static_cast<float>(b[c] / Pi);
        }
      }
    });
  return image;
}
} // namespace radiosity
