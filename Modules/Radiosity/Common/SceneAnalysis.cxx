#include "Radiosity/Common/SceneAnalysis.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>

namespace radiosity
{
SceneAnalysis AnalyzeScene(const Scene& scene)
{
  SceneAnalysis result;
  const std::size_t nt = scene.Triangles.size();
  result.Triangles = nt;
  result.Diagonal = scene.Diagonal();
  result.CanOcclude.assign(nt, 0);
  for (const Material& m : scene.Materials)
  {
    result.Emitters += MaxComponent(m.Emission) > 0 ? 1 : 0;
  }
  // Points actually used by triangles (a file may carry unreferenced ones).
  std::vector<unsigned char> used(scene.Points.size(), 0);
  for (const Triangle& t : scene.Triangles)
  {
    for (auto v : t.V)
    {
      used[v] = 1;
    }
  }
  std::vector<Vec3> pts;
  pts.reserve(scene.Points.size());
  for (std::size_t i = 0; i < scene.Points.size(); ++i)
  {
    if (used[i])
    {
      pts.push_back(scene.Points[i]);
    }
  }
  // A point counts as behind only beyond rounding of the scene size.
  const double tol = 1e-9 * result.Diagonal;
  std::atomic<std::size_t> occluders{ 0 };
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nt),
    [&](const tbb::blocked_range<std::size_t>& range)
    {
      std::size_t local = 0;
      for (std::size_t t = range.begin(); t != range.end(); ++t)
      {
        const Vec3 n = scene.Normal(t);
        const Vec3 o = scene.Vertex(t, 0);
        for (const Vec3& p : pts)
        {
          if (glm::dot(p - o, n) < -tol)
          {
            result.CanOcclude[t] = 1;
            ++local;
            break;
          }
        }
      }
      occluders += local;
    });
  result.Occluders = occluders;
  return result;
}
} // namespace radiosity
