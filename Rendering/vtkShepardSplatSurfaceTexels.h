// The multilevel Shepard field of vtkShepardSplatMapper evaluated once on
// the surface (its SURFACE_TEXELS evaluation): a grid of nodes on each
// polygon's plane, E(x, n) of the mapper's formula at every node, computed
// on the CPU in double precision from the mapper's level-sorted point
// texels. The fragment shader then interpolates the cell's four nearest
// nodes bilinearly: a redraw is one pass over the surface, where splatting
// rasterises every support ball again for every camera (seconds on
// llvmpipe). The price is the interpolation error between nodes, largest
// where a level's support ends (E jumps there) and measured in
// TestShepardSplatMapper. Not wrapped.
#ifndef vtkShepardSplatSurfaceTexels_h
#define vtkShepardSplatSurfaceTexels_h

#include <cstddef>
#include <string>
#include <vector>

class vtkPolyData;

class vtkShepardSplatSurfaceTexels
{
public:
  /// Floats of a cell's frame: (origin, first node), (s axis / spacing,
  /// nodes a row), (t axis / spacing, rows).
  static constexpr int FrameFloats = 12;
  /// Node indices travel as floats: exact up to 2^24.
  static constexpr size_t MaximumNodes = size_t(1) << 24;

  /**
   * Fills, for every polygon i of `surface`, the frame floats at
   * cellTexels[i * stride + frameOffset] and the polygon's nodes (RGBA
   * floats, A unused) in `nodes`. The polygon's normal and group are read
   * from cellTexels[i * stride + 8..10] and [i * stride + 3] (the mapper's
   * layout); the points from `points` (12 floats each: x, r, n, group,
   * alpha, 0), level l being [levelOffsets[l], levelOffsets[l + 1]).
   * The node spacing is `spacing` times the smallest support radius, made
   * larger when the nodes would exceed `maximumNodes`. Returns the
   * spacing used (model units), 0 for no points, -1 (no nodes) when even
   * four nodes a polygon exceed MaximumNodes.
   */
  static double Evaluate(vtkPolyData* surface, const std::vector<float>& points,
    const std::vector<size_t>& levelOffsets, double spacing, size_t maximumNodes,
    std::vector<float>& cellTexels, int stride, int frameOffset, std::vector<float>& nodes);
};

#endif
