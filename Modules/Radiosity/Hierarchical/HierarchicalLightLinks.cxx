// The light-to-node links of hierarchical radiosity (SPEC "Lights and sky";
// README "Lights and sky"): the lights' exact direct irradiance as a link of
// its own per node, refined like a BF link.
#include "Radiosity/Hierarchical/HierarchicalRadiosity.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>

namespace radiosity
{
double HierarchicalRadiosity::LinkLights()
{
  if (!this->Lights)
  {
    return 0.0;
  }
  ElementMesh& mesh = *this->Elements;
  std::vector<std::uint32_t> pending = this->Roots;
  std::vector<RGB> mean;
  std::vector<unsigned char> split;
  double power = 0.0;
  while (!pending.empty())
  {
    mean.assign(pending.size(), RGB(0.0));
    split.assign(pending.size(), 0);
    tbb::parallel_for(std::size_t(0), pending.size(), [&](std::size_t i) {
      const std::uint32_t e = pending[i];
      const Element& el = mesh[e];
      const TriangleCorners c = this->Corners(e);
      // Corners (from inside, as the discontinuity mesher samples them), edge
      // midpoints and the centre; the rays of those on the boundary from
      // inside too (DirectLighting::VisibilityPoint: a node's edge on a
      // wall saw the sky through the wall).
      const Vec3 points[7] = { c[0] + 1e-7 * (el.Centroid - c[0]), c[1] + 1e-7 * (el.Centroid - c[1]),
        c[2] + 1e-7 * (el.Centroid - c[2]), 0.5 * (c[0] + c[1]), 0.5 * (c[1] + c[2]),
        0.5 * (c[2] + c[0]), el.Centroid };
      RGB h[7];
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (int k = 0; k < 7; ++k)
      {
        h[k] = k < 6
          ? this->Lights->IrradianceSeenFrom(points[k], this->Lights->VisibilityPoint(points[k], el.Centroid), el.Normal)
          : this->Lights->Irradiance(points[k], el.Normal);
        lo = std::min(lo, MaxComponent(h[k]));
        hi = std::max(hi, MaxComponent(h[k]));
      }
      // Two rules exact for quadratics (the mean of the edge midpoints, and
      // 3/4 centre + 1/12 corners), averaged.
      const RGB midpoints = (h[3] + h[4] + h[5]) / 3.0;
      const RGB centroidRule = 0.75 * h[6] + (h[0] + h[1] + h[2]) / 12.0;
      mean[i] = 0.5 * (midpoints + centroidRule);
      split[i] = hi - lo > this->Epsilon && this->Splittable(e);
    });
    std::vector<std::uint32_t> next;
    for (std::size_t i = 0; i < pending.size(); ++i)
    {
      const std::uint32_t e = pending[i];
      if (split[i])
      {
        const std::uint32_t first = this->Children(e);
        for (std::uint32_t k = 0; k < 4; ++k)
        {
          next.push_back(first + k);
        }
        continue;
      }
      if (MaxComponent(mean[i]) > 0.0)
      {
        this->NodeDirect[e] = mean[i];
        ++this->LightLinks;
        power += Mean(mean[i]) * mesh[e].Area;
        // The first links are refined against B = E + rho H_direct.
        this->NodeRadiosity[e] = mesh.MaterialOf(e).Emission + mesh.MaterialOf(e).Reflectance * mean[i];
      }
    }
    pending.swap(next);
  }
  for (std::uint32_t r : this->Roots)
  {
    this->Pull(r);
  }
  return power;
}
} // namespace radiosity
