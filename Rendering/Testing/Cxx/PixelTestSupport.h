// Helpers of the mappers' per-pixel tests: the ray through a pixel, the 8-bit
// value the tone-mapped pipeline shows for a radiance, the window's pixels.
#ifndef PixelTestSupport_h
#define PixelTestSupport_h

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPolyData.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkToneMappingPass.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkRadiosityView.h"
#include "vtkNew.h"
#include "vtkTestErrorObserver.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace PixelTestSupport
{
using Vec3 = std::array<double, 3>;

// A mapper's actor alone in an offscreen window without multisampling,
// black background, drawn through a vtkToneMappingPass (the mappers' HDR
// radiance), the camera at (0, 0, 5) looking down -z with a 30 degree view.
struct ToneMappedWindow
{
  vtkNew<vtkActor> Actor;
  vtkNew<vtkOpenGLRenderer> Renderer;
  vtkNew<vtkRenderStepsPass> Steps;
  vtkNew<vtkToneMappingPass> ToneMapping;
  vtkNew<vtkRenderWindow> Window;

  ToneMappedWindow(vtkMapper* mapper, int width, int height)
  {
    this->Actor->SetMapper(mapper);
    this->Renderer->SetBackground(0.0, 0.0, 0.0);
    this->Renderer->AddActor(this->Actor);
    this->ToneMapping->SetDelegatePass(this->Steps);
    this->Renderer->SetPass(this->ToneMapping);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(0.0, 0.0, 5.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetViewAngle(30.0);
    camera->SetClippingRange(0.5, 20.0);
    this->Window->SetMultiSamples(0);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetSize(width, height);
    this->Window->AddRenderer(this->Renderer);
  }
};

// vtkRadiosityView, given `input` with the cell array `name` replaced by one
// of 6 components, refuses to render with an error naming the array and the
// count, as its mapper does.
inline bool ViewRefusesSixComponents(vtkRadiosityView* view, vtkPolyData* input, const char* name)
{
  vtkNew<vtkPolyData> bad;
  bad->DeepCopy(input);
  vtkNew<vtkDoubleArray> six;
  six->SetName(name);
  six->SetNumberOfComponents(6);
  six->SetNumberOfTuples(bad->GetNumberOfCells());
  bad->GetCellData()->AddArray(six);
  view->InterpolantRenderingOn();
  view->SetInputData(bad);
  vtkNew<vtkTest::ErrorObserver> observer;
  view->AddObserver(vtkCommand::ErrorEvent, observer);
  const std::string expected = std::string("'") + name + "' has 6 components";
  if (view->Render() || observer->GetErrorMessage().find(expected) == std::string::npos)
  {
    std::cerr << "vtkRadiosityView accepted a 6-component " << name << " ('" << observer->GetErrorMessage()
              << "')\n";
    return false;
  }
  return true;
}

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

// Moller-Trumbore: the ray parameter h > 0 and (s, t) of the hit of o + h d
// with the frame a + s (b - a) + t (c - a), inside the triangle abc (or, with
// `parallelogram`, inside the parallelogram it spans).
inline bool IntersectFrame(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& o, const Vec3& d,
  double& h, double& s, double& t, bool parallelogram = false)
{
  double e1[3], e2[3], pv[3], tv[3], qv[3];
  for (int i = 0; i < 3; ++i)
  {
    e1[i] = b[i] - a[i];
    e2[i] = c[i] - a[i];
    tv[i] = o[i] - a[i];
  }
  vtkMath::Cross(d.data(), e2, pv);
  const double det = vtkMath::Dot(e1, pv);
  if (std::abs(det) < 1e-14)
  {
    return false;
  }
  s = vtkMath::Dot(tv, pv) / det;
  vtkMath::Cross(tv, e1, qv);
  t = vtkMath::Dot(d.data(), qv) / det;
  h = vtkMath::Dot(e2, qv) / det;
  const bool inside = parallelogram ? (s <= 1.0 && t <= 1.0) : (s + t <= 1.0);
  return h > 0.0 && s >= 0.0 && t >= 0.0 && inside;
}

// The 8-bit value the pipeline should show for radiance L through the tone
// mapping operator `toneMapping` (vtkToneMappingPass's Clamp, Reinhard or
// Exponential with coefficient 1), applied either by the pass, which decodes
// the mapper's L^(1/2.2) first, or by the mapper itself (its ToneMapping,
// the pass clamping): the result is encoded with 1/2.2 either way.
inline double Displayed(double L, int toneMapping)
{
  L = std::max(L, 0.0);
  const double toned = toneMapping == vtkToneMappingPass::Reinhard ? L / (L + 1.0)
    : toneMapping == vtkToneMappingPass::Exponential             ? 1.0 - std::exp(-L)
                                                                 : std::min(L, 1.0);
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

// Compares every 3rd pixel whose centre sees a triangle well inside its edges
// with the field evaluated on the CPU at that point's barycentrics.
// Also reports how far a screen-space (affine, not perspective-correct)
// interpolation of (s,t) would be from the same values.
// Tolerance (of 255) beside its measurement: 8-bit rounding alone is 0.5,
// the worst measured here; the bounds of 2.5-3 (5-6x that) leave room for
// the rasteriser's sample positions at steep depth (1.94 measured once in
// the interpolant test) and stay 6-30x below what a wrong formula changes
// (affine barycentrics 25.8, ignoring the groups 45.9, the glossy lobe 93.6).
// `Triangle` has corners P[3] and Radiosity(s, t), the expected radiosity at
// the point P[0] + s (P[1] - P[0]) + t (P[2] - P[0]).
template <typename Triangle>
bool CheckPixels(vtkRenderer* ren, vtkRenderWindow* window, const std::vector<Triangle>& scene,
  double exposure, int toneMapping, double tolerance, double* affineDeviation)
{
  vtkSmartPointer<vtkUnsignedCharArray> pixels = ReadPixels(window);
  const int* size = window->GetSize();
  // Display positions of the corners, for the affine prediction.
  std::vector<std::array<double, 6>> screen(scene.size());
  for (size_t i = 0; i < scene.size(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      ren->SetWorldPoint(scene[i].P[k][0], scene[i].P[k][1], scene[i].P[k][2], 1.0);
      ren->WorldToDisplay();
      double dp[3];
      ren->GetDisplayPoint(dp);
      screen[i][2 * k] = dp[0];
      screen[i][2 * k + 1] = dp[1];
    }
  }

  int compared = 0;
  double worst = 0.0;
  double affineWorst = 0.0;
  for (int y = 1; y < size[1] - 1; y += 3)
  {
    for (int x = 1; x < size[0] - 1; x += 3)
    {
      Vec3 o, d;
      PixelRay(ren, x, y, o, d);
      double nearest = VTK_DOUBLE_MAX, s = 0, t = 0;
      int hit = -1;
      for (size_t i = 0; i < scene.size(); ++i)
      {
        double h, si, ti;
        if (IntersectFrame(scene[i].P[0], scene[i].P[1], scene[i].P[2], o, d, h, si, ti) && h < nearest)
        {
          nearest = h;
          s = si;
          t = ti;
          hit = static_cast<int>(i);
        }
      }
      // Stay clear of edges, where the pixel centre may fall either way.
      if (hit < 0 || std::min(std::min(s, t), 1.0 - s - t) < 0.03)
      {
        continue;
      }
      const Triangle& tri = scene[hit];
      const auto b = tri.Radiosity(s, t);

      // Screen-space barycentrics of the pixel centre.
      const auto& q = screen[hit];
      const double px = x + 0.5, py = y + 0.5;
      const double det = (q[2] - q[0]) * (q[5] - q[1]) - (q[4] - q[0]) * (q[3] - q[1]);
      const double sa = ((px - q[0]) * (q[5] - q[1]) - (q[4] - q[0]) * (py - q[1])) / det;
      const double ta = ((q[2] - q[0]) * (py - q[1]) - (px - q[0]) * (q[3] - q[1])) / det;
      const auto ba = tri.Radiosity(sa, ta);

      for (int c = 0; c < 3; ++c)
      {
        const double expected = Displayed(b[c] / vtkMath::Pi() * exposure, toneMapping);
        const double affine = Displayed(ba[c] / vtkMath::Pi() * exposure, toneMapping);
        const double got = pixels->GetComponent(static_cast<vtkIdType>(y) * size[0] + x, c);
        const double error = std::abs(got - expected);
        affineWorst = std::max(affineWorst, std::abs(affine - expected));
        if (error > worst)
        {
          worst = error;
        }
        if (error > tolerance)
        {
          std::cerr << "Pixel (" << x << ", " << y << ") channel " << c << " of triangle " << hit
                    << " at (s,t) = (" << s << ", " << t << "): got " << got << ", expected "
                    << expected << " (tone mapping " << toneMapping << ")\n";
          return false;
        }
      }
      ++compared;
    }
  }
  std::cout << "Tone mapping " << toneMapping << ": " << compared
            << " pixels match the field evaluated on the CPU, worst difference " << worst
            << "/255; an affine interpolation would be off by up to " << affineWorst << "/255\n";
  if (affineDeviation)
  {
    *affineDeviation = affineWorst;
  }
  if (compared < 500)
  {
    std::cerr << "Only " << compared << " pixels compared: the scene is not in view\n";
    return false;
  }
  return true;
}

// Renders `window` and compares its pixels (CheckPixels: Clamp, 3/255) with
// `scene` at `exposure`, which must be steep enough in depth that affine
// (screen-space) barycentrics would be at least 15/255 off somewhere.
template <typename Triangle>
bool CheckPerspectiveCorrectPixels(
  vtkRenderer* ren, vtkRenderWindow* window, const std::vector<Triangle>& scene, double exposure)
{
  window->Render();
  double affine = 0.0;
  if (!CheckPixels(ren, window, scene, exposure, vtkToneMappingPass::Clamp, 3.0, &affine))
  {
    return false;
  }
  if (affine < 15.0)
  {
    std::cerr << "The scene does not discriminate perspective-correct interpolation (" << affine
              << ")\n";
    return false;
  }
  return true;
}

// Renders `window` once after `feed` has given `mapper` its input, and
// expects an error event whose message contains `expected`.
template <typename Feed>
bool ExpectRenderError(vtkRenderWindow* window, vtkObject* mapper, Feed feed, const std::string& expected)
{
  vtkNew<vtkTest::ErrorObserver> observer;
  const unsigned long tag = mapper->AddObserver(vtkCommand::ErrorEvent, observer);
  feed();
  window->Render();
  mapper->RemoveObserver(tag);
  if (!observer->GetError() || observer->GetErrorMessage().find(expected) == std::string::npos)
  {
    std::cerr << "Expected an error containing '" << expected << "', got '"
              << observer->GetErrorMessage() << "'\n";
    return false;
  }
  return true;
}
// A null input is refused with "No input polydata.", whether or not the
// caller asks for the reason.
template <typename Validate>
bool RefusesNullInput(Validate validate)
{
  std::string why = "stale";
  if (validate(nullptr, &why) || why != "No input polydata." || validate(nullptr, nullptr))
  {
    std::cerr << "A null input was not refused: '" << why << "'\n";
    return false;
  }
  return true;
}

// Draws `actor` once with a fresh mapper of `original`'s class whose vertex
// coordinates are always shifted and scaled (ParaView's default), on a copy
// of `input` (the window shares the VBO of a points array among mappers, and
// the original's would be unshifted); `configure` sets the rest of the new
// mapper. Then `check()` compares the pixels; `original` is restored.
template <typename Mapper, typename Configure, typename Check>
bool CheckShiftedCoordinates(vtkRenderWindow* window, vtkActor* actor, Mapper* original,
  vtkPolyData* input, Configure configure, Check check)
{
  vtkSmartPointer<Mapper> shifted = vtkSmartPointer<Mapper>::New();
  shifted->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::ALWAYS_AUTO_SHIFT_SCALE);
  vtkNew<vtkPolyData> copy;
  copy->DeepCopy(input);
  shifted->SetInputData(copy);
  configure(shifted.GetPointer());
  actor->SetMapper(shifted);
  window->Render();
  vtkOpenGLVertexBufferObject* vbo = shifted->GetVBOs()->GetVBO("vertexMC");
  const bool enabled = vbo && vbo->GetCoordShiftAndScaleEnabled();
  const bool same = enabled && check();
  actor->SetMapper(original);
  shifted->ReleaseGraphicsResources(window);
  if (!same)
  {
    std::cerr << "With shifted and scaled coordinates (shift on: " << enabled << ") the pixels differ\n";
  }
  return same;
}
}

#endif
