#include "Radiosity/Meshless/MeshlessPoints.h"

#include "Radiosity/Common/Visibility.h"

#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <unordered_map>

namespace radiosity
{
// Named (not anonymous): PointHierarchy::Index holds these types.
namespace meshless_points_detail
{
/// nanoflann's view of a set of points.
struct Cloud
{
  const std::vector<MeshlessPoint>* Points = nullptr;
  std::size_t Begin = 0, End = 0;
  std::vector<std::uint32_t> Subset; ///< when non-empty: these indices only

  std::size_t kdtree_get_point_count() const
  {
    return this->Subset.empty() ? this->End - this->Begin : this->Subset.size();
  }
  std::size_t Global(std::size_t i) const
  {
    return this->Subset.empty() ? this->Begin + i : this->Subset[i];
  }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const
  {
    return (*this->Points)[this->Global(i)].Position[static_cast<int>(dim)];
  }
  template <class Box>
  bool kdtree_get_bbox(Box&) const
  {
    return false;
  }
};
using Tree =
  nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud, 3, std::size_t>;
} // namespace meshless_points_detail

namespace
{
using meshless_points_detail::Cloud;
using meshless_points_detail::Tree;

/// Accepted points of one group in a uniform grid of the current disk radius.
class AcceptanceGrid
{
public:
  void Reset(double cell)
  {
    this->Cell = cell;
    this->Cells.clear();
  }
  void Insert(const MeshlessPoint& p)
  {
    this->Cells[this->Key(this->CellOf(p.Position))].push_back(p);
  }
  /// Poisson-disk test with the radius scaled by the normals' dot product.
  bool Conflicts(const Vec3& x, const Vec3& n, double radius) const
  {
    const auto c = this->CellOf(x);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
    {
      for (std::int64_t dy = -1; dy <= 1; ++dy)
      {
        for (std::int64_t dz = -1; dz <= 1; ++dz)
        {
          const auto it = this->Cells.find(this->Key({ c[0] + dx, c[1] + dy, c[2] + dz }));
          if (it == this->Cells.end())
          {
            continue;
          }
          for (const MeshlessPoint& q : it->second)
          {
            if (glm::length(x - q.Position) < radius * std::max(0.0, glm::dot(n, q.Normal)))
            {
              return true;
            }
          }
        }
      }
    }
    return false;
  }

private:
  std::array<std::int64_t, 3> CellOf(const Vec3& x) const
  {
    return { static_cast<std::int64_t>(std::floor(x.x / this->Cell)),
      static_cast<std::int64_t>(std::floor(x.y / this->Cell)),
      static_cast<std::int64_t>(std::floor(x.z / this->Cell)) };
  }
  static std::uint64_t Key(const std::array<std::int64_t, 3>& c)
  {
    return (static_cast<std::uint64_t>(c[0]) * 73856093ull) ^
      (static_cast<std::uint64_t>(c[1]) * 19349663ull) ^ (static_cast<std::uint64_t>(c[2]) * 83492791ull);
  }
  double Cell = 1.0;
  std::unordered_map<std::uint64_t, std::vector<MeshlessPoint>> Cells;
};
} // namespace

// One level's points for the support searches, a k-d tree per group and
// radius class. A search must reach the largest support it can meet, so one
// tree per level, searched to the level's largest radius, returned every
// point within that radius of any group: a few isolated points with wide
// supports (a lamp's) made each query of the office's walls return
// thousands of matches to keep a dozen, and the searches were 84% of the
// meshless solve (perf, one thread). Here a query searches only its group's
// trees, each to its own largest radius, and the radii of one class are
// within a factor 2 of each other.
struct PointHierarchy::Index
{
  struct Bucket
  {
    Cloud Points;
    std::unique_ptr<Tree> KdTree;
    double MaxRadius = 0.0;
  };
  std::unordered_map<std::uint32_t, std::vector<Bucket>> Groups;
};

double MaxPoissonDiskPoints(const Scene& scene, const PointPlacementOptions& options)
{
  double area = 0.0;
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    area += scene.Area(t);
  }
  const double r0 = options.InitialRadius * (scene.Diagonal() > 0 ? scene.Diagonal() : 1.0);
  double points = 0.0;
  for (int level = 0; level < std::max(1, options.Levels); ++level)
  {
    const double r = r0 / std::ldexp(1.0, level);
    points += 2.0 / std::sqrt(3.0) * area / (r * r);
  }
  return points;
}

