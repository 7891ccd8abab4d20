#include "Radiosity/FaceCluster/FaceClusterHierarchy.h"
#include "Radiosity/Common/Morton.h"

#include "Radiosity/FaceCluster/FaceClusterGeometry.h"
#include "Radiosity/FaceCluster/MinimumRectangle.h"
#include "Radiosity/Common/Stopwatch.h"
#include "Radiosity/Common/ThreadLimit.h"

#include <Eigen/Eigenvalues>
#include <boost/container/small_vector.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <mutex>
#include <queue>
#include <unordered_map>

namespace radiosity
{
namespace
{
constexpr std::uint32_t None = FaceCluster::None;

// Area-weighted moments of a cluster's surface (the quantities of Garland et
// al.'s fit), about the scene's centre for precision.
struct Moments
{
  double Area = 0.0;
  Vec3 First{ 0.0 };              // integral of x
  std::array<double, 6> Second{}; // integral of x x^T: xx, xy, xz, yy, yz, zz
  Vec3 AreaVector{ 0.0 };         // sum A_k n_k
  double Perimeter = 0.0;

  void Add(const Moments& o)
  {
    this->Area += o.Area;
    this->First += o.First;
    for (int i = 0; i < 6; ++i)
    {
      this->Second[i] += o.Second[i];
    }
    this->AreaVector += o.AreaVector;
  }
};

Moments TriangleMoments(const Vec3& a, const Vec3& b, const Vec3& c)
{
  Moments m;
  const Vec3 areaVector = 0.5 * glm::cross(b - a, c - a);
  m.Area = glm::length(areaVector);
  m.AreaVector = areaVector;
  const Vec3 s = a + b + c;
  m.First = m.Area / 3.0 * s;
  // Integral of x x^T over a triangle: A / 12 (a a^T + b b^T + c c^T + s s^T).
  const Vec3 p[4] = { a, b, c, s };
  for (const Vec3& q : p)
  {
    m.Second[0] += q.x * q.x;
    m.Second[1] += q.x * q.y;
    m.Second[2] += q.x * q.z;
    m.Second[3] += q.y * q.y;
    m.Second[4] += q.y * q.z;
    m.Second[5] += q.z * q.z;
  }
  for (double& v : m.Second)
  {
    v *= m.Area / 12.0;
  }
  m.Perimeter = glm::length(b - a) + glm::length(c - b) + glm::length(a - c);
  return m;
}

// Garland et al. 2001's contraction cost, relative to area: the L2 plane-fit
// error (least eigenvalue of the covariance, a mean squared distance) over
// the area, the spread of the normals 1 - |sum A n| / A, and the compactness
// bias, the relative rise of the irregularity P^2 / (4 pi A).
double ContractionCost(const Moments& a, const Moments& b, double sharedLength, double shapeWeight)
{
  Moments m = a;
  m.Add(b);
  if (!(m.Area > 0.0))
  {
    return 0.0; // zero-area pieces merge first, at no cost
  }
  const Vec3 mu = m.First / m.Area;
  Eigen::Matrix3d c;
  c << m.Second[0] / m.Area - mu.x * mu.x, m.Second[1] / m.Area - mu.x * mu.y,
    m.Second[2] / m.Area - mu.x * mu.z, 0, m.Second[3] / m.Area - mu.y * mu.y,
    m.Second[4] / m.Area - mu.y * mu.z, 0, 0, m.Second[5] / m.Area - mu.z * mu.z;
  c(1, 0) = c(0, 1);
  c(2, 0) = c(0, 2);
  c(2, 1) = c(1, 2);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(c, Eigen::EigenvaluesOnly);
  const double fit = std::max(eigen.eigenvalues()(0), 0.0) / m.Area;
  const double direction = 1.0 - glm::length(m.AreaVector) / m.Area;
  auto irregularity = [](double perimeter, double area) {
    return area > 0.0 ? perimeter * perimeter / (4.0 * M_PI * area) : 0.0;
  };
  const double merged = irregularity(a.Perimeter + b.Perimeter - 2.0 * sharedLength, m.Area);
  const double before = std::max(irregularity(a.Perimeter, a.Area), irregularity(b.Perimeter, b.Area));
  const double shape = merged > 0.0 ? std::max(0.0, (merged - before) / merged) : 0.0;
  return fit + direction + shapeWeight * shape;
}

// A dual edge: the neighbour, the length of the shared boundary and the
// number of concave mesh edges along it.
struct Link
{
  std::uint32_t To;
  float Length;
  std::uint32_t Concave;
};

// A cluster's dual edges, the first few in place: most clusters of the
// early rounds have three to five neighbours, and the contraction visits
// every neighbour of each merged pair (one memory access, not two).
using Adjacency = boost::container::small_vector<Link, 4>;

struct Candidate
{
  float Cost;
  std::uint32_t A, B;
  bool operator<(const Candidate& o) const { return this->Cost > o.Cost; } // min-heap
};

} // namespace

//------------------------------------------------------------------------------
std::uint64_t FaceClusterHierarchy::FingerprintOf(const Scene& scene, const FaceClusterOptions& options)
{
  std::uint64_t h = 1469598103934665603ull; // FNV-1a
  auto mix = [&h](const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i)
    {
      h = (h ^ p[i]) * 1099511628211ull;
    }
  };
  mix(scene.Points.data(), scene.Points.size() * sizeof(Vec3));
  mix(scene.Triangles.data(), scene.Triangles.size() * sizeof(Triangle));
  mix(scene.ObjectIds.data(), scene.ObjectIds.size() * sizeof(int));
  for (const Material& m : scene.Materials)
  {
    mix(&m.Reflectance, sizeof(RGB));
    mix(&m.Emission, sizeof(RGB));
  }
  mix(&options.ShapeWeight, sizeof(double));
  return h;
}

