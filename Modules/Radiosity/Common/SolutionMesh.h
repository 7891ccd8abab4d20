// The leaves of a solved element mesh as a plain triangle mesh with the SPEC
// output fields: per element (cell) and per vertex, irradiance and radiosity.
// Vertex values are area-weighted averages of the incident elements' own
// corner samples (SPEC: "point data by area-weighted averaging at shared vertices").
#ifndef Radiosity_SolutionMesh_h
#define Radiosity_SolutionMesh_h

#include "Radiosity/Common/ElementMesh.h"

#include <vector>

namespace radiosity
{
struct SolutionMesh
{
  std::vector<Vec3> Points;
  std::vector<Triangle> Triangles;
  std::vector<RGB> CellIrradiance, CellRadiosity;
  std::vector<RGB> PointIrradiance, PointRadiosity;
  std::vector<std::uint32_t> ElementId;  ///< index in the element hierarchy
  std::vector<std::uint16_t> Level;
  std::vector<std::uint32_t> SourceTriangle; ///< input triangle of each element
  std::vector<ElementSamples> Samples;   ///< corner and centre irradiance per element
  std::vector<Vec3> Normals;             ///< per element
};

SolutionMesh ExtractSolution(const ElementMesh& mesh);
/// The power the surfaces of `solution` absorb, sum (1 - rho) E A over its
/// triangles (rho of each one's SourceTriangle in `scene`, mean over RGB):
/// the power balance of a method that does not keep it while it solves.
double AbsorbedPower(const SolutionMesh& solution, const Scene& scene);

/// Irradiance inside element `t` at barycentric (u, v, w): linear through the
/// corner samples plus the cubic bubble 27uvw that also matches the centre sample.
RGB InterpolateSamples(const ElementSamples& s, double u, double v, double w);
} // namespace radiosity

#endif
