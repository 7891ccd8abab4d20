// The path-traced reference against exact answers: direct light from a
// polygon (Lambert's contour formula), the contact singularity that defeats
// emitter sampling alone, closed cubes (H = E / (1 - rho)), determinism, and
// a small rendered image.
#include "Radiosity/Reference/AnalyticReference.h"
#include "Radiosity/Common/FormFactor.h"
#include "Radiosity/Reference/PathTracer.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <iostream>
#include <stdexcept>

using namespace radiosity;

namespace
{
constexpr double PtPi = 3.14159265358979323846;

// Emitter: unit square at z = 1 centred over the origin, facing down.
const Vec3 SquareEmitter[4] = { { -0.5, -0.5, 1.0 }, { -0.5, 0.5, 1.0 }, { 0.5, 0.5, 1.0 },
  { 0.5, -0.5, 1.0 } };
const RGB SquareEmission(1.0, 0.5, 2.0);

Scene SquareOverFloor(double floorReflectance)
{
  Scene s;
  Material floor, light;
  floor.Reflectance = RGB(floorReflectance);
  light.Reflectance = RGB(0.0);
  light.Emission = SquareEmission;
  AppendQuad(s, Vec3(-2, -2, 0), Vec3(2, -2, 0), Vec3(2, 2, 0), Vec3(-2, 2, 0), floor, 4, "floor");
  AppendQuad(
    s, SquareEmitter[0], SquareEmitter[1], SquareEmitter[2], SquareEmitter[3], light, 2, "light");
  return s;
}

Probe MakeProbe(const Vec3& p, const Vec3& n)
{
  Probe probe;
  probe.Position = p;
  probe.Normal = glm::normalize(n);
  return probe;
}

/// Both: within `sigmas` standard errors and within `relative` of the exact value, per channel.
/// The bound that matters is the statistical one, 3 standard errors (measured
/// |error| / SE up to 2.96 over this file's probes, as a normal sample of this
/// size gives); `relative` (1%, measured relative errors up to 0.69%) guards
/// against a standard error that grew instead of the error shrinking.
void ExpectAgrees(const ReferenceValue& v, const RGB& exact, const std::string& what,
  double sigmas = 3.0, double relative = 0.01)
{
  for (int c = 0; c < 3; ++c)
  {
    const double err = v.Value[c] - exact[c];
    ASSERT_TRUE(std::isfinite(v.Value[c]) && std::isfinite(v.StandardError[c])) << what;
    EXPECT_LE(std::abs(err), sigmas * v.StandardError[c])
      << what << " channel " << c << ": " << v.Value[c] << " vs exact " << exact[c]
      << ", SE " << v.StandardError[c];
    EXPECT_LE(std::abs(err), relative * exact[c])
      << what << " channel " << c << ": " << v.Value[c] << " vs exact " << exact[c];
  }
  std::cout << "  " << what << ": H = " << v.Value.r << " exact " << exact.r
            << " rel.err " << (v.Value.r - exact.r) / exact.r << " SE/H "
            << v.StandardError.r / exact.r << " err/SE "
            << (v.Value.r - exact.r) / v.StandardError.r << "\n";
}

double Seconds(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Irradiance at the probes, with the time and rays it took on the test log.
std::vector<ReferenceValue> TimedIrradiance(
  const Scene& scene, const PathTracerOptions& options, const std::vector<Probe>& probes)
{
  const auto start = std::chrono::steady_clock::now();
  const PathTracer tracer(scene, options);
  std::vector<ReferenceValue> values = tracer.Irradiance(probes);
  std::cout << "  " << probes.size() << " probes x " << options.SamplesPerProbe << " samples: "
            << Seconds(start) << " s, " << tracer.RaysCast() << " rays\n";
  return values;
}
} // namespace

TEST(PathTracer, DirectLightFromSquareMatchesContourFormula)
{
  const Scene scene = SquareOverFloor(0.0);
  PathTracerOptions options;
  options.SamplesPerProbe = 262144;
  const PathTracer tracer(scene, options);
  const std::vector<Probe> probes = { MakeProbe({ 0, 0, 0 }, { 0, 0, 1 }),
    MakeProbe({ 0.5, 0.5, 0 }, { 0, 0, 1 }), MakeProbe({ 1.0, 0.3, 0 }, { 0, 0, 1 }),
    MakeProbe({ 1.7, -1.6, 0 }, { 0, 0, 1 }),
    // Tilted sensors in the air: the emitter is cut by their horizon.
    MakeProbe({ 0.2, 0.1, 0.5 }, { 1, 0, 1 }), MakeProbe({ -0.3, 0, 0.7 }, { 0, 1, 0.2 }) };
  const auto start = std::chrono::steady_clock::now();
  const std::vector<ReferenceValue> values = tracer.Irradiance(probes);
  std::cout << "  " << probes.size() << " probes x " << options.SamplesPerProbe << " samples: "
            << Seconds(start) << " s\n";
  ASSERT_EQ(values.size(), probes.size());
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    const double f =
      PointToPolygonFormFactor(probes[i].Position, probes[i].Normal, SquareEmitter, 4);
    ASSERT_GT(f, 0.0);
    ExpectAgrees(values[i], SquareEmission * f, "probe " + std::to_string(i));
  }
}