//------------------------------------------------------------------------------
std::shared_ptr<const FaceClusterHierarchy> FaceClusterHierarchy::Shared(
  const Scene& scene, const FaceClusterOptions& options, const ProgressCallback& progress,
  bool* reused)
{
  return Share(scene, [&scene] { return std::make_shared<const Scene>(scene); }, options,
    progress, reused);
}

std::shared_ptr<const FaceClusterHierarchy> FaceClusterHierarchy::Shared(
  std::shared_ptr<const Scene> scene, const FaceClusterOptions& options,
  const ProgressCallback& progress, bool* reused)
{
  return Share(*scene, [&scene] { return scene; }, options, progress, reused);
}

std::shared_ptr<const FaceClusterHierarchy> FaceClusterHierarchy::Share(const Scene& scene,
  const std::function<std::shared_ptr<const Scene>()>& own, const FaceClusterOptions& options,
  const ProgressCallback& progress, bool* reused)
{
  static std::mutex mutex;
  static std::map<std::uint64_t, std::weak_ptr<const FaceClusterHierarchy>> cache;
  const std::uint64_t key = FingerprintOf(scene, options);
  if (reused)
  {
    *reused = false;
  }
  {
    const std::lock_guard<std::mutex> lock(mutex);
    auto it = cache.find(key);
    if (it != cache.end())
    {
      if (auto held = it->second.lock())
      {
        if (reused)
        {
          *reused = true;
        }
        return held;
      }
    }
  }
  std::shared_ptr<const FaceClusterHierarchy> built(
    new FaceClusterHierarchy(own(), key, options, progress));
  const std::lock_guard<std::mutex> lock(mutex);
  cache[key] = built;
  return built;
}

//------------------------------------------------------------------------------
FaceClusterHierarchy::FaceClusterHierarchy(
  const Scene& scene, const FaceClusterOptions& options, const ProgressCallback& progress)
  : FaceClusterHierarchy(std::make_shared<const Scene>(scene), options, progress)
{
}

FaceClusterHierarchy::FaceClusterHierarchy(std::shared_ptr<const Scene> scene,
  const FaceClusterOptions& options, const ProgressCallback& progress)
  : FaceClusterHierarchy(scene, FingerprintOf(*scene, options), options, progress)
{
}

FaceClusterHierarchy::FaceClusterHierarchy(std::shared_ptr<const Scene> scene, std::uint64_t key,
  const FaceClusterOptions& options, const ProgressCallback& progress)
  : Source(std::move(scene))
  , Triangles(this->Source->Triangles.size())
  , Key(key)
{
  const Stopwatch clock;
  // The thread limit applies to this build alone (a task arena of its own).
  RunWithThreads(options.Threads, [&]() {
    if (this->Triangles >= None / 2)
    {
      throw SceneError("Face cluster hierarchy: " + std::to_string(this->Triangles) +
        " triangles exceed the 2^31 the hierarchy can index.");
    }
    this->Contract(options, progress);
    this->LayOut();
    this->OrderByHeight();
    this->ComputeBoxes(options);
    this->Seconds = clock.Seconds();
  });
}

