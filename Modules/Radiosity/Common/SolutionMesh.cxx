#include "Radiosity/Common/SolutionMesh.h"

#include <limits>

namespace radiosity
{
RGB InterpolateSamples(const ElementSamples& s, double u, double v, double w)
{
  const RGB linear = u * s.Corner[0] + v * s.Corner[1] + w * s.Corner[2];
  const RGB bubble = s.Centre - (s.Corner[0] + s.Corner[1] + s.Corner[2]) / 3.0;
  return linear + 27.0 * u * v * w * bubble;
}

SolutionMesh ExtractSolution(const ElementMesh& mesh)
{
  SolutionMesh out;
  const Scene& scene = mesh.GetScene();
  const auto leaves = mesh.Leaves();
  const std::uint32_t unused = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> remap(mesh.Points().size(), unused);
  std::vector<double> weight;
  for (std::uint32_t e : leaves)
  {
    const Element& el = mesh[e];
    Triangle tri;
    for (int k = 0; k < 3; ++k)
    {
      std::uint32_t& id = remap[el.V[k]];
      if (id == unused)
      {
        id = static_cast<std::uint32_t>(out.Points.size());
        out.Points.push_back(mesh.Points()[el.V[k]]);
        out.PointIrradiance.emplace_back(0.0);
        out.PointRadiosity.emplace_back(0.0);
        weight.push_back(0.0);
      }
      tri.V[k] = id;
    }
    const Material& m = scene.Materials[el.Source];
    const RGB h = el.Irradiance.Mean();
    out.Triangles.push_back(tri);
    out.CellIrradiance.push_back(h);
    out.CellRadiosity.push_back(m.Emission + m.Reflectance * h);
    out.ElementId.push_back(e);
    out.Level.push_back(el.Level);
    out.SourceTriangle.push_back(el.Source);
    out.Samples.push_back(el.Irradiance);
    out.Normals.push_back(el.Normal);
    for (int k = 0; k < 3; ++k)
    {
      const RGB hk = el.Irradiance.Corner[k];
      out.PointIrradiance[tri.V[k]] += el.Area * hk;
      out.PointRadiosity[tri.V[k]] += el.Area * (m.Emission + m.Reflectance * hk);
      weight[tri.V[k]] += el.Area;
    }
  }
  for (std::size_t p = 0; p < out.Points.size(); ++p)
  {
    if (weight[p] > 0)
    {
      out.PointIrradiance[p] /= weight[p];
      out.PointRadiosity[p] /= weight[p];
    }
  }
  return out;
}
double AbsorbedPower(const SolutionMesh& solution, const Scene& scene)
{
  double absorbed = 0.0;
  for (std::size_t t = 0; t < solution.Triangles.size() && t < solution.CellIrradiance.size(); ++t)
  {
    const std::uint32_t source = t < solution.SourceTriangle.size() ? solution.SourceTriangle[t] : 0;
    if (source >= scene.Materials.size())
    {
      continue;
    }
    const Triangle& tri = solution.Triangles[t];
    const double area = 0.5 *
      glm::length(glm::cross(solution.Points[tri.V[1]] - solution.Points[tri.V[0]],
        solution.Points[tri.V[2]] - solution.Points[tri.V[0]]));
    absorbed += Mean((RGB(1.0) - scene.Materials[source].Reflectance) * solution.CellIrradiance[t]) * area;
  }
  return absorbed;
}
} // namespace radiosity
