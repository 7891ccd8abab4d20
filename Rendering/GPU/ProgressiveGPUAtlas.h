// The texel atlases of progressive radiosity on the GPU, laid out from the
// element mesh and read back into it: the host's "bookkeeping and data
// structure management" (Coombe et al. 2004, section 1). One texel per leaf
// element, the leaves of one shooter node in one contiguous range (the node
// power pass sums a range); laid out again after a subdivision (section 4.1).
#ifndef Radiosity_ProgressiveGPUAtlas_h
#define Radiosity_ProgressiveGPUAtlas_h

#include "ProgressiveGPUPasses.h"
#include "Radiosity/Common/ElementMesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace radiosity
{
struct GPUAtlas
{
  std::vector<std::uint32_t> Leaves; ///< the element of each texel
  std::vector<std::size_t> NodeFirst, NodeCount; ///< per shooter (mesh.Shooters() order)
  GPUElementTexels Elements;
  GPUNodeTexels Nodes;
};

/// Scaled coordinates: centred on the scene's box, divided by its diagonal.
struct GPUFrame
{
  Vec3 Centre{ 0.0 };
  double Diagonal = 1.0;
  Vec3 Scaled(const Vec3& p) const { return (p - this->Centre) / this->Diagonal; }
  double ScaledArea(double area) const { return area / (this->Diagonal * this->Diagonal); }
};

/// The leaves of `mesh` with their irradiance samples and unshot
/// radiosity; `maxLevel` per input triangle (an element below it may split).
GPUAtlas LayOutAtlas(const ElementMesh& mesh, const GPUFrame& frame, const std::vector<std::uint16_t>& maxLevel);

/// What the GPU holds (ProgressiveGPUPasses::ReadElements) back into the
/// atlas's leaves: irradiance samples and unshot radiosity.
void ReadBackAtlas(ElementMesh& mesh, const GPUAtlas& atlas, const std::array<std::vector<float>, 5>& targets);

/// float values of `v` (the GPU's uniforms).
std::array<float, 3> ToFloat(const Vec3& v);
/// `v` as float (high) and what rounding dropped (low): a two-float position.
void SplitFloat(const Vec3& v, std::array<float, 3>& hi, std::array<float, 3>& lo);
} // namespace radiosity

#endif
