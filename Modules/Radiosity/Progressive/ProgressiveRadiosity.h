// Progressive refinement radiosity with adaptive quadtree subdivision.
//
// Algorithm: Cohen, Chen, Wallace, Greenberg 1988 in the form of Coombe,
// Harris, Lastra 2004, section 3 (shoot from the element of largest unshot
// power; every receiver gathers the shot at its own samples, eq. 1) and
// section 4 (texture quadtrees: a leaf is subdivided where the received
// radiosity is not smooth, judged on its gradient as Vedel & Puech 1992
// suggest, and the existing radiosity is pushed to the children).
// Form factors: Coombe eq. 2 (disc approximation) where the shooter is small
// seen from the receiver, the exact contour formula elsewhere (FormFactor.h).
// Acceleration: overshooting with Cohen 1988's ambient estimate (Feda and
// Purgathofer 1992), so that closed rooms with reflectance 0.999 converge.
#ifndef Radiosity_ProgressiveRadiosity_h
#define Radiosity_ProgressiveRadiosity_h

#include "Radiosity/Common/WorkShare.h"
#include "Radiosity/Common/ElementMesh.h"
#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Common/SceneAnalysis.h"
#include "Radiosity/Common/SolverTypes.h"

#include <array>
#include <memory>
#include <unordered_map>

namespace radiosity
{
class DirectLighting;
class Visibility;

struct ProgressiveOptions
{
  double Tolerance = 1e-3;         ///< stop at this unshot power / emitted power
  long long MaxIterations = 200000; ///< shots
  double MaxTimeSeconds = 0.0;     ///< 0: no limit
  int Threads = 0;                 ///< 0: all cores
  bool Overshooting = true;
  double ShooterElementSize = 0.25; ///< longest shooter edge / scene diagonal
  double InitialElementSize = 1.0 / 16.0; ///< longest initial receiver edge / scene diagonal
  int MaxSubdivisionLevels = 2;    ///< adaptive levels below the initial mesh
  /// Further levels the lights' and the sky's shot may split receivers to,
  /// where an element's own 4-point rule misjudges the light it receives by
  /// more than SubdivisionThreshold (a hard shadow, a spot's cone or a
  /// window's sky patch across it): what it reflects is that light.
  int LightSubdivisionLevels = 2;
  double SubdivisionThreshold = 0.1;  ///< allowed departure from linear, relative
  /// Disc approximation where A/(pi r^2) is below this times (1 - mean
  /// reflectance): interreflection amplifies form factor errors by 1/(1 - rho).
  double FormFactorTolerance = 2e-3;
  int VisibilitySamples = 16;      ///< rays per receiver sample from emitters: 1, 4 or 16
  int IndirectVisibilitySamples = 1; ///< rays per receiver sample from reflectors
  int SkySamples = 1024; ///< sky quadrature directions per receiver sample (DirectLighting)
  /// Bytes the elements may use; 0: 75% of physical memory. Checked before
  /// the initial mesh is made and at every adaptive subdivision.
  double MemoryBudgetBytes = 0.0;
  /// Reference irradiance at probes: when given, every history row carries the
  /// solution's error there (error against run time).
  std::vector<Probe> ErrorProbes;
  std::vector<RGB> ErrorReference;
  /// MPI ranks: the receivers of each shot split over them (WorkShare.h); none: all here.
  std::shared_ptr<WorkShare> Share;
};

class ProgressiveRadiosity
{
public:
  ProgressiveRadiosity(const Scene& scene, const ProgressiveOptions& options);
  ~ProgressiveRadiosity();

  /// Runs to a stop condition; can be called once.
  SolverStatistics Solve(const ProgressCallback& progress = {});

