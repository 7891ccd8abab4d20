// Helpers of the filters' tests.
#ifndef FilterTestSupport_h
#define FilterTestSupport_h

#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <iostream>
#include <string>

namespace FilterTestSupport
{
// `ok`, reporting `what` on stderr when it is false: a test runs every
// check and fails at the end if any failed.
inline bool Check(bool ok, const std::string& what)
{
  if (!ok)
  {
    std::cerr << "FAILED: " << what << "\n";
  }
  return ok;
}

// For a window of two width x height halves side by side: the mean 8-bit
// value of the left half and the mean absolute difference between
// corresponding pixels of the halves (RGB).
struct Halves
{
  double LeftMean = 0.0;
  double Difference = 0.0;
};
inline Halves CompareHalves(vtkRenderWindow* window, int width, int height)
{
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetRGBACharPixelData(0, 0, 2 * width - 1, height - 1, 1, pixels);
  Halves out;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        const double a = pixels->GetValue(4 * (y * 2 * width + x) + c);
        const double b = pixels->GetValue(4 * (y * 2 * width + x + width) + c);
        out.Difference += std::fabs(a - b);
        out.LeftMean += a;
      }
    }
  }
  out.Difference /= 3.0 * width * height;
  out.LeftMean /= 3.0 * width * height;
  return out;
}
}

#endif
