#include "Radiosity/Meshless/ShepardField.h"

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
