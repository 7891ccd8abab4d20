#include "Radiosity/Common/DirectLighting.h"

#include "Radiosity/Common/Visibility.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace radiosity
{
namespace
{
/// An orthonormal frame (t, b) around the unit normal n (Duff et al. 2017).
void FrameAround(const Vec3& n, Vec3& t, Vec3& b)
{
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double c = n.x * n.y * a;
  t = Vec3(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
  b = Vec3(c, sign + n.y * n.y * a, -n.y);
}
}

DirectLighting::DirectLighting(const Scene& scene, int skySamples, const Visibility* occluders)
  : DirectLighting(scene, scene.Lighting, skySamples, occluders)
{
}

DirectLighting::DirectLighting(
  const Scene& scene, const LightSet& lighting, int skySamples, const Visibility* occluders)
  : SourceScene(scene)
  , Set(lighting)
  , Occluders(occluders)
{
  this->SkySampleCount = std::max(skySamples, 4);
  this->SkyLattice = MakeSkyLattice(this->SkySampleCount);
  if (!scene.Triangles.empty())
  {
    Vec3 lo, hi;
    scene.BoundingBox(lo, hi);
    this->Centre = 0.5 * (lo + hi);
    this->Extent = std::max(glm::length(hi - lo), 1e-300);
  }
  if (!this->Set.Empty() && !this->Occluders)
  {
    this->OwnOccluders = std::make_unique<Visibility>(scene, Visibility::AllTriangles(scene));
    this->Occluders = this->OwnOccluders.get();
  }
}

DirectLighting::~DirectLighting() = default;

double DirectLighting::FarDistance(const Vec3& x) const
{
  return 2.0 * (this->Extent + glm::length(x - this->Centre));
}

RGB DirectLighting::PunctualOne(std::size_t index, const Vec3& x, const Vec3& n) const
{
  const Light& light = this->Set.Lights[index];
  const RGB h = UnshadowedIrradiance(light, x, n);
  if (MaxComponent(h) <= 0.0)
  {
    return RGB(0.0);
  }
  const Vec3 origin = this->RayOrigin(x, n);
  const Vec3 target = ShadowRayTarget(light, x, this->FarDistance(x));
  unsigned char visible = 1;
  this->Occluders->TestSegments(&origin, &target, 1, &visible);
  return visible ? h : RGB(0.0);
}

RGB DirectLighting::PunctualSeenFrom(const Vec3& x, const Vec3& visibilityPoint, const Vec3& n) const
{
  RGB sum(0.0);
  const Vec3 origin = this->RayOrigin(visibilityPoint, n);
  const double far = this->FarDistance(visibilityPoint);
  for (const Light& light : this->Set.Lights)
  {
    const RGB h = UnshadowedIrradiance(light, x, n);
    if (MaxComponent(h) > 0.0)
    {
      const Vec3 target = ShadowRayTarget(light, visibilityPoint, far);
      unsigned char visible = 0;
      this->Occluders->TestSegments(&origin, &target, 1, &visible);
      sum += visible ? h : RGB(0.0);
    }
  }
  return sum;
}

RGB DirectLighting::Punctual(const Vec3& x, const Vec3& n) const
{
  return this->PunctualSeenFrom(x, x, n);
}

namespace
{
/// Direction i of m of the sky quadrature in the frame (t, b, n): its
/// coordinates there are SkyLattice's entry i.
Vec3 SkyDirection(const Vec3& local, const Vec3& t, const Vec3& b, const Vec3& n)
{
  return local.x * t + local.y * b + local.z * n;
}
}

/// Malley: a point of the Fibonacci lattice of the unit square -> the disc
/// -> the hemisphere. A lattice, not a grid of stratum centres: a grid's rows
/// and columns alias with straight aperture edges (a window seen from inside
/// was 15% off at 1024 samples, converging erratically). Tabulated once:
/// every sky point of a solve turns the same m directions into its frame.
std::vector<Vec3> DirectLighting::MakeSkyLattice(int m)
{
  std::vector<Vec3> lattice(static_cast<std::size_t>(m));
  for (int i = 0; i < m; ++i)
  {
    const double u1 = (i + 0.5) / m;
    const double u2 = std::fmod(i * 0.6180339887498949, 1.0);
    const double r = std::sqrt(u1), phi = 2.0 * Pi * u2;
    lattice[static_cast<std::size_t>(i)] = Vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(1.0 - u1));
  }
  return lattice;
}

void DirectLighting::SkyVisibility(const Vec3& x, const Vec3& n, std::uint64_t* mask) const
{
  const int m = this->SkySampleCount;
  std::fill(mask, mask + this->SkyMaskWords(), 0);
  Vec3 t, b;
  FrameAround(n, t, b);
  const double far = this->FarDistance(x);
  const Vec3 origin = this->RayOrigin(x, n);
  std::vector<Vec3> from(m, origin), to(m);
  for (int i = 0; i < m; ++i)
  {
    to[i] = x + far * SkyDirection(this->SkyLattice[static_cast<std::size_t>(i)], t, b, n);
  }
  std::vector<unsigned char> visible(m, 0);
  this->Occluders->TestSegments(from.data(), to.data(), from.size(), visible.data());
  for (int i = 0; i < m; ++i)
  {
    if (visible[i])
    {
      mask[i / 64] |= std::uint64_t(1) << (i % 64);
    }
  }
}

DirectLighting::SkyMoments DirectLighting::SkyMomentsOf(const Vec3& n, const std::uint64_t* mask) const
{
  const int m = this->SkySampleCount;
  Vec3 t, b;
  FrameAround(n, t, b);
  SkyMoments out;
  for (int i = 0; i < m; ++i)
  {
    if (mask[i / 64] >> (i % 64) & 1)
    {
      const Vec3 w = SkyDirection(this->SkyLattice[static_cast<std::size_t>(i)], t, b, n);
      const double c = glm::dot(w, this->Set.SkyLight.Up);
      if (c > 0.0)
      {
        out.Count += 1.0;
        out.Cosines += c;
      }
    }
  }
  return out;
}

RGB DirectLighting::SkyIrradianceFromMoments(const SkyMoments& moments) const
{
  const Sky& sky = this->Set.SkyLight;
  const int m = this->SkySampleCount;
  switch (this->HasSky() ? sky.Model : SkyModel::None)
  {
    case SkyModel::Uniform:
      return (Pi / m) * moments.Count * sky.Radiance;
    case SkyModel::CieOvercast:
      return (Pi / m) * ((moments.Count + 2.0 * moments.Cosines) / 3.0) * sky.Radiance;
    case SkyModel::None:
      break;
  }
  return RGB(0.0);
}

void DirectLighting::SkyFirstHits(const Vec3& x, const Vec3& n, std::uint32_t* triangles) const
{
  const int m = this->SkySampleCount;
  Vec3 t, b;
  FrameAround(n, t, b);
  const double far = this->FarDistance(x);
  const Vec3 origin = this->RayOrigin(x, n);
  thread_local std::vector<Vec3> from, to;
  thread_local std::vector<int> direction;
  thread_local std::vector<std::uint32_t> hits;
  from.clear();
  to.clear();
  direction.clear();
  std::fill(triangles, triangles + 64 * this->SkyMaskWords(), Visibility::NoHit);
  for (int i = 0; i < m; ++i)
  {
    const Vec3 w = SkyDirection(this->SkyLattice[static_cast<std::size_t>(i)], t, b, n);
    if (MaxComponent(SkyRadiance(this->Set.SkyLight, w)) > 0.0)
    {
      from.push_back(origin);
      to.push_back(x + far * w);
      direction.push_back(i);
    }
  }
  hits.resize(from.size());
  this->Occluders->FirstHits(from.data(), to.data(), from.size(), hits.data());
  for (std::size_t k = 0; k < hits.size(); ++k)
  {
    triangles[direction[k]] = hits[k];
  }
}

void DirectLighting::SkyQuadrature(const Vec3& n, std::vector<Vec3>& directions) const
{
  Vec3 t, b;
  FrameAround(n, t, b);
  directions.resize(this->SkyLattice.size());
  for (std::size_t i = 0; i < directions.size(); ++i)
  {
    directions[i] = SkyDirection(this->SkyLattice[i], t, b, n);
  }
}

DirectLighting::SkyDirectionSet DirectLighting::SkyDirections(const Vec3& n, const std::uint64_t* hidden) const
{
  SkyDirectionSet set;
  this->FillSkyDirections(n, hidden, set);
  return set;
}

void DirectLighting::FillSkyDirections(const Vec3& n, const std::uint64_t* hidden, SkyDirectionSet& set) const
{
  set.Direction.clear();
  set.Radiance.clear();
  if (!this->HasSky())
  {
    return;
  }
  Vec3 t, b;
  FrameAround(n, t, b);
  const int m = this->SkySampleCount;
  for (int i = 0; i < m; ++i)
  {
    if (hidden && (hidden[i / 64] >> (i % 64) & 1))
    {
      continue;
    }
    const Vec3 w = SkyDirection(this->SkyLattice[static_cast<std::size_t>(i)], t, b, n);
    const RGB l = SkyRadiance(this->Set.SkyLight, w);
    if (MaxComponent(l) > 0.0)
    {
      set.Direction.push_back(w);
      set.Radiance.push_back(l);
    }
  }
}

RGB DirectLighting::SkyIrradiance(const Vec3& x, const Vec3& n, const std::uint64_t* hidden) const
{
  if (!this->HasSky())
  {
    return RGB(0.0);
  }
  // Per thread, kept between calls (the solve's light links ask this at
  // seven points of every node).
  thread_local SkyDirectionSet directions;
  this->FillSkyDirections(n, hidden, directions);
  return this->SkyIrradiance(x, n, directions);
}

RGB DirectLighting::SkyIrradiance(const Vec3& x, const Vec3& n, const SkyDirectionSet& directions) const
{
  if (!this->HasSky())
  {
    return RGB(0.0);
  }
  const double far = this->FarDistance(x);
  const Vec3 origin = this->RayOrigin(x, n);
  // Per thread, kept between calls: the mesher asks this of every sample.
  thread_local std::vector<Vec3> from, to;
  thread_local std::vector<unsigned char> visible;
  const std::size_t count = directions.Direction.size();
  from.assign(count, origin);
  to.resize(count);
  for (std::size_t k = 0; k < count; ++k)
  {
    to[k] = x + far * directions.Direction[k];
  }
  visible.assign(count, 0);
  this->Occluders->TestSegments(from.data(), to.data(), count, visible.data());
  RGB sum(0.0);
  for (std::size_t k = 0; k < count; ++k)
  {
    if (visible[k])
    {
      sum += directions.Radiance[k];
    }
  }
  return (Pi / this->SkySampleCount) * sum;
}

std::array<Vec3, 3> DirectLighting::IrradianceVector(const Vec3& x, const Vec3& n, bool withSky) const
{
  std::array<Vec3, 3> out = this->PunctualVectorSeenFrom(x, x, n);
  if (withSky && this->HasSky())
  {
    const RGB sky = this->SkyIrradiance(x, n);
    for (int k = 0; k < 3; ++k)
    {
      out[k] += sky[k] * n;
    }
  }
  return out;
}

std::array<Vec3, 3> DirectLighting::PunctualVectorSeenFrom(
  const Vec3& x, const Vec3& visibilityPoint, const Vec3& n) const
{
  std::array<Vec3, 3> out{ Vec3(0.0), Vec3(0.0), Vec3(0.0) };
  const Vec3 origin = this->RayOrigin(visibilityPoint, n);
  const double far = this->FarDistance(visibilityPoint);
  for (const Light& light : this->Set.Lights)
  {
    const RGB h = UnshadowedIrradiance(light, x, n);
    if (!(MaxComponent(h) > 0.0))
    {
      continue;
    }
    const Vec3 target = ShadowRayTarget(light, visibilityPoint, far);
    unsigned char visible = 0;
    this->Occluders->TestSegments(&origin, &target, 1, &visible);
    if (!visible)
    {
      continue;
    }
    const Vec3 towards = light.Type == LightType::Directional ? -light.Direction
                                                              : glm::normalize(light.Position - x);
    const double c = glm::dot(n, towards); // > 0: UnshadowedIrradiance is zero behind the surface
    for (int k = 0; k < 3; ++k)
    {
      out[k] += (h[k] / c) * towards;
    }
  }
  return out;
}

DirectLighting::PowerEstimate DirectLighting::EstimatePower(std::size_t maxTriangles) const
{
  PowerEstimate result;
  const Scene& scene = this->SourceScene;
  const std::size_t nt = scene.Triangles.size();
  if (this->Empty() || nt == 0)
  {
    return result;
  }
  const std::size_t stride = std::max<std::size_t>(1, (nt + maxTriangles - 1) / std::max<std::size_t>(maxTriangles, 1));
  std::vector<std::size_t> chosen;
  for (std::size_t t = 0; t < nt; t += stride)
  {
    chosen.push_back(t);
  }
  std::vector<RGB> h(chosen.size());
  tbb::parallel_for(std::size_t(0), chosen.size(), [&](std::size_t i) {
    h[i] = this->Irradiance(scene.Centroid(chosen[i]), scene.Normal(chosen[i]));
  });
  double sampledArea = 0.0, totalArea = 0.0, power = 0.0;
  for (std::size_t i = 0; i < chosen.size(); ++i)
  {
    const double a = scene.Area(chosen[i]);
    sampledArea += a;
    power += Mean(h[i]) * a;
    result.PeakIrradiance = std::max(result.PeakIrradiance, MaxComponent(h[i]));
  }
  for (std::size_t t = 0; t < nt; ++t)
  {
    totalArea += scene.Area(t);
  }
  result.Power = sampledArea > 0.0 ? power * totalArea / sampledArea : 0.0;
  return result;
}

void DirectLighting::Evaluate(const Vec3* x, const Vec3* n, std::size_t count, RGB* out) const
{
  if (this->Empty())
  {
    std::fill(out, out + count, RGB(0.0));
    return;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 64),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      for (std::size_t i = r.begin(); i != r.end(); ++i)
      {
        out[i] = this->Irradiance(x[i], n[i]);
      }
    });
}

