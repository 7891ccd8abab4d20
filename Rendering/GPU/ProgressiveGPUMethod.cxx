#include "ProgressiveGPUMethod.h"

#include "ProgressiveGPUAtlas.h"
#include "ProgressiveGPUPasses.h"
#include "Radiosity/Common/DirectLighting.h"
#include "Radiosity/Common/ElementMesh.h"
#include "Radiosity/Common/FormFactor.h"
#include "Radiosity/Common/MemoryBudget.h"
#include "Radiosity/Common/SceneAnalysis.h"
#include "Radiosity/Common/SolutionMesh.h"
#include "Radiosity/Common/Stopwatch.h"
#include "Radiosity/Common/ThreadLimit.h"
#include "Radiosity/Common/Visibility.h"
#include "Radiosity/Progressive/ShooterSamples.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace radiosity
{
namespace
{
// The GPU side per element: twenty RGBA32F texels (ten inputs, five
// targets, four deltas, the split flag); the CPU keeps the element mesh and
// the fifteen staging arrays (ProgressiveGPUAtlas).
constexpr double BytesPerGPUElement = 20 * 16.0 + sizeof(Element) + 15 * 16.0;
// Element and node indices travel as float texel values: exact below 2^24.
constexpr double MaxIndexedByFloat = 16777216.0;
} // namespace

ProgressiveGPUMethod::ProgressiveGPUMethod(std::shared_ptr<const Scene> scene, const ProgressiveGPUOptions& options)
  : RadiositySolver(std::move(scene))
  , Settings(options)
{
  const Scene& s = *this->SceneRef;
  const double diag = s.Diagonal();
  const double initialEdge = std::max(options.InitialElementSize, 1e-6) * diag;
  const double shooterEdge = std::max(options.ShooterElementSize, options.InitialElementSize) * diag;
  const double leaves = UniformQuadtreeLeaves(s, initialEdge, 12);
  CheckMemoryBudget(4.0 / 3.0 * leaves * BytesPerGPUElement, ResolveMemoryBudget(options.MemoryBudgetBytes),
    "progressive-gpu radiosity: the element atlas of " + FormatCount(leaves) + " elements",
    "raise --element-size (InitialElementSize)");
  if (leaves >= MaxIndexedByFloat)
  {
    throw SceneError("progressive-gpu radiosity: " + FormatCount(leaves) +
      " elements; the texel atlas indexes at most 16.7 million (raise --element-size)");
  }
  this->Elements = std::make_unique<ElementMesh>(s, shooterEdge, initialEdge, 12);
  // Section 4.4's maximum depth, as the CPU solver's: the initial levels
  // of each input triangle and MaxSubdivisionLevels below them.
  this->MaxLevel = this->Elements->MaxLevels(options.MaxSubdivisionLevels);
  const double budget = ResolveMemoryBudget(options.MemoryBudgetBytes);
  this->ElementCapacity = budget > 0 ? static_cast<std::size_t>(std::min(budget / BytesPerGPUElement, MaxIndexedByFloat))
                                     : static_cast<std::size_t>(MaxIndexedByFloat);
  if (this->Settings.HemicubeResolution < 16 || this->Settings.HemicubeResolution > 4096)
  {
    throw SceneError("progressive-gpu radiosity: hemicube resolution " +
      std::to_string(this->Settings.HemicubeResolution) + " outside [16, 4096]");
  }
}

ProgressiveGPUMethod::~ProgressiveGPUMethod() = default;

SolutionMesh ProgressiveGPUMethod::Surface() const
{
  return ExtractSolution(*this->Elements);
}

SolverProduct ProgressiveGPUMethod::Product(const ProgressCallback&) const
{
  return {};
}

void ProgressiveGPUMethod::LightElements(const std::vector<std::uint32_t>& elements)
{
  ElementMesh& mesh = *this->Elements;
  const DirectLighting& lights = *this->Lights;
  RunWithThreads(this->Settings.Threads, [&] {
    tbb::parallel_for(std::size_t(0), elements.size(), [&](std::size_t i) {
      Element& e = mesh[elements[i]];
      for (int k = 0; k < 3; ++k)
      {
        const Vec3 corner = mesh.Corner(elements[i], k);
        e.Irradiance.Corner[k] =
          lights.IrradianceSeenFrom(corner, lights.VisibilityPoint(corner, e.Centroid), e.Normal);
      }
      e.Irradiance.Centre = lights.Irradiance(e.Centroid, e.Normal);
    });
  });
}

void ProgressiveGPUMethod::ShootLights(SolverStatistics& stats)
{
  // The lights and the sky shoot first, once, on the CPU: their exact direct
  // light (DirectLighting, the CPU solver's) at every element's corners and
  // centroid becomes its first irradiance (and a split's children's, exact
  // again). The GPU then shoots what the surfaces reflect.
  const Scene& scene = this->GetScene();
  if (scene.Lighting.Empty())
  {
    return;
  }
  ElementMesh& mesh = *this->Elements;
  this->Lights = std::make_unique<DirectLighting>(scene, this->Settings.SkySamples);
  std::vector<std::uint32_t> pending = mesh.Leaves();
  this->LightElements(pending);
  // The receivers split where the lights' light departs from linear (the
  // gradient criterion of section 4.1, as for every shot), exact light at
  // the children, down to LightSubdivisionLevels below the elements'
  // maximum depth (the CPU solver's rule): hard shadows of point lights and
  // the sun otherwise fell across elements as dark blotches.
  const double threshold = this->Settings.SubdivisionThreshold;
  const int extra = std::max(0, this->Settings.LightSubdivisionLevels);
  while (!pending.empty())
  {
    std::vector<std::uint32_t> children;
    for (std::uint32_t e : pending)
    {
      const ElementSamples& h = mesh[e].Irradiance;
      const double departure = std::fabs(Luminance(h.Centre) -
        (Luminance(h.Corner[0]) + Luminance(h.Corner[1]) + Luminance(h.Corner[2])) / 3.0);
      if (mesh[e].Level < this->MaxLevel[mesh[e].Source] + extra && departure > threshold * std::fabs(Luminance(h.Mean())) &&
        mesh.Elements().size() + 4 <= this->ElementCapacity)
      {
        const std::uint32_t first = mesh.Subdivide(e);
        for (std::uint32_t c = first; c < first + 4; ++c)
        {
          children.push_back(c);
        }
      }
    }
    stats.Subdivisions += children.size() / 4;
    this->LightElements(children);
    pending = std::move(children);
  }
  const std::vector<std::uint32_t> leaves = mesh.Leaves();
  double power = 0.0;
  for (std::uint32_t l : leaves)
  {
    power += Mean(mesh[l].Irradiance.Mean()) * mesh[l].Area;
  }
  stats.LightPowerW = power;
}

int ProgressiveGPUMethod::PartsDepth(std::uint32_t node, double initialEdge, bool occluders) const
{
  // Coombe 3.1: "all of the elements on the polygon shoot their energy in
  // turn", each part with its own item buffer. Shooting in parts samples
  // visibility from each; with nothing to occlude one shot is the same
  // light (the contour formula is additive).
  // A part is no smaller than a quarter of a receiving element: a shadow
  // is resolved no finer (the subdivided light of a tessellated scene
  // shoots each of its small triangles whole; a part of a receiving
  // element's size made the exact penumbra's error 0.143 of the peak
  // instead of 0.075).
  const ElementMesh& mesh = *this->Elements;
  const bool emitter = MaxComponent(mesh.MaterialOf(node).Emission) > 0.0;
  const int samples = !occluders ? 1
    : emitter                    ? this->Settings.VisibilitySamples
                                 : this->Settings.IndirectVisibilitySamples;
  int depth = SubdivisionLevelsOfSamples(samples);
  while (depth > 0 && mesh.LongestEdge(node) < std::ldexp(initialEdge, depth - 2))
  {
    --depth;
  }
  return depth;
}

void ProgressiveGPUMethod::GatherHistory(const std::vector<std::uint32_t>& children,
  const std::vector<std::pair<std::size_t, RGB>>& active, const Visibility& rays, double initialEdge,
  bool convex)
{
  // What a new child received from every earlier shot: each shooter's total
  // radiosity times the exact form factor from the child's samples (the
  // corners 1e-3 of the way inside, as the shot pass takes them) times
  // the fraction of the shooter's parts seen (the rays of the CPU solver).
  ElementMesh& mesh = *this->Elements;
  const std::vector<std::uint32_t>& shooters = mesh.Shooters();
  std::vector<std::vector<Vec3>> targets(active.size());
  for (std::size_t a = 0; a < active.size(); ++a)
  {
    const std::uint32_t node = shooters[active[a].first];
    AppendSubtriangleCentroids(mesh.Corner(node, 0), mesh.Corner(node, 1), mesh.Corner(node, 2),
      this->PartsDepth(node, initialEdge, !convex), targets[a]);
  }
  RunWithThreads(this->Settings.Threads, [&] {
    tbb::parallel_for(std::size_t(0), children.size(), [&](std::size_t c) {
      Element& e = mesh[children[c]];
      std::array<Vec3, 4> points, origins;
      for (int k = 0; k < 3; ++k)
      {
        const Vec3 corner = mesh.Corner(children[c], k);
        points[k] = corner + 1e-3 * (e.Centroid - corner); // the shot pass's inset
        origins[k] = points[k] + rays.Offset() * e.Normal;
      }
      points[3] = e.Centroid;
      origins[3] = e.Centroid + rays.Offset() * e.Normal;
      std::vector<Vec3> from, to;
      std::vector<unsigned char> seen;
      for (std::size_t a = 0; a < active.size(); ++a)
      {
        const std::uint32_t node = shooters[active[a].first];
        if (mesh[node].Source == e.Source)
        {
          continue;
        }
        const Vec3 tri[3] = { mesh.Corner(node, 0), mesh.Corner(node, 1), mesh.Corner(node, 2) };
        for (int k = 0; k < 4; ++k)
        {
          double f = PointToPolygonFormFactor(points[k], e.Normal, tri, 3);
          if (!(f > 0.0))
          {
            continue;
          }
          if (!convex && !rays.Empty())
          {
            const std::vector<Vec3>& t = targets[a];
            from.assign(t.size(), origins[k]);
            seen.assign(t.size(), 0);
            rays.TestSegments(from.data(), t.data(), t.size(), seen.data());
            std::size_t visible = 0;
            for (unsigned char v : seen)
            {
              visible += v != 0;
            }
            f *= static_cast<double>(visible) / static_cast<double>(t.size());
          }
          RGB& h = k < 3 ? e.Irradiance.Corner[k] : e.Irradiance.Centre;
          h += active[a].second * f;
        }
      }
    });
  });
}

SolverStatistics ProgressiveGPUMethod::Solve(const ProgressCallback& progress)
{
  SolverStatistics stats;
  const Stopwatch start;
  const Scene& scene = this->GetScene();
  ElementMesh& mesh = *this->Elements;
  this->ShootLights(stats);

  GPUFrame frame;
  Vec3 lo, hi;
  scene.BoundingBox(lo, hi);
  frame.Centre = 0.5 * (lo + hi);
  frame.Diagonal = std::max(scene.Diagonal(), 1e-300);
  double emitted = 0.0, area = 0.0, rhoMaxArea = 0.0;
  RGB rhoMean(0.0);
  for (std::uint32_t l : mesh.Leaves())
  {
    Element& e = mesh[l];
    const Material& m = mesh.MaterialOf(l);
    e.Unshot = m.Emission + m.Reflectance * e.Irradiance.Mean();
    emitted += Mean(m.Emission) * e.Area;
    rhoMean += m.Reflectance * e.Area;
    rhoMaxArea += MaxComponent(m.Reflectance) * e.Area;
    area += e.Area;
  }
  rhoMean /= std::max(area, 1e-300);
  emitted += stats.LightPowerW;
  stats.EmittedPowerW = emitted;
  stats.Elements = mesh.NumberOfLeaves();
  if (!(emitted > 0.0))
  {
    stats.Stop = StopReason::NoEmitters;
    stats.SolveSeconds = start.Seconds();
    return stats;
  }
  // The item buffer draws the triangles that can block a transfer (the
  // CPU solver casts rays against the same set): none in a convex room.
  const SceneAnalysis analysis = AnalyzeScene(scene);
  stats.Occluders = analysis.Occluders;
  std::vector<float> triangles;
  triangles.reserve(12 * analysis.Occluders);
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    for (int k = 0; k < 3 && analysis.CanOcclude[t]; ++k)
    {
      const std::array<float, 3> p = ToFloat(frame.Scaled(scene.Vertex(t, k)));
      triangles.insert(triangles.end(), { p[0], p[1], p[2], static_cast<float>(t) });
    }
  }
  if (!ReportProgress(progress, "uploading the element atlas", 0, 1.0, this->Settings.Tolerance))
  {
    stats.Stop = StopReason::Aborted;
    stats.SolveSeconds = start.Seconds();
    return stats;
  }

  ProgressiveGPUPasses gpu;
  this->RendererName = gpu.Renderer();
  std::string error;
  GPUAtlas atlas;
  // Lays the atlas out (again) and uploads it.
  auto upload = [&] {
    atlas = LayOutAtlas(mesh, frame, this->MaxLevel);
    if (atlas.Elements.Height > gpu.MaxTextureSize() || atlas.Nodes.Width > gpu.MaxTextureSize())
    {
      throw SceneError("progressive-gpu radiosity: " + FormatCount(static_cast<double>(atlas.Leaves.size())) +
        " elements need a texture of height " + std::to_string(atlas.Elements.Height) + "; " +
        this->RendererName + " allows " + std::to_string(gpu.MaxTextureSize()) + " (raise --element-size)");
    }
    if (!gpu.UploadAtlas(atlas.Elements, atlas.Nodes, error))
    {
      throw SceneError(error);
    }
  };
  if (!gpu.Prepare(triangles, this->Settings.HemicubeResolution, error))
  {
    throw SceneError(error);
  }
  upload();
  stats.PreprocessSeconds = start.Seconds();

  // Cohen 1988's interreflection factor for the overshooting (as ProgressiveRadiosity::Solve).
  const RGB interreflection = RGB(1.0) / (RGB(1.0) - rhoMean);
  const float discTolerance =
    static_cast<float>(this->Settings.FormFactorTolerance * (1.0 - rhoMaxArea / std::max(area, 1e-300)));
  const double scaledArea = frame.ScaledArea(area);
  const double scaledEmitted = frame.ScaledArea(emitted);
  const double initialEdge = std::max(this->Settings.InitialElementSize, 1e-6) * scene.Diagonal();
  const std::vector<std::uint32_t>& shooters = mesh.Shooters();
  const bool adaptive = this->Settings.MaxSubdivisionLevels > 0;
  // Every shooter that has shot, with the radiosity it shot in total: a
  // split's children gather their history from them.
  std::vector<std::pair<std::size_t, RGB>> active;
  std::unordered_map<std::size_t, std::size_t> activeSlot;
  std::vector<std::array<Vec3, 3>> parts;
  std::unique_ptr<Visibility> rays; // the CPU's rays for GatherHistory, made at the first need
  // Node k shoots radiosity `shot` into the deltas.
  auto shootNode = [&](std::size_t k, const RGB& shot) {
    const std::uint32_t node = shooters[k];
    const Vec3 normal = mesh[node].Normal;
    GPUShooter shooter;
    shooter.Normal = ToFloat(normal);
    const Vec3 axis = std::fabs(normal.x) < 0.6 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 u = glm::normalize(glm::cross(normal, axis));
    shooter.FrameU = ToFloat(u);
    shooter.FrameV = ToFloat(glm::cross(normal, u));
    shooter.Triangle = static_cast<float>(mesh[node].Source);
    shooter.Shot = ToFloat(shot);
    const int depth = this->PartsDepth(node, initialEdge, analysis.Occluders > 0);
    parts.clear();
    AppendSubtriangles(mesh.Corner(node, 0), mesh.Corner(node, 1), mesh.Corner(node, 2), depth, parts);
    gpu.BeginShot();
    for (const auto& part : parts)
    {
      for (int v = 0; v < 3; ++v)
      {
        SplitFloat(frame.Scaled(part[v]), shooter.Vertices[v], shooter.VerticesLo[v]);
      }
      SplitFloat(frame.Scaled((part[0] + part[1] + part[2]) / 3.0), shooter.Centre, shooter.CentreLo);
      shooter.Area = static_cast<float>(frame.ScaledArea(mesh[node].Area) / static_cast<double>(parts.size()));
      gpu.Shoot(shooter, discTolerance);
    }
  };
  stats.Stop = StopReason::IterationLimit;
  for (long long iteration = 0;; ++iteration)
  {
    const std::array<double, 4> totals = gpu.NodeTotals();
    const RGB signedPower(totals[0], totals[1], totals[2]);
    const double absPower = totals[3];
    const RGB ambient = this->Settings.Overshooting ? interreflection * signedPower / scaledArea : RGB(0.0);
    const double elapsed = start.Seconds();
    ConvergenceRow row;
    row.Iteration = iteration;
    row.TimeSeconds = elapsed;
    row.UnshotPowerW = absPower * frame.Diagonal * frame.Diagonal;
    // Not measured here: the GPU does not integrate the power leaving an
    // open scene per shot (the CPU solver's shooter-side integral).
    row.EnergyBalance = std::numeric_limits<double>::quiet_NaN();
    stats.Iterations = iteration;
    stats.UnshotPowerW = row.UnshotPowerW;
    const double relative = absPower / scaledEmitted;
    if (!ReportProgress(progress, "shooting", iteration, relative, this->Settings.Tolerance))
    {
      stats.History.Rows.push_back(row);
      stats.Stop = StopReason::Aborted;
      break;
    }
    if (relative <= this->Settings.Tolerance)
    {
      stats.History.Rows.push_back(row);
      stats.Stop = StopReason::Converged;
      break;
    }
    if (ReachedLimit(iteration, this->Settings.MaxIterations, elapsed, this->Settings.MaxTimeSeconds, stats.Stop))
    {
      stats.History.Rows.push_back(row);
      break;
    }
    const float powerScale = static_cast<float>(std::max(absPower / static_cast<double>(atlas.Nodes.Count), 1e-30));
    std::array<double, 3> power{};
    const long long k = gpu.SelectShooter(ToFloat(ambient), powerScale, power);
    if (k < 0)
    {
      stats.History.Rows.push_back(row);
      stats.Stop = StopReason::Converged; // no node holds power float can see
      break;
    }
    const std::uint32_t node = shooters[static_cast<std::size_t>(k)];
    const Material& material = mesh.MaterialOf(node);
    const double nodeArea = mesh[node].Area;
    const RGB overshoot = material.Reflectance * ambient;
    const RGB shot = RGB(power[0], power[1], power[2]) / frame.ScaledArea(nodeArea) + overshoot;
    row.OvershootPowerW = Mean(glm::abs(overshoot)) * nodeArea;
    stats.History.Rows.push_back(row);

    shootNode(static_cast<std::size_t>(k), shot);
    // Section 4.1: where the shot is not smooth the receivers split, down to
    // the maximum depth, and the shot is taken again. The paper pushes the
    // parent's radiosity down to the children; that interpolated what every
    // earlier shot left (6% of a closed cube's light at rho 0, a 13% bias
    // at 0.999), so, as the CPU solver, a child gathers its history exactly
    // from every earlier shooter's total (and the lights' exact light), and
    // its residual takes the difference from its parent's share. The few
    // children of a split gather on the CPU (GatherHistory): on the GPU
    // each earlier shooter would draw its item buffer again (the Cornell
    // box took 22.6 s so instead of 1.4 s).
    while (adaptive && gpu.CountSplits(static_cast<float>(this->Settings.SubdivisionThreshold)) > 0)
    {
      const std::vector<float> flags = gpu.ReadSplitFlags();
      ReadBackAtlas(mesh, atlas, gpu.ReadElements());
      std::vector<std::uint32_t> children;
      std::vector<RGB> parentShare;
      for (std::size_t i = 0; i < atlas.Leaves.size(); ++i)
      {
        if (flags[4 * i] > 0.5 && mesh.Elements().size() + 4 <= this->ElementCapacity)
        {
          const std::uint32_t parent = atlas.Leaves[i];
          const RGB share = mesh.MaterialOf(parent).Reflectance * mesh[parent].Irradiance.Mean();
          const std::uint32_t first = mesh.Subdivide(parent);
          for (std::uint32_t c = first; c < first + 4; ++c)
          {
            children.push_back(c);
            parentShare.push_back(share);
          }
        }
      }
      if (children.empty())
      {
        break; // the memory budget holds no more elements
      }
      stats.Subdivisions += children.size() / 4;
      for (std::uint32_t child : children)
      {
        mesh[child].Irradiance = ElementSamples();
      }
      if (this->Lights)
      {
        this->LightElements(children);
      }
      if (!active.empty())
      {
        if (!rays)
        {
          rays = std::make_unique<Visibility>(scene, analysis.CanOcclude);
        }
        this->GatherHistory(children, active, *rays, initialEdge, analysis.Occluders == 0);
      }
      for (std::size_t c = 0; c < children.size(); ++c)
      {
        Element& child = mesh[children[c]];
        child.Unshot += mesh.MaterialOf(children[c]).Reflectance * child.Irradiance.Mean() - parentShare[c];
      }
      upload();
      shootNode(static_cast<std::size_t>(k), shot);
    }
    gpu.CommitShot();
    // The shooter keeps minus what it shot in advance (ProgressiveRadiosity::Solve).
    gpu.SetUnshot(atlas.NodeFirst[k], atlas.NodeCount[k], ToFloat(-overshoot));
    auto found = activeSlot.find(static_cast<std::size_t>(k));
    if (found == activeSlot.end())
    {
      activeSlot.emplace(static_cast<std::size_t>(k), active.size());
      active.emplace_back(static_cast<std::size_t>(k), shot);
    }
    else
    {
      active[found->second].second += shot;
    }
  }

  // The solution comes back once.
  ReadBackAtlas(mesh, atlas, gpu.ReadElements());
  double absorbed = 0.0, unshot = 0.0;
  for (std::uint32_t l : atlas.Leaves)
  {
    Element& e = mesh[l];
    ElementSamples& h = e.Irradiance;
    if (this->Settings.Overshooting)
    {
      // As the CPU solver: a sample that advance shots left below zero
      // (stopped early, or by rounding) is clamped; irradiance is never negative.
      for (RGB& c : h.Corner)
      {
        c = glm::max(c, RGB(0.0));
      }
      h.Centre = glm::max(h.Centre, RGB(0.0));
    }
    absorbed += Mean((RGB(1.0) - mesh.MaterialOf(l).Reflectance) * h.Mean()) * e.Area;
    unshot += Mean(e.Unshot) * e.Area;
  }
  stats.Elements = atlas.Leaves.size();
  stats.RaysCast += this->Lights ? this->Lights->RaysCast() : 0;
  stats.AbsorbedPowerW = absorbed;
  // By difference: what is neither absorbed nor left unshot has left the scene.
  stats.EscapedPowerW = std::max(0.0, emitted - absorbed - unshot);
  stats.SolveSeconds = start.Seconds();
  return stats;
}
} // namespace radiosity
