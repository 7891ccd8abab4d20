// Exact irradiance for scenes lit by lights (SPEC.md "Lights and sky"), the
// analytic answers of the light cases (Scenes/LightScenes.h). Written from
// the definitions, not from Common/Lights.cxx (they check it): the glTF spot
// falloff, the inverse-square law, the sphere's power balance and Lambert's
// contour formula for the part of the sky a wall hides.
//
// - a point light of intensity I at height h over a plane: H = I h / d^3 at
//   distance d from the light (I cos / d^2 with cos = h / d);
// - a spot light: the same times glTF's falloff (KHR_lights_punctual: the
//   square of the linear ramp in the cosine of the angle to the axis between
//   the outer and the inner cone);
// - the sun (directional, irradiance E on a surface facing it) over a floor
//   with a convex plate between: H = E cos(theta) outside the plate's shadow,
//   the plate projected along the light's direction onto the floor (an exact
//   polygon), and 0 inside it;
// - punctual lights inside a closed sphere of uniform reflectance rho: every
//   area element sees every other alike (F = dA / A), so the reflected light
//   is uniform: H(x) = E0(x) + rho P / ((1 - rho) A), with E0 the direct light
//   at x, P the power the lights emit (4 pi I for a point light; all of it
//   lands on the closed sphere) and A the sphere's area; with emission E on
//   the sphere too, + mean(E) / (1 - rho). For the smooth sphere A = 4 pi R^2
//   and a point light gives rho I / ((1 - rho) R^2); for a tessellated one the
//   facets' total area is the power balance's own (the area the light lands
//   on), which is what is used;
// - a uniform sky of radiance L: H = L pi (1 + cos beta) / 2 on an
//   unobstructed surface tilted by beta from the sky's up (pi L horizontal),
//   less L pi F with F the form factor from the point to a convex blocker
//   (Lambert's contour formula, the blocker clipped to the upper half-space);
// - the CIE overcast sky, L = L_z (1 + 2 cos theta) / 3: on an unobstructed
//   horizontal surface H = L_z / 3 (pi + 2 (2 pi / 3)) = 7/9 pi L_z.
#ifndef Radiosity_AnalyticLights_h
#define Radiosity_AnalyticLights_h

#include "Radiosity/Common/Lights.h"
#include "Radiosity/Common/Types.h"

#include <vector>

namespace radiosity
{
namespace analyticlights
{
/// glTF's reference spot falloff from the cone angles (radians) and the
/// cosine of the angle to the axis.
double SpotFalloff(double innerConeAngle, double outerConeAngle, double cosAngleToAxis);

/// The inverse-square law on a plane: I h / d^3 (d the distance to the light, h its height).
double PointLightOnPlane(double intensity, double height, double distance);

/// Direct irradiance of a punctual light at p (unit normal n) with nothing in
/// between: I cos / d^2 (times the falloff for a spot), E cos for the sun,
/// zero behind the surface.
RGB PunctualIrradiance(const Light& light, const Vec3& p, const Vec3& n);

/// Radiant power of a point (4 pi I) or spot light (2 pi I ((1 - cos inner)
/// + (cos inner - cos outer) / 3), the falloff integrated over the sphere).
RGB PunctualPower(const Light& light);

/// The convex polygon `blocker` projected along `travel` onto the plane
/// through `planePoint` with normal `planeNormal`: the exact shadow of a sun
/// travelling along `travel`.
std::vector<Vec3> ShadowOnPlane(const std::vector<Vec3>& blocker, const Vec3& travel,
  const Vec3& planePoint, const Vec3& planeNormal);

/// p inside (or on the edge of) the convex planar polygon `poly` (p in its plane).
bool InsideConvexPolygon(const Vec3& p, const std::vector<Vec3>& poly);

/// The open segment a-b crosses the convex planar polygon `poly` (ends
/// within `tolerance` of its plane do not count).
bool SegmentCrossesConvexPolygon(
  const Vec3& a, const Vec3& b, const std::vector<Vec3>& poly, double tolerance);

/// The sun over a floor (plane through floorPoint, normal floorNormal) with
/// a convex blocker: E cos at p on the floor, 0 inside the exact shadow polygon.
RGB SunOnFloorWithBlocker(const Light& sun, const std::vector<Vec3>& blocker,
  const Vec3& floorPoint, const Vec3& floorNormal, const Vec3& p);

/// Punctual (point, spot) lights inside a closed sphere of area `area` and
/// uniform reflectance `rho`: H = E0(p) + rho P / ((1 - rho) area).
RGB LightsInSphere(const std::vector<Light>& lights, const RGB& rho, double area,
  const Vec3& p, const Vec3& n);

/// Form factor from (p, n) to the convex polygon `blocker`, whichever side
/// faces p, clipped to the half-space above p along `up` (the part of the
/// blocker that can hide the sky).
double SkyHiddenBy(const Vec3& p, const Vec3& n, const Vec3& up, const std::vector<Vec3>& blocker);

/// A uniform sky at (p, n) with at most one convex blocker (may be empty):
/// L pi ((1 + n.up) / 2 - F).
RGB UniformSkyIrradiance(const Sky& sky, const Vec3& p, const Vec3& n, const std::vector<Vec3>& blocker);

/// The CIE overcast sky on an unobstructed horizontal surface: 7/9 pi L_z.
RGB CieOvercastHorizontal(const Sky& sky);
} // namespace analyticlights
} // namespace radiosity

#endif
