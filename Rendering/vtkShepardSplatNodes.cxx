#include "vtkShepardSplatNodes.h"

#include "vtkMatrix4x4.h"

#include "Radiosity/Common/Morton.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

namespace
{
// Row k of the real model-to-clip matrix (VTK keeps it transposed for OpenGL).
void Row(vtkMatrix4x4* m, int k, double row[4])
{
  for (int i = 0; i < 4; ++i)
  {
    row[i] = m->GetElement(i, k);
  }
}

double Det3(const double a[3], const double b[3], const double c[3])
{
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
    a[2] * (b[0] * c[1] - b[1] * c[0]);
}
}

//------------------------------------------------------------------------------
void vtkShepardSplatNodes::SortLevels(
  std::vector<float>& points, int floatsPerPoint, const std::vector<size_t>& levelOffsets)
{
  std::vector<float> sorted;
  std::vector<std::pair<std::uint64_t, size_t>> keys;
  for (size_t level = 0; level + 1 < levelOffsets.size(); ++level)
  {
    const size_t first = levelOffsets[level];
    const size_t count = levelOffsets[level + 1] - first;
    if (count < 2)
    {
      continue;
    }
    double lo[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL };
    double hi[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
    for (size_t i = first; i < first + count; ++i)
    {
      const float* x = points.data() + i * floatsPerPoint;
      for (int c = 0; c < 3; ++c)
      {
        lo[c] = std::min(lo[c], static_cast<double>(x[c]));
        hi[c] = std::max(hi[c], static_cast<double>(x[c]));
      }
    }
    // One scale for the three axes, so that the curve's tiles stay cubes.
    const double extent = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-30 });
    keys.resize(count);
    for (size_t i = 0; i < count; ++i)
    {
      const float* x = points.data() + (first + i) * floatsPerPoint;
      const radiosity::Vec3 unit((x[0] - lo[0]) / extent, (x[1] - lo[1]) / extent,
        (x[2] - lo[2]) / extent);
      keys[i] = { radiosity::Morton(unit), i };
    }
    std::sort(keys.begin(), keys.end());
    sorted.resize(count * floatsPerPoint);
    for (size_t i = 0; i < count; ++i)
    {
      std::copy_n(points.data() + (first + keys[i].second) * floatsPerPoint, floatsPerPoint,
        sorted.data() + i * floatsPerPoint);
    }
    std::copy(sorted.begin(), sorted.end(), points.begin() + first * floatsPerPoint);
  }
}

//------------------------------------------------------------------------------
void vtkShepardSplatNodes::Build(const std::vector<float>& points, int floatsPerPoint,
  const std::vector<size_t>& levelOffsets, int pointsPerNode)
{
  this->Nodes.clear();
  this->LevelNodes.assign(1, 0);
  this->BoxTexels.clear();
  this->PointsPerNode = pointsPerNode;
  const size_t perNode = static_cast<size_t>(std::max(1, pointsPerNode));
  for (size_t level = 0; level + 1 < levelOffsets.size(); ++level)
  {
    for (size_t first = levelOffsets[level]; first < levelOffsets[level + 1]; first += perNode)
    {
      Node node;
      node.First = first;
      node.Count = std::min(perNode, levelOffsets[level + 1] - first);
      double rMax = 0.0, xMax = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        node.Lo[c] = HUGE_VAL;
        node.Hi[c] = -HUGE_VAL;
      }
      for (size_t i = first; i < first + node.Count; ++i)
      {
        const float* x = points.data() + i * floatsPerPoint;
        const double r = x[3];
        rMax = std::max(rMax, r);
        for (int c = 0; c < 3; ++c)
        {
          node.Lo[c] = std::min(node.Lo[c], x[c] - r);
          node.Hi[c] = std::max(node.Hi[c], x[c] + r);
          xMax = std::max(xMax, std::abs(static_cast<double>(x[c])) + r);
        }
      }
      // The splat's fragment shader keeps |x - x_j| < r_j in float: 1% of
      // the largest radius, and 1e-5 of the coordinates' magnitude, are far
      // above its rounding, the G-buffer position's and the boxes' own in
      // float texels (6e-8 of the magnitude).
      const double margin = 0.01 * rMax + 1e-5 * xMax;
      for (int c = 0; c < 3; ++c)
      {
        node.Lo[c] -= margin;
        node.Hi[c] += margin;
      }
      this->Nodes.push_back(node);
      for (const double* corner : { node.Lo, node.Hi })
      {
        for (int c = 0; c < 3; ++c)
        {
          this->BoxTexels.push_back(static_cast<float>(corner[c]));
        }
        this->BoxTexels.push_back(0.0f);
      }
    }
    this->LevelNodes.push_back(this->Nodes.size());
  }
}

