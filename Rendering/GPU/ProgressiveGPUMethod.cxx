#include "ProgressiveGPUMethod.h"

#include "ProgressiveGPUPasses.h"
#include "Radiosity/Common/DirectLighting.h"
#include "Radiosity/Common/ElementMesh.h"
#include "Radiosity/Common/MemoryBudget.h"
#include "Radiosity/Common/SceneAnalysis.h"
#include "Radiosity/Common/SolutionMesh.h"
#include "Radiosity/Common/Stopwatch.h"
#include "Radiosity/Common/ThreadLimit.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace radiosity
{
namespace
{
// The GPU side per element: eleven RGBA32F texels (inputs and targets); the
// CPU keeps the element mesh and the staging arrays.
constexpr double BytesPerGPUElement = 11 * 16.0 + sizeof(Element) + 12 * 16.0;
// Element and node indices travel as float texel values: exact below 2^24.
constexpr double MaxIndexedByFloat = 16777216.0;

std::array<float, 3> ToFloat(const Vec3& v)
{
  return { static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z) };
}

void Put(std::vector<float>& texels, std::size_t i, const Vec3& xyz, double w)
{
  texels[4 * i + 0] = static_cast<float>(xyz.x);
  texels[4 * i + 1] = static_cast<float>(xyz.y);
  texels[4 * i + 2] = static_cast<float>(xyz.z);
  texels[4 * i + 3] = static_cast<float>(w);
}

/// `xyz` as float (hi) and what rounding dropped (lo): a two-float position.
void PutSplit(std::vector<float>& hi, std::vector<float>& lo, std::size_t i, const Vec3& xyz, double w)
{
  Put(hi, i, xyz, w);
  const Vec3 rounded(hi[4 * i], hi[4 * i + 1], hi[4 * i + 2]);
  Put(lo, i, xyz - rounded, 0.0);
}

void Split(const Vec3& xyz, std::array<float, 3>& hi, std::array<float, 3>& lo)
{
  hi = ToFloat(xyz);
  lo = ToFloat(xyz - Vec3(hi[0], hi[1], hi[2]));
}

RGB Get(const std::vector<float>& texels, std::size_t i)
{
  return RGB(texels[4 * i], texels[4 * i + 1], texels[4 * i + 2]);
}

/// The midpoint subdivision of triangle (a, b, c) to `depth` levels: the
/// parts that shoot in turn (Coombe 3.1: "all of the elements on the
/// polygon shoot their energy in turn"), each with its own item buffer.
void SubTriangles(const Vec3& a, const Vec3& b, const Vec3& c, int depth, std::vector<std::array<Vec3, 3>>& out)
{
  if (depth <= 0)
  {
    out.push_back({ a, b, c });
    return;
  }
  const Vec3 ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
  SubTriangles(a, ab, ca, depth - 1, out);
  SubTriangles(ab, b, bc, depth - 1, out);
  SubTriangles(ca, bc, c, depth - 1, out);
  SubTriangles(ab, bc, ca, depth - 1, out);
}

/// 1, 4 or 16 visibility samples (ProgressiveOptions) as subdivision depth 0, 1 or 2.
int DepthOfSamples(int samples)
{
  return samples >= 16 ? 2 : samples >= 4 ? 1 : 0;
}
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

void ProgressiveGPUMethod::ShootLights(SolverStatistics& stats)
{
  // The lights and the sky shoot first, once, on the CPU: their exact direct
  // light (DirectLighting, the CPU solver's) at every element's corners and
  // centroid becomes its first irradiance. The GPU then shoots what the
  // surfaces reflect. The uniform mesh does not split along their shadows
  // (the CPU solver's LightSubdivisionLevels).
  const Scene& scene = this->GetScene();
  if (scene.Lighting.Empty())
  {
    return;
  }
  ElementMesh& mesh = *this->Elements;
  const DirectLighting lights(scene, this->Settings.SkySamples);
  const std::vector<std::uint32_t> leaves = mesh.Leaves();
  RunWithThreads(this->Settings.Threads, [&] {
    tbb::parallel_for(std::size_t(0), leaves.size(), [&](std::size_t i) {
      Element& e = mesh[leaves[i]];
      for (int k = 0; k < 3; ++k)
      {
        const Vec3 corner = mesh.Corner(leaves[i], k);
        e.Irradiance.Corner[k] =
          lights.IrradianceSeenFrom(corner, lights.VisibilityPoint(corner, e.Centroid), e.Normal);
      }
      e.Irradiance.Centre = lights.Irradiance(e.Centroid, e.Normal);
    });
  });
  double power = 0.0;
  for (std::uint32_t l : leaves)
  {
    power += Mean(mesh[l].Irradiance.Mean()) * mesh[l].Area;
  }
  stats.LightPowerW = power;
  stats.RaysCast += lights.RaysCast();
}

SolverStatistics ProgressiveGPUMethod::Solve(const ProgressCallback& progress)
{
  SolverStatistics stats;
  const Stopwatch start;
  const Scene& scene = this->GetScene();
  ElementMesh& mesh = *this->Elements;
  this->ShootLights(stats);

  // Scaled coordinates: centred, divided by the diagonal (ProgressiveGPUShaders.cxx).
  Vec3 lo, hi;
  scene.BoundingBox(lo, hi);
  const Vec3 centre = 0.5 * (lo + hi);
  const double diag = std::max(scene.Diagonal(), 1e-300);
  const double areaScale = 1.0 / (diag * diag);
  auto scaled = [&](const Vec3& p) { return (p - centre) / diag; };

  // The elements grouped by shooter node, each node's a contiguous range.
  const std::vector<std::uint32_t>& shooters = mesh.Shooters();
  std::vector<std::uint32_t> slot(mesh.Elements().size(), 0);
  for (std::size_t k = 0; k < shooters.size(); ++k)
  {
    slot[shooters[k]] = static_cast<std::uint32_t>(k);
  }
  std::vector<std::uint32_t> leaves = mesh.Leaves();
  std::stable_sort(leaves.begin(), leaves.end(),
    [&](std::uint32_t a, std::uint32_t b) { return slot[mesh[a].ShooterNode] < slot[mesh[b].ShooterNode]; });

  GPUElementTexels elements;
  elements.Count = leaves.size();
  elements.Width = static_cast<int>(std::min<std::size_t>(2048, std::max<std::size_t>(1, leaves.size())));
  elements.Height = static_cast<int>((leaves.size() + elements.Width - 1) / elements.Width);
  const std::size_t texels = 4 * static_cast<std::size_t>(elements.Width) * elements.Height;
  for (std::vector<float>* v : { &elements.Centre, &elements.Corner0, &elements.Corner1, &elements.Corner2,
         &elements.CentreLo, &elements.Corner0Lo, &elements.Corner1Lo, &elements.Corner2Lo,
         &elements.Normal, &elements.Reflectance, &elements.Irradiance0, &elements.Irradiance1,
         &elements.Irradiance2, &elements.IrradianceCentre, &elements.Unshot })
  {
    v->assign(texels, 0.0f);
  }
  GPUNodeTexels nodes;
  nodes.Count = shooters.size();
  nodes.Width = 1;
  while (static_cast<std::size_t>(nodes.Width) * nodes.Width < nodes.Count)
  {
    nodes.Width *= 2;
  }
  nodes.Range.assign(4 * static_cast<std::size_t>(nodes.Width) * nodes.Width, 0.0f);
  nodes.Reflectance = nodes.Range;
  std::vector<std::size_t> nodeFirst(shooters.size(), 0), nodeCount(shooters.size(), 0);

  double emitted = 0.0, area = 0.0, rhoMaxArea = 0.0;
  RGB rhoMean(0.0);
  for (std::size_t i = 0; i < leaves.size(); ++i)
  {
    const std::uint32_t l = leaves[i];
    Element& e = mesh[l];
    const Material& m = mesh.MaterialOf(l);
    const double a = e.Area * areaScale;
    PutSplit(elements.Centre, elements.CentreLo, i, scaled(e.Centroid), a);
    PutSplit(elements.Corner0, elements.Corner0Lo, i, scaled(mesh.Corner(l, 0)), 0.0);
    PutSplit(elements.Corner1, elements.Corner1Lo, i, scaled(mesh.Corner(l, 1)), 0.0);
    PutSplit(elements.Corner2, elements.Corner2Lo, i, scaled(mesh.Corner(l, 2)), 0.0);
    Put(elements.Normal, i, e.Normal, static_cast<double>(e.Source));
    Put(elements.Reflectance, i, m.Reflectance, 0.0);
    Put(elements.Irradiance0, i, e.Irradiance.Corner[0], 0.0);
    Put(elements.Irradiance1, i, e.Irradiance.Corner[1], 0.0);
    Put(elements.Irradiance2, i, e.Irradiance.Corner[2], 0.0);
    Put(elements.IrradianceCentre, i, e.Irradiance.Centre, 0.0);
    e.Unshot = m.Emission + m.Reflectance * e.Irradiance.Mean();
    Put(elements.Unshot, i, e.Unshot, 0.0);
    emitted += Mean(m.Emission) * e.Area;
    rhoMean += m.Reflectance * e.Area;
    rhoMaxArea += MaxComponent(m.Reflectance) * e.Area;
    area += e.Area;
    const std::uint32_t k = slot[e.ShooterNode];
    if (nodeCount[k]++ == 0)
    {
      nodeFirst[k] = i;
    }
  }
  for (std::size_t k = 0; k < shooters.size(); ++k)
  {
    const Element& n = mesh[shooters[k]];
    Put(nodes.Range, k, Vec3(static_cast<double>(nodeFirst[k]), static_cast<double>(nodeCount[k]), n.Area * areaScale), 0.0);
    Put(nodes.Reflectance, k, mesh.MaterialOf(shooters[k]).Reflectance, 0.0);
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
      const std::array<float, 3> p = ToFloat(scaled(scene.Vertex(t, k)));
      triangles.insert(triangles.end(), { p[0], p[1], p[2], static_cast<float>(t) });
    }
  }
  rhoMean /= std::max(area, 1e-300);
  emitted += stats.LightPowerW;
  stats.EmittedPowerW = emitted;
  stats.Elements = leaves.size();
  if (!(emitted > 0.0))
  {
    stats.Stop = StopReason::NoEmitters;
    stats.SolveSeconds = start.Seconds();
    return stats;
  }
  if (progress)
  {
    ProgressStatus status;
    status.Phase = "uploading the element atlas";
    if (!progress(status))
    {
      stats.Stop = StopReason::Aborted;
      stats.SolveSeconds = start.Seconds();
      return stats;
    }
  }

  ProgressiveGPUPasses gpu;
  this->RendererName = gpu.Renderer();
  if (elements.Height > gpu.MaxTextureSize() || nodes.Width > gpu.MaxTextureSize())
  {
    throw SceneError("progressive-gpu radiosity: " + FormatCount(static_cast<double>(leaves.size())) +
      " elements need a texture of height " + std::to_string(elements.Height) + "; " + this->RendererName +
      " allows " + std::to_string(gpu.MaxTextureSize()) + " (raise --element-size)");
  }
  std::string error;
  if (!gpu.Upload(elements, nodes, triangles, this->Settings.HemicubeResolution, error))
  {
    throw SceneError(error);
  }
  stats.PreprocessSeconds = start.Seconds();

  // Cohen 1988's interreflection factor for the overshooting (as ProgressiveRadiosity::Solve).
  const RGB interreflection = RGB(1.0) / (RGB(1.0) - rhoMean);
  const float discTolerance =
    static_cast<float>(this->Settings.FormFactorTolerance * (1.0 - rhoMaxArea / std::max(area, 1e-300)));
  const double scaledArea = area * areaScale;
  const double scaledEmitted = emitted * areaScale;
  std::vector<std::array<Vec3, 3>> parts;
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
    row.UnshotPowerW = absPower / areaScale;
    // Not measured here: the GPU does not integrate the power leaving an
    // open scene per shot (the CPU solver's shooter-side integral).
    row.EnergyBalance = std::numeric_limits<double>::quiet_NaN();
    stats.Iterations = iteration;
    stats.UnshotPowerW = row.UnshotPowerW;
    const double relative = absPower / scaledEmitted;
    if (progress)
    {
      ProgressStatus status;
      status.Phase = "shooting";
      status.Iteration = iteration;
      status.Residual = relative;
      status.Fraction = std::clamp(
        std::log(std::max(relative, 1e-300)) / std::log(this->Settings.Tolerance), 0.0, 1.0);
      if (!progress(status))
      {
        stats.History.Rows.push_back(row);
        stats.Stop = StopReason::Aborted;
        break;
      }
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
    const float powerScale = static_cast<float>(std::max(absPower / static_cast<double>(nodes.Count), 1e-30));
    std::array<double, 3> power{};
    const long long k = gpu.SelectShooter(ToFloat(ambient), powerScale, power);
    if (k < 0)
    {
      stats.History.Rows.push_back(row);
      stats.Stop = StopReason::Converged; // no node holds power float can see
      break;
    }
    const std::uint32_t node = shooters[static_cast<std::size_t>(k)];
    const Element& n = mesh[node];
    const Material& material = mesh.MaterialOf(node);
    const RGB overshoot = material.Reflectance * ambient;
    const RGB shot = RGB(power[0], power[1], power[2]) / (n.Area * areaScale) + overshoot;
    row.OvershootPowerW = Mean(glm::abs(overshoot)) * n.Area;
    stats.History.Rows.push_back(row);

    GPUShooter shooter;
    shooter.Normal = ToFloat(n.Normal);
    const Vec3 axis = std::fabs(n.Normal.x) < 0.6 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 u = glm::normalize(glm::cross(n.Normal, axis));
    shooter.FrameU = ToFloat(u);
    shooter.FrameV = ToFloat(glm::cross(n.Normal, u));
    shooter.Triangle = static_cast<float>(n.Source);
    shooter.Shot = ToFloat(shot);
    parts.clear();
    const bool emitter = MaxComponent(material.Emission) > 0.0;
    // Shooting in parts samples visibility from each; with nothing to
    // occlude one shot is the same light (the contour formula is additive).
    const int samples = analysis.Occluders == 0 ? 1
      : emitter                                 ? this->Settings.VisibilitySamples
                                                : this->Settings.IndirectVisibilitySamples;
    SubTriangles(mesh.Corner(node, 0), mesh.Corner(node, 1), mesh.Corner(node, 2), DepthOfSamples(samples), parts);
    for (const auto& part : parts)
    {
      for (int v = 0; v < 3; ++v)
      {
        Split(scaled(part[v]), shooter.Vertices[v], shooter.VerticesLo[v]);
      }
      Split(scaled((part[0] + part[1] + part[2]) / 3.0), shooter.Centre, shooter.CentreLo);
      shooter.Area = static_cast<float>(n.Area * areaScale / static_cast<double>(parts.size()));
      gpu.Shoot(shooter, discTolerance);
    }
    // The shooter keeps minus what it shot in advance (ProgressiveRadiosity::Solve).
    gpu.SetUnshot(nodeFirst[k], nodeCount[k], ToFloat(-overshoot));
  }

  // The solution comes back once.
  const std::array<std::vector<float>, 5> result = gpu.ReadElements();
  double absorbed = 0.0, unshot = 0.0;
  for (std::size_t i = 0; i < leaves.size(); ++i)
  {
    Element& e = mesh[leaves[i]];
    ElementSamples& h = e.Irradiance;
    for (int c = 0; c < 3; ++c)
    {
      h.Corner[c] = Get(result[c], i);
    }
    h.Centre = Get(result[3], i);
    e.Unshot = Get(result[4], i);
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
    absorbed += Mean((RGB(1.0) - mesh.MaterialOf(leaves[i]).Reflectance) * h.Mean()) * e.Area;
    unshot += Mean(e.Unshot) * e.Area;
  }
  stats.AbsorbedPowerW = absorbed;
  // By difference: what is neither absorbed nor left unshot has left the scene.
  stats.EscapedPowerW = std::max(0.0, emitted - absorbed - unshot);
  stats.SolveSeconds = start.Seconds();
  return stats;
}
} // namespace radiosity
