#include "Radiosity/Common/DirectLighting.h"

#include "Radiosity/Common/Visibility.h"

#include <tbb/parallel_for.h>

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

DirectLighting::DirectLighting(const Scene& scene, int skySamples)
  : SourceScene(scene)
  , Set(scene.Lighting)
{
  this->SkyStrata = std::max(2, static_cast<int>(std::lround(std::sqrt(std::max(skySamples, 4)))));
  if (!scene.Triangles.empty())
  {
    Vec3 lo, hi;
    scene.BoundingBox(lo, hi);
    this->Centre = 0.5 * (lo + hi);
    this->Extent = std::max(glm::length(hi - lo), 1e-300);
  }
  if (!this->Set.Empty())
  {
    this->Occluders = std::make_unique<Visibility>(scene, Visibility::AllTriangles(scene));
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
  const Vec3 target = ShadowRayTarget(light, x, this->FarDistance(x));
  unsigned char visible = 1;
  this->Occluders->TestSegments(&x, &target, 1, &visible);
  return visible ? h : RGB(0.0);
}

RGB DirectLighting::Punctual(const Vec3& x, const Vec3& n) const
{
  const std::size_t count = this->Set.Lights.size();
  if (count == 0)
  {
    return RGB(0.0);
  }
  std::vector<Vec3> from, to;
  std::vector<RGB> contribution;
  from.reserve(count);
  to.reserve(count);
  contribution.reserve(count);
  const double far = this->FarDistance(x);
  for (const Light& light : this->Set.Lights)
  {
    const RGB h = UnshadowedIrradiance(light, x, n);
    if (MaxComponent(h) > 0.0)
    {
      from.push_back(x);
      to.push_back(ShadowRayTarget(light, x, far));
      contribution.push_back(h);
    }
  }
  std::vector<unsigned char> visible(from.size(), 0);
  this->Occluders->TestSegments(from.data(), to.data(), from.size(), visible.data());
  RGB sum(0.0);
  for (std::size_t i = 0; i < from.size(); ++i)
  {
    if (visible[i])
    {
      sum += contribution[i];
    }
  }
  return sum;
}

RGB DirectLighting::SkyIrradiance(const Vec3& x, const Vec3& n) const
{
  if (!this->HasSky())
  {
    return RGB(0.0);
  }
  const Sky& sky = this->Set.SkyLight;
  Vec3 t, b;
  FrameAround(n, t, b);
  const int m = this->SkyStrata;
  const double far = this->FarDistance(x);
  std::vector<Vec3> from, to;
  std::vector<RGB> radiance;
  from.reserve(m * m);
  to.reserve(m * m);
  radiance.reserve(m * m);
  for (int i = 0; i < m; ++i)
  {
    for (int j = 0; j < m; ++j)
    {
      // Malley: a stratum centre of the unit square -> the disc -> the hemisphere.
      const double u1 = (i + 0.5) / m, u2 = (j + 0.5) / m;
      const double r = std::sqrt(u1), phi = 2.0 * Pi * u2;
      const Vec3 w = r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(1.0 - u1) * n;
      const RGB l = SkyRadiance(sky, w);
      if (MaxComponent(l) > 0.0)
      {
        from.push_back(x);
        to.push_back(x + far * w);
        radiance.push_back(l);
      }
    }
  }
  std::vector<unsigned char> visible(from.size(), 0);
  this->Occluders->TestSegments(from.data(), to.data(), from.size(), visible.data());
  RGB sum(0.0);
  for (std::size_t k = 0; k < from.size(); ++k)
  {
    if (visible[k])
    {
      sum += radiance[k];
    }
  }
  return (Pi / (m * m)) * sum;
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
  std::vector<std::vector<RGB>> perTriangle(nt);
  tbb::parallel_for(std::size_t(0), nt,
    [&](std::size_t tri)
    {
      const Vec3 c = scene.Centroid(tri), nrm = scene.Normal(tri);
      const double a = scene.Area(tri);
      std::vector<RGB>& row = perTriangle[tri];
      row.assign(power.size(), RGB(0.0));
      for (std::size_t l = 0; l < lights; ++l)
      {
        row[l] = a * this->PunctualOne(l, c, nrm);
      }
      if (this->HasSky())
      {
        row[lights] = a * this->SkyIrradiance(c, nrm);
      }
    });
  for (const auto& row : perTriangle)
  {
    for (std::size_t l = 0; l < power.size(); ++l)
    {
      power[l] += row[l];
    }
  }
  return power;
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