TEST(PathTracer, BackFacesAreBlackAndOpaque)
{
  const Scene scene = SquareOverFloor(0.0);
  PathTracerOptions options;
  options.SamplesPerProbe = 1024;
  const PathTracer tracer(scene, options);
  // Below the floor, facing up: the floor's back face hides the emitter.
  // Above the emitter, facing down: it sees only the emitter's back face.
  const auto values = tracer.Irradiance(
    { MakeProbe({ 0.1, 0.2, -0.5 }, { 0, 0, 1 }), MakeProbe({ 0, 0, 1.5 }, { 0, 0, -1 }) });
  for (const auto& v : values)
  {
    EXPECT_EQ(v.Value, RGB(0.0));
    EXPECT_EQ(v.StandardError, RGB(0.0));
  }
}

TEST(PathTracer, RejectsZeroNormal)
{
  const Scene scene = SquareOverFloor(0.0);
  const PathTracer tracer(scene, PathTracerOptions());
  EXPECT_THROW(tracer.Irradiance({ MakeProbe({ 0, 0, 0 }, { 0, 0, 1 }),
                 Probe{ Vec3(0.0), Vec3(0.0) } }),
    std::invalid_argument);
}

// A floor probe 1 mm from an emitting wall: cos cos / r^2 is nearly singular
// along the contact line, so emitter sampling alone has a huge variance there
// while MIS with cosine sampling stays accurate.
TEST(PathTracer, ContactWithEmittingWall)
{
  const double e = 1.0;
  const Scene scene = MakeContactScene(4, 0.0, e);
  const Vec3 wall[4] = { { 0, 0, 0 }, { 0, 1, 0 }, { 0, 1, 1 }, { 0, 0, 1 } };
  const std::vector<Probe> probes = { MakeProbe({ 0.001, 0.5, 0 }, { 0, 0, 1 }),
    MakeProbe({ 0.01, 0.5, 0 }, { 0, 0, 1 }), MakeProbe({ 0.1, 0.5, 0 }, { 0, 0, 1 }) };
  PathTracerOptions options;
  options.SamplesPerProbe = 262144;
  const auto start = std::chrono::steady_clock::now();
  const auto mis = PathTracer(scene, options).Irradiance(probes);
  std::cout << "  MIS: " << Seconds(start) << " s\n";
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    const double f = PointToPolygonFormFactor(probes[i].Position, probes[i].Normal, wall, 4);
    ExpectAgrees(mis[i], RGB(e * f), "MIS, " + std::to_string(probes[i].Position.x) + " m");
  }

  // The three strategies at equal sample counts.
  options.SamplesPerProbe = 16384;
  const auto misSmall = PathTracer(scene, options).Irradiance(probes);
  options.Sampling = PathSampling::EmitterOnly;
  const auto emitterOnly = PathTracer(scene, options).Irradiance(probes);
  options.Sampling = PathSampling::CosineOnly;
  const auto cosineOnly = PathTracer(scene, options).Irradiance(probes);
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    std::cout << "  x = " << probes[i].Position.x << ": SE/H at 16384 samples: MIS "
              << misSmall[i].StandardError.r / misSmall[i].Value.r
              << "  emitter only " << emitterOnly[i].StandardError.r / emitterOnly[i].Value.r
              << "  cosine only " << cosineOnly[i].StandardError.r / cosineOnly[i].Value.r
              << "  (emitter-only value " << emitterOnly[i].Value.r << ")\n";
    // MIS is never much worse than the better of the two strategies.
    EXPECT_LE(misSmall[i].StandardError.r,
      1.5 * std::min(emitterOnly[i].StandardError.r, cosineOnly[i].StandardError.r));
  }
  // At 1 mm emitter sampling alone is far noisier than the combination.
  EXPECT_GT(emitterOnly[0].StandardError.r, 5.0 * misSmall[0].StandardError.r);
}

