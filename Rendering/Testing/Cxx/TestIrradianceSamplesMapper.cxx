// Renders elements carrying their own irradiance samples (three corners and
// the centroid, as the progressive and hierarchical methods write them) with
// vtkIrradianceSamplesMapper through a vtkToneMappingPass and compares it
// with the baseline. Also checks, pixel by pixel, that what is drawn is
// linear through the corners plus the cubic bubble through the centroid at
// the exact (perspective-correct) barycentrics of the visible point, with
// negative irradiance drawn as 0; that a T-junction shows each element's own
// samples; that vtkRadiosityView takes this path for such input and the
// Gouraud path when asked; and that bad input is refused naming the array.

#include "vtkIrradianceSamplesMapper.h"
#include "vtkRadiosityView.h"

#include "PixelTestSupport.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderer.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkToneMappingPass.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using namespace PixelTestSupport;
using RGB = std::array<double, 3>;

// One element: corners, its irradiance samples at the corners (H[0..2]) and
// the centroid (H[3]), and the materials.
struct Element
{
  Vec3 P[3];
  RGB H[4];
  RGB Reflectance;
  RGB Emission;

  // Written here from the mapper's description, not taken from the code
  // under test: u H0 + s H1 + t H2 + 27 u s t (Hc - (H0 + H1 + H2) / 3).
  RGB Irradiance(double s, double t) const
  {
    const double u = 1.0 - s - t;
    RGB h;
    for (int c = 0; c < 3; ++c)
    {
      const double mean = (this->H[0][c] + this->H[1][c] + this->H[2][c]) / 3.0;
      h[c] = u * this->H[0][c] + s * this->H[1][c] + t * this->H[2][c] +
        27.0 * u * s * t * (this->H[3][c] - mean);
    }
    return h;
  }

  // What is drawn: negative radiosity cut to 0.
  RGB Radiosity(double s, double t) const
  {
    const RGB h = this->Irradiance(s, t);
    RGB b;
    for (int c = 0; c < 3; ++c)
    {
      b[c] = std::max(0.0, this->Emission[c] + this->Reflectance[c] * h[c]);
    }
    return b;
  }
};

Vec3 Lerp3(const Vec3 p[3], double s, double t)
{
  Vec3 x;
  for (int i = 0; i < 3; ++i)
  {
    x[i] = p[0][i] + s * (p[1][i] - p[0][i]) + t * (p[2][i] - p[0][i]);
  }
  return x;
}

// An element sampling a function of the world position at its corners and
// centroid, as a solver's element gathers.
Element Sampling(const Vec3& p0, const Vec3& p1, const Vec3& p2,
  const std::function<RGB(const Vec3&)>& irradiance, const RGB& reflectance)
{
  Element e{ { p0, p1, p2 }, {}, reflectance, { 0.0, 0.0, 0.0 } };
  for (int k = 0; k < 3; ++k)
  {
    e.H[k] = irradiance(e.P[k]);
  }
  e.H[3] = irradiance(Lerp3(e.P, 1.0 / 3.0, 1.0 / 3.0));
  return e;
}

