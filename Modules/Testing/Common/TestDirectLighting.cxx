// DirectLighting (Common/DirectLighting.h) against the exact answers of the
// analytic light cases (Scenes/LightScenes.h; ComputeAnalyticReference,
// checked by hand-derived forms in Reference/TestAnalyticLights.cxx):
// punctual lights exact (one shadow ray), the sky within its stratified
// quadrature's error, measured here.
#include "Radiosity/Common/DirectLighting.h"
#include "Radiosity/Reference/AnalyticLights.h"
#include "Radiosity/Reference/AnalyticReference.h"
#include "Radiosity/Scenes/LightScenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace radiosity;

namespace
{
/// The largest |DirectLighting - exact| / peak over the case's probes, with
/// the exact direct light (for the sphere: its direct part, I cos / d^2).
double WorstOfPeak(const LightCase& c, int skySamples)
{
  std::vector<RGB> exact;
  if (c.Name == "point light in a sphere")
  {
    for (const Probe& p : c.Probes)
    {
      exact.push_back(analyticlights::PunctualIrradiance(c.Geometry.Lighting.Lights[0], p.Position, p.Normal));
    }
  }
  else
  {
    AnalyticReference ref;
    std::string why;
    EXPECT_TRUE(ComputeAnalyticReference(c.Geometry, c.Probes, ref, why)) << c.Name << ": " << why;
    exact = ref.Irradiance;
  }
  const DirectLighting direct(c.Geometry, skySamples);
  double peak = 0.0, worst = 0.0;
  std::size_t worstProbe = 0;
  for (const RGB& e : exact)
  {
    peak = std::max(peak, MaxComponent(e));
  }
  for (std::size_t i = 0; i < c.Probes.size(); ++i)
  {
    const RGB h = direct.Irradiance(c.Probes[i].Position, glm::normalize(c.Probes[i].Normal));
    for (int k = 0; k < 3; ++k)
    {
      const double e = std::fabs(h[k] - exact[i][k]) / peak;
      worstProbe = e > worst ? i : worstProbe;
      worst = std::max(worst, e);
    }
    if (exact[i].r == 0.0)
    {
      EXPECT_EQ(h.r, 0.0) << c.Name << " probe " << i << ": an exact zero (shadow, outside the cone)";
    }
  }
  if (worst > 0.0)
  {
    const Vec3& x = c.Probes[worstProbe].Position;
    std::cout << "  " << c.Name << ": worst at probe " << worstProbe << " (" << x.x << ", " << x.y
              << ", " << x.z << ")\n";
  }
  return worst;
}
}

TEST(DirectLighting, PunctualLightsAreExact)
{
  // Measured (every scale): at most 1.5e-15 of the peak (the spot; the others
  // below 1.5e-16: rounding of the closed form; the shadow rays decide the
  // plate's shadow as the exact polygon does at every probe).
  for (double scale : { 1.0, 1e-3, 1e3 })
  {
    for (const LightCase& c : AnalyticLightCases(scale))
    {
      if (c.HasSky)
      {
        continue;
      }
      const double worst = WorstOfPeak(c, 256);
      std::cout << c.Name << " (scale " << scale << "): worst " << worst << " of the peak\n";
      EXPECT_LT(worst, 1e-12) << c.Name << " at scale " << scale;
    }
  }
}

TEST(DirectLighting, SkyWithinItsQuadrature)
{
  // The stratified cosine quadrature (n x n strata at their centres): an
  // unobstructed uniform sky is exact (every weight pi / N); the CIE sky's
  // (1 + 2 cos) / 3 and the wall's silhouette are not. Measured, of the peak:
  // 256 samples (the default): uniform 0, CIE 7.5e-4, wall 2.6e-2; 1024:
  // wall 1.8e-2; 4096: CIE 9.8e-5, wall 5.3e-3 (the CIE error falls as 1 / N,
  // the wall's, from its edges cutting strata, more slowly and unevenly; its
  // worst probe is the one 0.3 from the wall at 256 and 1024 samples, where
  // the wall's top edge crosses the strata near the zenith). At the default
  // 256 the wall's 2.6% is above the 2% that LightCases.* asks of the methods.
  // Bounds 1.5 times these.
  struct Expected
  {
    const char* Name;
    int Samples;
    double Bound;
  };
  const Expected expected[] = { { "uniform sky over a plane", 256, 1e-13 },
    { "CIE overcast sky over a plane", 256, 1.1e-3 }, { "CIE overcast sky over a plane", 4096, 1.5e-4 },
    { "uniform sky beside a wall", 256, 4e-2 }, { "uniform sky beside a wall", 1024, 2.8e-2 },
    { "uniform sky beside a wall", 4096, 8e-3 } };
  const std::vector<LightCase> cases = AnalyticLightCases(1.0);
  for (const Expected& e : expected)
  {
    for (const LightCase& c : cases)
    {
      if (c.Name == e.Name)
      {
        const double worst = WorstOfPeak(c, e.Samples);
        std::cout << c.Name << ", " << e.Samples << " sky samples: worst " << worst
                  << " of the peak\n";
        EXPECT_LT(worst, e.Bound) << c.Name << ", " << e.Samples << " samples";
      }
    }
  }
}