TEST(PathTracer, ClosedCubeHalfReflectance)
{
  const double rho = 0.5, e = 1.0;
  const Scene scene = MakeClosedCube(1.0, 2, rho, e);
  const std::vector<Probe> probes = { MakeProbe({ 0.5, 0.5, 0 }, { 0, 0, 1 }),
    MakeProbe({ 0.03, 0.02, 0 }, { 0, 0, 1 }), MakeProbe({ 1.0, 0.3, 0.7 }, { -1, 0, 0 }),
    MakeProbe({ 0.4, 0.5, 0.6 }, { 1, 2, -3 }) };
  PathTracerOptions options;
  options.SamplesPerProbe = 65536;
  const auto values = TimedIrradiance(scene, options, probes);
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    ExpectAgrees(values[i], RGB(e / (1.0 - rho)), "rho 0.5, probe " + std::to_string(i));
  }

  // Direct light only: the bounce cap counts reflections after the probe.
  options.MaxBounces = 0;
  options.SamplesPerProbe = 65536;
  const auto direct = PathTracer(scene, options).Irradiance(probes);
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    ExpectAgrees(direct[i], RGB(e), "direct only, probe " + std::to_string(i));
  }
}

TEST(PathTracer, ClosedCubeHighReflectanceWithRoulette)
{
  const double rho = 0.9, e = 1.0;
  const Scene scene = MakeClosedCube(1.0, 2, rho, e);
  const std::vector<Probe> probes = { MakeProbe({ 0.5, 0.5, 0 }, { 0, 0, 1 }),
    MakeProbe({ 0.3, 1.0, 0.9 }, { 0, -1, 0 }) };
  PathTracerOptions options;
  options.SamplesPerProbe = 262144;
  const auto values = TimedIrradiance(scene, options, probes);
  // Exact up to the bounce cap: the reflections past 64 carry rho^65 ~ 0.1 %.
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    ExpectAgrees(values[i], RGB(e / (1.0 - rho)), "rho 0.9, probe " + std::to_string(i));
  }
}

TEST(PathTracer, DeterministicAndIndependentOfThreads)
{
  const Scene scene = MakeCornellBox();
  std::vector<Probe> probes;
  for (int i = 0; i < 40; ++i)
  {
    // In the open front part of the box, clear of the blocks.
    probes.push_back(MakeProbe(
      { 0.05 + 0.011 * i, 0.02 + 0.012 * i, 0.03 }, { std::sin(0.3 * i), 1.0, std::cos(0.7 * i) }));
  }
  PathTracerOptions options;
  options.SamplesPerProbe = 700; // not a multiple of the chunk size
  const auto a = PathTracer(scene, options).Irradiance(probes);
  const auto b = PathTracer(scene, options).Irradiance(probes);
  options.Threads = 1;
  const auto c = PathTracer(scene, options).Irradiance(probes);
  options.Seed = 2;
  const auto d = PathTracer(scene, options).Irradiance(probes);
  ASSERT_EQ(a.size(), probes.size());
  bool seedMatters = false;
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    EXPECT_EQ(0, std::memcmp(&a[i], &b[i], sizeof(ReferenceValue))) << "run to run, probe " << i;
    EXPECT_EQ(0, std::memcmp(&a[i], &c[i], sizeof(ReferenceValue))) << "threads, probe " << i;
    EXPECT_GT(a[i].Value.r, 0.0);
    seedMatters = seedMatters || a[i].Value != d[i].Value;
  }
  EXPECT_TRUE(seedMatters);

  // Many probes take the one-task-per-probe path: also independent of threads.
  std::vector<Probe> grid;
  for (int i = 0; i < 300; ++i)
  {
    grid.push_back(MakeProbe({ 0.01 + 0.0018 * i, 0.3, 0.02 }, { 0, 1, 0 }));
  }
  options.Seed = 7;
  options.SamplesPerProbe = 300;
  options.Threads = 0;
  const auto g0 = PathTracer(scene, options).Irradiance(grid);
  options.Threads = 1;
  const auto g1 = PathTracer(scene, options).Irradiance(grid);
  for (std::size_t i = 0; i < grid.size(); ++i)
  {
    EXPECT_EQ(0, std::memcmp(&g0[i], &g1[i], sizeof(ReferenceValue))) << "grid probe " << i;
  }
}

