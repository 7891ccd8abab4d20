#include "vtkShepardSplatSurfaceTexels.h"

#include "vtkCellArray.h"
#include "vtkMath.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <limits>
#include <map>

namespace
{
constexpr int FloatsPerPoint = 12;

// A polygon's node grid: node (i, j) at O + i * Ds * A + j * Dt * B,
// 0 <= i <= Ms, 0 <= j <= Mt, covering the polygon's extent along A and B.
struct Grid
{
  double O[3], A[3], B[3];
  double Ds = 1.0, Dt = 1.0;
  int Ms = 1, Mt = 1;
};

Grid MakeGrid(vtkPoints* points, vtkIdType npts, const vtkIdType* ids, const float* normal, double h)
{
  Grid g;
  double p0[3], n[3] = { normal[0], normal[1], normal[2] };
  points->GetPoint(ids[0], p0);
  // A: the first edge in the plane; any direction normal to n without one.
  double e[3] = { 0.0, 0.0, 0.0 };
  for (vtkIdType k = 1; k < npts && vtkMath::Norm(e) < 1e-12; ++k)
  {
    double p[3];
    points->GetPoint(ids[k], p);
    for (int c = 0; c < 3; ++c)
    {
      e[c] = p[c] - p0[c];
    }
    const double along = vtkMath::Dot(e, n);
    for (int c = 0; c < 3; ++c)
    {
      e[c] -= along * n[c];
    }
  }
  if (vtkMath::Normalize(e) < 1e-12)
  {
    // A degenerate polygon: any frame (it covers no pixels).
    double unused[3];
    e[0] = 1.0;
    e[1] = e[2] = 0.0;
    if (vtkMath::Norm(n) > 0.0)
    {
      vtkMath::Perpendiculars(n, e, unused, 0.0);
    }
  }
  std::copy(e, e + 3, g.A);
  vtkMath::Cross(n, g.A, g.B);
  double lo[2] = { 0.0, 0.0 }, hi[2] = { 0.0, 0.0 };
  for (vtkIdType k = 1; k < npts; ++k)
  {
    double p[3];
    points->GetPoint(ids[k], p);
    const double d[3] = { p[0] - p0[0], p[1] - p0[1], p[2] - p0[2] };
    const double st[2] = { vtkMath::Dot(d, g.A), vtkMath::Dot(d, g.B) };
    for (int c = 0; c < 2; ++c)
    {
      lo[c] = std::min(lo[c], st[c]);
      hi[c] = std::max(hi[c], st[c]);
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    g.O[c] = p0[c] + lo[0] * g.A[c] + lo[1] * g.B[c];
  }
  const double ls = hi[0] - lo[0], lt = hi[1] - lo[1];
  g.Ms = std::max(1, static_cast<int>(std::min(4096.0, std::ceil(ls / h))));
  g.Mt = std::max(1, static_cast<int>(std::min(4096.0, std::ceil(lt / h))));
  g.Ds = ls > 0.0 ? ls / g.Ms : 1.0;
  g.Dt = lt > 0.0 ? lt / g.Mt : 1.0;
  return g;
}
}

double vtkShepardSplatSurfaceTexels::Evaluate(vtkPolyData* surface, const std::vector<float>& points,
  const std::vector<size_t>& levelOffsets, double spacing, size_t maximumNodes,
  std::vector<float>& cellTexels, int stride, int frameOffset, std::vector<float>& nodes)
{
  const size_t nPoints = points.size() / FloatsPerPoint;
  const vtkIdType nCells = surface->GetNumberOfCells();
  vtkCellArray* polys = surface->GetPolys();
  vtkPoints* vertices = surface->GetPoints();

  // The spacing: a fraction of the smallest support radius (the finest
  // detail of the field), widened until the nodes fit.
  double rMin = std::numeric_limits<double>::infinity();
  for (size_t j = 0; j < nPoints; ++j)
  {
    rMin = std::min(rMin, static_cast<double>(points[j * FloatsPerPoint + 3]));
  }
  double h = nPoints > 0 ? spacing * rMin : std::numeric_limits<double>::infinity();
  std::vector<Grid> grids(static_cast<size_t>(nCells));
  std::vector<size_t> first(static_cast<size_t>(nCells) + 1, 0);
  for (int attempt = 0; attempt < 8; ++attempt)
  {
    const vtkIdType* ids = nullptr;
    vtkIdType npts = 0;
    for (vtkIdType i = 0; i < nCells; ++i)
    {
      polys->GetCellAtId(i, npts, ids);
      grids[i] = MakeGrid(vertices, npts, ids, cellTexels.data() + i * stride + 8, h);
      first[i + 1] = first[i] + static_cast<size_t>(grids[i].Ms + 1) * (grids[i].Mt + 1);
    }
    if (first.back() <= maximumNodes || first.back() <= 4 * static_cast<size_t>(nCells))
    {
      break;
    }
    h *= 1.05 * std::sqrt(static_cast<double>(first.back()) / maximumNodes);
  }

  // Each grid's box: a point whose ball misses it never weighs there.
  std::vector<double> boxes(6 * static_cast<size_t>(nCells));
  double sceneLo[3] = { 1e300, 1e300, 1e300 }, sceneHi[3] = { -1e300, -1e300, -1e300 };
  for (vtkIdType i = 0; i < nCells; ++i)
  {
    const Grid& g = grids[i];
    double* box = boxes.data() + 6 * i;
    for (int c = 0; c < 3; ++c)
    {
      const double s = g.Ms * g.Ds * g.A[c], t = g.Mt * g.Dt * g.B[c];
      box[c] = g.O[c] + std::min(0.0, s) + std::min(0.0, t);
      box[3 + c] = g.O[c] + std::max(0.0, s) + std::max(0.0, t);
      sceneLo[c] = std::min(sceneLo[c], box[c]);
      sceneHi[c] = std::max(sceneHi[c], box[3 + c]);
    }
  }
  // Clusters of neighbouring polygons (in Morton order of their boxes'
  // centres) share one scan of the field, so that a million small polygons
  // do not each scan every point.
  std::vector<std::pair<std::uint32_t, vtkIdType>> order(static_cast<size_t>(nCells));
  for (vtkIdType i = 0; i < nCells; ++i)
  {
    std::uint32_t code = 0;
    std::uint32_t q[3];
    for (int c = 0; c < 3; ++c)
    {
      const double extent = std::max(sceneHi[c] - sceneLo[c], 1e-30);
      const double centre = 0.5 * (boxes[6 * i + c] + boxes[6 * i + 3 + c]);
      q[c] = static_cast<std::uint32_t>(std::min(1023.0, std::max(0.0, 1024.0 * (centre - sceneLo[c]) / extent)));
    }
    for (int bit = 9; bit >= 0; --bit)
    {
      for (int c = 0; c < 3; ++c)
      {
        code = (code << 1) | ((q[c] >> bit) & 1u);
      }
    }
    order[i] = { code, i };
  }
  std::sort(order.begin(), order.end());
  constexpr vtkIdType ClusterSize = 256;
  const vtkIdType clusters = (nCells + ClusterSize - 1) / ClusterSize;
  const auto ballMisses = [&points](size_t j, const double* box) {
    const float* p = points.data() + j * FloatsPerPoint;
    double d2 = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      const double d = p[c] < box[c] ? box[c] - p[c] : (p[c] > box[3 + c] ? p[c] - box[3 + c] : 0.0);
      d2 += d * d;
    }
    return !(d2 < static_cast<double>(p[3]) * p[3]);
  };