//------------------------------------------------------------------------------
void FaceClusterHierarchy::Contract(const FaceClusterOptions& options, const ProgressCallback& progress)
{
  const Scene& scene = *this->Source;
  const std::size_t n = this->Triangles;
  Vec3 lo, hi;
  scene.BoundingBox(lo, hi);
  const Vec3 centre = 0.5 * (lo + hi);
  const Vec3 extent = glm::max(hi - lo, Vec3(1e-300));

  // Cluster state lives in slots: a merged cluster takes its first child's.
  std::vector<Moments> state(n);
  std::vector<Adjacency> adjacency(n);
  std::vector<std::uint32_t> slot(2 * n, None);
  std::vector<char> alive(2 * n, 0);
  std::vector<char> convex(2 * n, 1);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t t) {
    state[t] = TriangleMoments(
      scene.Vertex(t, 0) - centre, scene.Vertex(t, 1) - centre, scene.Vertex(t, 2) - centre);
  });
  for (std::size_t t = 0; t < n; ++t)
  {
    slot[t] = static_cast<std::uint32_t>(t);
    alive[t] = 1;
  }

  // The dual graph: triangles of one object sharing a mesh edge.
  {
    // (v0, v1, triangle), v0 < v1: listed and sorted in parallel (the
    // entries are distinct, so any sort gives the same order).
    std::vector<std::array<std::uint32_t, 3>> edges(3 * n);
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t t) {
      for (int k = 0; k < 3; ++k)
      {
        std::uint32_t a = scene.Triangles[t].V[k], b = scene.Triangles[t].V[(k + 1) % 3];
        edges[3 * t + k] = { std::min(a, b), std::max(a, b), static_cast<std::uint32_t>(t) };
      }
    });
    tbb::parallel_sort(edges.begin(), edges.end());
    for (std::size_t i = 0; i < edges.size();)
    {
      std::size_t j = i;
      while (j < edges.size() && edges[j][0] == edges[i][0] && edges[j][1] == edges[i][1])
      {
        ++j;
      }
      const float length = static_cast<float>(
        glm::length(scene.Points[edges[i][1]] - scene.Points[edges[i][0]]));
      for (std::size_t p = i; p < j; ++p)
      {
        for (std::size_t q = p + 1; q < j; ++q)
        {
          const std::uint32_t s = edges[p][2], t = edges[q][2];
          if (s == t || scene.ObjectIds[s] != scene.ObjectIds[t])
          {
            continue;
          }
          const std::uint32_t concave = EdgeIsConcave(scene, s, t) ? 1u : 0u;
          adjacency[s].push_back({ t, length, concave });
          adjacency[t].push_back({ s, length, concave });
        }
      }
      i = j;
    }
  }

  // Contraction in rounds: a round takes the candidates in cost order and
  // merges each cluster at most once (a greedy matching of the dual graph);
  // pairs with a cluster born in the round wait for the next. A single
  // greedy queue lets a large cluster absorb its neighbours one by one (a
  // tree thousands of levels deep); rounds keep the depth logarithmic.
  std::priority_queue<Candidate> queue, nextRound;
  auto candidate = [&](std::uint32_t a, std::uint32_t b, double shared) {
    return Candidate{ static_cast<float>(ContractionCost(state[slot[a]], state[slot[b]], shared, options.ShapeWeight)),
      a, b };
  };
  auto push = [&](std::uint32_t a, std::uint32_t b, double shared) { nextRound.push(candidate(a, b, shared)); };
  {
    // The first round's costs in parallel, pushed in the same order as one
    // at a time (the heap's order among equal costs depends on it).
    std::vector<std::size_t> first(n + 1, 0);
    for (std::uint32_t t = 0; t < n; ++t)
    {
      std::size_t count = 0;
      for (const Link& l : adjacency[t])
      {
        count += l.To > t;
      }
      first[t + 1] = first[t] + count;
    }
    std::vector<Candidate> initial(first[n]);
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t t) {
      std::size_t i = first[t];
      for (const Link& l : adjacency[t])
      {
        if (l.To > t)
        {
          initial[i++] = candidate(static_cast<std::uint32_t>(t), l.To, l.Length);
        }
      }
    });
    for (const Candidate& c : initial)
    {
      queue.push(c);
    }
  }

  std::uint32_t next = static_cast<std::uint32_t>(n);
  this->Internal.reserve(n);
  this->LeafParent.assign(n, None);
  auto parentSlot = [&](std::uint32_t id) -> std::uint32_t& {
    return id < n ? this->LeafParent[id] : this->Internal[id - n].Parent;
  };
  std::size_t merges = 0;
  std::vector<Link> merged;
  for (;;)
  {
    if (queue.empty() && !nextRound.empty())
    {
      std::swap(queue, nextRound);
    }
    while (!queue.empty())
    {
      const Candidate c = queue.top();
      queue.pop();
      if (!alive[c.A] || !alive[c.B])
      {
        continue;
      }
      const std::uint32_t sa = slot[c.A], sb = slot[c.B];
      const std::uint32_t k = next++;
      // The shared boundary, then the union of the two neighbourhoods.
      Link between{ c.B, 0.0f, 0 };
      merged.clear();
      for (std::uint32_t s : { sa, sb })
      {
        for (const Link& l : adjacency[s])
        {
          if (l.To == c.A || l.To == c.B)
          {
            if (s == sa)
            {
              between = l;
            }
            continue;
          }
          merged.push_back(l);
        }
      }
      std::sort(merged.begin(), merged.end(),
        [](const Link& x, const Link& y) { return x.To < y.To; });
      std::size_t w = 0;
      for (std::size_t r = 0; r < merged.size(); ++r)
      {
        if (w > 0 && merged[w - 1].To == merged[r].To)
        {
          merged[w - 1].Length += merged[r].Length;
          merged[w - 1].Concave += merged[r].Concave;
        }
        else
        {
          merged[w++] = merged[r];
        }
      }
      merged.resize(w);

      const double perimeter =
        state[sa].Perimeter + state[sb].Perimeter - 2.0 * between.Length;
      state[sa].Add(state[sb]);
      state[sa].Perimeter = std::max(perimeter, 0.0);
      FaceCluster cluster;
      cluster.Child[0] = c.A;
      cluster.Child[1] = c.B;
      cluster.Object = scene.ObjectIds[sa];
      this->Internal.push_back(cluster);
      convex[k] = convex[c.A] && convex[c.B] && between.Concave == 0;
      parentSlot(c.A) = k;
      parentSlot(c.B) = k;
      alive[c.A] = alive[c.B] = 0;
      alive[k] = 1;
      slot[k] = sa;
      adjacency[sb].clear();
      adjacency[sb].shrink_to_fit();
      adjacency[sa].assign(merged.begin(), merged.end());
      for (const Link& l : merged)
      {
        Adjacency& theirs = adjacency[slot[l.To]];
        theirs.erase(std::remove_if(theirs.begin(), theirs.end(),
                       [&](const Link& x) { return x.To == c.A || x.To == c.B; }),
          theirs.end());
        theirs.push_back({ k, l.Length, l.Concave });
        push(k, l.To, l.Length);
      }
      if ((++merges & 0xffff) == 0 && progress)
      {
        ProgressStatus status;
        status.Phase = "clustering faces";
        status.Fraction = static_cast<double>(merges) / static_cast<double>(n);
        if (!progress(status))
        {
          throw FaceClusterBuildAborted("Face cluster hierarchy: aborted while clustering.");
        }
      }
    }

    if (!nextRound.empty())
    {
      continue;
    }
    // Components of one object that share no edge: chain each object's roots
    // in Morton order of their centroids, and go on contracting.
    std::map<int, std::vector<std::pair<std::uint64_t, std::uint32_t>>> roots;
    for (std::uint32_t id = 0; id < next; ++id)
    {
      if (alive[id])
      {
        const Moments& m = state[slot[id]];
        const Vec3 c = m.Area > 0.0 ? m.First / m.Area : Vec3(0.0);
        const int object = id < n ? scene.ObjectIds[id] : this->Internal[id - n].Object;
        roots[object].push_back({ Morton((c + centre - lo) / extent), id });
      }
    }
    bool chained = false;
    for (auto& [object, ids] : roots)
    {
      std::sort(ids.begin(), ids.end());
      for (std::size_t i = 0; i + 1 < ids.size(); ++i)
      {
        const std::uint32_t a = ids[i].second, b = ids[i + 1].second;
        adjacency[slot[a]].push_back({ b, 0.0f, 1 });
        adjacency[slot[b]].push_back({ a, 0.0f, 1 });
        push(a, b, 0.0);
        chained = true;
      }
    }
    if (!chained)
    {
      for (auto& [object, ids] : roots)
      {
        for (const auto& r : ids)
        {
          this->RootIds.push_back(r.second);
        }
      }
      break;
    }
  }
  for (std::size_t i = 0; i < this->Internal.size(); ++i)
  {
    this->Internal[i].Convex = convex[n + i] != 0;
  }
}