std::vector<Element> MakeScene()
{
  // Camera at (0, 0, 5) looking down -z; the elements do not overlap on screen.
  std::vector<Element> scene;
  // Left, steeply receding in depth: equal corners and a bright centroid (a
  // spot of light inside the element), which Gouraud shading would not show.
  scene.push_back({ { { -1.55, -1.1, 0.3 }, { -0.35, -1.0, -3.0 }, { -1.5, 1.0, 0.0 } },
    { RGB{ 0.3, 0.6, 3.0 }, RGB{ 0.3, 0.6, 3.0 }, RGB{ 0.3, 0.6, 3.0 }, RGB{ 13.6, 4.6, 1.0 } },
    { 0.8, 0.6, 0.6 }, { 0.0, 0.0, 0.0 } });
  // Bottom right: one bright corner per channel and a dark centroid, so each
  // channel's bubble goes below zero between the centroid and the far edge
  // (drawn as 0).
  scene.push_back({ { { 0.0, -1.2, 0.0 }, { 1.6, -1.2, -0.4 }, { 0.3, 0.0, -1.2 } },
    { RGB{ 6.0, 0.3, 0.3 }, RGB{ 0.3, 6.0, 0.3 }, RGB{ 0.3, 0.3, 6.0 }, RGB{ 0.05, 0.05, 0.05 } },
    { 0.7, 0.7, 0.7 }, { 0.0, 0.0, 0.0 } });
  // Top right: a quad lit by a spot, one large element beside two half-size
  // ones (a T-junction at the middle of the shared edge, as a subdivision
  // leaves it): each draws its own samples.
  auto spot = [](const Vec3& x) {
    const double d2 = (x[0] - 1.2) * (x[0] - 1.2) + (x[1] - 0.9) * (x[1] - 0.9);
    const double f = 10.0 * std::exp(-6.0 * d2);
    return RGB{ 0.2 + 0.3 * f, 0.2 + 0.8 * f, 0.3 + 1.1 * f };
  };
  const Vec3 q0 = { 0.6, 0.15, -0.3 }, q1 = { 1.6, 0.15, -0.6 }, q2 = { 1.55, 1.15, -0.9 },
             q3 = { 0.6, 1.1, -0.6 };
  const Vec3 m = { 0.5 * (q0[0] + q2[0]), 0.5 * (q0[1] + q2[1]), 0.5 * (q0[2] + q2[2]) };
  scene.push_back(Sampling(q0, q1, q2, spot, { 0.3, 0.6, 0.8 }));
  scene.push_back(Sampling(q0, m, q3, spot, { 0.3, 0.6, 0.8 }));
  scene.push_back(Sampling(m, q2, q3, spot, { 0.3, 0.6, 0.8 }));
  // Top middle: a warm emitter, irradiated by nothing: B = Emission.
  scene.push_back({ { { -0.3, 0.7, -0.3 }, { 0.35, 0.7, -0.3 }, { 0.0, 1.15, -0.3 } },
    { RGB{ 0, 0, 0 }, RGB{ 0, 0, 0 }, RGB{ 0, 0, 0 }, RGB{ 0, 0, 0 } }, { 0.5, 0.5, 0.5 },
    { 9.0, 6.5, 3.0 } });
  return scene;
}

// The elements as the filter writes them: shared nothing, the cell array
// `IrradianceSamples` (sample-major), the materials, and the point array
// `Radiosity` at the corners for the Gouraud path.
vtkSmartPointer<vtkPolyData> MakePolyData(const std::vector<Element>& scene)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkFloatArray> samples;
  samples->SetName("IrradianceSamples");
  samples->SetNumberOfComponents(12);
  vtkNew<vtkDoubleArray> reflectance;
  reflectance->SetName("Reflectance");
  reflectance->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> emission;
  emission->SetName("Emission");
  emission->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> radiosity;
  radiosity->SetName("Radiosity");
  radiosity->SetNumberOfComponents(3);
  const double corners[3][2] = { { 0, 0 }, { 1, 0 }, { 0, 1 } };
  for (const Element& e : scene)
  {
    vtkIdType ids[3];
    for (int k = 0; k < 3; ++k)
    {
      ids[k] = points->InsertNextPoint(e.P[k].data());
      radiosity->InsertNextTuple(e.Radiosity(corners[k][0], corners[k][1]).data());
    }
    polys->InsertNextCell(3, ids);
    double tuple[12];
    for (int k = 0; k < 4; ++k)
    {
      std::copy(e.H[k].begin(), e.H[k].end(), tuple + 3 * k);
    }
    samples->InsertNextTuple(tuple);
    reflectance->InsertNextTuple(e.Reflectance.data());
    emission->InsertNextTuple(e.Emission.data());
  }
  vtkSmartPointer<vtkPolyData> pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetPolys(polys);
  pd->GetCellData()->AddArray(samples);
  pd->GetCellData()->AddArray(reflectance);
  pd->GetCellData()->AddArray(emission);
  pd->GetPointData()->AddArray(radiosity);
  return pd;
}

bool ExpectError(vtkRenderWindow* window, vtkIrradianceSamplesMapper* mapper, vtkPolyData* input,
  const std::string& expected)
{
  if (!ExpectRenderError(window, mapper, [&] { mapper->SetInputData(input); }, expected))
  {
    return false;
  }
  std::string message;
  if (vtkIrradianceSamplesMapper::ValidateInput(input, &message) ||
    message.find(expected) == std::string::npos)
  {
    std::cerr << "ValidateInput did not refuse with '" << expected << "': '" << message << "'\n";
    return false;
  }
  return true;
}

