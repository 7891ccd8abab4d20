#include "Radiosity/Scenes/StandardScenes.h"

#include "Radiosity/Scenes/BunnyScene.h"
#include "Radiosity/Reference/PathTracer.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <algorithm>
#include <cstdio>

namespace radiosity
{
std::vector<Probe> CentroidSample(const Scene& scene)
{
  std::vector<Probe> probes;
  const std::size_t stride = std::max<std::size_t>(1, scene.Triangles.size() / 40);
  for (std::size_t t = 0; t < scene.Triangles.size(); t += stride)
  {
    probes.push_back(Probe{ scene.Centroid(t), scene.Normal(t) });
  }
  return probes;
}

AnalyticReference StandardReference(const Scene& scene, const std::vector<Probe>& probes,
  std::size_t pathsPerProbe, bool* analytic)
{
  AnalyticReference reference;
  std::string why;
  const bool closedForm = ComputeAnalyticReference(scene, probes, reference, why);
  if (analytic)
  {
    *analytic = closedForm;
  }
  if (closedForm)
  {
    return reference;
  }
  PathTracerOptions options;
  options.SamplesPerProbe = pathsPerProbe;
  const PathTracer tracer(scene, options);
  double worst = 0.0;
  reference.Irradiance.clear();
  for (const ReferenceValue& v : tracer.Irradiance(probes))
  {
    reference.Irradiance.push_back(v.Value);
    worst = std::max(worst, Luminance(v.StandardError) / std::max(Luminance(v.Value), 1e-300));
  }
  char kind[128];
  std::snprintf(kind, sizeof kind, "path traced, %zu paths per probe, largest relative SE %.1e",
    options.SamplesPerProbe, worst);
  reference.Kind = kind;
  return reference;
}

std::vector<StandardScene> StandardScenes(const std::string& bunnyJs)
{
  std::vector<StandardScene> scenes = {
    { "cornell", [] { return MakeCornellBox(); }, CentroidSample },
    { "shadow", [] { return MakeShadowScene(4, 10.0); },
      [](const Scene&)
      {
        std::vector<Probe> p;
        for (int i = 0; i <= 30; ++i)
        {
          p.push_back(Probe{ Vec3(-0.6 + 0.05 * i, 0.03, 0.0), Vec3(0, 0, 1) });
        }
        return p;
      } },
    { "contact", [] { return MakeContactScene(4, 0.0, 10.0); },
      [](const Scene&)
      {
        std::vector<Probe> p;
        for (double d : { 1e-3, 1e-2, 0.05, 0.1, 0.3, 1.0 })
        {
          p.push_back(Probe{ Vec3(d, 0.5, 0.0), Vec3(0, 0, 1) });
        }
        return p;
      } },
    { "sphere", [] { return MakeSphereInterior(1.0, 3, 0.9, RGB(10.0)); }, CentroidSample, false,
      false },
    { "closed-room-0.99", [] { return MakeClosedCube(1.0, 2, 0.99, 1.0); }, CentroidSample },
    { "closed-room-0.999", [] { return MakeClosedCube(1.0, 2, 0.999, 1.0); }, CentroidSample },
  };
  if (!bunnyJs.empty())
  {
    scenes.push_back({ "bunny-4k", [bunnyJs] { return MakeBunnyRoom(ReadNpmBunny(bunnyJs), 0); },
      CentroidSample, true, false });
    scenes.push_back({ "bunny-235k", [bunnyJs] { return MakeBunnyRoom(ReadNpmBunny(bunnyJs), 3); },
      CentroidSample, true, false, false });
  }
  return scenes;
}
} // namespace radiosity