  std::vector<int> levelOf(nPoints, 0);
  for (size_t l = 0; l + 1 < levelOffsets.size(); ++l)
  {
    std::fill(levelOf.begin() + levelOffsets[l], levelOf.begin() + levelOffsets[l + 1], static_cast<int>(l));
  }
  const int levels = levelOffsets.empty() ? 0 : static_cast<int>(levelOffsets.size()) - 1;

  if (first.back() > MaximumNodes)
  {
    nodes.clear();
    return -1.0; // the shader's float node indices would be inexact
  }
  nodes.assign(4 * first.back(), 0.0f);
  vtkSMPTools::For(0, clusters, [&](vtkIdType beginCluster, vtkIdType endCluster) {
    std::vector<size_t> candidates, near;
    std::vector<double> sums(4 * std::max(levels, 1));
    for (vtkIdType k = beginCluster * ClusterSize; k < std::min(nCells, endCluster * ClusterSize); ++k)
    {
      if (k % ClusterSize == 0)
      {
        // The points whose balls reach the cluster's box.
        double box[6] = { 1e300, 1e300, 1e300, -1e300, -1e300, -1e300 };
        for (vtkIdType m = k; m < std::min(nCells, k + ClusterSize); ++m)
        {
          for (int c = 0; c < 3; ++c)
          {
            box[c] = std::min(box[c], boxes[6 * order[m].second + c]);
            box[3 + c] = std::max(box[3 + c], boxes[6 * order[m].second + 3 + c]);
          }
        }
        near.clear();
        for (size_t j = 0; j < nPoints; ++j)
        {
          if (!ballMisses(j, box))
          {
            near.push_back(j);
          }
        }
      }
      const vtkIdType i = order[k].second;
      const Grid& g = grids[i];
      float* frame = cellTexels.data() + i * stride + frameOffset;
      for (int c = 0; c < 3; ++c)
      {
        frame[c] = static_cast<float>(g.O[c]);
        frame[4 + c] = static_cast<float>(g.A[c] / g.Ds);
        frame[8 + c] = static_cast<float>(g.B[c] / g.Dt);
      }
      frame[3] = static_cast<float>(first[i]);
      frame[7] = static_cast<float>(g.Ms + 1);
      frame[11] = static_cast<float>(g.Mt + 1);

      const float* cell = cellTexels.data() + i * stride;
      const double n[3] = { cell[8], cell[9], cell[10] };
      const int group = static_cast<int>(std::lround(cell[3]));
      candidates.clear();
      for (size_t j : near)
      {
        const float* p = points.data() + j * FloatsPerPoint;
        if ((group < 0 || std::lround(p[7]) == group) && n[0] * p[4] + n[1] * p[5] + n[2] * p[6] > 0.0 &&
          !ballMisses(j, boxes.data() + 6 * i))
        {
          candidates.push_back(j);
        }
      }
      for (int jt = 0; jt <= g.Mt; ++jt)
      {
        for (int is = 0; is <= g.Ms; ++is)
        {
          double x[3];
          for (int c = 0; c < 3; ++c)
          {
            x[c] = g.O[c] + is * g.Ds * g.A[c] + jt * g.Dt * g.B[c];
          }
          std::fill(sums.begin(), sums.end(), 0.0);
          for (size_t j : candidates)
          {
            const float* p = points.data() + j * FloatsPerPoint;
            const double d[3] = { x[0] - p[0], x[1] - p[1], x[2] - p[2] };
            const double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) / p[3];
            if (!(r < 1.0))
            {
              continue;
            }
            // w_j = K(r) max(0, n . n_j), K(r) = 2r^3 - 3r^2 + 1 (eq. 13).
            const double w = ((2.0 * r - 3.0) * r * r + 1.0) * (n[0] * p[4] + n[1] * p[5] + n[2] * p[6]);
            double* s = sums.data() + 4 * levelOf[j];
            s[0] += w * p[8];
            s[1] += w * p[9];
            s[2] += w * p[10];
            s[3] += w;
          }
          // Eq. 9: the levels' normalised sums; a level without weight adds nothing.
          double e[3] = { 0.0, 0.0, 0.0 };
          for (int l = 0; l < levels; ++l)
          {
            const double* s = sums.data() + 4 * l;
            if (s[3] > 0.0)
            {
              for (int c = 0; c < 3; ++c)
              {
                e[c] += s[c] / s[3];
              }
            }
          }
          float* node = nodes.data() + 4 * (first[i] + static_cast<size_t>(jt) * (g.Ms + 1) + is);
          for (int c = 0; c < 3; ++c)
          {
            node[c] = static_cast<float>(e[c]);
          }
        }
      }
    }
  });
  return nPoints > 0 ? h : 0.0;
}
