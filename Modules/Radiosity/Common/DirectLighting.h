// Direct light from the punctual lights and the sky of a scene (SPEC.md
// "Lights and sky"), the one place every method takes it from.
//
// Punctual lights are exact: the closed form (Lights.h) times the visibility
// of the light from the point, one shadow ray per light per point, so a
// point, spot or sun gives a sharp shadow edge wherever a method evaluates it.
//
// The sky is an integral over the hemisphere: H = int L(w) V(x, w) cos dw.
// It is evaluated by a cosine-weighted quasi-Monte Carlo quadrature
// (Malley's method: the Fibonacci lattice of the unit square mapped onto the
// disc and lifted onto the hemisphere; deterministic and smooth in x), each
// direction weighted by the sky radiance where its ray escapes the scene.
// Every weight is pi / N, so an unobstructed uniform sky gives pi L exactly.
#ifndef Radiosity_DirectLighting_h
#define Radiosity_DirectLighting_h

#include "Radiosity/Common/Lights.h"
#include "Radiosity/Common/Scene.h"

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace radiosity
{
class Visibility;

class DirectLighting
{
public:
  /// `skySamples` directions of the sky quadrature (at least 4).
  /// `occluders`: rays over every triangle of `scene` built already (a
  /// relight of a solved scene reuses its solver's), kept alive by the
  /// caller; null: built here when there is a light.
  explicit DirectLighting(const Scene& scene, int skySamples = 256, const Visibility* occluders = nullptr);
  /// The lights and sky of `lighting` over the surfaces of `scene` (a
  /// solver's own lights where its scene is shared with another's).
  DirectLighting(const Scene& scene, const LightSet& lighting, int skySamples, const Visibility* occluders = nullptr);
  ~DirectLighting();
  DirectLighting(const DirectLighting&) = delete;
  DirectLighting& operator=(const DirectLighting&) = delete;

  /// No punctual light and no sky.
  bool Empty() const { return this->Set.Empty(); }
  bool HasPunctualLights() const { return !this->Set.Lights.empty(); }
  bool HasSky() const { return this->Set.SkyLight.Enabled(); }
  const LightSet& Lights() const { return this->Set; }
  int SkySamples() const { return this->SkySampleCount; }

  /// Exact direct irradiance of the punctual lights at x (unit normal n).
  RGB Punctual(const Vec3& x, const Vec3& n) const;
  /// The closed form at x, with the visibility of each light seen from
  /// `visibilityPoint` (a point a little inside one side of a shadow edge
  /// through x, so that x takes that side's limit; see DiscontinuityMesher).
  RGB PunctualSeenFrom(const Vec3& x, const Vec3& visibilityPoint, const Vec3& n) const;
  /// Exact direct irradiance of punctual light `light` alone, with its shadow ray.
  RGB PunctualOne(std::size_t light, const Vec3& x, const Vec3& n) const;
  /// Sky irradiance at x by the stratified quadrature.
  RGB SkyIrradiance(const Vec3& x, const Vec3& n) const { return this->SkyIrradiance(x, n, nullptr); }
  /// The same where the directions of the set bits of `hidden`
  /// (SkyMaskWords() words; null: none) are known hidden: no ray for them.
  RGB SkyIrradiance(const Vec3& x, const Vec3& n, const std::uint64_t* hidden) const;
  /// The sky quadrature's directions about a normal that may bring light:
  /// the sky bright there and not in `hidden` (as above), with their
  /// radiance. The same for every point of one normal (the mesher's leaf).
  struct SkyDirectionSet
  {
    std::vector<Vec3> Direction;
    std::vector<RGB> Radiance;
  };
  SkyDirectionSet SkyDirections(const Vec3& n, const std::uint64_t* hidden = nullptr) const;
  /// SkyIrradiance at x through the directions SkyDirections(n, ...) gave.
  RGB SkyIrradiance(const Vec3& x, const Vec3& n, const SkyDirectionSet& directions) const;
  /// The occluder (scene triangle) each sky quadrature direction's ray from
  /// x (normal n) meets first, Visibility::NoHit where none or where the
  /// sky is dark (no ray then): SkyMaskWords() times 64 entries, the last
  /// ones unused. The rays of SkyIrradiance.
  void SkyFirstHits(const Vec3& x, const Vec3& n, std::uint32_t* triangles) const;
  /// Every direction of the sky quadrature about n, in quadrature order,
  /// into `directions` (SkySamples() of them): the rays of SkyFirstHits and
  /// SkyVisibility.
  void SkyQuadrature(const Vec3& n, std::vector<Vec3>& directions) const;
  /// Words of a SkyVisibility mask: one bit per quadrature direction.
  std::size_t SkyMaskWords() const { return (static_cast<std::size_t>(this->SkySampleCount) + 63) / 64; }
  /// Which of the sky quadrature's directions at x (normal n) reach the sky,
  /// every direction whatever the sky's radiance there: bit i of `mask`
  /// (SkyMaskWords() words). It depends on the geometry alone, so a relight
  /// keeps it (MeshlessRadiosity) and SkyMomentsOf replays the quadrature
  /// for any sky without a ray. Needs the shadow rays (a light or
  /// a sky, or the caller's occluders).
  void SkyVisibility(const Vec3& x, const Vec3& n, std::uint64_t* mask) const;
  /// What SkyIrradiance needs of a point's visible directions for every sky
  /// of one Up: each sky model's radiance is affine in the cosine to Up
  /// above the horizon (SkyRadiance), so the quadrature is fixed by how many
  /// visible directions lie above it and the sum of their cosines.
  struct SkyMoments
  {
    double Count = 0.0;
    double Cosines = 0.0;
  };
  /// The moments of a SkyVisibility mask (normal n) for this sky's Up.
  SkyMoments SkyMomentsOf(const Vec3& n, const std::uint64_t* mask) const;
  /// SkyIrradiance from the moments: the same sum over the same directions.
  RGB SkyIrradianceFromMoments(const SkyMoments& moments) const;
  RGB Irradiance(const Vec3& x, const Vec3& n) const
  {
    return this->Punctual(x, n) + this->SkyIrradiance(x, n);
  }
  /// Irradiance at x with every ray (shadow and sky) cast from
  /// `visibilityPoint` (VisibilityPoint: x on an element's boundary).
  RGB IrradianceSeenFrom(const Vec3& x, const Vec3& visibilityPoint, const Vec3& n) const
  {
    return this->PunctualSeenFrom(x, visibilityPoint, n) + this->SkyIrradiance(visibilityPoint, n);
  }

  /**
   * Where to test visibility for a sample x on the boundary of a planar
   * element (a corner, an edge midpoint): x moved towards `inner` (a point
   * inside the element, its centroid) by at least 4 times the rays'
   * self-intersection offset (and at least `fraction` of the way, at most
   * half).
   * The rays skip what lies closer than that offset, so from a point on a
   * seam (a floor's edge at a wall) the rays aimed behind the adjacent
   * surface would pass through it: the office's floor saw the sky through
   * its walls, and its hierarchical solution took 9.6% more daylight in
   * than the window lets through.
   */
  Vec3 VisibilityPoint(const Vec3& x, const Vec3& inner, double fraction = 1e-3) const;
  /**
   * Where to test visibility for a vertex x of input triangle `source`
   * shared by the elements meeting there: on the triangle's boundary (a
   * seam with another surface) VisibilityPoint towards its centroid by 4
   * offsets; inside it x itself, so that a shadow edge through a vertex
   * is decided the same way for every element sharing it (moved towards
   * one side, the elements on the other side drew a saw tooth).
   */
  Vec3 SharedVertexVisibility(const Scene& scene, std::size_t source, const Vec3& x) const;

  /**
   * Vector irradiance (one vector per channel) at x on a surface of normal n:
   * each visible punctual light in front of the surface contributes its
   * I falloff / d^2 along the direction towards it (so n . E is the scalar
   * irradiance, and a glossy display sees where the lamp is); the sky, which
   * has no single direction, contributes its irradiance along n (`withSky`
   * off: the punctual lights alone).
   */
  std::array<Vec3, 3> IrradianceVector(const Vec3& x, const Vec3& n, bool withSky = true) const;
  /// The punctual lights' vector irradiance at x, each light's visibility
  /// seen from `visibilityPoint` (as PunctualSeenFrom).
  std::array<Vec3, 3> PunctualVectorSeenFrom(const Vec3& x, const Vec3& visibilityPoint, const Vec3& n) const;

  struct PowerEstimate
  {
    double Power = 0.0;          ///< W reaching the surfaces (mean of the channels)
    double PeakIrradiance = 0.0; ///< the largest channel's largest irradiance seen
  };
  /// The power the lights deliver to the scene, from the triangles' centroids
  /// (every triangle up to `maxTriangles`, else an even subset scaled by area).
  PowerEstimate EstimatePower(std::size_t maxTriangles = 20000) const;

  /// Irradiance at many points, in parallel (TBB).
  void Evaluate(const Vec3* x, const Vec3* n, std::size_t count, RGB* out) const;

  /**
   * Power each punctual light delivers to the scene's front faces (the
   * centroids of each triangle's midpoint subdivision: the report's figure,
   * and a directional light's only one, having no power of its own), and
   * the sky's (last entry, when there is a sky).
   */
  std::vector<RGB> ReceivedPower() const;

  /// Where the shadow rays from x on a surface of normal n start.
  Vec3 RayOrigin(const Vec3& x, const Vec3& n) const;
  /// The distance beyond which a shadow ray has left the scene.
  double FarDistance(const Vec3& x) const;
  std::size_t RaysCast() const;
  /// The BVH over every triangle the shadow rays use (null without lights).
  const Visibility* ShadowRays() const { return this->Occluders; }

private:
  /// SkyDirections into `set`, its storage reused.
  void FillSkyDirections(const Vec3& n, const std::uint64_t* hidden, SkyDirectionSet& set) const;
  const Scene& SourceScene;
  LightSet Set;
  int SkySampleCount = 256;
  /// The sky quadrature's directions in a normal's frame (MakeSkyLattice).
  std::vector<Vec3> SkyLattice;
  static std::vector<Vec3> MakeSkyLattice(int m);
  Vec3 Centre{ 0.0 };
  double Extent = 1.0;
  std::unique_ptr<Visibility> OwnOccluders;
  const Visibility* Occluders = nullptr; ///< OwnOccluders, or the caller's
};

/// The point-placement rules of DirectLighting (VisibilityPoint,
/// SharedVertexVisibility, RayOrigin) for rays of any visibility structure
/// of self-intersection offset `offset` (Visibility::Offset()): face cluster
/// radiosity casts its emitters' shadow rays from the same points as its
/// punctual lights'.
Vec3 VisibilityPointToward(double offset, const Vec3& x, const Vec3& inner, double fraction);
Vec3 SharedVertexPoint(double offset, const Scene& scene, std::size_t source, const Vec3& x);
Vec3 RayOriginOff(double offset, const Vec3& x, const Vec3& n);

/// The scene's lights rescaled: every punctual intensity and the sky radiance times `scale`.
LightSet ScaledLights(const LightSet& lights, double scale);
} // namespace radiosity

#endif
