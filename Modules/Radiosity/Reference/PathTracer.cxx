// Monte Carlo path tracing of the rendering equation for one-sided Lambertian
// surfaces, as a reference for the error harness.
//
// The estimator of the irradiance H(x, n) = integral of L_i cos(theta) over the
// hemisphere follows a random walk x0 = probe, x1, x2, ... Each vertex k has a
// "BRDF" f_k: f_0 = 1 for the probe (a perfectly white Lambertian receiver
// whose reflected radiance, times pi, is the irradiance), f_k = rho_k / pi for
// surface vertices. At every vertex two strategies estimate the emitted light
// arriving there and are combined by multiple importance sampling with the
// power heuristic (Veach & Guibas 1995, "Optimally combining sampling
// techniques for Monte Carlo rendering", SIGGRAPH 95):
//  - emitter sampling (next-event estimation): an emitter triangle chosen with
//    probability proportional to its power (area times mean exitance), a
//    uniform point on it, one shadow ray; its solid-angle density is
//    p_A r^2 / cos(theta_y);
//  - BSDF sampling: a cosine-weighted direction (density cos(theta_x) / pi),
//    one nearest-hit ray; if it hits the front face of an emitter, the emitted
//    radiance E / pi counts with the complementary weight. The same ray
//    continues the walk.
// Emitter sampling alone has unbounded variance near contacts (its integrand
// cos cos / r^2 is singular where the receiver touches the emitter); cosine
// sampling is bounded there, and the power heuristic keeps the better of the
// two in each region.
// Punctual lights (SPEC "Lights and sky": point, spot, directional) are
// delta lights: no direction sampling can find them, so they are estimated by
// next-event estimation alone (no MIS), at every vertex: one shadow ray per
// light towards its position (or far towards a directional light), the
// closed-form unshadowed irradiance (Lights.h UnshadowedIrradiance) times the
// vertex's f = albedo / pi. At the probe (f = 1/pi, albedo pi) this is the
// light's exact direct irradiance. Every strategy (PathSampling) does it.
// The sky has no area to sample: a path direction that leaves the scene (no
// hit, the probe's first direction included) picks up SkyRadiance(sky, w)
// times the throughput; cosine sampling makes an unobstructed uniform sky
// exact for every sample (pi L at the probe). Every strategy counts it.
// Back faces are black and opaque: a ray that hits one ends the walk (and
// hides the sky).
// Russian roulette (Arvo & Kirk 1990) from depth RouletteStart on, with
// survival probability min(0.95, max component of the throughput / pi).
#include "Radiosity/Reference/PathTracer.h"