//------------------------------------------------------------------------------
void vtkShepardSplatNodes::Cull(vtkMatrix4x4* modelToClip, std::vector<unsigned char>& visible) const
{
  double rows[4][4];
  for (int k = 0; k < 4; ++k)
  {
    Row(modelToClip, k, rows[k]);
  }
  // The clip volume -w <= x, y, z <= w: the planes w + x, w - x, ... >= 0.
  double planes[6][4];
  for (int k = 0; k < 3; ++k)
  {
    for (int i = 0; i < 4; ++i)
    {
      planes[2 * k][i] = rows[3][i] + rows[k][i];
      planes[2 * k + 1][i] = rows[3][i] - rows[k][i];
    }
  }
  visible.assign(this->Nodes.size(), 1);
  for (size_t n = 0; n < this->Nodes.size(); ++n)
  {
    const Node& node = this->Nodes[n];
    for (const double* plane : planes)
    {
      // The box's corner farthest along the plane's normal.
      double d = plane[3];
      for (int c = 0; c < 3; ++c)
      {
        d += plane[c] * (plane[c] > 0.0 ? node.Hi[c] : node.Lo[c]);
      }
      if (d < 0.0)
      {
        visible[n] = 0;
        break;
      }
    }
  }
}

//------------------------------------------------------------------------------
void vtkShepardSplatNodes::Eye(vtkMatrix4x4* modelToClip, double eye[4])
{
  double x[4], y[4], z[4], w[4];
  Row(modelToClip, 0, x);
  Row(modelToClip, 1, y);
  Row(modelToClip, 2, z);
  Row(modelToClip, 3, w);
  // The generalised cross product of the rows x, y and w: each component the
  // signed 3 x 3 minor without its column.
  for (int i = 0; i < 4; ++i)
  {
    double a[3], b[3], c[3];
    for (int j = 0, k = 0; j < 4; ++j)
    {
      if (j != i)
      {
        a[k] = x[j];
        b[k] = y[j];
        c[k] = w[j];
        ++k;
      }
    }
    eye[i] = (i % 2 ? -1.0 : 1.0) * Det3(a, b, c);
  }
  if (eye[3] != 0.0)
  {
    for (int i = 0; i < 3; ++i)
    {
      eye[i] /= eye[3];
    }
    eye[3] = 1.0;
  }
  else if (z[0] * eye[0] + z[1] * eye[1] + z[2] * eye[2] > 0.0)
  {
    // Parallel: towards the eye, where the depth decreases.
    for (int i = 0; i < 3; ++i)
    {
      eye[i] = -eye[i];
    }
  }
}

//------------------------------------------------------------------------------
bool vtkShepardSplatNodes::Contains(size_t node, const double eye[4]) const
{
  const Node& n = this->Nodes[node];
  return eye[3] != 0.0 && eye[0] >= n.Lo[0] && eye[0] <= n.Hi[0] && eye[1] >= n.Lo[1] &&
    eye[1] <= n.Hi[1] && eye[2] >= n.Lo[2] && eye[2] <= n.Hi[2];
}