PointHierarchy::PointHierarchy(const Scene& scene, const PointPlacementOptions& options,
  const Visibility* rays, const std::function<bool()>& keepGoing)
{
  std::size_t candidates = 0;
  const int levels = std::max(1, options.Levels);
  const double diagonal = scene.Diagonal() > 0 ? scene.Diagonal() : 1.0;
  const double r0 = options.InitialRadius * diagonal;
  std::mt19937_64 rng(options.Seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);

  // Triangles per reconstruction group, with cumulative areas.
  std::unordered_map<int, std::vector<std::uint32_t>> groups;
  for (std::uint32_t t = 0; t < scene.Triangles.size(); ++t)
  {
    if (scene.Area(t) > 0)
    {
      groups[scene.ObjectIds[t]].push_back(t);
    }
  }
  std::vector<int> groupOrder;
  for (const auto& g : groups)
  {
    groupOrder.push_back(g.first);
  }
  std::sort(groupOrder.begin(), groupOrder.end());

  std::vector<std::vector<MeshlessPoint>> perLevel(static_cast<std::size_t>(levels));
  for (int g : groupOrder)
  {
    const std::vector<std::uint32_t>& tris = groups[g];
    std::vector<double> cumulative;
    double total = 0.0;
    for (std::uint32_t t : tris)
    {
      total += scene.Area(t);
      cumulative.push_back(total);
    }
    std::vector<MeshlessPoint> accepted;
    AcceptanceGrid grid;
    for (int level = 0; level < levels; ++level)
    {
      const double radius = r0 / std::ldexp(1.0, level);
      grid.Reset(radius);
      for (const MeshlessPoint& p : accepted)
      {
        grid.Insert(p);
      }
      int failures = 0;
      while (failures < options.MaxRejections)
      {
        if (keepGoing && (++candidates & 1023) == 0 && !keepGoing())
        {
          throw PlacementAborted();
        }
        // Every surface point equally likely: a triangle by area, a point in it.
        const double pick = uniform(rng) * total;
        const std::size_t k = static_cast<std::size_t>(
          std::lower_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin());
        const std::uint32_t t = tris[std::min(k, tris.size() - 1)];
        const double s = std::sqrt(uniform(rng)), u = uniform(rng);
        const Vec3 x = (1.0 - s) * scene.Vertex(t, 0) + s * (1.0 - u) * scene.Vertex(t, 1) +
          s * u * scene.Vertex(t, 2);
        const Vec3 n = scene.Normal(t);
        if (grid.Conflicts(x, n, radius))
        {
          ++failures;
          continue;
        }
        if (options.RejectInsideGeometry && rays)
        {
          // Inside geometry: the normal ray meets the back of a surface.
          double hit = 0, hu = 0, hv = 0;
          unsigned other = 0;
          const Vec3 origin = x + rays->Offset() * n;
          if (rays->Intersect(origin, n, hit, other, hu, hv) && glm::dot(n, scene.Normal(other)) > 0)
          {
            // A double polygon (two coincident faces back to back, a
            // two-sided blocker) shows its back face or its front face first
            // at random: the point is inside only when no face met at that
            // same distance faces it.
            std::vector<std::uint32_t> there;
            const Vec3 beyond = origin + (hit + 2.0 * rays->Offset()) * n;
            rays->CollectOccluders(&origin, &beyond, 1, there);
            bool facing = false;
            for (std::uint32_t f : there)
            {
              facing = facing || glm::dot(n, scene.Normal(f)) < 0;
            }
            if (!facing)
            {
              ++this->Inside;
              ++failures;
              continue;
            }
          }
        }
        failures = 0;
        MeshlessPoint p;
        p.Position = x;
        p.Normal = n;
        p.Level = static_cast<std::uint16_t>(level);
        p.Group = static_cast<std::uint32_t>(g);
        p.Triangle = t;
        accepted.push_back(p);
        grid.Insert(p);
        perLevel[static_cast<std::size_t>(level)].push_back(p);
      }
    }
  }

  this->LevelStart.push_back(0);
  for (const auto& l : perLevel)
  {
    this->All.insert(this->All.end(), l.begin(), l.end());
    this->LevelStart.push_back(this->All.size());
  }

  // Support radii: the k-th nearest neighbour on the same level and group.
  const std::size_t k = static_cast<std::size_t>(std::max(1, options.Neighbours));
  for (int level = 0; level < levels; ++level)
  {
    const double disk = r0 / std::ldexp(1.0, level);
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> members;
    for (std::size_t i = this->LevelStart[level]; i < this->LevelStart[level + 1]; ++i)
    {
      members[this->All[i].Group].push_back(static_cast<std::uint32_t>(i));
    }
    for (auto& [group, ids] : members)
    {
      Cloud cloud;
      cloud.Points = &this->All;
      cloud.Subset = ids;
      Tree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
      tree.buildIndex();
      const std::size_t want = std::min(k + 1, ids.size()); // the point itself comes first
      std::vector<std::size_t> index(want);
      std::vector<double> d2(want);
      for (std::uint32_t i : ids)
      {
        nanoflann::KNNResultSet<double, std::size_t> result(want);
        result.init(index.data(), d2.data());
        const double q[3] = { this->All[i].Position.x, this->All[i].Position.y, this->All[i].Position.z };
        tree.findNeighbors(result, q, nanoflann::SearchParams());
        const double far = std::sqrt(d2[result.size() - 1]);
        // Never less than the level's disk: too few neighbours would leave holes.
        this->All[i].Radius = std::max(far, disk);
      }
    }
  }

  for (int level = 0; level < levels; ++level)
  {
    auto index = std::make_unique<Index>();
    // Each group's points by radius class: floor(log2(r / smallest r)).
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> members;
    std::unordered_map<std::uint32_t, double> smallest;
    for (std::size_t i = this->LevelStart[level]; i < this->LevelStart[level + 1]; ++i)
    {
      const MeshlessPoint& p = this->All[i];
      members[p.Group].push_back(static_cast<std::uint32_t>(i));
      const auto it = smallest.find(p.Group);
      smallest[p.Group] = it == smallest.end() ? p.Radius : std::min(it->second, p.Radius);
    }
    for (auto& [group, ids] : members)
    {
      std::vector<std::vector<std::uint32_t>> classes;
      const double base = std::max(smallest[group], 1e-300);
      for (std::uint32_t i : ids)
      {
        const double ratio = std::max(this->All[i].Radius / base, 1.0);
        const std::size_t c = std::min<std::size_t>(static_cast<std::size_t>(std::log2(ratio)), 64);
        if (classes.size() <= c)
        {
          classes.resize(c + 1);
        }
        classes[c].push_back(i);
      }
      std::vector<Index::Bucket>& buckets = index->Groups[group];
      buckets.reserve(classes.size()); // a tree keeps a reference to its bucket's cloud
      for (std::vector<std::uint32_t>& subset : classes)
      {
        if (subset.empty())
        {
          continue;
        }
        buckets.emplace_back();
        Index::Bucket& b = buckets.back();
        for (std::uint32_t i : subset)
        {
          b.MaxRadius = std::max(b.MaxRadius, this->All[i].Radius);
        }
        b.Points.Points = &this->All;
        b.Points.Subset = std::move(subset);
        b.KdTree = std::make_unique<Tree>(3, b.Points, nanoflann::KDTreeSingleIndexAdaptorParams(10));
        b.KdTree->buildIndex();
      }
    }
    this->Indices.push_back(std::move(index));
  }
}