std::vector<RGB> DirectLighting::ReceivedPower() const
{
  const std::size_t lights = this->Set.Lights.size();
  std::vector<RGB> power(lights + (this->HasSky() ? 1 : 0), RGB(0.0));
  if (this->Empty())
  {
    return power;
  }
  const Scene& scene = this->SourceScene;
  const std::size_t nt = scene.Triangles.size();
  // The centroids of each triangle's n x n midpoint subdivision (n = 8 for
  // up to 2,000 triangles, 4 up to 20,000, else 1: the centroid rule put
  // 12.3 W on a two-triangle floor that receives 7.4 W), and at most 20,000
  // triangles, an even subset scaled by area beyond.
  const std::size_t stride = std::max<std::size_t>(1, (nt + 19999) / 20000);
  const int n = nt <= 2000 ? 8 : (nt <= 20000 ? 4 : 1);
  std::vector<std::size_t> chosen;
  for (std::size_t t = 0; t < nt; t += stride)
  {
    chosen.push_back(t);
  }
  std::vector<std::vector<RGB>> perTriangle(chosen.size());
  tbb::parallel_for(std::size_t(0), chosen.size(),
    [&](std::size_t k)
    {
      const std::size_t tri = chosen[k];
      const Vec3 a = scene.Vertex(tri, 0), e1 = scene.Vertex(tri, 1) - a, e2 = scene.Vertex(tri, 2) - a;
      const Vec3 nrm = scene.Normal(tri);
      const double w = scene.Area(tri) / (n * n);
      std::vector<RGB>& row = perTriangle[k];
      row.assign(power.size(), RGB(0.0));
      for (int i = 0; i < n; ++i)
      {
        for (int j = 0; i + j < n; ++j)
        {
          // The upright sub-triangle (i, j) and, where there is one, the inverted one beside it.
          for (int flip = 0; flip < (i + j < n - 1 ? 2 : 1); ++flip)
          {
            const double u = (i + (flip ? 2.0 : 1.0) / 3.0) / n, v = (j + (flip ? 2.0 : 1.0) / 3.0) / n;
            const Vec3 x = a + u * e1 + v * e2;
            for (std::size_t l = 0; l < lights; ++l)
            {
              row[l] += w * this->PunctualOne(l, x, nrm);
            }
            if (this->HasSky())
            {
              row[lights] += w * this->SkyIrradiance(x, nrm);
            }
          }
        }
      }
    });
  double sampledArea = 0.0, totalArea = 0.0;
  for (std::size_t k = 0; k < chosen.size(); ++k)
  {
    sampledArea += scene.Area(chosen[k]);
    for (std::size_t l = 0; l < power.size(); ++l)
    {
      power[l] += perTriangle[k][l];
    }
  }
  for (std::size_t t = 0; t < nt; ++t)
  {
    totalArea += scene.Area(t);
  }
  for (RGB& p : power)
  {
    p *= sampledArea > 0.0 ? totalArea / sampledArea : 0.0;
  }
  return power;
}

