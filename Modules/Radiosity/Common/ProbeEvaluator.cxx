#include "Radiosity/Common/ProbeEvaluator.h"

#include "Radiosity/Common/DirectLighting.h"
#include "Radiosity/Common/FormFactor.h"
#include "Radiosity/Common/MeshProbeTracker.h"
#include "Radiosity/Common/Visibility.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace radiosity
{
namespace
{
/// The punctual lights at an element's corners and centre, where the
/// methods sample them (the points of ElementSamples).
ElementSamples PunctualSamples(
  const DirectLighting& lights, const SolutionMesh& solution, const Scene& scene, std::size_t t)
{
  const auto& tri = solution.Triangles[t];
  const Vec3& n = solution.Normals[t];
  ElementSamples s;
  const Vec3 centre =
    (solution.Points[tri.V[0]] + solution.Points[tri.V[1]] + solution.Points[tri.V[2]]) / 3.0;
  const bool sourced = t < solution.SourceTriangle.size() && solution.SourceTriangle[t] < scene.Triangles.size();
  for (int k = 0; k < 3; ++k)
  {
    // As progressive lights its shared corner samples (on a seam from inside
    // the input triangle: DirectLighting::SharedVertexVisibility).
    const Vec3& x = solution.Points[tri.V[k]];
    s.Corner[k] = sourced
      ? lights.PunctualSeenFrom(x, lights.SharedVertexVisibility(scene, solution.SourceTriangle[t], x), n)
      : lights.Punctual(x, n);
  }
  s.Centre = lights.Punctual(centre, n);
  return s;
}

Scene AsScene(const SolutionMesh& solution)
{
  Scene s;
  s.Points = solution.Points;
  s.Triangles = solution.Triangles;
  s.Materials.resize(solution.Triangles.size());
  s.ObjectIds.assign(solution.Triangles.size(), 0);
  return s;
}

std::int64_t OnTriangle(const Scene& scene, const Visibility& rays, const Probe& probe, double tolerance)
{
  const Vec3 n = glm::normalize(probe.Normal);
  const double edgeTolerance = 1e-6;
  // A triangle the probe lies on is within `tolerance` (1e-6 of the
  // diagonal) of its plane and at most 1e-6 of an edge (so of the diagonal)
  // outside its edges: well within three tolerances of the probe.
  return rays.NearestTriangle(probe.Position, 3.0 * tolerance,
    [&](std::uint32_t e) {
      const Vec3 nt = scene.Normal(e);
      if (glm::dot(nt, n) < 0.9)
      {
        return std::numeric_limits<double>::infinity();
      }
      const Vec3 a = scene.Vertex(e, 0);
      const double dist = std::fabs(glm::dot(probe.Position - a, nt));
      double pu, pv, pw;
      if (dist > tolerance || !ProjectOnTriangle(probe.Position, a, scene.Vertex(e, 1), scene.Vertex(e, 2), pu, pv, pw) ||
        pu < -edgeTolerance || pv < -edgeTolerance || pw < -edgeTolerance)
      {
        return std::numeric_limits<double>::infinity();
      }
      return dist;
    },
    false);
}
}

ProbeEvaluator::ProbeEvaluator(const SolutionMesh& solution, const Scene& scene)
  : Solution(solution)
  , SourceScene(scene)
{
  const Scene geometry = AsScene(solution);
  this->Rays = std::make_unique<Visibility>(geometry, Visibility::AllTriangles(geometry));
  this->Tolerance = 1e-6 * std::max(geometry.Diagonal(), 1e-300);
  if (!scene.Lighting.Empty())
  {
    this->Lights = std::make_unique<DirectLighting>(scene, 4096);
  }
}

ProbeEvaluator::~ProbeEvaluator() = default;

std::vector<RGB> ProbeEvaluator::Evaluate(const std::vector<Probe>& probes) const
{
  return this->Evaluate(probes, SurfaceValue());
}

std::vector<RGB> ProbeEvaluator::Evaluate(const std::vector<Probe>& probes, const SurfaceValue& onSurface) const
{
  std::vector<RGB> values(probes.size(), RGB(0.0));
  std::atomic<std::size_t> gathered{ 0 };
  const Scene geometry = AsScene(this->Solution);
  tbb::parallel_for(std::size_t(0), probes.size(),
    [&](std::size_t i)
    {
      const Probe& probe = probes[i];
      const Vec3 n = glm::normalize(probe.Normal);
      double u = 0, v = 0, w = 0;
      // The element whose plane is nearest among those the probe lies on and
      // that face its normal (the Embree point query over the elements).
      const std::int64_t t = OnTriangle(geometry, *this->Rays, Probe{ probe.Position, n }, this->Tolerance);
      if (t < 0)
      {
        values[i] = this->Gather(Probe{ probe.Position, n });
        ++gathered;
        return;
      }
      if (onSurface)
      {
        const std::uint32_t source =
          t < static_cast<std::int64_t>(this->Solution.SourceTriangle.size()) ? this->Solution.SourceTriangle[t] : 0;
        values[i] = onSurface(source, probe.Position, n);
        return;
      }
      const auto& tri = this->Solution.Triangles[t];
      ProjectOnTriangle(probe.Position, this->Solution.Points[tri.V[0]], this->Solution.Points[tri.V[1]],
        this->Solution.Points[tri.V[2]], u, v, w);
      values[i] = InterpolateSamples(this->Solution.Samples[t], u, v, w);
      if (this->ExactPunctual && this->Lights && this->Lights->HasPunctualLights())
      {
        values[i] += this->Lights->Punctual(probe.Position, this->Solution.Normals[t]) -
          InterpolateSamples(PunctualSamples(*this->Lights, this->Solution, this->SourceScene, t), u, v, w);
      }
    });
  this->Gathered = gathered;
  return values;
}

RGB ProbeEvaluator::Gather(const Probe& probe) const
{
  RGB h(0.0);
  const Vec3 origin = probe.Position + this->Rays->Offset() * probe.Normal;
  for (std::size_t t = 0; t < this->Solution.Triangles.size(); ++t)
  {
    const RGB& b = this->Solution.CellRadiosity[t];
    if (MaxComponent(b) <= 0)
    {
      continue;
    }
    const auto& tri = this->Solution.Triangles[t];
    const Vec3 poly[3] = { this->Solution.Points[tri.V[0]], this->Solution.Points[tri.V[1]],
      this->Solution.Points[tri.V[2]] };
    const double f = PointToPolygonFormFactor(probe.Position, probe.Normal, poly, 3);
    if (f <= 0)
    {
      continue;
    }
    const Vec3 centre = (poly[0] + poly[1] + poly[2]) / 3.0;
    unsigned char visible = 1;
    this->Rays->TestSegments(&origin, &centre, 1, &visible);
    if (visible)
    {
      h += f * b;
    }
  }
  if (this->Lights)
  {
    h += this->Lights->Irradiance(probe.Position, probe.Normal);
  }
  return h;
}

std::vector<RGB> EvaluateOnNearestTriangles(const Scene& scene, const std::vector<Probe>& probes,
  const std::function<RGB(std::uint32_t triangle, const Vec3& x, const Vec3& n)>& at,
  const Visibility* allTriangles)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<RGB> values(probes.size(), RGB(nan));
  std::unique_ptr<Visibility> built;
  if (!allTriangles)
  {
    built = std::make_unique<Visibility>(scene, Visibility::AllTriangles(scene));
    allTriangles = built.get();
  }
  tbb::parallel_for(std::size_t(0), probes.size(), [&](std::size_t i) {
    const Vec3 n = glm::normalize(probes[i].Normal);
    const Vec3& x = probes[i].Position;
    // The Euclidean distance to each facing triangle (its nearest edge when
    // the foot is off it), minimised by an Embree point query that shrinks.
    const std::int64_t nearest = allTriangles->NearestTriangle(x, std::numeric_limits<double>::infinity(),
      [&](std::uint32_t t) {
        if (glm::dot(scene.Normal(t), n) <= 0)
        {
          return std::numeric_limits<double>::infinity();
        }
        double u, v, w;
        if (!ProjectOnTriangle(x, scene.Vertex(t, 0), scene.Vertex(t, 1), scene.Vertex(t, 2), u, v, w))
        {
          return std::numeric_limits<double>::infinity();
        }
        const Vec3 corner[3] = { scene.Vertex(t, 0), scene.Vertex(t, 1), scene.Vertex(t, 2) };
        if (u >= 0.0 && v >= 0.0 && w >= 0.0)
        {
          return glm::length(x - (u * corner[0] + v * corner[1] + w * corner[2]));
        }
        double d = std::numeric_limits<double>::infinity(); // off the triangle: its nearest edge
        for (int k = 0; k < 3; ++k)
        {
          d = std::min(d, DistanceToSegment(x, corner[k], corner[(k + 1) % 3]));
        }
        return d;
      },
      true);
    if (nearest >= 0)
    {
      values[i] = at(static_cast<std::uint32_t>(nearest), x, n);
    }
  });
  return values;
}

