// Surfaces modelled the wrong way round (issue 53: a nave floor whose normal
// pointed down was solved black with no word). Surfaces are one-sided (SPEC
// "Scenes"): a triangle whose front faces no light, no emitter and no sky
// gets no direct light. That alone is common and right (a ceiling under a
// sky, the underside of a table). What is not: a triangle whose back side
// sees a punctual light directly, nothing in between, while its front faces
// away from every source. Its back is open to the light, so a user looking
// at that side sees a dark surface that the light plainly reaches. Only
// lamps (point and spot lights) are tested: the back of a one-sided room's
// walls, outside, sees the sun, and that is how rooms are modelled.
#ifndef Radiosity_FacingAway_h
#define Radiosity_FacingAway_h

#include "Radiosity/Common/Scene.h"

#include <cstddef>
#include <string>

namespace radiosity
{
struct FacingAway
{
  std::size_t Triangles = 0; ///< triangles facing away whose back sees a light
  double Area = 0.0;         ///< their area
  double TotalArea = 0.0;    ///< the scene's area
  int Object = -1;           ///< the object holding most of Area (an ObjectIds value)
};

/// Finds the one-sided triangles facing away from every source whose back
/// side sees a point or spot light (the first FacingAwayLights) directly.
FacingAway FindFacingAway(const Scene& scene);

/// At most this many punctual lights are tested (one ray per triangle each).
constexpr std::size_t FacingAwayLights = 16;

/// Above this share of the scene's area, FacingAwayWarning warns.
constexpr double FacingAwayShare = 0.02;

/// A warning when more than FacingAwayShare of the area faces away while its
/// back sees a light (naming the triangles, the share and the main object,
/// and the two-sided switch); empty otherwise.
std::string FacingAwayWarning(const Scene& scene);
} // namespace radiosity

#endif