// The array's absence and its component count are named; the cells and the
// materials are the base's checks (TestQuadraticInterpolantMapper).
bool TestInvalidInput(vtkRenderWindow* window, vtkIrradianceSamplesMapper* mapper, vtkPolyData* good)
{
  bool ok = RefusesNullInput(vtkIrradianceSamplesMapper::ValidateInput);
  vtkNew<vtkPolyData> bad;
  bad->DeepCopy(good);
  bad->GetCellData()->RemoveArray("IrradianceSamples");
  ok &= ExpectError(window, mapper, bad, "No cell array 'IrradianceSamples' (12 components");
  bad->DeepCopy(good);
  vtkNew<vtkDoubleArray> nine;
  nine->SetName("IrradianceSamples");
  nine->SetNumberOfComponents(9);
  nine->SetNumberOfTuples(bad->GetNumberOfCells());
  nine->Fill(1.0);
  bad->GetCellData()->AddArray(nine);
  ok &= ExpectError(window, mapper, bad, "'IrradianceSamples' has 9 components, 12");
  mapper->SetInputData(good);
  return ok;
}

// The pixel at the world point `x`.
double PixelAt(vtkRenderer* ren, vtkRenderWindow* window, const Vec3& x, int channel)
{
  ren->SetWorldPoint(x[0], x[1], x[2], 1.0);
  ren->WorldToDisplay();
  double dp[3];
  ren->GetDisplayPoint(dp);
  const vtkIdType pixel =
    static_cast<vtkIdType>(dp[1]) * window->GetSize()[0] + static_cast<vtkIdType>(dp[0]);
  return ReadPixels(window)->GetComponent(pixel, channel);
}

// vtkRadiosityView takes the samples path for such input, the Gouraud path
// when forced: at the left centroid the samples show the bright centroid
// sample, Gouraud the (equal) corners.
bool TestView(vtkPolyData* input, const std::vector<Element>& scene)
{
  vtkNew<vtkRadiosityView> view;
  view->SetInputData(input);
  view->SetSize(200, 150);
  view->SetToneMappingTypeToClamp();
  view->SetExposure(0.25);
  const double position[3] = { 0.0, 0.0, 5.0 }, focal[3] = { 0, 0, 0 }, up[3] = { 0, 1, 0 };
  view->SetCamera(position, focal, up, 30.0);
  if (!view->UsesIrradianceSamplesMapper() || view->UsesInterpolantMapper() || !view->Render())
  {
    std::cerr << "vtkRadiosityView did not take the irradiance samples path\n";
    return false;
  }
  const Vec3 centroid = Lerp3(scene[0].P, 1.0 / 3.0, 1.0 / 3.0);
  const double peak = PixelAt(view->GetRenderer(), view->GetRenderWindow(), centroid, 0);
  view->InterpolantRenderingOff();
  if (view->UsesIrradianceSamplesMapper() || !view->Render())
  {
    std::cerr << "vtkRadiosityView did not take the Gouraud path\n";
    return false;
  }
  const double flat = PixelAt(view->GetRenderer(), view->GetRenderWindow(), centroid, 0);
  const double corner = Displayed(scene[0].Radiosity(0, 0)[0] / vtkMath::Pi() * 0.25, 0);
  const double top = Displayed(scene[0].Radiosity(1.0 / 3, 1.0 / 3)[0] / vtkMath::Pi() * 0.25, 0);
  std::cout << "vtkRadiosityView at the left centroid, red: samples " << peak << " (expected "
            << top << "), Gouraud " << flat << " (corners " << corner << ")\n";
  if (std::abs(peak - top) > 3.0 || std::abs(flat - corner) > 3.0 || peak - flat < 40.0)
  {
    std::cerr << "The two paths of vtkRadiosityView do not show the centroid sample as expected\n";
    return false;
  }
  // The view refuses what the mapper refuses, naming the array.
  return ViewRefusesSixComponents(view, input, "IrradianceSamples");
}
}

