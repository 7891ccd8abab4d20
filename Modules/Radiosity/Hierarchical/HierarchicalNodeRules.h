// The quadrature points of hierarchical radiosity's node-to-node form
// factors, shared by the link estimate, the links' form factors and blockers
// and the row normalisation (HierarchicalRadiosity.cxx,
// HierarchicalLinkFactors.cxx). Internal.
#ifndef Radiosity_HierarchicalNodeRules_h
#define Radiosity_HierarchicalNodeRules_h

#include "Radiosity/Hierarchical/Backprojection.h"

namespace radiosity
{
namespace hierarchical
{
// Receiver points: the centroids of the four midpoint sub-triangles, equal
// weights (exact for linear integrands).
constexpr double RuleA[4][3] = { { 2.0 / 3, 1.0 / 6, 1.0 / 6 }, { 1.0 / 6, 2.0 / 3, 1.0 / 6 },
  { 1.0 / 6, 1.0 / 6, 2.0 / 3 }, { 1.0 / 3, 1.0 / 3, 1.0 / 3 } };
// A second set nearer the corners, for finding the blockers of partial links.
constexpr double RuleB[4][3] = { { 0.8, 0.1, 0.1 }, { 0.1, 0.8, 0.1 }, { 0.1, 0.1, 0.8 },
  { 0.45, 0.45, 0.1 } };

inline Vec3 At(const TriangleCorners& t, const double (&b)[3])
{
  return b[0] * t[0] + b[1] * t[1] + b[2] * t[2];
}
} // namespace hierarchical
} // namespace radiosity

#endif
