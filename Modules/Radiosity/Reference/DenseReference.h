// A dense reference for small scenes: the radiosity system (I - rho F) B = E
// on a fine uniform mesh, solved directly (Eigen's LU with partial pivoting),
// for checking the iterative solvers. F_ij is the exact point-to-polygon form
// factor from element i's centroid to element j (Lambert's contour formula),
// times the visible fraction of 4 points on j seen from that centroid.
#ifndef Radiosity_DenseReference_h
#define Radiosity_DenseReference_h

#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Common/Scene.h"

#include <vector>

namespace radiosity
{
struct DenseReferenceOptions
{
  double ElementSize = 0.05;     ///< longest edge / scene diagonal
  std::size_t MaxElements = 4000; ///< refused beyond this (memory and time grow as N^2 and N^3)
};

struct DenseSolution
{
  std::vector<Vec3> Centroids, Normals;
  std::vector<Vec3> Corners;  ///< 3 per element
  std::vector<RGB> Radiosity; ///< per element
  std::vector<RGB> Irradiance;
  std::vector<std::uint32_t> Source; ///< input triangle per element
};

/// Throws std::invalid_argument when the mesh would exceed MaxElements.
DenseSolution SolveDense(const Scene& scene, const DenseReferenceOptions& options);

/// Irradiance at probes by gathering the dense solution's radiosity with
/// exact form factors and the same visibility rule.
std::vector<RGB> DenseIrradianceAt(
  const Scene& scene, const DenseSolution& solution, const std::vector<Probe>& probes);
} // namespace radiosity

#endif
