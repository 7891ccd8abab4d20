#include "Radiosity/Meshless/ShepardField.h"

#include <algorithm>

namespace radiosity
{
ShepardField::ShepardField(const PointHierarchy& points)
  : Hierarchy(&points)
  , Alpha(points.Points().size(), RGB(0.0))
{
}

void ShepardField::Basis(int level, std::uint32_t group, const Vec3& x, const Vec3& n,
  std::vector<std::pair<std::uint32_t, double>>& out) const
{
  thread_local std::vector<std::uint32_t> near;
  near.clear();
  this->Hierarchy->Supporting(level, group, x, near);
  const std::size_t first = out.size();
  double total = 0.0;
  for (std::uint32_t j : near)
  {
    const double w = ShepardWeight(this->Hierarchy->Points()[j], x, n);
    if (w > 0.0)
    {
      out.emplace_back(j, w);
      total += w;
    }
  }
  // Eq. 8: normalised within the level, so the level's functions sum to one.
  for (std::size_t k = first; k < out.size(); ++k)
  {
    out[k].second /= total;
  }
}

RGB ShepardField::Evaluate(const Vec3& x, const Vec3& n, std::uint32_t group, int maxLevel) const
{
  const int levels = this->Hierarchy->NumberOfLevels();
  const int last = maxLevel < 0 ? levels - 1 : std::min(maxLevel, levels - 1);
  thread_local std::vector<std::pair<std::uint32_t, double>> basis;
  RGB f(0.0);
  for (int level = 0; level <= last; ++level)
  {
    basis.clear();
    this->Basis(level, group, x, n, basis);
    for (const auto& [j, b] : basis)
    {
      f += b * this->Alpha[j];
    }
  }
  return f;
}

namespace
{
/// The centre of `count` points and a distance beyond which none lies.
std::pair<Vec3, double> Enclosing(const Vec3* x, std::size_t count)
{
  Vec3 centre(0.0);
  for (std::size_t s = 0; s < count; ++s)
  {
    centre += x[s];
  }
  centre /= static_cast<double>(std::max<std::size_t>(count, 1));
  double reach = 0.0;
  for (std::size_t s = 0; s < count; ++s)
  {
    reach = std::max(reach, glm::length(x[s] - centre));
  }
  // A little more, so that rounding cannot leave out a function whose
  // support ends at a point (its weight there is zero anyway).
  return { centre, reach * (1.0 + 1e-9) + 1e-12 * glm::length(centre) };
}
}

void ShepardField::EvaluateTile(const Vec3* x, const Vec3* n, std::size_t sets, std::size_t perSet,
  std::uint32_t group, RGB* out) const
{
  const std::size_t count = sets * perSet;
  std::fill(out, out + count, RGB(0.0));
  const auto [centre, reach] = Enclosing(x, count);
  thread_local std::vector<std::pair<Vec3, double>> around; // per set
  around.resize(sets);
  for (std::size_t set = 0; set < sets; ++set)
  {
    around[set] = Enclosing(x + set * perSet, perSet);
  }
  const std::vector<MeshlessPoint>& points = this->Hierarchy->Points();
  thread_local std::vector<std::uint32_t> tile, near;
  thread_local std::vector<double> weights, total;
  for (int level = 0; level < this->Hierarchy->NumberOfLevels(); ++level)
  {
    tile.clear();
    this->Hierarchy->Reaching(level, group, centre, reach, tile);
    for (std::size_t set = 0; set < sets; ++set)
    {
      // The tile's functions that reach this set (as Reaching would find).
      near.clear();
      const auto& [c, r] = around[set];
      for (std::uint32_t j : tile)
      {
        const MeshlessPoint& p = points[j];
        const Vec3 d = p.Position - c;
        if (glm::dot(d, d) < (p.Radius + r) * (p.Radius + r))
        {
          near.push_back(j);
        }
      }
      // Eqs. 12 and 8 at each point of the set, within the level.
      const Vec3* xs = x + set * perSet;
      RGB* values = out + set * perSet;
      weights.assign(near.size() * perSet, 0.0);
      total.assign(perSet, 0.0);
      for (std::size_t k = 0; k < near.size(); ++k)
      {
        for (std::size_t s = 0; s < perSet; ++s)
        {
          const double w = ShepardWeight(points[near[k]], xs[s], n[set]);
          weights[k * perSet + s] = w > 0.0 ? w : 0.0;
          total[s] += weights[k * perSet + s];
        }
      }
      for (std::size_t k = 0; k < near.size(); ++k)
      {
        for (std::size_t s = 0; s < perSet; ++s)
        {
          if (weights[k * perSet + s] > 0.0)
          {
            values[s] += weights[k * perSet + s] / total[s] * this->Alpha[near[k]];
          }
        }
      }
    }
  }
}

void ShepardField::Fit(const std::vector<RGB>& values)
{
  const auto& points = this->Hierarchy->Points();
  std::fill(this->Alpha.begin(), this->Alpha.end(), RGB(0.0));
  for (int level = 0; level < this->Hierarchy->NumberOfLevels(); ++level)
  {
    // Eq. 10: level 0 takes the values, finer levels the difference to the
    // coarser levels' approximation at their points.
    for (std::size_t j = this->Hierarchy->LevelBegin(level); j < this->Hierarchy->LevelEnd(level); ++j)
    {
      const MeshlessPoint& p = points[j];
      this->Alpha[j] = level == 0
        ? values[j]
        : values[j] - this->Evaluate(p.Position, p.Normal, p.Group, level - 1);
    }
  }
}
} // namespace radiosity