//------------------------------------------------------------------------------
void FaceClusterHierarchy::LayOut()
{
  const std::size_t n = this->Triangles;
  this->Order.clear();
  this->Order.reserve(n);
  this->LeafDepth.assign(n, 0);
  this->LeafPosition.assign(n, 0);
  this->MaxDepth = 0;
  // Depth first, children in order: each cluster's triangles are contiguous.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> stack; // (id, depth)
  for (std::uint32_t root : this->RootIds)
  {
    stack.push_back({ root, 0 });
    while (!stack.empty())
    {
      const auto [id, depth] = stack.back();
      stack.pop_back();
      this->MaxDepth = std::max<int>(this->MaxDepth, static_cast<int>(depth));
      if (id < n)
      {
        this->LeafDepth[id] = depth;
        this->LeafPosition[id] = static_cast<std::uint32_t>(this->Order.size());
        this->Order.push_back(id);
        continue;
      }
      FaceCluster& c = this->Internal[id - n];
      c.Depth = depth;
      stack.push_back({ c.Child[1], depth + 1 });
      stack.push_back({ c.Child[0], depth + 1 });
    }
  }
  this->Cumulative.assign(this->Order.size() + 1, 0.0);
  for (std::size_t i = 0; i < this->Order.size(); ++i)
  {
    this->Cumulative[i + 1] = this->Cumulative[i] + this->Source->Area(this->Order[i]);
  }
  // Ranges bottom-up: children have smaller ids than their parent.
  for (std::size_t i = 0; i < this->Internal.size(); ++i)
  {
    FaceCluster& c = this->Internal[i];
    std::uint32_t first = None, last = 0;
    for (std::uint32_t child : c.Child)
    {
      const std::uint32_t f = child < n ? this->LeafPosition[child] : this->Internal[child - n].First;
      const std::uint32_t cnt = child < n ? 1u : this->Internal[child - n].Count;
      first = std::min(first, f);
      last = std::max(last, f + cnt);
    }
    c.First = first;
    c.Count = last - first;
  }
}

