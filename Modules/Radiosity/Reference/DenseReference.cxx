#include "Radiosity/Reference/DenseReference.h"

#include "Radiosity/Common/ElementMesh.h"
#include "Radiosity/Common/FormFactor.h"
#include "Radiosity/Common/SceneAnalysis.h"
#include "Radiosity/Progressive/ShooterSamples.h"
#include "Radiosity/Common/Visibility.h"

#include <Eigen/Dense>
#include <tbb/parallel_for.h>

#include <stdexcept>

namespace radiosity
{
namespace
{
/// Form factor times visible fraction from (p, n) to element j.
double VisibleFactor(const DenseSolution& s, std::size_t j, const Vec3& p, const Vec3& n,
  const Visibility& rays)
{
  const Vec3* poly = &s.Corners[3 * j];
  const double f = PointToPolygonFormFactor(p, n, poly, 3);
  if (f <= 0.0 || rays.Empty())
  {
    return f;
  }
  const std::vector<Vec3> targets = ShooterSamplePoints(poly[0], poly[1], poly[2], 4);
  const Vec3 origin = p + rays.Offset() * n;
  std::vector<Vec3> from(targets.size(), origin);
  std::vector<unsigned char> visible(targets.size());
  rays.TestSegments(from.data(), targets.data(), targets.size(), visible.data());
  int seen = 0;
  for (unsigned char v : visible)
  {
    seen += v;
  }
  return f * seen / static_cast<double>(targets.size());
}
}

DenseSolution SolveDense(const Scene& scene, const DenseReferenceOptions& options)
{
  const SceneAnalysis analysis = AnalyzeScene(scene);
  const double edge = options.ElementSize * analysis.Diagonal;
  const ElementMesh mesh(scene, edge, edge, 16);
  DenseSolution s;
  for (std::uint32_t e : mesh.Leaves())
  {
    s.Centroids.push_back(mesh[e].Centroid);
    s.Normals.push_back(mesh[e].Normal);
    for (int k = 0; k < 3; ++k)
    {
      s.Corners.push_back(mesh.Corner(e, k));
    }
    s.Source.push_back(mesh[e].Source);
  }
  const std::size_t n = s.Centroids.size();
  if (n > options.MaxElements)
  {
    throw std::invalid_argument("dense reference: " + std::to_string(n) +
      " elements exceed the limit of " + std::to_string(options.MaxElements));
  }
  const Visibility rays(scene, analysis.CanOcclude);
  Eigen::MatrixXd F(n, n);
  tbb::parallel_for(std::size_t(0), n,
    [&](std::size_t i)
    {
      for (std::size_t j = 0; j < n; ++j)
      {
        F(i, j) = i == j ? 0.0 : VisibleFactor(s, j, s.Centroids[i], s.Normals[i], rays);
      }
    });
  s.Radiosity.assign(n, RGB(0.0));
  s.Irradiance.assign(n, RGB(0.0));
  for (int c = 0; c < 3; ++c)
  {
    Eigen::MatrixXd A = -F;
    Eigen::VectorXd b(n);
    for (std::size_t i = 0; i < n; ++i)
    {
      const Material& m = scene.Materials[s.Source[i]];
      A.row(i) *= m.Reflectance[c];
      A(i, i) += 1.0;
      b(i) = m.Emission[c];
    }
    const Eigen::VectorXd B = A.partialPivLu().solve(b);
    const Eigen::VectorXd H = F * B;
    for (std::size_t i = 0; i < n; ++i)
    {
      s.Radiosity[i][c] = B(i);
      s.Irradiance[i][c] = H(i);
    }
  }
  return s;
}

std::vector<RGB> DenseIrradianceAt(
  const Scene& scene, const DenseSolution& solution, const std::vector<Probe>& probes)
{
  const SceneAnalysis analysis = AnalyzeScene(scene);
  const Visibility rays(scene, analysis.CanOcclude);
  std::vector<RGB> out(probes.size(), RGB(0.0));
  tbb::parallel_for(std::size_t(0), probes.size(),
    [&](std::size_t p)
    {
      const Vec3 n = glm::normalize(probes[p].Normal);
      // Gathered from just off the surface, so a probe on an element does not
      // see its own plane edge-on.
      const Vec3 x = probes[p].Position + 1e-9 * analysis.Diagonal * n;
      for (std::size_t j = 0; j < solution.Centroids.size(); ++j)
      {
        out[p] += VisibleFactor(solution, j, x, n, rays) * solution.Radiosity[j];
      }
    });
  return out;
}
} // namespace radiosity
