// The spatial index of vtkShepardSplatMapper's basis functions for culling
// (Lehtinen et al. 2007, section 6.2: "view frustum culling and occlusion
// queries using the nodes of the R-Tree that hold the basis functions").
// Each level's points, sorted along a Morton curve of their centres (SortLevels,
// once per field), are cut into nodes of consecutive points; a node holds the
// bounding box of its points' support balls, widened so that float rounding
// never puts a point of a ball outside it. Per frame, Cull tests each node's
// box against the view frustum (the planes of the model-to-clip matrix, so in
// model coordinates through the actor's matrix); the mapper's passes then
// test the frustum-visible boxes against the G-buffer with occlusion queries
// (vtkShepardSplatPasses::Splat). Not wrapped.
#ifndef vtkShepardSplatNodes_h
#define vtkShepardSplatNodes_h

#include <cstddef>
#include <vector>

class vtkMatrix4x4;

class vtkShepardSplatNodes
{
public:
  /**
   * Sorts the points of each level (floatsPerPoint floats each, the centre
   * first; levelOffsets[l] the first point of level l) along a Morton curve
   * of their centres, so that consecutive points are near each other.
   */
  static void SortLevels(
    std::vector<float>& points, int floatsPerPoint, const std::vector<size_t>& levelOffsets);

  /**
   * Cuts each level's points into nodes of `pointsPerNode` consecutive
   * points (the last one of a level shorter) with the boxes of their balls
   * (x_j, r_j in the first texel of each point).
   */
  void Build(const std::vector<float>& points, int floatsPerPoint,
    const std::vector<size_t>& levelOffsets, int pointsPerNode);

  struct Node
  {
    size_t First = 0; ///< the first point, an index into the level-sorted points
    size_t Count = 0;
    double Lo[3] = { 0.0, 0.0, 0.0 };
    double Hi[3] = { 0.0, 0.0, 0.0 };
  };
  const std::vector<Node>& GetNodes() const { return this->Nodes; }
  /// Nodes [LevelNodes[l], LevelNodes[l + 1]) hold level l.
  const std::vector<size_t>& GetLevelNodes() const { return this->LevelNodes; }
  /// Per node (lo, 0), (hi, 0), as floats for a texture buffer.
  const std::vector<float>& GetBoxTexels() const { return this->BoxTexels; }
  int GetPointsPerNode() const { return this->PointsPerNode; }

  /**
   * `visible[i]`: whether node i's box meets the view frustum of
   * `modelToClip` (MCDCMatrix as VTK keeps it, transposed). Conservative: a
   * node is dropped only when its box lies wholly outside one clip plane.
   */
  void Cull(vtkMatrix4x4* modelToClip, std::vector<unsigned char>& visible) const;

  /**
   * The eye in homogeneous model coordinates (w = 1), or for a parallel
   * projection the direction towards it (w = 0): the null vector of the
   * clip matrix's x, y and w rows.
   */
  static void Eye(vtkMatrix4x4* modelToClip, double eye[4]);

  /// Whether the point `eye` (w = 1) lies in node i's box.
  bool Contains(size_t node, const double eye[4]) const;

private:
  std::vector<Node> Nodes;
  std::vector<size_t> LevelNodes;
  std::vector<float> BoxTexels;
  int PointsPerNode = 0;
};

#endif
