// Follows probe points down an adaptive element mesh while it is refined, so
// that the solution's own interpolant can be read at every iteration (error
// against run time) without searching the mesh again.
#ifndef Radiosity_MeshProbeTracker_h
#define Radiosity_MeshProbeTracker_h

#include "Radiosity/Common/ElementMesh.h"
#include "Radiosity/Common/ProbeEvaluator.h"

#include <memory>
#include <vector>

namespace radiosity
{
class MeshProbeTracker
{
public:
  /// Locates each probe on the mesh (within `tolerance` of a surface whose
  /// normal is within 25 degrees of the probe's); others are not tracked.
  MeshProbeTracker(const ElementMesh& mesh, const std::vector<Probe>& probes, double tolerance);

  /// A tracker for a solver's error reference (probes within 1e-6 of the
  /// scene diagonal of a surface), or null when there is no usable reference.
  static std::unique_ptr<MeshProbeTracker> ForReference(const ElementMesh& mesh,
    const std::vector<Probe>& probes, const std::vector<RGB>& reference, double diagonal)
  {
    if (probes.empty() || reference.size() != probes.size())
    {
      return nullptr;
    }
    return std::make_unique<MeshProbeTracker>(mesh, probes, 1e-6 * diagonal);
  }

  /// The current irradiance at every probe (NaN for untracked ones).
  std::vector<RGB> Evaluate();

  std::size_t Tracked() const;

private:
  struct Location
  {
    std::int64_t Element = -1;
    Vec3 Point{ 0.0 };
  };
  const ElementMesh& Mesh;
  std::vector<Location> Locations;
};

/// Barycentric coordinates of the projection of p on triangle abc.
bool ProjectOnTriangle(
  const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, double& u, double& v, double& w);
} // namespace radiosity

#endif