std::vector<RGB> EvaluateSensorsOnInputTriangles(const std::function<SolutionMesh()>& surface, const Scene& scene,
  const std::vector<Probe>& probes,
  const std::function<std::vector<RGB>(const std::vector<Probe>&)>& onTriangles, std::size_t* gathered)
{
  // Which sensors lie on an input triangle, by ProbeEvaluator's rule, found
  // over the input triangles themselves: the surface (a whole evaluation of
  // the solution, the lights exact at its samples: minutes on a large
  // scene) is made only for the sensors in the air that gather it.
  const Visibility rays(scene, Visibility::AllTriangles(scene));
  const double tolerance = 1e-6 * std::max(scene.Diagonal(), 1e-300);
  std::vector<char> onSurface(probes.size(), 0);
  tbb::parallel_for(std::size_t(0), probes.size(), [&](std::size_t i) {
    onSurface[i] = OnTriangle(scene, rays, probes[i], tolerance) >= 0;
  });
  std::vector<Probe> on, off;
  std::vector<std::size_t> onIndex, offIndex;
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    (onSurface[i] ? on : off).push_back(probes[i]);
    (onSurface[i] ? onIndex : offIndex).push_back(i);
  }
  std::vector<RGB> values(probes.size(), RGB(0.0));
  std::size_t count = 0;
  if (!off.empty())
  {
    // The sensors in the air are gathered from the surface; any the
    // evaluator still finds on it (NaN) join the method's own.
    const SolutionMesh mesh = surface();
    const ProbeEvaluator evaluator(mesh, scene);
    const std::vector<RGB> fromSurface = evaluator.Evaluate(off,
      [](std::uint32_t, const Vec3&, const Vec3&) { return RGB(std::numeric_limits<double>::quiet_NaN()); });
    count = evaluator.GatheredCount();
    for (std::size_t k = 0; k < off.size(); ++k)
    {
      if (std::isnan(fromSurface[k].x))
      {
        on.push_back(off[k]);
        onIndex.push_back(offIndex[k]);
      }
      else
      {
        values[offIndex[k]] = fromSurface[k];
      }
    }
  }
  const std::vector<RGB> fromMethod = onTriangles(on);
  for (std::size_t k = 0; k < onIndex.size(); ++k)
  {
    values[onIndex[k]] = fromMethod[k];
  }
  if (gathered)
  {
    *gathered = count;
  }
  return values;
}
} // namespace radiosity