int TestIrradianceSamplesMapper(int argc, char* argv[])
{
  // Mesa's llvmpipe raises SIGFPE when VTK's driver enables FP exceptions.
  vtkFloatingPointExceptions::Disable();

  {
    vtkNew<vtkIrradianceSamplesMapper> mapper;
    std::ostringstream printed;
    mapper->SetExposure(-1.0);
    mapper->Print(printed);
    if (mapper->GetExposure() != 0.0 ||
      printed.str().find("SamplesArrayName: IrradianceSamples") == std::string::npos ||
      printed.str().find("FieldArrayName: IrradianceSamples (12 components") == std::string::npos)
    {
      std::cerr << "Exposure not clamped, or PrintSelf is missing properties:\n" << printed.str();
      return EXIT_FAILURE;
    }
  }

  const std::vector<Element> scene = MakeScene();
  vtkSmartPointer<vtkPolyData> input = MakePolyData(scene);

  vtkNew<vtkIrradianceSamplesMapper> mapper;
  mapper->SetInputData(input);
  ToneMappedWindow view(mapper, 400, 300);
  vtkRenderer* renderer = view.Renderer;
  vtkToneMappingPass* toneMapping = view.ToneMapping;
  vtkRenderWindow* window = view.Window;

  if (!TestInvalidInput(window, mapper, input))
  {
    return EXIT_FAILURE;
  }

  // Radiance below 1 (B under 11 W/m^2, exposure 0.25) through Clamp: the
  // displayed value is L^(1/2.2) itself, as sensitive as 8 bits allow.
  // Bound 3/255 as the interpolant mapper's test (0.5 is 8-bit rounding).
  const double exposure = 0.25;
  mapper->SetExposure(exposure);
  toneMapping->SetToneMappingType(vtkToneMappingPass::Clamp);
  if (!CheckPerspectiveCorrectPixels(renderer, window, scene, exposure))
  {
    return EXIT_FAILURE;
  }

  // Negative irradiance is drawn as 0 (CheckPixels compared the cut values;
  // here the most negative red of the bottom-right element, away from its
  // edges, shows no red).
  double lowest = 0.0, sLow = 0.0, tLow = 0.0;
  for (double s = 0.05; s < 0.9; s += 0.01)
  {
    for (double t = 0.05; s + t < 0.95; t += 0.01)
    {
      const double red = scene[1].Irradiance(s, t)[0];
      if (red < lowest)
      {
        lowest = red;
        sLow = s;
        tLow = t;
      }
    }
  }
  const double shown = PixelAt(renderer, window, Lerp3(scene[1].P, sLow, tLow), 0);
  std::cout << "Lowest red irradiance " << lowest << " W/m^2 at (s, t) = (" << sLow << ", " << tLow
            << "), drawn as " << shown << "/255\n";
  if (lowest > -0.2 || shown > 1.0)
  {
    std::cerr << "The negative part is not drawn as 0 (or the scene has none)\n";
    return EXIT_FAILURE;
  }

  // The T-junction: at the middle of the large element's edge the two small
  // ones show their own corner sample, the large one the mean of its
  // corners; here they differ by more than the bound.
  const RGB own = scene[3].Radiosity(1.0, 0.0);
  const RGB large = scene[2].Radiosity(0.5, 0.5);
  std::cout << "T-junction: the small elements' corner " << own[2] << ", the large element's edge "
            << large[2] << " W/m^2 (blue)\n";
  if (std::abs(Displayed(own[2] / vtkMath::Pi() * exposure, 0) -
        Displayed(large[2] / vtkMath::Pi() * exposure, 0)) < 10.0)
  {
    std::cerr << "The T-junction does not discriminate the elements' own samples\n";
    return EXIT_FAILURE;
  }

  if (!TestView(input, scene))
  {
    return EXIT_FAILURE;
  }

  // The baseline: HDR radiance (up to about 3) through Reinhard.
  mapper->SetExposure(1.0);
  toneMapping->SetToneMappingType(vtkToneMappingPass::Reinhard);
  window->Render();
  if (!CheckPixels(renderer, window, scene, 1.0, vtkToneMappingPass::Reinhard, 3.0, nullptr))
  {
    return EXIT_FAILURE;
  }
  const int retVal = vtkRegressionTestImage(window);
  return !retVal;
}
