// A path-traced reference for the error harness: Monte Carlo path tracing of
// the rendering equation (Kajiya 1986) for one-sided Lambertian surfaces,
// with next-event estimation and BSDF (cosine-weighted hemisphere) sampling
// combined at every path vertex by multiple importance sampling with the
// power heuristic (Veach & Guibas 1995), and Russian roulette (Arvo & Kirk
// 1990) after a few bounces. Unbiased up to the bounce cap (MaxBounces: the
// light after more reflections is left out, a relative bias of about
// rho^(MaxBounces+1) in a closed scene of reflectance rho, 1e-3 for rho = 0.9
// and the default 64); every value comes with its standard error.
//
// Lights (SPEC "Lights and sky", scene.Lighting): every punctual light
// (point, spot, directional) by next-event estimation at every vertex, one
// shadow ray each (delta lights: no MIS); the sky on every path direction
// that leaves the scene (SkyRadiance of that direction). Lights and sky are
// not seen by the camera (Render's background stays black).
//
// Determinism: each probe (or pixel) is split into fixed chunks of samples,
// each chunk seeded from (Seed, index, chunk) by splitmix64 and drawing from
// its own PCG32 stream; chunk sums are combined in a fixed order. The result
// is bit-identical across runs and for any thread count.
#ifndef Radiosity_PathTracer_h
#define Radiosity_PathTracer_h

#include "Radiosity/Common/WorkShare.h"
#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Common/RadianceImage.h"
#include "Radiosity/Common/Scene.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace radiosity
{
class Visibility;

/// Which estimators are combined (the alternatives exist to test the MIS).
enum class PathSampling
{
  MultipleImportance, ///< emitter sampling + cosine sampling, power heuristic
  EmitterOnly,        ///< next-event estimation only (unbounded variance at contacts)
  CosineOnly          ///< cosine-weighted hemisphere sampling only (emission found by hits)
  // Punctual lights (NEE only) and the sky (found by escaping paths) are
  // estimated the same way under every strategy.
};

struct PathTracerOptions
{
  std::uint64_t Seed = 1;
  std::size_t SamplesPerProbe = 4096;
  int MaxBounces = 64;    ///< reflections counted after the probe (0: direct light only)
  int RouletteStart = 3;  ///< vertices at this depth and deeper may be killed
  int Threads = 0;        ///< 0: TBB's default
  PathSampling Sampling = PathSampling::MultipleImportance;
  /// MPI ranks: the paths split over them, in chunks of one sensor's
  /// samples (or, with many sensors, whole sensors), each with its own random
  /// stream, so that any number of ranks gives the same estimates to the
  /// bit (WorkShare.h). None: all here.
  std::shared_ptr<WorkShare> Share;
};

struct ReferenceValue
{
  RGB Value{ 0.0 };
  RGB StandardError{ 0.0 }; ///< per channel, sqrt(sample variance / n)
};

class PathTracer
{
public:
  /// The scene is referenced, not copied: it must outlive the tracer.
  PathTracer(const Scene& scene, const PathTracerOptions& options);
  ~PathTracer();
  PathTracer(const PathTracer&) = delete;
  PathTracer& operator=(const PathTracer&) = delete;

  /**
   * Irradiance H (W/m^2) at each probe: the integral over the hemisphere
   * around the probe's normal of the incoming radiance times cos(theta),
   * with SamplesPerProbe paths each. Probes are sensors, not surfaces: a
   * probe on a surface sees the hemisphere above it (its origin is offset by
   * Visibility::Offset() along its normal). Throws std::invalid_argument for
   * a zero or non-finite normal or a non-finite position.
   */
  std::vector<ReferenceValue> Irradiance(const std::vector<Probe>& probes) const;

  /// Same with an explicit sample count (and seed stream `stream`, so that
  /// several calls can draw independent samples).
  std::vector<ReferenceValue> Irradiance(
    const std::vector<Probe>& probes, std::size_t samples, std::uint64_t stream = 0) const;

  /**
   * Linear radiance image (same camera convention as RenderRadiance: vertical
   * view angle, one primary ray through each pixel centre, top row first):
   * L = E/pi + rho/pi * H at the front face hit, H estimated with
   * `samplesPerPixel` paths; 0 for the background and for back faces.
   */
  RadianceImage Render(
    const PinholeCamera& camera, int width, int height, std::size_t samplesPerPixel) const;

  /// Same with the per-pixel standard errors of L (3 per pixel, same layout).
  RadianceImage Render(const PinholeCamera& camera, int width, int height,
    std::size_t samplesPerPixel, std::vector<float>* standardError) const;

  const PathTracerOptions& Options() const { return this->Settings; }

  /// Rays traced so far (nearest-hit and shadow rays).
  std::size_t RaysCast() const;

private:
  struct Internals;
  const Scene& SourceScene;
  PathTracerOptions Settings;
  std::unique_ptr<Internals> Impl;
};
} // namespace radiosity

#endif