//------------------------------------------------------------------------------
void FaceClusterHierarchy::OrderByHeight()
{
  const std::size_t n = this->Triangles, internal = this->Internal.size();
  // Children have smaller ids than their parent.
  std::vector<std::uint32_t> height(internal, 1);
  std::uint32_t highest = 0;
  for (std::size_t i = 0; i < internal; ++i)
  {
    for (std::uint32_t child : this->Internal[i].Child)
    {
      if (child >= n)
      {
        height[i] = std::max(height[i], height[child - n] + 1);
      }
    }
    highest = std::max(highest, height[i]);
  }
  this->HeightStart.assign(highest + 1, 0);
  for (std::uint32_t h : height)
  {
    ++this->HeightStart[h];
  }
  for (std::size_t h = 1; h < this->HeightStart.size(); ++h)
  {
    this->HeightStart[h] += this->HeightStart[h - 1];
  }
  this->ByHeight.resize(internal);
  std::vector<std::uint32_t> at(this->HeightStart.begin(), this->HeightStart.end() - 1);
  for (std::size_t i = 0; i < internal; ++i)
  {
    this->ByHeight[at[height[i] - 1]++] = static_cast<std::uint32_t>(i);
  }
}

//------------------------------------------------------------------------------
void FaceClusterHierarchy::ComputeBoxes(const FaceClusterOptions&)
{
  const Scene& scene = *this->Source;
  const std::size_t n = this->Triangles;
  // Pass 1, bottom-up: areas, area vectors, materials, and the box axes from
  // the hull candidates (the vertices of the children's projected hulls).
  std::vector<std::vector<Vec3>> hull(this->Internal.size());
  auto candidates = [&](std::uint32_t id, std::vector<Vec3>& out) {
    if (id < n)
    {
      for (int k = 0; k < 3; ++k)
      {
        out.push_back(scene.Vertex(id, k));
      }
    }
    else
    {
      std::vector<Vec3>& h = hull[id - n];
      out.insert(out.end(), h.begin(), h.end());
      h.clear();
      h.shrink_to_fit();
    }
  };
  // One height at a time (a cluster after its children), each in parallel.
  auto merge = [&](std::size_t i, std::vector<Vec3>& points, std::vector<glm::dvec2>& planar) {
    FaceCluster& c = this->Internal[i];
    const FaceCluster a = this->Cluster(c.Child[0]);
    const FaceCluster b = this->Cluster(c.Child[1]);
    MergeClusterAttributes(a, b, c);
    Vec3 z = Vec3(c.AreaVector);
    if (glm::length(z) <= 1e-3 * c.Area)
    {
      z = DominantNormal(scene, this->Order, c.First, c.Count);
    }
    z = glm::normalize(z);
    points.clear();
    candidates(c.Child[0], points);
    candidates(c.Child[1], points);
    Vec3 e1, e2;
    PerpendicularAxes(z, e1, e2);
    planar.clear();
    for (const Vec3& p : points)
    {
      planar.emplace_back(glm::dot(p, e1), glm::dot(p, e2));
    }
    const PlanarHullRectangle rectangle = MinimumAreaRectangle(planar);
    const Vec3 x = rectangle.Axis.x * e1 + rectangle.Axis.y * e2;
    c.Axis[0] = glm::vec3(x);
    c.Axis[1] = glm::vec3(glm::cross(z, x));
    c.Axis[2] = glm::vec3(z);
    if (c.Parent != None)
    {
      // Keep the hull vertices (at most 64, evenly spread) for the parent.
      std::vector<Vec3>& kept = hull[i];
      const std::size_t h = rectangle.Hull.size();
      const std::size_t step = h > 64 ? (h + 63) / 64 : 1;
      for (std::size_t v = 0; v < h; v += step)
      {
        for (std::size_t p = 0; p < points.size(); ++p)
        {
          if (planar[p] == rectangle.Hull[v])
          {
            kept.push_back(points[p]);
            break;
          }
        }
      }
    }
  };
  for (std::size_t h = 0; h + 1 < this->HeightStart.size(); ++h)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(this->HeightStart[h], this->HeightStart[h + 1], 256),
      [&](const tbb::blocked_range<std::size_t>& range) {
        std::vector<Vec3> points;
        std::vector<glm::dvec2> planar;
        for (std::size_t k = range.begin(); k != range.end(); ++k)
        {
          merge(this->ByHeight[k], points, planar);
        }
      });
  }
  // Pass 2, in parallel: the box extents and the six directional samples
  // over each cluster's triangles.
  tbb::parallel_for(std::size_t(0), this->Internal.size(), [&](std::size_t i) {
    FitBoxAndSamples(scene, this->Order, this->Internal[i]);
  });
}