PointHierarchy::~PointHierarchy() = default;

void PointHierarchy::Supporting(
  int level, std::uint32_t group, const Vec3& x, std::vector<std::uint32_t>& out) const
{
  this->Search(level, group, x, 0.0, true, out);
}

void PointHierarchy::Reaching(
  int level, std::uint32_t group, const Vec3& c, double reach, std::vector<std::uint32_t>& out) const
{
  this->Search(level, group, c, reach, false, out);
}

void PointHierarchy::Search(int level, std::uint32_t group, const Vec3& c, double reach, bool sorted,
  std::vector<std::uint32_t>& out) const
{
  if (level < 0 || level >= this->NumberOfLevels())
  {
    return;
  }
  const Index& index = *this->Indices[static_cast<std::size_t>(level)];
  const auto found = index.Groups.find(group);
  if (found == index.Groups.end())
  {
    return;
  }
  thread_local std::vector<std::pair<std::size_t, double>> matches;
  thread_local std::vector<std::pair<double, std::uint32_t>> kept;
  kept.clear();
  const std::size_t first = out.size();
  const double q[3] = { c.x, c.y, c.z };
  nanoflann::SearchParams params;
  params.sorted = false;
  for (const Index::Bucket& bucket : found->second)
  {
    const double far = bucket.MaxRadius + reach;
    matches.clear();
    bucket.KdTree->radiusSearch(q, far * far, matches, params);
    for (const auto& m : matches)
    {
      const std::size_t j = bucket.Points.Global(m.first);
      const double r = this->All[j].Radius + reach;
      if (m.second < r * r)
      {
        kept.emplace_back(sorted ? m.second : 0.0, static_cast<std::uint32_t>(j));
      }
    }
  }
  // Sorted: nearest first, ties by index (the solve's summation order).
  // Unsorted: by index, so that the order does not depend on the trees.
  std::sort(kept.begin(), kept.end());
  out.resize(first + kept.size());
  for (std::size_t k = 0; k < kept.size(); ++k)
  {
    out[first + k] = kept[k].second;
  }
}
} // namespace radiosity