Vec3 VisibilityPointToward(double offset, const Vec3& x, const Vec3& inner, double fraction)
{
  const double distance = glm::length(inner - x);
  if (!(distance > 0.0))
  {
    return x;
  }
  const double t = std::min(std::max(4.0 * offset / distance, fraction), 0.5);
  return x + t * (inner - x);
}

Vec3 SharedVertexPoint(double offset, const Scene& scene, std::size_t source, const Vec3& x)
{
  // Within 1e-5 of its size of an edge: the corner samples sit 1e-6 of their element inside.
  const Vec3 a = scene.Vertex(source, 0), b = scene.Vertex(source, 1), c = scene.Vertex(source, 2);
  const double size = std::max({ glm::length(b - a), glm::length(c - b), glm::length(a - c) });
  const double nearest = std::min({ DistanceToSegment(x, a, b), DistanceToSegment(x, b, c), DistanceToSegment(x, c, a) });
  return nearest <= 1e-5 * size ? VisibilityPointToward(offset, x, scene.Centroid(source), 0.0) : x;
}

Vec3 RayOriginOff(double offset, const Vec3& x, const Vec3& n)
{
  // Off the surface along its normal by a hundredth of Visibility's offset
  // (1e-7 of the scene's size, a few float ulps): TestSegments also shortens
  // the segment by the offset along the ray, which keeps it off its own
  // triangle without moving the shadow; a full offset along the normal would
  // move every hard shadow edge by about that much (1e-5 of the scene).
  return x + 0.01 * offset * n;
}

Vec3 DirectLighting::VisibilityPoint(const Vec3& x, const Vec3& inner, double fraction) const
{
  return VisibilityPointToward(this->Occluders ? this->Occluders->Offset() : 0.0, x, inner, fraction);
}

Vec3 DirectLighting::SharedVertexVisibility(const Scene& scene, std::size_t source, const Vec3& x) const
{
  return SharedVertexPoint(this->Occluders ? this->Occluders->Offset() : 0.0, scene, source, x);
}

Vec3 DirectLighting::RayOrigin(const Vec3& x, const Vec3& n) const
{
  return RayOriginOff(this->Occluders->Offset(), x, n);
}

std::size_t DirectLighting::RaysCast() const
{
  return this->Occluders ? this->Occluders->RaysCast() : 0;
}

LightSet ScaledLights(const LightSet& lights, double scale)
{
  LightSet out = lights;
  for (Light& l : out.Lights)
  {
    l.Intensity *= scale;
  }
  out.SkyLight.Radiance *= scale;
  return out;
}
} // namespace radiosity
