// Memory budgets for the solvers: an estimate before a solve allocates (from
// the scene's size and the settings: elements, links, points as the method
// will make them) and a guard on what grows during the solve, so that a
// setting or a scene too large for the machine is refused with a message
// naming what to change instead of the process being killed.
#ifndef Radiosity_MemoryBudget_h
#define Radiosity_MemoryBudget_h

#include "Radiosity/Common/Scene.h"

#include <cstddef>
#include <string>

namespace radiosity
{
/// A solve that would not fit in its memory budget: bad input (exit status 2),
/// the message says how much, for what, and which setting to change.
class MemoryBudgetExceeded : public SceneError
{
public:
  using SceneError::SceneError;
};

/// The default budget: 75% of physical memory (SystemInfo.h; --max-memory).
double DefaultMemoryBudgetBytes();

/// `budget` when positive, else the default.
double ResolveMemoryBudget(double budget);

/// "1.5 GB", "820 MB", "12 kB" (decimal units, as --max-memory takes them).
std::string FormatBytes(double bytes);

/// "950", "4.2 thousand", "1.6 million", "420 million", "3.1 billion".
std::string FormatCount(double count);

/**
 * Throws MemoryBudgetExceeded when `bytes` exceeds `budget` (> 0):
 * "<method>: <what> need about <bytes> (budget <budget>, --max-memory): <advice>".
 */
void CheckMemoryBudget(
  double bytes, double budget, const std::string& what, const std::string& advice);

/**
 * Ordered pairs (p, q), p != q, of input triangles each with a vertex in
 * front of the other's plane: the links hierarchical radiosity makes before
 * any refinement. Exact up to 2,000 triangles, estimated from a fixed sample
 * of 4 million pairs beyond (relative standard error below 0.1%).
 */
double FacingTrianglePairs(const Scene& scene);

/// Leaves of the uniform quadtrees that split every input triangle until its
/// longest edge is at most `edge` (at most `maxLevel` levels): the element
/// count an ElementMesh starts from.
double UniformQuadtreeLeaves(const Scene& scene, double edge, int maxLevel);
} // namespace radiosity

#endif