TEST(PathTracer, RenderSeesEmitterAndLitFloor)
{
  const double rhoFloor = 0.5;
  const Scene scene = SquareOverFloor(rhoFloor);
  PathTracerOptions options;
  const PathTracer tracer(scene, options);
  PinholeCamera camera;
  camera.Position = Vec3(0.0, -1.0, 0.5);
  camera.FocalPoint = Vec3(0.0, 0.0, 0.5);
  camera.ViewUp = Vec3(0.0, 0.0, 1.0);
  camera.ViewAngleDegrees = 90.0;
  const int w = 16, h = 16;
  std::vector<float> se;
  const auto start = std::chrono::steady_clock::now();
  const RadianceImage image = tracer.Render(camera, w, h, 256, &se);
  std::cout << "  16 x 16 x 256 spp: " << Seconds(start) << " s\n";
  ASSERT_EQ(image.Width, w);
  ASSERT_EQ(image.Height, h);
  ASSERT_EQ(image.RGB.size(), static_cast<std::size_t>(3 * w * h));
  ASSERT_EQ(se.size(), image.RGB.size());

  // The same primary rays as the tracer, intersected with the two planes by hand.
  const Vec3 forward(0, 1, 0), right(1, 0, 0), up(0, 0, 1);
  const double half = std::tan(0.5 * camera.ViewAngleDegrees * PtPi / 180.0);
  int emitterPixels = 0, floorPixels = 0, floorOutliers = 0;
  double sumZ2 = 0.0; // the errors in units of the reported standard errors
  for (int row = 0; row < h; ++row)
  {
    for (int col = 0; col < w; ++col)
    {
      const float* px = &image.RGB[3 * (row * w + col)];
      for (int c = 0; c < 3; ++c)
      {
        ASSERT_TRUE(std::isfinite(px[c]) && px[c] >= 0.f) << row << " " << col;
      }
      const Vec3 dir = forward + (2.0 * (col + 0.5) / w - 1.0) * half * right +
        (1.0 - 2.0 * (row + 0.5) / h) * half * up;
      if (dir.z > 0)
      {
        const Vec3 p = camera.Position + (0.5 / dir.z) * dir;
        if (std::abs(p.x) < 0.49 && std::abs(p.y) < 0.49)
        {
          ++emitterPixels;
          for (int c = 0; c < 3; ++c)
          {
            EXPECT_NEAR(px[c], SquareEmission[c] / PtPi, 1e-6) << row << " " << col;
          }
        }
        else if (std::abs(p.x) > 0.51 || std::abs(p.y) > 0.51)
        {
          EXPECT_EQ(px[0] + px[1] + px[2], 0.f) << "background at " << row << " " << col;
        }
      }
      else if (dir.z < 0)
      {
        const Vec3 p = camera.Position + (-0.5 / dir.z) * dir;
        if (std::abs(p.x) < 1.99 && std::abs(p.y) < 1.99)
        {
          // The emitter is black, so the floor's radiance is rho / pi times the direct light.
          ++floorPixels;
          const double f = PointToPolygonFormFactor(p, Vec3(0, 0, 1), SquareEmitter, 4);
          for (int c = 0; c < 3; ++c)
          {
            const double exact = rhoFloor / PtPi * SquareEmission[c] * f;
            const double sigma = se[3 * (row * w + col) + c];
            const double err = px[c] - exact;
            ASSERT_GT(sigma, 0.0) << row << " " << col;
            EXPECT_LT(std::abs(err), 0.25 * exact) << row << " " << col << " channel " << c;
            if (c == 0) // the channels are proportional: one z-score per pixel
            {
              const double z = err / sigma;
              sumZ2 += z * z;
              floorOutliers += std::abs(z) > 4.0;
            }
          }
        }
      }
    }
  }
  EXPECT_GT(emitterPixels, 10);
  EXPECT_GT(floorPixels, 50);
  // Honest standard errors: the mean squared z-score is about 1 (chi-square).
  const double meanZ2 = sumZ2 / std::max(floorPixels, 1);
  EXPECT_GT(meanZ2, 0.5);
  EXPECT_LT(meanZ2, 1.6);
  EXPECT_LE(floorOutliers, 1);
  std::cout << "  " << emitterPixels << " emitter pixels, " << floorPixels
            << " floor pixels: mean (err/SE)^2 " << meanZ2 << ", " << floorOutliers
            << " beyond 4 SE\n";
}

