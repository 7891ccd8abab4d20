// Adaptive quadtrees over the input triangles (Coombe et al. 2004, section 4.1:
// "this method subdivides the scene geometry hierarchically into a quadtree
// with the radiosity data stored at the leaf nodes"). A triangle's quadtree
// splits it into four at its edge midpoints; midpoints are shared between
// neighbouring elements so that the leaves form one vertex pool.
#ifndef Radiosity_ElementMesh_h
#define Radiosity_ElementMesh_h

#include "Radiosity/Common/Scene.h"

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace radiosity
{
/// Irradiance samples of one element: its three corners and its centroid.
struct ElementSamples
{
  std::array<RGB, 3> Corner{ RGB(0.0), RGB(0.0), RGB(0.0) };
  RGB Centre{ 0.0 };

  /// Area mean by the degree-2 exact rule 3/4 f(centroid) + 1/12 sum f(corner).
  RGB Mean() const { return 0.75 * Centre + (Corner[0] + Corner[1] + Corner[2]) / 12.0; }
  ElementSamples& operator+=(const ElementSamples& o)
  {
    for (int k = 0; k < 3; ++k)
    {
      Corner[k] += o.Corner[k];
    }
    Centre += o.Centre;
    return *this;
  }
};

constexpr std::uint32_t NoShooter = 0xFFFFFFFFu;

struct Element
{
  std::array<std::uint32_t, 3> V{};
  std::int32_t Parent = -1;
  std::int32_t FirstChild = -1; ///< children are four consecutive elements
  std::uint32_t Source = 0;     ///< input triangle
  std::uint16_t Level = 0;
  /// The quadtree node that shoots for this element: Coombe 3.1 shoots from a
  /// coarser level than it receives at ("we typically shoot from two levels
  /// above the base resolution"), after Heckbert 1990.
  std::uint32_t ShooterNode = NoShooter;
  double Area = 0.0;
  Vec3 Normal{ 0.0 };
  Vec3 Centroid{ 0.0 };
  ElementSamples Irradiance; ///< accumulated incident flux density, W/m^2
  RGB Unshot{ 0.0 };         ///< residual radiosity not yet shot, W/m^2

  bool IsLeaf() const { return FirstChild < 0; }
};

class ElementMesh
{
public:
  /**
   * One root per input triangle, each subdivided uniformly until its longest
   * edge is at most `initialEdge` (or `maxLevel` is reached). The nodes whose
   * longest edge first drops to `shooterEdge` or below are the shooters.
   */
  ElementMesh(const Scene& scene, double shooterEdge, double initialEdge, int maxLevel);

  /// Nodes that shoot (every leaf has exactly one shooter ancestor or is one).
  const std::vector<std::uint32_t>& Shooters() const { return this->ShooterNodes; }

  const Scene& GetScene() const { return *this->SourceScene; }
  const std::vector<Vec3>& Points() const { return this->Pool; }
  const std::vector<Element>& Elements() const { return this->Nodes; }
  std::vector<Element>& Elements() { return this->Nodes; }
  const Element& operator[](std::uint32_t e) const { return this->Nodes[e]; }
  Element& operator[](std::uint32_t e) { return this->Nodes[e]; }

  /// Leaf indices; valid until the next Subdivide.
  std::vector<std::uint32_t> Leaves() const;
  std::size_t NumberOfLeaves() const { return this->LeafCount; }

  Vec3 Corner(std::uint32_t e, int k) const { return this->Pool[this->Nodes[e].V[k]]; }
  const Material& MaterialOf(std::uint32_t e) const
  {
    return this->SourceScene->Materials[this->Nodes[e].Source];
  }

  /**
   * Splits a leaf into four children at its edge midpoints. The accumulated
   * irradiance is pushed down (Coombe 4.1: "we must push the existing
   * radiosity at the former leaf node down to the four children"): linear
   * interpolation of the corners plus the offset that keeps the parent's area
   * mean, so no power is created or lost; the unshot radiosity is copied (same
   * flux density, so the same power). Returns the first child's index.
   */
  std::uint32_t Subdivide(std::uint32_t e);

  double LongestEdge(std::uint32_t e) const;

  /// Per input triangle, the deepest level its elements may reach: that of
  /// its deepest element now plus `levels` (Coombe 4.4's maximum depth).
  std::vector<std::uint16_t> MaxLevels(int levels) const;

private:
  std::uint32_t Midpoint(std::uint32_t a, std::uint32_t b);
  std::uint32_t AddElement(const std::array<std::uint32_t, 3>& v, std::int32_t parent,
    std::uint32_t source, std::uint16_t level);

  const Scene* SourceScene;
  std::vector<Vec3> Pool;
  std::vector<Element> Nodes;
  std::unordered_map<std::uint64_t, std::uint32_t> Midpoints;
  std::size_t LeafCount = 0;
  std::vector<std::uint32_t> ShooterNodes;
};
} // namespace radiosity

#endif
