// Linear radiance image of a solution by ray casting (for the OpenEXR output):
// one primary ray per pixel through Embree, radiance L = B / pi of the
// Lambertian surface hit, B interpolated from the solution's vertex values.
#ifndef Radiosity_RadianceImage_h
#define Radiosity_RadianceImage_h

#include "Radiosity/Common/SolutionMesh.h"

#include <vector>

namespace radiosity
{
struct PinholeCamera
{
  Vec3 Position{ 0.0, 0.0, 1.0 };
  Vec3 FocalPoint{ 0.0 };
  Vec3 ViewUp{ 0.0, 1.0, 0.0 };
  double ViewAngleDegrees = 30.0; ///< vertical, as vtkCamera's
};

struct RadianceImage
{
  int Width = 0, Height = 0;
  std::vector<float> RGB; ///< row-major, top row first, 3 floats per pixel
};

RadianceImage RenderRadiance(const SolutionMesh& solution, const PinholeCamera& camera,
  int width, int height);
} // namespace radiosity

#endif
