// Procedural scenes: the Cornell box and the closed and open test scenes with
// known answers. Generators, not data files (they are small and exact).
#ifndef Radiosity_SceneGenerators_h
#define Radiosity_SceneGenerators_h

#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Common/Scene.h"

#include <functional>
#include <string>
#include <vector>

namespace radiosity
{
/// A planar quad a-b-c-d split into n x n cells of two triangles each; the
/// right-hand normal of a-b-c is the front. Appended to `scene` as one object.
void AppendQuad(Scene& scene, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
  const Material& material, int n, const std::string& object);

/**
 * The Cornell box (Cornell University Program of Computer Graphics, measured
 * data, converted from millimetres to metres) with the light 0.1 mm below the
 * ceiling, the common RGB reflectances (white 0.725/0.71/0.68, red
 * 0.63/0.065/0.05, green 0.14/0.45/0.091) and a light of radiance (17, 12, 4),
 * i.e. exitance pi times that. Objects: floor, ceiling, back wall, red wall,
 * green wall, light, short block, tall block.
 */
Scene MakeCornellBox();

/// The camera of the Cornell box data: eye (0.278, 0.273, -0.8), looking +z, 39.3 degrees.
struct CornellCamera
{
  static constexpr double Position[3] = { 0.278, 0.273, -0.800 };
  static constexpr double FocalPoint[3] = { 0.278, 0.273, 0.0 };
  static constexpr double ViewAngle = 39.3;
};

/// Closed cube of side `size`, faces inward, each face n x n quads, uniform
/// reflectance and emission: the exact radiosity is E / (1 - rho) everywhere.
Scene MakeClosedCube(double size, int n, double reflectance, double emission);

/// Two directly opposed parallel squares of side a at distance c (open scene):
/// the lower one emits `emission` upward, the upper one reflects `reflectance`.
Scene MakeParallelSquares(double a, double c, int n, double reflectance, double emission);
/**
 * Splits every triangle into four at its edge midpoints (shared between
 * neighbours, so a watertight mesh stays watertight); `place`, when given,
 * moves each new midpoint (onto a sphere, say).
 */
void SubdivideAtMidpoints(std::vector<Vec3>& points, std::vector<Triangle>& triangles,
  const std::function<Vec3(const Vec3&)>& place = {});

/// `scene` with every triangle split into 4^levels at edge midpoints, each
/// part keeping its triangle's material, object and source cell.
Scene SubdividedScene(const Scene& scene, int levels);

/// About `count` probes at triangle centroids (every k-th triangle, k from
/// the triangle count), each with its triangle's normal.
std::vector<Probe> CentroidProbes(const Scene& scene, std::size_t count);

/// The exact-penumbra scene's floor line (MakeShadowScene): 37 probes from
/// x = -0.9 to 0.9 at y = 0.05, facing up, across both penumbrae.
std::vector<Probe> PenumbraLineProbes();

/// The inside of a sphere (an icosphere subdivided `levels` times, faces
/// inward), uniform reflectance, emission `emission` on the cap z > 0.5 r only.
Scene MakeSphereInterior(double radius, int levels, double reflectance, const RGB& emission);

/// The exact-penumbra scene: a square emitter of side 0.5 facing down at
/// height 1, a square black blocker of side 0.4 at height 0.5 shifted by 0.15
/// in x, and a 2 x 2 black floor at z = 0 (n x n quads); everything black, so
/// the floor's irradiance is the direct light with exact penumbrae.
Scene MakeShadowScene(int n, double emission);

/// The contact scene: an emitting vertical wall (x = 0, facing +x, 1 x 1)
/// standing on a floor (z = 0, 2 x 1) of reflectance `reflectance`.
Scene MakeContactScene(int n, double reflectance, double emission);
} // namespace radiosity

#endif