TEST(PathTracer, ExactPenumbraBehindConvexBlocker)
{
  // The analytic reference's penumbra case: emitter, blocker and floor all
  // black, so the irradiance on the floor is the direct light with the
  // emitter clipped by the projected blocker.
  const Scene scene = MakeShadowScene(4, 10.0);
  std::vector<Probe> probes;
  for (double x : { -0.5, -0.2, 0.05, 0.2, 0.45, 0.7 })
  {
    probes.push_back(MakeProbe(Vec3(x, 0.03, 0.0), Vec3(0, 0, 1)));
  }
  AnalyticReference exact;
  std::string why;
  ASSERT_TRUE(ComputeAnalyticReference(scene, probes, exact, why)) << why;
  PathTracerOptions options;
  options.SamplesPerProbe = 1 << 19;
  const std::vector<ReferenceValue> values = PathTracer(scene, options).Irradiance(probes);
  int umbra = 0;
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    const std::string where = "x = " + std::to_string(probes[i].Position.x);
    if (exact.Irradiance[i].r < 1e-9)
    {
      // The umbra (exact: zero up to rounding): a relative error means
      // nothing there; grazing paths may still add a trace.
      ++umbra;
      EXPECT_LE(values[i].Value.r, 3.0 * values[i].StandardError.r) << where;
      EXPECT_LE(values[i].Value.r, 1e-4) << where;
      continue;
    }
    ExpectAgrees(values[i], exact.Irradiance[i], "penumbra " + where);
  }
  EXPECT_GE(umbra, 1);
}

TEST(PathTracer, InsideTheSphere)
{
  // Every area element of a sphere sees every other alike: H = mean(E) / (1 - rho)
  // for any emission. The icosphere (1280 faces) departs from the sphere by
  // less than the 1% allowed; the 3-SE bound then holds as long as the
  // standard error stays above that departure / 3, hence the sample count.
  const Scene sphere = MakeSphereInterior(1.0, 3, 0.5, RGB(4.0));
  std::vector<Probe> probes;
  for (std::size_t t = 0; t < sphere.Triangles.size(); t += 331)
  {
    probes.push_back(MakeProbe(sphere.Centroid(t), sphere.Normal(t)));
  }
  AnalyticReference exact;
  std::string why;
  ASSERT_TRUE(ComputeAnalyticReference(sphere, probes, exact, why)) << why;
  PathTracerOptions options;
  options.SamplesPerProbe = 1 << 15;
  const std::vector<ReferenceValue> values = PathTracer(sphere, options).Irradiance(probes);
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    ExpectAgrees(values[i], exact.Irradiance[i], "sphere probe " + std::to_string(i));
  }
}
