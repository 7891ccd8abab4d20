// The discontinuity mesh's quadratic interpolants as a plain SolutionMesh for
// the ray-cast radiance image (--exr): RenderRadiance interpolates vertex
// radiosity linearly over the triangle hit, so each mesh triangle is split
// n x n and every sub-vertex gets B = emission + reflectance * E(s, t), E the
// triangle's quadratic interpolant there. n = 2 reproduces the interpolant at
// its six samples; n = 4 (the default) stays within a few 1e-3 of it.
#ifndef vtkradiosity_InterpolantSolution_h
#define vtkradiosity_InterpolantSolution_h

#include "Radiosity/Hierarchical/DiscontinuityMesher.h"

namespace radiosity
{
namespace cli
{
SolutionMesh InterpolantSolution(const DiscontinuityMesh& mesh, const Scene& scene, int n = 4);
}
}

#endif
