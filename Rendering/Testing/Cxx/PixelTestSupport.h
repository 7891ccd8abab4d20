// Helpers of the mappers' per-pixel tests: the ray through a pixel, the 8-bit
// value the tone-mapped pipeline shows for a radiance, the window's pixels.
#ifndef PixelTestSupport_h
#define PixelTestSupport_h

#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkToneMappingPass.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace PixelTestSupport
{
using Vec3 = std::array<double, 3>;

// Ray through the centre of pixel (x, y) (display coordinates, origin at the
// lower left): a point on it and its direction, in world coordinates.
inline void PixelRay(vtkRenderer* ren, int x, int y, Vec3& origin, Vec3& direction)
{
  double p[2][4];
  for (int k = 0; k < 2; ++k)
  {
    ren->SetDisplayPoint(x + 0.5, y + 0.5, k == 0 ? 0.0 : 1.0);
    ren->DisplayToWorld();
    ren->GetWorldPoint(p[k]);
    for (int i = 0; i < 3; ++i)
    {
      p[k][i] /= p[k][3];
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    origin[i] = p[0][i];
    direction[i] = p[1][i] - p[0][i];
  }
}

// The 8-bit value the pipeline should show for radiance L: the mapper
// writes L^(1/2.2), the tone mapping pass decodes it, applies its operator
// and encodes the result with 1/2.2 again.
inline double Displayed(double L, int toneMapping)
{
  L = std::max(L, 0.0);
  const double toned = toneMapping == vtkToneMappingPass::Clamp ? std::min(L, 1.0) : L / (L + 1.0);
  return 255.0 * std::pow(toned, 1.0 / 2.2);
}

inline vtkSmartPointer<vtkUnsignedCharArray> ReadPixels(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  return vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
}
}

#endif