  const ElementMesh& Mesh() const { return *this->Elements; }
  const SceneAnalysis& Analysis() const { return this->SceneInfo; }
  const Visibility& GetVisibility() const { return *this->Rays; }
  const ProgressiveOptions& Options() const { return this->Settings; }
  /// The apparent size below which the disc approximation is used.
  double GetDiscTolerance() const { return this->DiscTolerance; }

private:
  struct ShotResult;
  struct TransferScratch;
  /// The lights and the sky shoot first, all in one shot (DirectLighting:
  /// exact at every corner sample and centre, one shadow ray per light), the
  /// receivers splitting along shadow edges by the gradient criterion.
  /// Returns the power received by the surfaces.
  double ShootLights(SolverStatistics& stats);
  /// The lights' and the sky's exact irradiance at the shared corner
  /// samples of `elements` that have none yet (one ray batch; each sample
  /// is lit once for the whole solve).
  void LightCornerSamples(const std::vector<std::uint32_t>& elements);
  /// The lights' and the sky's irradiance at element e's samples: the
  /// corners' from LightCornerSamples, the centre's evaluated here. What
  /// ShootLights gave a leaf, and what a child made by a later shot's split
  /// adds to the history it gathers from the element shooters (the lights
  /// are not among them).
  ElementSamples LightSamples(std::uint32_t e) const;
  /// Subdivides receiver e (within the memory budget), registers its
  /// children's corner samples and appends them to `children`.
  void SplitReceiver(std::uint32_t e, SolverStatistics& stats, std::vector<std::uint32_t>& children);
  /// One shot; `leaves` are the current leaves (the selection pass has them).
  void Shoot(std::uint32_t shooter, const RGB& shot, const std::vector<std::uint32_t>& leaves,
    SolverStatistics& stats);
  /// Form factors times visibility from the receiver's four samples to the
  /// shooter node; false when the pair faces away (no transfer).
  /// `cornerFactors`, when given, are the three corners' values already computed.
  bool Transfer(std::uint32_t receiver, std::uint32_t shooter, TransferScratch& scratch,
    std::array<double, 4>& factors, ShotResult& counts, bool shooterSide,
    const double* cornerFactors = nullptr) const;
  /// Form factor times visibility from one receiving point to a shooter node.
  double PointTransfer(const Vec3& p, const Vec3& n, const Vec3& rayOrigin, std::uint32_t shooter,
    TransferScratch& scratch, ShotResult& counts, double* visibility = nullptr) const;
  /// The form factor kernel (disc or exact, by apparent size), no visibility.
  double PointFormFactor(const Vec3& p, const Vec3& n, std::uint32_t shooter, ShotResult& counts) const;
  bool FacesShooter(std::uint32_t receiver, std::uint32_t shooter) const;
  /// Weighted fraction of the shooter's visibility targets seen (`visible` per target).
  double VisibleFraction(std::uint32_t shooter, const unsigned char* visible) const;
  /// Weights the shooter's targets by the unshot power of its leaves.
  void WeighTargets(std::uint32_t shooter, const std::vector<std::uint32_t>& own);
  /// Evaluates the shared corner samples `ids` for one shot (one ray batch).
  void SampleTransfers(
    const std::uint32_t* ids, std::size_t count, std::uint32_t shooter, ShotResult& counts);
  void RegisterCorners(std::uint32_t leaf);

  /// A corner sample shared by the leaves of one input triangle meeting at a vertex.
  struct SharedSample
  {
    Vec3 Point, RayOrigin, Normal;
    std::uint32_t Source = 0; ///< its input triangle (DirectLighting::SharedVertexVisibility)
  };

  const Scene& SourceScene;
  ProgressiveOptions Settings;
  SceneAnalysis SceneInfo;
  std::unique_ptr<Visibility> Rays;
  std::unique_ptr<ElementMesh> Elements;
  std::vector<std::uint16_t> MaxLevel; ///< per input triangle
  std::vector<std::uint32_t> ShooterSlot; ///< element -> index among the shooters
  std::vector<std::vector<Vec3>> Targets; ///< visibility sample points per shooter
  std::vector<std::vector<double>> TargetWeights; ///< their weights at the last shot
  std::vector<RGB> ShotTotal;             ///< radiosity shot so far per shooter
  std::vector<double> EscapeFraction;     ///< per shooter, negative until first shot
  std::vector<SharedSample> Samples;
  std::unique_ptr<DirectLighting> Lights; ///< null when the scene has no lights or sky
  std::vector<RGB> SampleLight;           ///< per shared sample, once lit (SampleLit)
  std::vector<unsigned char> SampleLit;
  std::unordered_map<std::uint64_t, std::uint32_t> SampleIndex; ///< (vertex, input triangle)
  std::vector<std::array<std::uint32_t, 3>> CornerSamples;     ///< per element
  std::vector<double> SampleFactor;     ///< this shot's value per sample
  std::vector<std::uint32_t> SampleStamp; ///< pass in which a sample was last evaluated
  std::uint32_t Stamp = 0;
  std::vector<std::uint32_t> ActiveShooters; ///< shooters that have shot
  double DiscTolerance = 0.0; ///< FormFactorTolerance scaled by (1 - mean reflectance)
  double PlaneTolerance = 0.0; ///< distance below which a point lies in a plane
  double Absorbed = 0.0;
  double Escaped = 0.0;
  double Budget = 0.0;                ///< bytes (MemoryBudgetBytes resolved)
  std::size_t ElementCapacity = 0;    ///< elements the budget holds
};
} // namespace radiosity

#endif
