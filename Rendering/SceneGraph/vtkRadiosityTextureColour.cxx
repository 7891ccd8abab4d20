#include "vtkRadiosityTextureColour.h"

#include "vtkAlgorithm.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkTexture.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkRadiosityTextureColour);

vtkRadiosityTextureColour::vtkRadiosityTextureColour() = default;
vtkRadiosityTextureColour::~vtkRadiosityTextureColour() = default;

namespace
{
/// The sRGB transfer function's inverse (IEC 61966-2-1).
double SRGBToLinear(double c)
{
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
}

bool vtkRadiosityTextureColour::SetTexture(vtkTexture* texture, std::string& error)
{
  this->Texels.clear();
  this->Width = this->Height = 0;
  if (!texture)
  {
    error = "no texture";
    return false;
  }
  if (texture->GetInputAlgorithm())
  {
    texture->GetInputAlgorithm()->Update();
  }
  vtkImageData* image = texture->GetInput();
  int dims[3] = { 0, 0, 0 };
  if (image)
  {
    image->GetDimensions(dims);
  }
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  if (!image || !scalars || dims[0] < 1 || dims[1] < 1 || dims[2] != 1)
  {
    error = image ? "the texture's image is empty, has no scalars or is not 2D (" +
        std::to_string(dims[0]) + " x " + std::to_string(dims[1]) + " x " + std::to_string(dims[2]) + ")"
                  : "the texture has no image";
    return false;
  }
  const int nc = scalars->GetNumberOfComponents();
  if (nc < 1 || nc > 4)
  {
    error = "the texture's image has " + std::to_string(nc) + " components (1 to 4 expected)";
    return false;
  }
  this->Width = dims[0];
  this->Height = dims[1];
  this->Wrap = texture->GetWrap();
  float border[4];
  texture->GetBorderColor(border);
  for (int k = 0; k < 3; ++k)
  {
    this->Border[k] = std::max(0.0, static_cast<double>(border[k]));
  }
  this->SRGB = texture->GetUseSRGBColorSpace();
  const bool bytes = scalars->GetDataType() == VTK_UNSIGNED_CHAR;
  const vtkIdType n = static_cast<vtkIdType>(this->Width) * this->Height;
  this->Texels.resize(3 * static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      // Grey (1 or 2 components) fills the three channels.
      double v = scalars->GetComponent(i, nc < 3 ? 0 : k);
      if (!std::isfinite(v) || v < 0.0)
      {
        error = "texel " + std::to_string(i) + " component " + std::to_string(nc < 3 ? 0 : k) +
          " is " + std::to_string(v) + " (not a colour)";
        this->Texels.clear();
        this->Width = this->Height = 0;
        return false;
      }
      if (bytes)
      {
        v /= 255.0;
        if (this->SRGB)
        {
          v = SRGBToLinear(v);
        }
      }
      this->Texels[3 * i + k] = v;
    }
  }
  return true;
}

const double* vtkRadiosityTextureColour::Texel(int i, int j) const
{
  const int w = this->Width, h = this->Height;
  switch (this->Wrap)
  {
    case vtkTexture::Repeat:
      i = ((i % w) + w) % w;
      j = ((j % h) + h) % h;
      break;
    case vtkTexture::MirroredRepeat:
      // Period 2n: 0 .. n-1, then n-1 .. 0.
      i = ((i % (2 * w)) + 2 * w) % (2 * w);
      j = ((j % (2 * h)) + 2 * h) % (2 * h);
      i = i < w ? i : 2 * w - 1 - i;
      j = j < h ? j : 2 * h - 1 - j;
      break;
    case vtkTexture::ClampToBorder:
      if (i < 0 || j < 0 || i >= w || j >= h)
      {
        return this->Border;
      }
      break;
    default: // ClampToEdge
      i = std::clamp(i, 0, w - 1);
      j = std::clamp(j, 0, h - 1);
  }
  return this->Texels.data() + 3 * (static_cast<std::size_t>(j) * w + i);
}

void vtkRadiosityTextureColour::Sample(double s, double t, double rgb[3]) const
{
  // Texel centres at (i + 1/2) / Width, as OpenGL's linear filter has them.
  const double x = s * this->Width - 0.5;
  const double y = t * this->Height - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const double ax = x - fx, ay = y - fy;
  const int i = static_cast<int>(fx), j = static_cast<int>(fy);
  const double* a = this->Texel(i, j);
  const double* b = this->Texel(i + 1, j);
  const double* c = this->Texel(i, j + 1);
  const double* d = this->Texel(i + 1, j + 1);
  for (int k = 0; k < 3; ++k)
  {
    rgb[k] = (1.0 - ay) * ((1.0 - ax) * a[k] + ax * b[k]) + ay * ((1.0 - ax) * c[k] + ax * d[k]);
  }
}

void vtkRadiosityTextureColour::TriangleMean(const double uv[3][2], double rgb[3]) const
{
  rgb[0] = rgb[1] = rgb[2] = 0.0;
  if (this->Texels.empty())
  {
    return;
  }
  // Subdivisions per edge: 8 per texel of the longest edge, 8 to 64.
  double longest = 0.0;
  for (int e = 0; e < 3; ++e)
  {
    const double* p = uv[e];
    const double* q = uv[(e + 1) % 3];
    longest = std::max(longest, std::hypot((q[0] - p[0]) * this->Width, (q[1] - p[1]) * this->Height));
  }
  const double wanted = std::isfinite(longest) ? std::ceil(8.0 * longest) : 64.0;
  const int n = static_cast<int>(std::clamp(wanted, 8.0, 64.0));
  // The n^2 triangles of the regular subdivision, in barycentric steps of
  // 1/n: (i, j) upright with centroid ((i + 1/3), (j + 1/3)) / n, and
  // (i, j) inverted with centroid ((i + 2/3), (j + 2/3)) / n.
  double sum[3] = { 0.0, 0.0, 0.0 };
  const auto add = [&](double b1, double b2)
  {
    const double b0 = 1.0 - b1 - b2;
    double c[3];
    this->Sample(b0 * uv[0][0] + b1 * uv[1][0] + b2 * uv[2][0],
      b0 * uv[0][1] + b1 * uv[1][1] + b2 * uv[2][1], c);
    for (int k = 0; k < 3; ++k)
    {
      sum[k] += c[k];
    }
  };
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; i + j < n; ++j)
    {
      add((i + 1.0 / 3.0) / n, (j + 1.0 / 3.0) / n);
      if (i + j < n - 1)
      {
        add((i + 2.0 / 3.0) / n, (j + 2.0 / 3.0) / n);
      }
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    rgb[k] = sum[k] / (static_cast<double>(n) * n);
  }
}

void vtkRadiosityTextureColour::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Width: " << this->Width << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "Wrap: " << this->Wrap << "\n";
  os << indent << "SRGB: " << (this->SRGB ? "On" : "Off") << "\n";
}