//------------------------------------------------------------------------------
FaceCluster FaceClusterHierarchy::Cluster(std::uint32_t id) const
{
  if (id >= this->Triangles)
  {
    return this->Internal[id - this->Triangles];
  }
  FaceCluster c = TriangleCluster(*this->Source, id);
  c.Parent = this->LeafParent[id];
  c.First = this->LeafPosition[id];
  c.Count = 1;
  c.Depth = this->LeafDepth[id];
  return c;
}

std::uint32_t FaceClusterHierarchy::Parent(std::uint32_t id) const
{
  return id < this->Triangles ? this->LeafParent[id] : this->Internal[id - this->Triangles].Parent;
}

std::uint32_t FaceClusterHierarchy::Depth(std::uint32_t id) const
{
  return id < this->Triangles ? this->LeafDepth[id] : this->Internal[id - this->Triangles].Depth;
}

std::uint32_t FaceClusterHierarchy::AncestorAtDepth(std::uint32_t id, std::uint32_t depth) const
{
  while (this->Depth(id) > depth)
  {
    id = this->Parent(id);
  }
  return id;
}

std::size_t FaceClusterHierarchy::MemoryBytes() const
{
  return this->Internal.capacity() * sizeof(FaceCluster) +
    (this->LeafParent.capacity() + this->LeafDepth.capacity() + this->LeafPosition.capacity() +
      this->Order.capacity() + this->RootIds.capacity()) *
    sizeof(std::uint32_t) +
    this->Cumulative.capacity() * sizeof(double);
}
} // namespace radiosity
