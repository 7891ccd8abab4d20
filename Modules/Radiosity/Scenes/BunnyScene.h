// The highly tessellated standard scene: the Stanford bunny (as the npm
// package `bunny` ships it: 1839 points, 3674 triangles, watertight),
// midpoint-subdivided to 100k - 1M triangles, in a closed room with a light.
#ifndef Radiosity_BunnyScene_h
#define Radiosity_BunnyScene_h

#include "Radiosity/Common/Scene.h"

#include <cstddef>
#include <string>

namespace radiosity
{
/// Reads `index.js` of the npm package `bunny` (`exports.positions=[[x,y,z],...]`
/// and `exports.cells=[[a,b,c],...]`). Throws SceneError when malformed.
Scene ReadNpmBunny(const std::string& indexJs);

/**
 * The bunny subdivided `levels` times at its edge midpoints (3674 x 4^levels
 * triangles; the shape is unchanged), faces outward, scaled to 0.5 m high and
 * standing on the floor of a closed 2 x 2 x 2 m room (walls 0.7, floor 0.5
 * grey) lit by a 0.5 x 0.5 m ceiling light of exitance 50 W/m^2.
 */
Scene MakeBunnyRoom(const Scene& bunny, int levels);

/// Turns `bunny`'s faces outward (a positive enclosed volume), scales it to
/// `height` along y and stands it with the centre of its base at `base`.
void StandUpright(Scene& bunny, double height, const Vec3& base);

/**
 * The same room with the bunny at exactly `triangles` triangles (at least the
 * source's): midpoint subdivision while it fits, then the longest edges of
 * evenly spread triangles bisected (T-junctions; the shape is unchanged).
 */
Scene MakeBunnyRoomWithTriangles(const Scene& bunny, std::size_t triangles);

/**
 * The glossy statue (TestGlossyBunnyCornell, TestFaceClusterVectorIrradiance):
 * the Cornell box without its blocks, every triangle split in 16, and the
 * bunny subdivided `levels` times, 0.25 m high on the middle of the floor,
 * reflectance (0.6, 0.55, 0.5), specular 0.35, shininess 10, object 0.
 * `firstBunnyPoint`: where the bunny's points start.
 */
Scene MakeGlossyStatueCornell(Scene bunny, int levels, std::size_t* firstBunnyPoint = nullptr);
} // namespace radiosity

#endif
