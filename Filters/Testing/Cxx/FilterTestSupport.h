// Helpers of the filters' tests.
#ifndef FilterTestSupport_h
#define FilterTestSupport_h

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRadiosityView.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

namespace FilterTestSupport
{
/// The largest difference of two outputs' point `Irradiance`, over the
/// second's peak (1e300 when either lacks it or their sizes differ).
inline double RelativeDifference(vtkPolyData* a, vtkPolyData* b)
{
  vtkDataArray* x = a->GetPointData()->GetArray("Irradiance");
  vtkDataArray* y = b->GetPointData()->GetArray("Irradiance");
  if (!x || !y || x->GetNumberOfTuples() != y->GetNumberOfTuples() || x->GetNumberOfTuples() == 0)
  {
    return 1e300;
  }
  double peak = 0.0, worst = 0.0;
  for (vtkIdType i = 0; i < x->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      peak = std::max(peak, std::fabs(y->GetComponent(i, c)));
      worst = std::max(worst, std::fabs(x->GetComponent(i, c) - y->GetComponent(i, c)));
    }
  }
  return peak > 0 ? worst / peak : 1e300;
}

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

// Two views side by side in one window of two width x height halves, with the
// same camera (and `exposure`, when positive): the comparisons of two
// displays of one scene.
inline void SideBySide(vtkRenderWindow* window, vtkRadiosityView* left, vtkRadiosityView* right, int width,
  int height, const double position[3], const double focal[3], const double up[3], double viewAngle,
  double exposure = 0.0)
{
  window->SetMultiSamples(0);
  window->SetSize(2 * width, height);
  int half = 0;
  for (vtkRadiosityView* view : { left, right })
  {
    view->SetRenderWindow(window);
    view->SetSize(2 * width, height);
    view->SetCamera(position, focal, up, viewAngle);
    if (exposure > 0.0)
    {
      view->SetExposure(exposure);
    }
    view->GetRenderer()->SetViewport(0.5 * half, 0.0, 0.5 * (half + 1), 1.0);
    ++half;
  }
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
