// Which triangles are enclosed: every ray over the hemisphere in front of
// the triangle's centroid hits a surface of the scene. Light leaving an
// enclosed triangle cannot escape the scene, so the form factors from it sum
// to one (the row-sum normalisation of Baum, Rushmeier & Winget 1989, used
// by the clustered hierarchical solver) and, in a scene whose triangles are
// all enclosed, every bounce's received power equals the power shot (the
// face cluster solver's energy balance).
#ifndef Radiosity_Enclosure_h
#define Radiosity_Enclosure_h

#include "Radiosity/Common/Scene.h"

#include <cstdint>
#include <vector>

namespace radiosity
{
class Visibility;

/// Per listed triangle: 1 when none of `rays` segments (cosine-weighted over
/// its hemisphere, stratified in the cosine, golden-angle turns, each
/// `reach` long from its centroid) escapes past every occluder of
/// `visibility`. Parallel.
std::vector<unsigned char> EnclosedTriangles(const Scene& scene, const Visibility& visibility,
  const std::vector<std::uint32_t>& triangles, double reach, int rays = 32);

/// Whether the whole scene is enclosed, judged on up to `samples` triangles
/// at the scene's area quantiles (every triangle when it has fewer): a hole
/// smaller than the samples' spacing can be missed, and lets out a share of
/// the light about its share of the area.
bool SceneIsEnclosed(const Scene& scene, std::size_t samples = 2048);
} // namespace radiosity

#endif