#include "Radiosity/Common/Lights.h"
#include "Radiosity/Common/Visibility.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace radiosity
{
namespace pathtracing
{
constexpr double Pi = 3.14159265358979323846;
/// Samples per independent random stream: the unit of parallel work. Fixed,
/// so that the partition (and the result) does not depend on the thread count.
constexpr std::size_t ChunkSize = 256;

inline std::uint64_t SplitMix64(std::uint64_t x)
{
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

/// PCG32 (O'Neill 2014, pcg32_random_r), one stream per chunk of samples.
class Pcg32
{
public:
  Pcg32(std::uint64_t initState, std::uint64_t initSeq)
  {
    this->Inc = (initSeq << 1u) | 1u;
    this->Next();
    this->State += initState;
    this->Next();
  }
  std::uint32_t Next()
  {
    const std::uint64_t old = this->State;
    this->State = old * 6364136223846793005ull + this->Inc;
    const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<std::uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }
  /// Uniform in [0, 1) with 53 random bits.
  double Uniform()
  {
    const std::uint64_t hi = this->Next(), lo = this->Next();
    return static_cast<double>(((hi << 32) | lo) >> 11) * 0x1.0p-53;
  }

private:
  std::uint64_t State = 0;
  std::uint64_t Inc = 0;
};

inline Pcg32 StreamFor(std::uint64_t seed, std::uint64_t stream, std::uint64_t index,
  std::uint64_t chunk)
{
  std::uint64_t h = SplitMix64(seed);
  h = SplitMix64(h ^ stream);
  h = SplitMix64(h ^ index);
  h = SplitMix64(h ^ chunk);
  return Pcg32(h, SplitMix64(h ^ 0xDA3E39CB94B95BDBull));
}

/// Orthonormal basis around a unit vector (Duff et al. 2017).
inline void Basis(const Vec3& n, Vec3& t, Vec3& b)
{
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double c = n.x * n.y * a;
  t = Vec3(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
  b = Vec3(c, sign + n.y * n.y * a, -n.y);
}

/// A point where the irradiance is estimated: position and unit normal.
struct Sensor
{
  Vec3 Position{ 0.0 };
  Vec3 Normal{ 0.0, 0.0, 1.0 };
};

struct Moments
{
  RGB Sum{ 0.0 };
  RGB SumSquares{ 0.0 };
};
} // namespace pathtracing

struct PathTracer::Internals
{
  // Class-scope names: no clash with other files of a unity build.
  static constexpr double Pi = pathtracing::Pi;
  using Sensor = pathtracing::Sensor;
  using Moments = pathtracing::Moments;
  using Pcg32 = pathtracing::Pcg32;
  static constexpr std::size_t ChunkSize = pathtracing::ChunkSize;

  std::unique_ptr<Visibility> Rays;
  double Epsilon = 0.0;
  std::vector<Vec3> Normals;          ///< unit, 0 for degenerate triangles
  std::vector<unsigned> Emitters;     ///< emitter triangles
  std::vector<double> EmitterCdf;     ///< cumulative selection probability, last = 1
  std::vector<double> AreaDensity;    ///< per triangle: density of emitter samples per m^2
  std::vector<Light> Punctual;        ///< the scene's point, spot and directional lights
  Sky SkyLight;                       ///< the scene's sky (Model None: none)
  bool HasSky = false;
  Vec3 Centre{ 0.0 };                 ///< of the scene's bounding box
  double Extent = 1.0;                ///< the bounding box's diagonal

  /// Beyond this distance from x a shadow ray has left the scene (as DirectLighting).
  double FarDistance(const Vec3& x) const
  {
    return 2.0 * (this->Extent + glm::length(x - this->Centre));
  }
  /// The punctual lights' direct irradiance at x (normal n), each with one
  /// shadow ray from `origin` (x offset along n).
  RGB PunctualLight(const Vec3& x, const Vec3& n, const Vec3& origin) const;

  RGB Path(const Scene& scene, const PathTracerOptions& options, const Sensor& sensor,
    Pcg32& rng) const;
  /// `indices[s]` (or s when null) names sensor s's random streams.
  std::vector<ReferenceValue> Estimate(const Scene& scene, const PathTracerOptions& options,
    const std::vector<Sensor>& sensors, const std::vector<std::size_t>* indices,
    std::size_t samples, std::uint64_t stream) const;
};

PathTracer::PathTracer(const Scene& scene, const PathTracerOptions& options)
  : SourceScene(scene)
  , Settings(options)
  , Impl(new Internals)
{
  if (options.MaxBounces < 0)
  {
    throw std::invalid_argument("PathTracer: MaxBounces must be >= 0");
  }
  if (options.Threads < 0)
  {
    throw std::invalid_argument("PathTracer: Threads must be >= 0");
  }
  if (scene.Materials.size() != scene.Triangles.size())
  {
    throw std::invalid_argument("PathTracer: the scene needs one material per triangle");
  }
  this->Impl->Rays = std::make_unique<Visibility>(scene, Visibility::AllTriangles(scene));
  this->Impl->Epsilon = this->Impl->Rays->Offset();

  const std::size_t nt = scene.NumberOfTriangles();
  this->Impl->Normals.resize(nt);
  this->Impl->AreaDensity.assign(nt, 0.0);
  std::vector<double> power, area;
  double total = 0.0;
  for (std::size_t t = 0; t < nt; ++t)
  {
    const Vec3 av = AreaVector(scene.Vertex(t, 0), scene.Vertex(t, 1), scene.Vertex(t, 2));
    const double a = glm::length(av);
    this->Impl->Normals[t] = a > 0.0 ? av / a : Vec3(0.0);
    const double p = a * SumComponents(scene.Materials[t].Emission) / 3.0;
    if (p > 0.0 && std::isfinite(p))
    {
      this->Impl->Emitters.push_back(static_cast<unsigned>(t));
      power.push_back(p);
      area.push_back(a);
      total += p;
    }
  }
  double running = 0.0;
  for (std::size_t i = 0; i < power.size(); ++i)
  {
    running += power[i];
    this->Impl->EmitterCdf.push_back(running / total);
    const unsigned t = this->Impl->Emitters[i];
    this->Impl->AreaDensity[t] = (power[i] / total) / area[i];
  }
  if (!this->Impl->EmitterCdf.empty())
  {
    this->Impl->EmitterCdf.back() = 1.0;
  }
  // Lights: only those that can give light (a zero intensity is none).
  for (const Light& light : scene.Lighting.Lights)
  {
    if (MaxComponent(light.Intensity) > 0.0)
    {
      this->Impl->Punctual.push_back(light);
    }
  }
  this->Impl->SkyLight = scene.Lighting.SkyLight;
  this->Impl->HasSky = scene.Lighting.SkyLight.Enabled();
  if (nt > 0)
  {
    Vec3 lo, hi;
    scene.BoundingBox(lo, hi);
    this->Impl->Centre = 0.5 * (lo + hi);
    this->Impl->Extent = std::max(glm::length(hi - lo), 1e-300);
  }
}

RGB PathTracer::Internals::PunctualLight(const Vec3& x, const Vec3& n, const Vec3& origin) const
{
  RGB sum(0.0);
  const double far = this->FarDistance(x);
  for (const Light& light : this->Punctual)
  {
    const RGB h = UnshadowedIrradiance(light, x, n);
    if (!(MaxComponent(h) > 0.0))
    {
      continue;
    }
    const Vec3 target = ShadowRayTarget(light, x, far);
    unsigned char visible = 0;
    this->Rays->TestSegments(&origin, &target, 1, &visible);
    if (visible)
    {
      sum += h;
    }
  }
  return sum;
}

PathTracer::~PathTracer() = default;

std::size_t PathTracer::RaysCast() const
{
  return this->Impl->Rays->RaysCast();
}

RGB PathTracer::Internals::Path(const Scene& scene, const PathTracerOptions& options,
  const Sensor& sensor, Pcg32& rng) const
{
  const bool lightSampling =
    options.Sampling != PathSampling::CosineOnly && !this->Emitters.empty();
  const bool hitSampling = options.Sampling != PathSampling::EmitterOnly;
  const bool mis = options.Sampling == PathSampling::MultipleImportance;
  const double eps = this->Epsilon;

  RGB sum(0.0);
  RGB beta(1.0);   // throughput up to the current vertex
  RGB albedo(Pi);  // pi f at the current vertex: pi for the probe, rho for a surface
  Vec3 x = sensor.Position;
  Vec3 n = sensor.Normal;
  for (int depth = 0;; ++depth)
  {
    const Vec3 origin = x + eps * n;
    // Emitter sampling.
    if (lightSampling)
    {
      const double ue = rng.Uniform();
      const double u1 = rng.Uniform();
      const double u2 = rng.Uniform();
      const std::size_t k = static_cast<std::size_t>(
        std::upper_bound(this->EmitterCdf.begin(), this->EmitterCdf.end(), ue) -
        this->EmitterCdf.begin());
      const unsigned e = this->Emitters[std::min(k, this->Emitters.size() - 1)];
      const double su = std::sqrt(u1);
      const Vec3 y = (1.0 - su) * scene.Vertex(e, 0) + su * (1.0 - u2) * scene.Vertex(e, 1) +
        su * u2 * scene.Vertex(e, 2);
      const Vec3 d = y - x;
      const double r2 = glm::dot(d, d);
      if (r2 > 0.0)
      {
        const Vec3 w = d / std::sqrt(r2);
        const double cosX = glm::dot(n, w);
        const double cosY = -glm::dot(this->Normals[e], w);
        if (cosX > 0.0 && cosY > 0.0)
        {
          unsigned char visible = 0;
          this->Rays->TestSegments(&origin, &y, 1, &visible);
          if (visible)
          {
            const double pLight = this->AreaDensity[e] * r2 / cosY; // per steradian
            const double pCos = cosX / Pi;
            const double weight = mis ? 1.0 / (1.0 + (pCos / pLight) * (pCos / pLight)) : 1.0;
            // f L_e cos / p with L_e = E / pi and f = albedo / pi.
            sum += beta * (albedo / Pi) * (scene.Materials[e].Emission / Pi) *
              (cosX / pLight * weight);
          }
        }
      }
    }
    // Punctual lights: next-event estimation only (delta lights), f = albedo / pi.
    if (!this->Punctual.empty())
    {
      sum += beta * (albedo / Pi) * this->PunctualLight(x, n, origin);
    }

    // Cosine-weighted direction: continues the walk and finds emitters by hitting them.
    const double u1 = rng.Uniform();
    const double u2 = rng.Uniform();
    const double r = std::sqrt(u1);
    const double phi = 2.0 * Pi * u2;
    const double cosX = std::sqrt(1.0 - u1); // > 0 since u1 < 1
    Vec3 t, b;
    pathtracing::Basis(n, t, b);
    const Vec3 w = r * std::cos(phi) * t + r * std::sin(phi) * b + cosX * n;
    beta *= albedo; // f cos / (cos / pi)
    double dist, bu, bv;
    unsigned hit;
    if (!this->Rays->Intersect(origin, w, dist, hit, bu, bv))
    {
      if (this->HasSky)
      {
        sum += beta * SkyRadiance(this->SkyLight, w); // f cos L / p = beta L
      }
      break; // the path leaves the scene: the sky, or black
    }
    const Vec3& nh = this->Normals[hit];
    const double cosY = -glm::dot(nh, w);
    if (!(cosY > 0.0))
    {
      break; // back face (or edge-on): black and opaque
    }
    const Vec3 y = (1.0 - bu - bv) * scene.Vertex(hit, 0) + bu * scene.Vertex(hit, 1) +
      bv * scene.Vertex(hit, 2);
    const Material& m = scene.Materials[hit];
    if (hitSampling && this->AreaDensity[hit] > 0.0)
    {
      double weight = 1.0;
      if (mis && lightSampling)
      {
        const Vec3 d = y - x;
        const double pLight = this->AreaDensity[hit] * glm::dot(d, d) / cosY;
        const double pCos = cosX / Pi;
        weight = 1.0 / (1.0 + (pLight / pCos) * (pLight / pCos));
      }
      sum += beta * (m.Emission / Pi) * weight;
    }
    if (depth + 1 > options.MaxBounces || !(MaxComponent(m.Reflectance) > 0.0))
    {
      break;
    }
    if (depth + 1 >= options.RouletteStart)
    {
      const double q = std::min(0.95, MaxComponent(beta * m.Reflectance) / Pi);
      if (!(q > 0.0) || rng.Uniform() >= q)
      {
        break;
      }
      beta /= q;
    }
    x = y;
    n = nh;
    albedo = m.Reflectance;
  }
  return sum;
}

std::vector<ReferenceValue> PathTracer::Internals::Estimate(const Scene& scene,
  const PathTracerOptions& options, const std::vector<Sensor>& sensors,
  const std::vector<std::size_t>* indices, std::size_t samples, std::uint64_t stream) const
{
  std::vector<ReferenceValue> result(sensors.size());
  if (samples == 0 || sensors.empty())
  {
    return result;
  }
  const std::size_t chunks = (samples + ChunkSize - 1) / ChunkSize;
  const auto chunkMoments = [&](std::size_t s, std::size_t c)
  {
    Pcg32 rng = pathtracing::StreamFor(options.Seed, stream, indices ? (*indices)[s] : s, c);
    const std::size_t begin = c * ChunkSize;
    const std::size_t end = std::min(samples, begin + ChunkSize);
    Moments m;
    for (std::size_t i = begin; i < end; ++i)
    {
      const RGB v = this->Path(scene, options, sensors[s], rng);
      m.Sum += v;
      m.SumSquares += v * v;
    }
    return m;
  };
  const double n = static_cast<double>(samples);
  const auto finish = [&](std::size_t s, const Moments& total)
  {
    const RGB mean = total.Sum / n;
    RGB variance(0.0);
    if (samples > 1)
    {
      variance = glm::max(RGB(0.0), (total.SumSquares - n * mean * mean) / (n - 1.0));
    }
    result[s].Value = mean;
    result[s].StandardError = glm::sqrt(variance / n);
  };
  // Chunk moments are summed per sensor in chunk order in both branches, so
  // the branch (chosen by the sensor count alone) does not change any bit.
  const bool perSensor = sensors.size() >= 256;
  WorkShare& share = ShareOrAlone(options.Share);
  const auto work = [&]()
  {
    if (perSensor)
    {
      // Many sensors (images, sensor grids): one task per sensor, no buffer;
      // on MPI ranks a share of the sensors each.
      const auto mine = share.Range(sensors.size());
      tbb::parallel_for(mine.first, mine.second,
        [&](std::size_t s)
        {
          Moments total;
          for (std::size_t c = 0; c < chunks; ++c)
          {
            const Moments m = chunkMoments(s, c);
            total.Sum += m.Sum;
            total.SumSquares += m.SumSquares;
          }
          finish(s, total);
        });
      share.Combine(result.data(), result.size());
      return;
    }
    // Few sensors with many samples: the chunks are the parallel work (on
    // MPI ranks a share of the chunks each).
    std::vector<Moments> partial(sensors.size() * chunks);
    const auto mine = share.Range(partial.size());
    tbb::parallel_for(mine.first, mine.second,
      [&](std::size_t item) { partial[item] = chunkMoments(item / chunks, item % chunks); });
    share.Combine(partial.data(), partial.size());
    for (std::size_t s = 0; s < sensors.size(); ++s)
    {
      Moments total;
      for (std::size_t c = 0; c < chunks; ++c)
      {
        total.Sum += partial[s * chunks + c].Sum;
        total.SumSquares += partial[s * chunks + c].SumSquares;
      }
      finish(s, total);
    }
  };
  if (options.Threads > 0)
  {
    tbb::task_arena arena(options.Threads);
    arena.execute(work);
  }
  else
  {
    work();
  }
  return result;
}

std::vector<ReferenceValue> PathTracer::Irradiance(const std::vector<Probe>& probes) const
{
  return this->Irradiance(probes, this->Settings.SamplesPerProbe, 0);
}

std::vector<ReferenceValue> PathTracer::Irradiance(
  const std::vector<Probe>& probes, std::size_t samples, std::uint64_t stream) const
{
  std::vector<Internals::Sensor> sensors(probes.size());
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    const Probe& p = probes[i];
    const double len = glm::length(p.Normal);
    if (!(len > 0.0) || !std::isfinite(len))
    {
      throw std::invalid_argument("PathTracer: probe " + std::to_string(i) +
        " has a zero or non-finite normal");
    }
    if (!std::isfinite(p.Position.x) || !std::isfinite(p.Position.y) ||
      !std::isfinite(p.Position.z))
    {
      throw std::invalid_argument(
        "PathTracer: probe " + std::to_string(i) + " has a non-finite position");
    }
    sensors[i].Position = p.Position;
    sensors[i].Normal = p.Normal / len;
  }
  return this->Impl->Estimate(
    this->SourceScene, this->Settings, sensors, nullptr, samples, stream);
}

RadianceImage PathTracer::Render(
  const PinholeCamera& camera, int width, int height, std::size_t samplesPerPixel) const
{
  return this->Render(camera, width, height, samplesPerPixel, nullptr);
}

RadianceImage PathTracer::Render(const PinholeCamera& camera, int width, int height,
  std::size_t samplesPerPixel, std::vector<float>* standardError) const
{
  if (width <= 0 || height <= 0)
  {
    throw std::invalid_argument("PathTracer::Render: the image size must be positive");
  }
  const Scene& scene = this->SourceScene;
  RadianceImage image;
  image.Width = width;
  image.Height = height;
  const std::size_t pixels = static_cast<std::size_t>(width) * height;
  image.RGB.assign(pixels * 3, 0.f);
  if (standardError)
  {
    standardError->assign(pixels * 3, 0.f);
  }

  // Same camera convention as RenderRadiance: primary rays through pixel centres.
  const Vec3 view = camera.FocalPoint - camera.Position;
  const Vec3 side = glm::cross(view, camera.ViewUp);
  if (!(glm::length(side) > 0.0) || !std::isfinite(glm::length(side)) ||
    !(camera.ViewAngleDegrees > 0.0 && camera.ViewAngleDegrees < 180.0))
  {
    throw std::invalid_argument("PathTracer::Render: degenerate camera (position at the focal "
                                "point, view-up along the view direction, or view angle)");
  }
  const Vec3 forward = glm::normalize(view);
  const Vec3 right = glm::normalize(glm::cross(forward, camera.ViewUp));
  const Vec3 up = glm::cross(right, forward);
  const double halfHeight = std::tan(0.5 * camera.ViewAngleDegrees * Internals::Pi / 180.0);
  const double halfWidth = halfHeight * width / static_cast<double>(height);
  std::vector<int> hitTriangle(pixels, -1);
  std::vector<Internals::Sensor> sensors(pixels);
  const auto primary = [&]()
  {
    tbb::parallel_for(0, height,
      [&](int row)
      {
        for (int col = 0; col < width; ++col)
        {
          const double x = (2.0 * (col + 0.5) / width - 1.0) * halfWidth;
          const double y = (1.0 - 2.0 * (row + 0.5) / height) * halfHeight;
          const Vec3 dir = glm::normalize(forward + x * right + y * up);
          double t, u, v;
          unsigned tri;
          if (!this->Impl->Rays->Intersect(camera.Position, dir, t, tri, u, v))
          {
            continue;
          }
          const Vec3& nh = this->Impl->Normals[tri];
          if (!(glm::dot(nh, dir) < 0.0))
          {
            continue; // back face: black
          }
          const std::size_t px = static_cast<std::size_t>(row) * width + col;
          hitTriangle[px] = static_cast<int>(tri);
          sensors[px].Position = (1.0 - u - v) * scene.Vertex(tri, 0) +
            u * scene.Vertex(tri, 1) + v * scene.Vertex(tri, 2);
          sensors[px].Normal = nh;
        }
      });
  };
  if (this->Settings.Threads > 0)
  {
    tbb::task_arena arena(this->Settings.Threads);
    arena.execute(primary);
  }
  else
  {
    primary();
  }

  // Irradiance estimates only where the surface reflects.
  std::vector<Internals::Sensor> reflecting;
  std::vector<std::size_t> where;
  for (std::size_t px = 0; px < pixels; ++px)
  {
    const int tri = hitTriangle[px];
    if (tri >= 0 && MaxComponent(scene.Materials[tri].Reflectance) > 0.0)
    {
      reflecting.push_back(sensors[px]);
      where.push_back(px);
    }
  }
  // Each pixel's random streams are named by its pixel index (stream "REND").
  const std::vector<ReferenceValue> irradiance = this->Impl->Estimate(
    scene, this->Settings, reflecting, &where, samplesPerPixel, 0x52454E44ull);
  for (std::size_t px = 0; px < pixels; ++px)
  {
    const int tri = hitTriangle[px];
    if (tri < 0)
    {
      continue;
    }
    const RGB le = scene.Materials[tri].Emission / Internals::Pi;
    for (int c = 0; c < 3; ++c)
    {
      image.RGB[3 * px + c] = static_cast<float>(le[c]);
    }
  }
  for (std::size_t i = 0; i < where.size(); ++i)
  {
    const std::size_t px = where[i];
    const Material& m = scene.Materials[hitTriangle[px]];
    const RGB l = m.Emission / Internals::Pi + m.Reflectance / Internals::Pi * irradiance[i].Value;
    const RGB se = m.Reflectance / Internals::Pi * irradiance[i].StandardError;
    for (int c = 0; c < 3; ++c)
    {
      image.RGB[3 * px + c] = static_cast<float>(l[c]);
      if (standardError)
      {
        (*standardError)[3 * px + c] = static_cast<float>(se[c]);
      }
    }
  }
  return image;
}
} // namespace radiosity
