#include "Radiosity/Hierarchical/DiscontinuityMesher.h"

#include "Radiosity/Hierarchical/CriticalSurfaces.h"
#include "Radiosity/Hierarchical/DiscontinuityMeshWork.h"
#include "Radiosity/Hierarchical/EdgeTopology.h"
#include "Radiosity/Hierarchical/HardShadowEdges.h"
#include "Radiosity/Hierarchical/LinkChain.h"
#include "Radiosity/Common/FormFactor.h"
#include "Radiosity/Common/MeshProbeTracker.h"
#include "Radiosity/Hierarchical/Shaft.h"
#include "Radiosity/Common/Stopwatch.h"
#include "Radiosity/Common/Visibility.h"
#include "Radiosity/Common/ThreadLimit.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>

namespace radiosity
{
using namespace discontinuity_mesh_detail;

namespace
{
/// On a leaf's boundary a sample can lie in a neighbour's plane (a contact
/// edge, the shared edge of a tessellated sphere), where the form factor of
/// that neighbour jumps to 0; the interpolant needs the limit from inside the
/// leaf, so samples are moved towards its centroid by a relative 1e-7.
Vec3 Inside(const Vec3& x, const Vec3& centroid)
{
  return x + 1e-7 * (centroid - x);
}


/// The kept discontinuity segments of one leaf (section 4.2).
std::vector<std::array<Vec3, 2>> LeafDiscontinuities(const HierarchicalRadiosity& s,
  const EdgeTopology& topology, std::uint32_t leaf, const DiscontinuityMeshOptions& options,
  double minWeight, std::size_t& found)
{
  const ElementMesh& mesh = s.Mesh();
  const Scene& scene = s.GetScene();
  // Most leaves of a large scene have no partial link in their chain: no map.
  bool partial = false;
  for (std::int32_t a = static_cast<std::int32_t>(leaf); a >= 0 && !partial;
       a = mesh[static_cast<std::uint32_t>(a)].Parent)
  {
    for (std::uint32_t i : s.LinksOf(static_cast<std::uint32_t>(a)))
    {
      partial = partial || s.Links()[i].Kind == HierarchicalLink::Partial;
    }
  }
  if (!partial)
  {
    return {};
  }
  // Sources are the input triangles behind partial links (a subdivided light
  // casts its discontinuities from its own edges, not from its quadtree's).
  std::map<std::uint32_t, std::pair<double, std::vector<std::uint32_t>>> sources;
  for (std::int32_t a = static_cast<std::int32_t>(leaf); a >= 0;
       a = mesh[static_cast<std::uint32_t>(a)].Parent)
  {
    for (std::uint32_t i : s.LinksOf(static_cast<std::uint32_t>(a)))
    {
      const HierarchicalLink& l = s.Links()[i];
      if (l.Kind != HierarchicalLink::Partial)
      {
        continue;
      }
      auto& entry = sources[mesh[l.Source].Source];
      entry.first = std::max(entry.first, MaxComponent(s.Radiosity(l.Source)));
      entry.second.insert(entry.second.end(), s.Blockers(l), s.Blockers(l) + l.BlockerCount);
    }
  }
  std::vector<DiscontinuitySegment> segments;
  const TriangleCorners receiver = s.Corners(leaf);
  const double minLength = 1e-4 * mesh.LongestEdge(leaf);
  for (auto& [source, entry] : sources)
  {
    if (entry.first < minWeight * 1e-6)
    {
      continue; // cannot reach w_min: the geometric factor is capped at 1e6
    }
    std::sort(entry.second.begin(), entry.second.end());
    entry.second.erase(std::unique(entry.second.begin(), entry.second.end()), entry.second.end());
    const TriangleCorners polygon = { scene.Vertex(source, 0), scene.Vertex(source, 1),
      scene.Vertex(source, 2) };
    const Shaft shaft(receiver, polygon);
    entry.second.erase(std::remove_if(entry.second.begin(), entry.second.end(),
                         [&](std::uint32_t b) {
                           return shaft.Excludes(
                             { scene.Vertex(b, 0), scene.Vertex(b, 1), scene.Vertex(b, 2) });
                         }),
      entry.second.end());
    if (entry.second.empty())
    {
      continue;
    }
    const std::array<bool, 3> edges = { !topology.InteriorEmitterEdge(source, 0),
      !topology.InteriorEmitterEdge(source, 1), !topology.InteriorEmitterEdge(source, 2) };
    FindCriticalSegments(receiver, mesh[leaf].Normal, polygon, entry.first,
      topology.Silhouette(entry.second), minLength, segments, edges, minWeight);
  }
  found += segments.size();
  segments.erase(std::remove_if(segments.begin(), segments.end(),
                   [&](const DiscontinuitySegment& d) { return !(d.Weight >= minWeight); }),
    segments.end());
  std::sort(segments.begin(), segments.end(),
    [](const DiscontinuitySegment& a, const DiscontinuitySegment& b) { return a.Weight > b.Weight; });
  if (segments.size() > static_cast<std::size_t>(options.MaxPerLeaf))
  {
    segments.resize(static_cast<std::size_t>(options.MaxPerLeaf));
  }
  std::vector<std::array<Vec3, 2>> kept;
  for (const DiscontinuitySegment& d : segments)
  {
    kept.push_back({ d.A, d.B });
  }
  return kept;
}

} // namespace

discontinuity_mesh_detail::LeafWorks::LeafWorks(std::size_t n)
  : Chunks((n + ChunkSize - 1) / ChunkSize)
  , Size(n)
{
  tbb::parallel_for(std::size_t(0), this->Chunks.size(),
    [&](std::size_t c) { this->Chunks[c] = std::make_unique<LeafWork[]>(ChunkSize); });
}

discontinuity_mesh_detail::LeafWorks::~LeafWorks()
{
  tbb::parallel_for(std::size_t(0), this->Chunks.size(), [&](std::size_t c) { this->Chunks[c].reset(); });
}

RGB AccuratePointIrradiance(
  const HierarchicalRadiosity& solution, std::uint32_t leaf, const Vec3& x, const Vec3& n)
{
  return ChainIrradiance(GatherChain(solution, leaf), x, n) + solution.DirectLight(x, n) +
    solution.ClusterIrradiance(leaf);
}

DiscontinuityMesh BuildDiscontinuityMesh(const HierarchicalRadiosity& s,
  const DiscontinuityMeshOptions& options, const ProgressCallback& progress)
{
  const Stopwatch clock;
  // The thread limit applies to this solve alone (a task arena of its own).
  return RunWithThreads(options.Threads, [&]() -> DiscontinuityMesh {
    DiscontinuityMesh out;
    const ElementMesh& mesh = s.Mesh();
    const Scene& scene = s.GetScene();
    const std::vector<std::uint32_t> leaves = mesh.Leaves();
    double brightest = 0.0;
    for (const Material& m : scene.Materials)
    {
      brightest = std::max(brightest, MaxComponent(m.Emission));
    }
    // A scene lit by lights and the sky alone has no emitter: w_min is then
    // relative to the brightest surface's radiosity (what the lights put
    // there), where 0 would keep every discontinuity however faint.
    if (!(brightest > 0.0))
    {
      for (std::uint32_t e = 0; e < static_cast<std::uint32_t>(mesh.Elements().size()); ++e)
      {
        brightest = std::max(brightest, MaxComponent(s.Radiosity(e)));
      }
    }
    const double minWeight = options.MinWeight * brightest;
    const EdgeTopology topology(scene);
    // The lights' hard shadow boundaries (D0) come before every EV/VE event.
    const DirectLighting* lights = s.GetDirectLighting();
    std::unique_ptr<HardShadowEdges> hardShadows;
    if (options.Discontinuities && lights && lights->HasPunctualLights())
    {
      hardShadows = std::make_unique<HardShadowEdges>(
        scene, *lights->ShadowRays(), 4.0 * std::max(s.Analysis().Diagonal, 1e-300));
    }
    auto report = [&](const char* phase, double fraction) {
      if (!progress)
      {
        return true;
      }
      ProgressStatus status;
      status.Phase = phase;
      status.Fraction = fraction;
      return progress(status);
    };

    // Phase 1: discontinuities and triangulations, per leaf.
    LeafWorks work(leaves.size());
    std::vector<std::size_t> found(leaves.size(), 0), kept(leaves.size(), 0);
    // In blocks of leaves, so that progress and an abort are seen between
    // them (on this thread) and not only after the whole phase.
    constexpr std::size_t Block = 256;
    for (std::size_t begin = 0; begin < leaves.size(); begin += Block)
    {
      if (!report("finding discontinuities", 0.3 * static_cast<double>(begin) / static_cast<double>(leaves.size())))
      {
        return out;
      }
      const std::size_t end = std::min(leaves.size(), begin + Block);
      // Half the time limit for the search, the rest for the samples.
      const bool search =
        options.Discontinuities && !(options.MaxSeconds > 0.0 && clock.Seconds() >= 0.5 * options.MaxSeconds);
      if (options.Discontinuities && !search)
      {
        out.LeavesPastTimeLimit += end - begin;
      }
      tbb::parallel_for(begin, end, [&](std::size_t i) {
        const std::uint32_t leaf = leaves[i];
        const TriangleCorners corners = s.Corners(leaf);
        std::vector<std::array<Vec3, 2>> segments;
        if (search)
        {
          if (hardShadows)
          {
            const double minLength = 1e-4 * mesh.LongestEdge(leaf);
            for (const Light& light : lights->Lights().Lights)
            {
              hardShadows->Find(light, corners, mesh[leaf].Normal, minLength, work[i].HardSegments);
            }
            found[i] += work[i].HardSegments.size();
          }
          // A boundary along the leaf's own edge splits no triangle: it is kept
          // for the per-side samples only, not as a constraint.
          const double onEdge = 1e-6 * mesh.LongestEdge(leaf);
          for (const auto& seg : work[i].HardSegments)
          {
            bool alongEdge = false;
            for (int k = 0; k < 3 && !alongEdge; ++k)
            {
              bool inside = false;
              alongEdge = EdgeDistance(seg[0], corners[k], corners[(k + 1) % 3], inside, 0.0) < onEdge &&
                EdgeDistance(seg[1], corners[k], corners[(k + 1) % 3], inside, 0.0) < onEdge;
            }
            if (!alongEdge)
            {
              segments.push_back(seg);
            }
          }
          const auto events = LeafDiscontinuities(s, topology, leaf, options, minWeight, found[i]);
          segments.insert(segments.end(), events.begin(), events.end());
          kept[i] = segments.size();
        }
        work[i].Mesh = segments.empty()
          ? PlanarTriangulation{ { corners[0], corners[1], corners[2] }, { { 0u, 1u, 2u } } }
          : TriangulateWithConstraints(corners, segments);
        work[i].Segments = std::move(segments);
      });
    }
    if (options.Conforming)
    {
      out.LeavesConformed = ConformBoundaries(s, leaves, work);
    }
    out.DiscontinuitySeconds = clock.Seconds();
    if (!report("meshing", 0.3))
    {
      return out;
    }

    // Phase 2: sample keys (DiscontinuityMeshSamples.cxx).
    for (std::size_t i = 0; i < leaves.size(); ++i)
    {
      out.SegmentsFound += found[i];
      out.SegmentsKept += kept[i];
      out.LeavesMeshed += kept[i] > 0;
      out.LeavesTriangulationFailed += work[i].Mesh.ConstraintsDropped;
    }
    const SharedSamples shared = ReferenceSamples(s, leaves, work);
    const std::vector<Vec3>& sharedPoints = shared.Points;

    // Phase 3: accurate point irradiance, shared samples grouped by owner leaf.
    const double samplesStart = clock.Seconds();
    // The shared samples of each owner: a run of them, as they are numbered in leaf order.
    std::vector<std::uint32_t> ownedStart(leaves.size() + 1, 0);
    for (std::uint32_t owner : shared.Owner)
    {
      ++ownedStart[owner + 1];
    }
    for (std::size_t i = 0; i < leaves.size(); ++i)
    {
      ownedStart[i + 1] += ownedStart[i];
    }
    // The links whose edges can be summed once per node (LinkChain.h).
    const MergedLinkEdges mergedEdges(s);
    std::vector<RGB> sharedValues(sharedPoints.size());
    std::atomic<std::size_t> pastLimit{ 0 };
    // `hidden`: the sky directions no point of the leaf sees (null: none known).
    auto sampleLeaf = [&](std::size_t i, const std::uint64_t* hidden) {
      if (ownedStart[i] == ownedStart[i + 1] && work[i].LocalPoints.empty() && !(lights && lights->HasPunctualLights()))
      {
        return;
      }
      const bool accurate = !(options.MaxSeconds > 0.0 && clock.Seconds() >= options.MaxSeconds);
      pastLimit += accurate ? 0 : 1;
      const std::vector<ChainSource> chain = GatherChain(s, leaves[i], !accurate, &mergedEdges);
      const std::vector<ChainEdge> edges = mergedEdges.ChainEdges(s, leaves[i]);
      const Vec3& n = mesh[leaves[i]].Normal;
      const Vec3& c = mesh[leaves[i]].Centroid;
      // Clustered: what the cluster links bring, a constant per input triangle.
      const RGB clustered = s.ClusterIrradiance(leaves[i]);
      const DirectLighting::SkyDirectionSet sky =
        lights ? lights->SkyDirections(n, hidden) : DirectLighting::SkyDirectionSet();
      for (std::uint32_t k = ownedStart[i]; k < ownedStart[i + 1]; ++k)
      {
        const Vec3 x = Inside(sharedPoints[k], c);
        // In an umbra the signed contour integrals cancel to a rounding, which may be below 0.
        sharedValues[k] = NonNegative(clustered + ChainIrradiance(chain, edges, x, n) +
          (lights ? lights->SkyIrradiance(lights->VisibilityPoint(sharedPoints[k], c), n, sky) : RGB(0.0)));
      }
      LeafWork& w = work[i];
      w.LocalValues.resize(w.LocalPoints.size());
      for (std::size_t k = 0; k < w.LocalPoints.size(); ++k)
      {
        const Vec3 x = Inside(w.LocalPoints[k], c);
        w.LocalValues[k] = NonNegative(clustered + ChainIrradiance(chain, edges, x, n) +
          (lights ? lights->SkyIrradiance(lights->VisibilityPoint(w.LocalPoints[k], c), n, sky) : RGB(0.0)));
      }
      if (lights && lights->HasPunctualLights())
      {
        // A hard shadow boundary is a jump of the irradiance (D0), and it
        // may pass through a sample (a leaf's corner, a vertex on a
        // boundary): the punctual lights are evaluated per triangle at its
        // six nodes, the closed form at the node itself and the visibility
        // from a hundredth of the way towards that triangle's centroid, so
        // that every triangle takes its own side's limit (far above the
        // single-precision shadow rays' error, 1e-7 of the scene; moving the
        // closed form too put 2e-4 of the peak on the smooth falloff).
        w.PunctualNodes.resize(6 * w.Mesh.Triangles.size());
        for (std::size_t t = 0; t < w.Mesh.Triangles.size(); ++t)
        {
          const auto& tri = w.Mesh.Triangles[t];
          const Vec3 centre = (w.Mesh.Points[tri[0]] + w.Mesh.Points[tri[1]] + w.Mesh.Points[tri[2]]) / 3.0;
          for (int k = 0; k < 3; ++k)
          {
            const Vec3& a = w.Mesh.Points[tri[k]];
            const Vec3 mid = 0.5 * (a + w.Mesh.Points[tri[(k + 1) % 3]]);
            w.PunctualNodes[6 * t + 2 * k] = lights->PunctualSeenFrom(Inside(a, c), a + 1e-2 * (centre - a), n);
            w.PunctualNodes[6 * t + 2 * k + 1] =
              lights->PunctualSeenFrom(Inside(mid, c), mid + 1e-2 * (centre - mid), n);
          }
        }
        w.PunctualVertices.resize(w.Mesh.Points.size());
        for (std::size_t v = 0; v < w.Mesh.Points.size(); ++v)
        {
          w.PunctualVertices[v] = lights->Punctual(Inside(w.Mesh.Points[v], c), n);
        }
      }
    };
    // In blocks of leaves, so that progress and an abort are seen between
    // them. With a sky, by input triangle, so that the leaves meeting at a
    // corner share its sky rays (SkyHiddenOverLeaves) and the rays' record
    // stays small.
    const bool sky = lights && lights->HasSky();
    std::vector<std::uint32_t> order(leaves.size());
    for (std::uint32_t i = 0; i < order.size(); ++i)
    {
      order[i] = i;
    }
    if (sky)
    {
      std::stable_sort(order.begin(), order.end(),
        [&](std::uint32_t a, std::uint32_t b) { return mesh[leaves[a]].Source < mesh[leaves[b]].Source; });
    }
    constexpr std::size_t SampleBlock = 1024; // the office: about a third of a second each
    const std::size_t words = sky ? lights->SkyMaskWords() : 0;
    const std::vector<std::array<std::uint32_t, 3>> quads = sky
      ? ConvexCoplanarNeighbours(scene, topology, *lights->ShadowRays())
      : std::vector<std::array<std::uint32_t, 3>>();
    for (std::size_t begin = 0; begin < order.size(); begin += SampleBlock)
    {
      if (!report("sampling", 0.3 + 0.6 * static_cast<double>(begin) / static_cast<double>(order.size())))
      {
        return out;
      }
      const std::size_t end = std::min(order.size(), begin + SampleBlock);
      const std::vector<std::uint64_t> hidden =
        sky ? SkyHiddenOverLeaves(s, *lights, quads, leaves, order, begin, end) : std::vector<std::uint64_t>();
      tbb::parallel_for(begin, end,
        [&](std::size_t k) { sampleLeaf(order[k], sky ? hidden.data() + (k - begin) * words : nullptr); });
    }
    out.PointSamples = sharedPoints.size();
    out.LeavesSampledPastTimeLimit = pastLimit;
    out.SampleSeconds = clock.Seconds() - samplesStart;
    if (!report("interpolants", 0.9))
    {
      return out;
    }

    // Phase 4: interpolants and the output mesh.
    auto value = [&](const LeafWork& w, const SampleRef& r) {
      return r.Shared ? sharedValues[r.Index] : w.LocalValues[r.Index];
    };
    // Each leaf's points and triangles at their offsets in leaf order, in parallel.
    std::vector<std::size_t> pointStart(leaves.size() + 1, 0), triangleStart(leaves.size() + 1, 0),
      punctualStart(leaves.size() + 1, 0);
    for (std::size_t i = 0; i < leaves.size(); ++i)
    {
      const LeafWork& w = work[i];
      out.PointSamples += w.LocalPoints.size();
      pointStart[i + 1] = pointStart[i] + w.Mesh.Points.size();
      triangleStart[i + 1] = triangleStart[i] + w.Mesh.Triangles.size();
      punctualStart[i + 1] = punctualStart[i] + (w.PunctualNodes.empty() ? 0 : w.Mesh.Triangles.size());
    }
    // Each array's first touch (page faults and zeroing: 1.2 s on one
    // thread for the 1.5M bunny room) beside the others; the interpolants
    // are the largest.
    const std::size_t points = pointStart.back(), triangles = triangleStart.back();
    tbb::parallel_invoke([&] { out.Interpolants.resize(triangles); },
      [&] { out.PunctualInterpolants.resize(punctualStart.back()); },
      [&] {
        out.Points.resize(points);
        out.PointIrradiance.resize(points);
      },
      [&] {
        out.Triangles.resize(triangles);
        out.Normals.resize(triangles);
      },
      [&] {
        out.Leaf.resize(triangles);
        out.SourceTriangle.resize(triangles);
        out.Level.resize(triangles);
      });
    tbb::parallel_for(std::size_t(0), leaves.size(), [&](std::size_t i) {
      LeafWork& w = work[i];
      const Element& el = mesh[leaves[i]];
      const auto base = static_cast<std::uint32_t>(pointStart[i]);
      for (std::uint32_t v = 0; v < w.Mesh.Points.size(); ++v)
      {
        out.Points[base + v] = w.Mesh.Points[v];
        out.PointIrradiance[base + v] =
          value(w, w.VertexSamples[v]) + (w.PunctualVertices.empty() ? RGB(0.0) : w.PunctualVertices[v]);
      }
      for (std::size_t t = 0; t < w.Mesh.Triangles.size(); ++t)
      {
        const std::size_t o = triangleStart[i] + t;
        const auto& tri = w.Mesh.Triangles[t];
        out.Triangles[o].V = { base + tri[0], base + tri[1], base + tri[2] };
        std::array<RGB, 6> r;
        for (int k = 0; k < 6; ++k)
        {
          r[k] = value(w, w.TriangleSamples[t][k]) + (w.PunctualNodes.empty() ? RGB(0.0) : w.PunctualNodes[6 * t + k]);
        }
        out.Interpolants[o] = QuadraticInterpolant::FromSamples(r);
        if (!w.PunctualNodes.empty())
        {
          std::array<RGB, 6> p;
          for (int k = 0; k < 6; ++k)
          {
            p[k] = w.PunctualNodes[6 * t + k];
          }
          out.PunctualInterpolants[punctualStart[i] + t] = QuadraticInterpolant::FromSamples(p);
        }
        out.Leaf[o] = leaves[i];
        out.SourceTriangle[o] = el.Source;
        out.Level[o] = el.Level;
        out.Normals[o] = el.Normal;
      }
      w = LeafWork(); // freed here, in parallel, not by one thread at the end
    });
    out.Seconds = clock.Seconds();
    report("interpolants", 1.0);
    return out;
  });
}

std::vector<RGB> EvaluateInterpolants(const DiscontinuityMesh& mesh, const std::vector<Probe>& probes,
  double tolerance, const DirectLighting* exactPunctual)
{
  const bool split = exactPunctual && exactPunctual->HasPunctualLights() &&
    mesh.PunctualInterpolants.size() == mesh.Interpolants.size();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<RGB> values(probes.size(), RGB(nan));
  const double cosLimit = std::cos(25.0 * 3.14159265358979323846 / 180.0);
  tbb::parallel_for(std::size_t(0), probes.size(), [&](std::size_t i) {
    const Probe& probe = probes[i];
    const Vec3 n = glm::normalize(probe.Normal);
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t t = 0; t < mesh.Triangles.size(); ++t)
    {
      if (glm::dot(mesh.Normals[t], n) < cosLimit)
      {
        continue;
      }
      const Vec3& a = mesh.Points[mesh.Triangles[t].V[0]];
      const double dist = std::fabs(glm::dot(probe.Position - a, mesh.Normals[t]));
      double u, v, w;
      if (dist <= tolerance && dist < best &&
        ProjectOnTriangle(probe.Position, a, mesh.Points[mesh.Triangles[t].V[1]],
          mesh.Points[mesh.Triangles[t].V[2]], u, v, w) &&
        u >= -1e-6 && v >= -1e-6 && w >= -1e-6)
      {
        best = dist;
        // A quadratic through non-negative samples can dip below 0 between them.
        values[i] = NonNegative(mesh.Interpolants[t].Evaluate(v, w));
        if (split)
        {
          values[i] = NonNegative(values[i] - mesh.PunctualInterpolants[t].Evaluate(v, w)) +
            exactPunctual->Punctual(probe.Position, mesh.Normals[t]);
        }
      }
    }
  });
  return values;
}
} // namespace radiosity
