#include "Radiosity/Meshless/MeshlessTransfer.h"

#include "Radiosity/Common/MemoryBudget.h"
#include "Radiosity/Common/Stopwatch.h"
#include "Radiosity/Meshless/BounceSeries.h"
#include "Radiosity/Meshless/MeshlessGather.h"
#include "Radiosity/Meshless/MeshlessNeighbourhoods.h"
#include "Radiosity/Meshless/ReceiverOracle.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>

namespace radiosity
{
namespace
{
/// Rows computed between two asks of keepGoing and two memory checks.
constexpr std::size_t RowsPerBlock = 2048;
}

MeshlessTransfer::MeshlessTransfer(const Scene& scene, const PointHierarchy& points, const Visibility& rays,
  const MeshlessNeighbourhoods& lists, const MeshlessOptions& options, std::vector<std::uint32_t> receivers, const std::function<bool()>& keepGoing,
  double memoryBudgetBytes)
  : SourceScene(&scene)
  , Rays(rays)
  , Lists(lists)
  , Options(options)
  , MemoryBudgetBytes(memoryBudgetBytes)
  , Points(points)
  , Rows(std::move(receivers))
{
  std::sort(this->Rows.begin(), this->Rows.end());
  this->Rows.erase(std::unique(this->Rows.begin(), this->Rows.end()), this->Rows.end());
  const auto& all = points.Points();

  // One reflectance per object: the weights need no colour.
  std::vector<RGB> objectReflectance;
  std::vector<unsigned char> seen;
  bool uniform = true;
  for (std::size_t t = 0; t < scene.Triangles.size() && uniform; ++t)
  {
    const auto object = static_cast<std::size_t>(std::max(0, scene.ObjectIds[t]));
    if (object >= seen.size())
    {
      seen.resize(object + 1, 0);
      objectReflectance.resize(object + 1, RGB(0.0));
    }
    if (!seen[object])
    {
      seen[object] = 1;
      objectReflectance[object] = scene.Materials[t].Reflectance;
    }
    uniform = objectReflectance[object] == scene.Materials[t].Reflectance;
  }
  this->WeightComponents = uniform ? 1 : 3;
  if (uniform)
  {
    this->SenderReflectance.resize(all.size());
    for (std::size_t k = 0; k < all.size(); ++k)
    {
      this->SenderReflectance[k] =
        all[k].Group < objectReflectance.size() ? objectReflectance[all[k].Group] : RGB(0.0);
    }
  }
  const ShepardField basis(points);
  struct Row
  {
    std::vector<std::uint32_t> Senders;
    std::vector<float> Weights;
  };
  this->RowStart.clear();
  this->RowEnd.clear();
  std::vector<Row> block;
  for (std::size_t begin = 0; begin < this->Rows.size(); begin += RowsPerBlock)
  {
    if (keepGoing && !keepGoing())
    {
      throw PlacementAborted();
    }
    const std::size_t end = std::min(this->Rows.size(), begin + RowsPerBlock);
    block.assign(end - begin, Row());
    tbb::parallel_for(begin, end, [&](std::size_t r) {
      Row& row = block[r - begin];
      this->GatherRow(this->Rows[r], basis, row.Senders, row.Weights);
    });
    for (Row& row : block)
    {
      this->RowStart.push_back(this->Senders.size());
      this->Senders.insert(this->Senders.end(), row.Senders.begin(), row.Senders.end());
      this->Weights.insert(this->Weights.end(), row.Weights.begin(), row.Weights.end());
      this->RowEnd.push_back(this->Senders.size());
    }
    this->CheckMemory(end, this->Rows.size());
  }
  this->IndexRows();
}

void MeshlessTransfer::GatherRow(std::uint32_t j, const ShepardField& basis, std::vector<std::uint32_t>& senders,
  std::vector<float>& weights) const
{
  const bool uniform = this->WeightComponents == 1;
  thread_local std::vector<std::pair<std::uint32_t, RGB>> raw;
  raw.clear();
  GatherWeights(*this->SourceScene, this->Points, basis, this->Rays, this->Options, j,
    [&](std::uint32_t k, double w, const RGB& reflectance) {
      raw.emplace_back(k, uniform ? RGB(w) : w * reflectance);
    });
  std::sort(raw.begin(), raw.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t i = 0; i < raw.size();)
  {
    RGB sum(0.0);
    const std::uint32_t k = raw[i].first;
    for (; i < raw.size() && raw[i].first == k; ++i)
    {
      sum += raw[i].second;
    }
    senders.push_back(k);
    if (uniform)
    {
      weights.push_back(static_cast<float>(sum.x));
    }
    else
    {
      weights.insert(weights.end(), { static_cast<float>(sum.x), static_cast<float>(sum.y), static_cast<float>(sum.z) });
    }
  }
}

void MeshlessTransfer::IndexRows()
{
  const auto& all = this->Points.Points();
  const int levels = this->Points.NumberOfLevels();
  this->LevelStart.assign(static_cast<std::size_t>(levels) + 1, this->Rows.size());
  for (std::size_t r = this->Rows.size(); r-- > 0;)
  {
    this->LevelStart[all[this->Rows[r]].Level] = r;
  }
  for (int level = levels - 1; level >= 0; --level)
  {
    this->LevelStart[level] = std::min(this->LevelStart[level], this->LevelStart[level + 1]);
  }
  this->CoarseRows = levels > 0 ? this->LevelStart[1] : 0;
  // Where each point sits in Rows (the fit's columns), or none.
  this->RowOf.assign(all.size(), UINT32_MAX);
  for (std::size_t r = 0; r < this->Rows.size(); ++r)
  {
    this->RowOf[this->Rows[r]] = static_cast<std::uint32_t>(r);
  }
  // The receiver oracle's neighbourhoods (MeshlessNeighbourhoods) in rows,
  // and eq. 10's fit: the coarser receivers' basis values at each row's point.
  const auto inRows = [&](auto list, std::vector<std::size_t>& start, std::vector<std::uint32_t>& items) {
    for (std::uint32_t k : list)
    {
      if (this->RowOf[k] != UINT32_MAX)
      {
        items.push_back(this->RowOf[k]);
      }
    }
    start.push_back(items.size());
  };
  for (auto* v : { &this->NeighbourStart, &this->ChildStart, &this->AncestorStart, &this->FitStart })
  {
    v->assign(1, 0);
  }
  for (auto* v : { &this->Neighbours, &this->Children, &this->Ancestors, &this->FitColumns })
  {
    v->clear();
  }
  this->FitWeights.clear();
  for (std::uint32_t j : this->Rows)
  {
    inRows(this->Lists.Neighbours(j), this->NeighbourStart, this->Neighbours);
    inRows(this->Lists.Children(j), this->ChildStart, this->Children);
    inRows(this->Lists.Ancestors(j), this->AncestorStart, this->Ancestors);
    for (const auto& [k, w] : this->Lists.Fit(j))
    {
      if (this->RowOf[k] != UINT32_MAX)
      {
        this->FitColumns.push_back(this->RowOf[k]);
        this->FitWeights.push_back(static_cast<float>(w));
      }
    }
    this->FitStart.push_back(this->FitColumns.size());
  }
}

void MeshlessTransfer::AddRows(std::vector<std::uint32_t> extra)
{
  std::sort(extra.begin(), extra.end());
  extra.erase(std::unique(extra.begin(), extra.end()), extra.end());
  // Their gathers, as the precomputation's.
  const ShepardField basis(this->Points);
  std::vector<std::vector<std::uint32_t>> senders(extra.size());
  std::vector<std::vector<float>> weights(extra.size());
  tbb::parallel_for(std::size_t(0), extra.size(),
    [&](std::size_t i) { this->GatherRow(extra[i], basis, senders[i], weights[i]); });
  // Their weights appended to the table as they are (a row's entries are
  // found by its own range, so the table is not rebuilt: copying the
  // office's 14M entries took 128 ms a pass, against 41 ms for the gathers
  // of 23 rows), the rows merged in point order with the rows there are.
  std::vector<std::size_t> begins(extra.size()), ends(extra.size());
  for (std::size_t i = 0; i < extra.size(); ++i)
  {
    begins[i] = this->Senders.size();
    this->Senders.insert(this->Senders.end(), senders[i].begin(), senders[i].end());
    this->Weights.insert(this->Weights.end(), weights[i].begin(), weights[i].end());
    ends[i] = this->Senders.size();
  }
  std::vector<std::uint32_t> rows;
  std::vector<std::size_t> rowStart, rowEnd;
  rows.reserve(this->Rows.size() + extra.size());
  rowStart.reserve(rows.capacity());
  rowEnd.reserve(rows.capacity());
  std::size_t old = 0, add = 0;
  while (old < this->Rows.size() || add < extra.size())
  {
    if (add == extra.size() || (old < this->Rows.size() && this->Rows[old] < extra[add]))
    {
      rows.push_back(this->Rows[old]);
      rowStart.push_back(this->RowStart[old]);
      rowEnd.push_back(this->RowEnd[old]);
      ++old;
    }
    else
    {
      rows.push_back(extra[add]);
      rowStart.push_back(begins[add]);
      rowEnd.push_back(ends[add]);
      ++add;
    }
  }
  this->Rows = std::move(rows);
  this->RowStart = std::move(rowStart);
  this->RowEnd = std::move(rowEnd);
  this->IndexRows();
  this->CheckMemory(this->Rows.size(), this->Rows.size());
}

void MeshlessTransfer::CheckMemory(std::size_t done, std::size_t of) const
{
  if (this->MemoryBudgetBytes > 0 && static_cast<double>(this->MemoryBytes()) > this->MemoryBudgetBytes)
  {
    throw SceneError("meshless relighting: the transfer's rows need more than the memory budget (" +
      FormatCount(static_cast<double>(this->MemoryBytes())) + " bytes after " + std::to_string(done) + " of " +
      std::to_string(of) + " receivers); raise the budget (MaxMemory) or --point-radius");
  }
}

std::size_t MeshlessTransfer::MemoryBytes() const
{
  return (this->Rows.size() + this->RowOf.size()) * sizeof(std::uint32_t) + (this->RowStart.size() + this->RowEnd.size()) * sizeof(std::size_t) +
    this->Senders.size() * sizeof(std::uint32_t) + this->Weights.size() * sizeof(float) +
    this->SenderReflectance.size() * sizeof(RGB) +
    this->FitStart.size() * sizeof(std::size_t) + this->FitColumns.size() * sizeof(std::uint32_t) +
    this->FitWeights.size() * sizeof(float) +
    (this->NeighbourStart.size() + this->ChildStart.size() + this->AncestorStart.size()) * sizeof(std::size_t) +
    (this->Neighbours.size() + this->Children.size() + this->Ancestors.size()) * sizeof(std::uint32_t);
}

MeshlessTransfer::Series MeshlessTransfer::Indirect(
  const std::vector<RGB>& direct, double tolerance, int maxBounces, double threshold, double gatherSeconds)
{
  // The rows a lighting wants are known only once its series is summed
  // (the oracle follows the values), and each added row may want its own
  // children: summed again until every wanted receiver is a row (at most
  // one pass per level), or the time for gathers is spent.
  const Stopwatch clock;
  std::vector<std::uint32_t> missing;
  Series out = this->Sum(direct, tolerance, maxBounces, threshold, missing);
  std::size_t added = 0;
  double addSeconds = 0.0;
  for (int pass = 0; !missing.empty() && pass <= this->Points.NumberOfLevels(); ++pass)
  {
    std::sort(missing.begin(), missing.end()); // point order: the coarsest first
    missing.erase(std::unique(missing.begin(), missing.end()), missing.end());
    if (gatherSeconds > 0.0)
    {
      // As many as the time left allows at the cost per row so far (a few
      // to measure it first).
      const double left = gatherSeconds - addSeconds;
      if (left <= 0.0)
      {
        break;
      }
      const std::size_t allowed = added > 0
        ? std::max<std::size_t>(1, static_cast<std::size_t>(left / (addSeconds / static_cast<double>(added))))
        : 8;
      if (missing.size() > allowed)
      {
        missing.resize(allowed);
      }
    }
    const double before = clock.Seconds();
    const std::size_t rows = this->Rows.size();
    this->AddRows(std::move(missing));
    added += this->Rows.size() - rows;
    addSeconds += clock.Seconds() - before;
    missing.clear();
    out = this->Sum(direct, tolerance, maxBounces, threshold, missing);
  }
  std::sort(missing.begin(), missing.end());
  out.RowsDeferred = static_cast<std::size_t>(std::unique(missing.begin(), missing.end()) - missing.begin());
  out.RowsAdded = added;
  out.RowsAddedSeconds = addSeconds;
  return out;
}

MeshlessTransfer::Series MeshlessTransfer::Sum(const std::vector<RGB>& direct, double tolerance, int maxBounces,
  double threshold, std::vector<std::uint32_t>& missing) const
{
  Series out;
  const auto& all = this->Points.Points();
  out.Indirect.assign(all.size(), RGB(0.0));
  double base = 0.0;
  for (std::size_t j = 0; j < all.size() && all[j].Level == 0; ++j)
  {
    base += MaxComponent(direct[j]);
  }
  out.Magnitudes.push_back(base);
  if (!(base > 0.0) || this->Rows.empty())
  {
    out.Converged = true;
    return out;
  }
  const std::size_t rows = this->Rows.size();
  // The previous bounce's coefficients over every point (the direct light's
  // first, then the receivers'; times the senders' reflectance with
  // one-float weights), this bounce's values and coefficients per row.
  const bool scalar = this->WeightComponents == 1;
  std::vector<RGB> previous = direct, value(rows), alpha(rows);
  if (scalar)
  {
    for (std::size_t k = 0; k < previous.size(); ++k)
    {
      previous[k] *= this->SenderReflectance[k];
    }
  }
  std::vector<unsigned char> computed(rows);
  std::vector<std::uint32_t> done;

  // A set of rows: their values from the previous bounce, then their
  // coefficients level by level (eq. 10; the coarser rows are final).
  const auto compute = [&](std::vector<std::uint32_t>& set) {
    std::sort(set.begin(), set.end()); // by row is by level
    set.erase(std::unique(set.begin(), set.end()), set.end());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, set.size(), 64),
      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i)
        {
          const std::uint32_t r = set[i];
          double x = 0, y = 0, z = 0;
          if (scalar)
          {
            const float* w = this->Weights.data() + this->RowStart[r];
            for (std::size_t s = this->RowStart[r]; s < this->RowEnd[r]; ++s, ++w)
            {
              const RGB& b = previous[this->Senders[s]];
              x += *w * b.x;
              y += *w * b.y;
              z += *w * b.z;
            }
          }
          else
          {
            const float* w = this->Weights.data() + 3 * this->RowStart[r];
            for (std::size_t s = this->RowStart[r]; s < this->RowEnd[r]; ++s, w += 3)
            {
              const RGB& b = previous[this->Senders[s]];
              x += w[0] * b.x;
              y += w[1] * b.y;
              z += w[2] * b.z;
            }
          }
          value[r] = RGB(x, y, z);
        }
      });
    std::size_t begin = 0;
    while (begin < set.size())
    {
      std::size_t end = begin;
      const int level = all[this->Rows[set[begin]]].Level;
      while (end < set.size() && all[this->Rows[set[end]]].Level == level)
      {
        ++end;
      }
      tbb::parallel_for(begin, end, [&](std::size_t i) {
        const std::uint32_t r = set[i];
        RGB a = value[r];
        for (std::size_t f = this->FitStart[r]; f < this->FitStart[r + 1]; ++f)
        {
          a -= static_cast<double>(this->FitWeights[f]) * alpha[this->FitColumns[f]];
        }
        alpha[r] = a;
      });
      begin = end;
    }
    for (std::uint32_t r : set)
    {
      computed[r] = 1;
      done.push_back(r);
    }
  };

  BounceSeries series;
  double previousMagnitude = base;
  std::vector<std::uint32_t> wave;
  for (int bounce = 1; bounce <= maxBounces; ++bounce)
  {
    // The solve's RECEIVER-ORACLE (MeshlessRadiosity::Refine) over the rows.
    for (std::uint32_t r : done)
    {
      alpha[r] = RGB(0.0);
      value[r] = RGB(0.0);
      computed[r] = 0;
    }
    done.clear();
    wave.resize(this->CoarseRows);
    for (std::size_t r = 0; r < this->CoarseRows; ++r)
    {
      wave[r] = static_cast<std::uint32_t>(r);
    }
    const auto listed = [](const std::vector<std::size_t>& start, const std::vector<std::uint32_t>& items) {
      return [&start, &items](std::uint32_t r, std::vector<std::uint32_t>& into) {
        into.insert(into.end(), items.begin() + start[r], items.begin() + start[r + 1]);
      };
    };
    // A refined row's children that are not rows, with their coarser
    // functions that are not either: wanted, and gathered by Indirect.
    const auto children = [&](std::uint32_t r, std::vector<std::uint32_t>& into) {
      listed(this->ChildStart, this->Children)(r, into);
      for (std::uint32_t c : this->Lists.Children(this->Rows[r]))
      {
        if (this->RowOf[c] == UINT32_MAX)
        {
          missing.push_back(c);
          for (std::uint32_t q : this->Lists.Ancestors(c))
          {
            if (this->RowOf[q] == UINT32_MAX)
            {
              missing.push_back(q);
            }
          }
        }
      }
    };
    RunReceiverOracle(wave, threshold, value, alpha, computed, compute,
      listed(this->NeighbourStart, this->Neighbours), children, listed(this->AncestorStart, this->Ancestors));
    double magnitude = 0.0;
    for (std::size_t r = 0; r < this->CoarseRows; ++r)
    {
      magnitude += MaxComponent(value[r]);
    }
    const BounceSeries::Step step = series.Next(previousMagnitude, magnitude);
    for (std::uint32_t r : done)
    {
      out.Indirect[this->Rows[r]] += step.Gain * alpha[r];
    }
    out.Bounces = bounce;
    out.RowsComputed += done.size();
    out.Magnitudes.push_back(magnitude);
    if (step.Steady || magnitude / base <= tolerance)
    {
      out.Converged = true;
      break;
    }
    if (bounce == 1)
    {
      std::fill(previous.begin(), previous.end(), RGB(0.0));
    }
    else
    {
      for (std::size_t r = 0; r < rows; ++r)
      {
        previous[this->Rows[r]] = RGB(0.0);
      }
    }
    for (std::uint32_t r : done)
    {
      const std::uint32_t j = this->Rows[r];
      previous[j] = scalar ? alpha[r] * this->SenderReflectance[j] : alpha[r];
    }
    previousMagnitude = magnitude;
  }
  return out;
}
} // namespace radiosity
