// The lights' shot of progressive refinement (SPEC "Lights and sky"; README
// "Lights and sky"): the lights and the sky shoot first, exactly, and the
// receivers split along shadow edges and spot cones.
#include "Radiosity/Progressive/ProgressiveRadiosity.h"

#include "Radiosity/Common/DirectLighting.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace radiosity
{
namespace
{
/// The element's mean irradiance from the lights and sky by the composite
/// degree-2 rule over its midpoint subdivision (3/4 of each quarter's
/// centroid, 1/12 of each of its corners): what it reflects and what the
/// gather reads. The element's own degree-2 rule (ElementSamples::Mean) on
/// a floor element that a window's sky patch crosses overestimated the light
/// entering the office by enough to put 10% on its ceiling.
RGB LightMean(const DirectLighting& lights, const ElementMesh& mesh, std::uint32_t e, const ElementSamples& d)
{
  const Element& r = mesh[e];
  const Vec3 c[3] = { mesh.Corner(e, 0), mesh.Corner(e, 1), mesh.Corner(e, 2) };
  const Vec3 m[3] = { 0.5 * (c[0] + c[1]), 0.5 * (c[1] + c[2]), 0.5 * (c[2] + c[0]) };
  RGB atMid[3];
  for (int k = 0; k < 3; ++k)
  {
    atMid[k] = lights.IrradianceSeenFrom(m[k], lights.VisibilityPoint(m[k], r.Centroid), r.Normal);
  }
  // Quarters: (c0, m0, m2), (m0, c1, m1), (m2, m1, c2), (m0, m1, m2).
  const RGB corners = d.Corner[0] + d.Corner[1] + d.Corner[2];
  const RGB mids = atMid[0] + atMid[1] + atMid[2];
  RGB centroids = lights.Irradiance((m[0] + m[1] + m[2]) / 3.0, r.Normal);
  centroids += lights.Irradiance((c[0] + m[0] + m[2]) / 3.0, r.Normal);
  centroids += lights.Irradiance((m[0] + c[1] + m[1]) / 3.0, r.Normal);
  centroids += lights.Irradiance((m[2] + m[1] + c[2]) / 3.0, r.Normal);
  // Each corner is in one quarter, each midpoint in three.
  return 0.25 * (0.75 * centroids + (corners + 3.0 * mids) / 12.0);
}
}

void ProgressiveRadiosity::LightCornerSamples(const std::vector<std::uint32_t>& elements)
{
  this->SampleLight.resize(this->Samples.size(), RGB(0.0));
  this->SampleLit.resize(this->Samples.size(), 0);
  std::vector<std::uint32_t> needed;
  for (std::uint32_t e : elements)
  {
    for (std::uint32_t id : this->CornerSamples[e])
    {
      if (!this->SampleLit[id])
      {
        this->SampleLit[id] = 1; // listed once
        needed.push_back(id);
      }
    }
  }
  const DirectLighting& lights = *this->Lights;
  tbb::parallel_for(std::size_t(0), needed.size(), [&](std::size_t i)
    {
      const SharedSample& sample = this->Samples[needed[i]];
      // On a seam the rays start inside the input triangle: from the
      // corner itself those aimed behind an adjacent wall would pass through it.
      this->SampleLight[needed[i]] = lights.IrradianceSeenFrom(sample.Point,
        lights.SharedVertexVisibility(this->SourceScene, sample.Source, sample.Point), sample.Normal);
    });
}

ElementSamples ProgressiveRadiosity::LightSamples(std::uint32_t e) const
{
  ElementSamples d;
  for (int k = 0; k < 3; ++k)
  {
    d.Corner[k] = this->SampleLight[this->CornerSamples[e][k]];
  }
  const Element& r = (*this->Elements)[e];
  d.Centre = this->Lights->Irradiance(r.Centroid, r.Normal);
  return d;
}

double ProgressiveRadiosity::ShootLights(SolverStatistics& stats)
{
  if (this->SourceScene.Lighting.Empty())
  {
    return 0.0;
  }
  ElementMesh& mesh = *this->Elements;
  this->Lights = std::make_unique<DirectLighting>(this->SourceScene, this->Settings.SkySamples);
  const DirectLighting& lights = *this->Lights;
  const double threshold = this->Settings.SubdivisionThreshold;
  std::vector<std::uint32_t> pending = mesh.Leaves();
  std::vector<ElementSamples> delta;
  std::vector<unsigned char> split;
  std::vector<RGB> power;
  double received = 0.0;
  while (!pending.empty())
  {
    // The corner samples are shared by the leaves meeting at a vertex: each is lit once.
    this->LightCornerSamples(pending);
    delta.assign(pending.size(), ElementSamples());
    split.assign(pending.size(), 0);
    power.assign(pending.size(), RGB(0.0));
    tbb::parallel_for(std::size_t(0), pending.size(), [&](std::size_t i)
      {
        const std::uint32_t e = pending[i];
        const Element& r = mesh[e];
        delta[i] = this->LightSamples(e);
        // The same gradient criterion as an element's shot (Shoot): a hard
        // shadow edge across the element moves its centre off the corners' mean.
        const ElementSamples& d = delta[i];
        const double departure = std::fabs(Luminance(d.Centre) -
          (Luminance(d.Corner[0]) + Luminance(d.Corner[1]) + Luminance(d.Corner[2])) / 3.0);
        // A spot's falloff ramp (between its cones) can pass between the
        // samples of an element that they all see dark: an element whose
        // angular extent seen from the spot meets the ramp is split as well.
        bool crossesCone = false;
        for (const Light& light : this->SourceScene.Lighting.Lights)
        {
          if (light.Type != LightType::Spot || crossesCone)
          {
            continue;
          }
          const Vec3 towards = r.Centroid - light.Position;
          const double distance = glm::length(towards);
          double radius = 0.0;
          for (int k = 0; k < 3; ++k)
          {
            radius = std::max(radius, glm::length(mesh.Corner(e, k) - r.Centroid));
          }
          if (!(distance > radius))
          {
            crossesCone = true;
            continue;
          }
          const double angle = std::acos(std::clamp(glm::dot(towards, light.Direction) / distance, -1.0, 1.0));
          const double spread = std::asin(radius / distance);
          crossesCone = angle - spread < light.OuterConeAngle && angle + spread > light.InnerConeAngle;
        }
        // Within the receivers' levels, the gradient criterion; below them (up
        // to LightSubdivisionLevels further) only where the element's own
        // 4-point rule misjudges the light it receives, which is what it
        // reflects: a sharp edge or a window's sky patch across it.
        power[i] = LightMean(lights, mesh, e, d);
        const bool gradient = departure > threshold * std::fabs(Luminance(d.Mean())) || crossesCone;
        const bool misjudged =
          std::fabs(Luminance(power[i]) - Luminance(d.Mean())) > threshold * std::fabs(Luminance(power[i]));
        const int level = r.Level, within = this->MaxLevel[r.Source];
        split[i] = (level < within && gradient) ||
          (level >= within && level < within + std::max(0, this->Settings.LightSubdivisionLevels) && misjudged);
      });
    std::vector<std::uint32_t> next;
    for (std::size_t i = 0; i < pending.size(); ++i)
    {
      const std::uint32_t e = pending[i];
      if (split[i])
      {
        this->SplitReceiver(e, stats, next);
        continue;
      }
      Element& r = mesh[e];
      const RGB rho = mesh.MaterialOf(e).Reflectance;
      r.Irradiance += delta[i];
      const RGB meanDelta = power[i];
      r.Unshot += rho * meanDelta;
      this->Absorbed += Mean((RGB(1.0) - rho) * meanDelta) * r.Area;
      received += Mean(meanDelta) * r.Area;
    }
    pending.swap(next);
    this->SampleFactor.resize(this->Samples.size());
    this->SampleStamp.resize(this->Samples.size(), 0);
  }
  return received; // the lights' rays are counted at the end of Solve
}
} // namespace radiosity
