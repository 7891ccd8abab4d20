// Renders a synthetic scene of Hardt & Teller quadratic interpolants with
// vtkQuadraticInterpolantMapper through a vtkToneMappingPass and compares it
// with the baseline. Also checks, pixel by pixel, that what is drawn is the
// interpolant evaluated at the exact (perspective-correct) barycentrics of the
// visible point, that vtkRadiosityView switches between the interpolant and
// the Gouraud paths, and that bad input is refused with an error naming the
// array or the cell, without a crash.

#include "vtkQuadraticInterpolantMapper.h"
#include "vtkRadiosityView.h"

#include "PixelTestSupport.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderer.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRendererCollection.h"
#include "vtkTestErrorObserver.h"
#include "vtkToneMappingPass.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

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

// One triangle of the scene: corners, the interpolant's coefficients
// (A, 2B, 2C, D, 2E, F) per channel, and the materials.
struct Triangle
{
  Vec3 P[3];
  double Coefficients[3][6]; // [channel][A, 2B, 2C, D, 2E, F]
  RGB Reflectance;
  RGB Emission;

  RGB Irradiance(double s, double t) const
  {
    RGB r;
    for (int c = 0; c < 3; ++c)
    {
      const double* k = this->Coefficients[c];
      r[c] = k[0] * s * s + k[1] * s * t + k[2] * s + k[3] * t * t + k[4] * t + k[5];
    }
    return r;
  }

  RGB Radiosity(double s, double t) const
  {
    const RGB r = this->Irradiance(s, t);
    return { this->Emission[0] + this->Reflectance[0] * r[0],
      this->Emission[1] + this->Reflectance[1] * r[1],
      this->Emission[2] + this->Reflectance[2] * r[2] };
  }
};

// Hardt & Teller section 2.2: the interpolant through six samples at the
// corners and edge midpoints, (0,0), (1/2,0), (1,0), (1/2,1/2), (0,1), (0,1/2).
// (E with the factor 2 on r5 that solving the paper's own system gives.)
Triangle MakeTriangle(const Vec3& p0, const Vec3& p1, const Vec3& p2,
  const std::function<RGB(double, double)>& irradiance, const RGB& reflectance,
  const RGB& emission)
{
  Triangle tri;
  tri.P[0] = p0;
  tri.P[1] = p1;
  tri.P[2] = p2;
  const double st[6][2] = { { 0, 0 }, { 0.5, 0 }, { 1, 0 }, { 0.5, 0.5 }, { 0, 1 }, { 0, 0.5 } };
  RGB r[6];
  for (int i = 0; i < 6; ++i)
  {
    r[i] = irradiance(st[i][0], st[i][1]);
  }
  for (int c = 0; c < 3; ++c)
  {
    const double A = 2 * r[0][c] - 4 * r[1][c] + 2 * r[2][c];
    const double B = 2 * r[0][c] - 2 * r[1][c] + 2 * r[3][c] - 2 * r[5][c];
    const double C = -1.5 * r[0][c] + 2 * r[1][c] - 0.5 * r[2][c];
    const double D = 2 * r[0][c] + 2 * r[4][c] - 4 * r[5][c];
    const double E = -1.5 * r[0][c] - 0.5 * r[4][c] + 2 * r[5][c];
    const double coefficients[6] = { A, 2 * B, 2 * C, D, 2 * E, r[0][c] };
    std::copy(coefficients, coefficients + 6, tri.Coefficients[c]);
  }
  tri.Reflectance = reflectance;
  tri.Emission = emission;
  return tri;
}

Vec3 Lerp3(const Triangle& tri, double s, double t)
{
  Vec3 x;
  for (int i = 0; i < 3; ++i)
  {
    x[i] = tri.P[0][i] + s * (tri.P[1][i] - tri.P[0][i]) + t * (tri.P[2][i] - tri.P[0][i]);
  }
  return x;
}

// A triangle whose irradiance is a function of the world position.
Triangle MakeWorldTriangle(const Vec3& p0, const Vec3& p1, const Vec3& p2,
  const std::function<RGB(const Vec3&)>& irradiance, const RGB& reflectance)
{
  Triangle frame;
  frame.P[0] = p0;
  frame.P[1] = p1;
  frame.P[2] = p2;
  return MakeTriangle(p0, p1, p2,
    [&](double s, double t) { return irradiance(Lerp3(frame, s, t)); }, reflectance,
    { 0.0, 0.0, 0.0 });
}

std::vector<Triangle> MakeScene()
{
  // Camera at (0, 0, 5) looking down -z; the triangles do not overlap on screen.
  std::vector<Triangle> scene;
  // Left, steeply receding in depth (its far corner is almost twice as far as
  // the near ones): an interpolant equal at the three corners that peaks at
  // the centroid, so a Gouraud rendering from vertex values would be flat.
  // Each channel has its own base and height: bluish corners, a red peak.
  scene.push_back(MakeTriangle({ -1.55, -1.1, 0.3 }, { -0.35, -1.0, -3.0 }, { -1.5, 1.0, 0.0 },
    [](double s, double t) {
      const double bump = s + t - s * s - t * t - s * t; // 0 at the corners, 1/3 at the centroid
      return RGB{ 0.3 + 40.0 * bump, 0.6 + 12.0 * bump, 3.0 - 6.0 * bump };
    },
    { 0.8, 0.6, 0.6 }, { 0.0, 0.0, 0.0 }));
  // Bottom right: a different quadratic per channel, each peaking at one
  // corner.
  scene.push_back(MakeTriangle({ 0.0, -1.2, 0.0 }, { 1.6, -1.2, -0.4 }, { 0.3, 0.0, -1.2 },
    [](double s, double t) {
      const double u = 1.0 - s - t;
      return RGB{ 14.0 * s * s + 0.3, 14.0 * t * t + 0.3, 14.0 * u * u + 0.3 };
    },
    { 0.7, 0.7, 0.7 }, { 0.0, 0.0, 0.0 }));
  // Top right: a quad of two triangles lit by one smooth spot, a quadratic in
  // world coordinates; each triangle has its own interpolant (in its own
  // frame), and the two agree on the shared edge.
  auto spot = [](const Vec3& x) {
    const double d2 = (x[0] - 1.1) * (x[0] - 1.1) + (x[1] - 0.65) * (x[1] - 0.65);
    const double f = 0.5 + 10.0 * (1.0 - 2.0 * d2);
    return RGB{ 0.2 + 0.3 * f, 0.2 + 0.8 * f, 0.3 + 1.1 * f };
  };
  const Vec3 q0 = { 0.6, 0.15, -0.3 }, q1 = { 1.6, 0.15, -0.6 }, q2 = { 1.55, 1.15, -0.9 },
             q3 = { 0.6, 1.1, -0.6 };
  scene.push_back(MakeWorldTriangle(q0, q1, q2, spot, { 0.3, 0.6, 0.8 }));
  scene.push_back(MakeWorldTriangle(q0, q2, q3, spot, { 0.3, 0.6, 0.8 }));
  // Top middle: a warm emitter, irradiated by nothing (R = 0): B = Emission.
  scene.push_back(MakeTriangle({ -0.3, 0.7, -0.3 }, { 0.35, 0.7, -0.3 }, { 0.0, 1.15, -0.3 },
    [](double, double) { return RGB{ 0.0, 0.0, 0.0 }; }, { 0.5, 0.5, 0.5 }, { 9.0, 6.5, 3.0 }));
  return scene;
}

// The scene as the mapper's input: triangles with points of their own here
// (the mapper makes its own unshared copy anyway), cell arrays as in SPEC.md,
// and the point array `Radiosity` at the corners for the Gouraud path.
vtkSmartPointer<vtkPolyData> MakePolyData(const std::vector<Triangle>& scene)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkDoubleArray> interpolant;
  interpolant->SetName("QuadraticInterpolant");
  interpolant->SetNumberOfComponents(18);
  vtkNew<vtkFloatArray> reflectance;
  reflectance->SetName("Reflectance");
  reflectance->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> emission;
  emission->SetName("Emission");
  emission->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> radiosity;
  radiosity->SetName("Radiosity");
  radiosity->SetNumberOfComponents(3);
  const double corners[3][2] = { { 0, 0 }, { 1, 0 }, { 0, 1 } };
  for (const Triangle& tri : scene)
  {
    vtkIdType ids[3];
    for (int k = 0; k < 3; ++k)
    {
      ids[k] = points->InsertNextPoint(tri.P[k].data());
      const RGB b = tri.Radiosity(corners[k][0], corners[k][1]);
      radiosity->InsertNextTuple(b.data());
    }
    polys->InsertNextCell(3, ids);
    double tuple[18];
    for (int c = 0; c < 3; ++c)
    {
      std::copy(tri.Coefficients[c], tri.Coefficients[c] + 6, tuple + 6 * c);
    }
    interpolant->InsertNextTuple(tuple);
    reflectance->InsertNextTuple(tri.Reflectance.data());
    emission->InsertNextTuple(tri.Emission.data());
  }
  vtkSmartPointer<vtkPolyData> pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetPolys(polys);
  pd->GetCellData()->AddArray(interpolant);
  pd->GetCellData()->AddArray(reflectance);
  pd->GetCellData()->AddArray(emission);
  pd->GetPointData()->AddArray(radiosity);
  return pd;
}

// Renders `mapper` once and expects an error containing `expected`.
bool ExpectError(vtkRenderWindow* window, vtkQuadraticInterpolantMapper* mapper,
  vtkPolyData* input, const std::string& expected)
{
  if (!PixelTestSupport::ExpectRenderError(
        window, mapper, [&] { mapper->SetInputData(input); }, expected))
  {
    return false;
  }
  std::string message;
  if (vtkQuadraticInterpolantMapper::ValidateInput(input, &message) ||
    message.find(expected) == std::string::npos)
  {
    std::cerr << "ValidateInput did not refuse with '" << expected << "': '" << message << "'\n";
    return false;
  }
  return true;
}

bool TestInvalidInput(vtkRenderWindow* window, vtkQuadraticInterpolantMapper* mapper,
  vtkPolyData* good)
{
  bool ok = true;
  vtkNew<vtkPolyData> bad;

  bad->DeepCopy(good);
  bad->GetCellData()->RemoveArray("QuadraticInterpolant");
  ok &= ExpectError(window, mapper, bad, "No cell array 'QuadraticInterpolant' (18 components");

  bad->DeepCopy(good);
  vtkNew<vtkDoubleArray> six;
  six->SetName("QuadraticInterpolant");
  six->SetNumberOfComponents(6);
  six->SetNumberOfTuples(bad->GetNumberOfCells());
  six->Fill(1.0);
  bad->GetCellData()->AddArray(six);
  ok &= ExpectError(window, mapper, bad, "'QuadraticInterpolant' has 6 components, 18");

  bad->DeepCopy(good);
  vtkNew<vtkDoubleArray> grey;
  grey->SetName("Reflectance");
  grey->SetNumberOfTuples(bad->GetNumberOfCells());
  grey->Fill(0.5);
  bad->GetCellData()->AddArray(grey);
  ok &= ExpectError(window, mapper, bad, "'Reflectance' has 1 components, 3");

  // A quad among the triangles, named by its cell id.
  bad->DeepCopy(good);
  vtkNew<vtkCellArray> polys;
  const vtkIdType tri[3] = { 0, 1, 2 };
  const vtkIdType quad[4] = { 3, 4, 5, 6 };
  polys->InsertNextCell(3, tri);
  polys->InsertNextCell(4, quad);
  for (vtkIdType i = 2; i < good->GetNumberOfPolys(); ++i)
  {
    polys->InsertNextCell(3, tri);
  }
  bad->SetPolys(polys);
  ok &= ExpectError(window, mapper, bad, "cell 1 is a vtkQuad (4 points)");

  // A line cell.
  bad->DeepCopy(good);
  vtkNew<vtkCellArray> lines;
  const vtkIdType line[2] = { 0, 1 };
  lines->InsertNextCell(2, line);
  bad->SetLines(lines);
  ok &= ExpectError(window, mapper, bad, "cell 0 is a vtkLine (2 points)");

  // Fixed input draws again, without errors.
  vtkNew<vtkTest::ErrorObserver> quiet;
  mapper->AddObserver(vtkCommand::ErrorEvent, quiet);
  mapper->SetInputData(good);
  window->Render();
  if (quiet->GetError())
  {
    std::cerr << "Error after the input was fixed: " << quiet->GetErrorMessage() << "\n";
    ok = false;
  }
  mapper->RemoveObservers(vtkCommand::ErrorEvent);

  // No materials: drawn with the defaults, one warning per missing array
  // however many renders.
  vtkNew<vtkPolyData> bare;
  bare->DeepCopy(good);
  bare->GetCellData()->RemoveArray("Reflectance");
  bare->GetCellData()->RemoveArray("Emission");
  vtkNew<vtkQuadraticInterpolantMapper> fresh;
  vtkNew<vtkTest::ErrorObserver> observer;
  fresh->AddObserver(vtkCommand::WarningEvent, observer);
  fresh->AddObserver(vtkCommand::ErrorEvent, observer);
  fresh->SetInputData(bare);
  vtkNew<vtkActor> actor;
  actor->SetMapper(fresh);
  vtkRenderer* ren = window->GetRenderers()->GetFirstRenderer();
  ren->AddActor(actor);
  window->Render();
  bare->Modified();
  window->Render();
  ren->RemoveActor(actor);
  auto count = [](const std::string& text, const std::string& what) {
    int n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    {
      ++n;
    }
    return n;
  };
  const std::string warnings = observer->GetWarningMessage();
  if (observer->GetError() || count(warnings, "No cell array 'Reflectance'") != 1 ||
    count(warnings, "No cell array 'Emission'") != 1)
  {
    std::cerr << "Expected one warning each for Reflectance and Emission and no error, got '"
              << warnings << "', error '" << observer->GetErrorMessage() << "'\n";
    ok = false;
  }
  return ok;
}

// vtkRadiosityView: the interpolant path by default for such input, the
// Gouraud path when forced. At the centroid of the left triangle the
// interpolant peaks while Gouraud shows the (equal) corner values.
bool TestView(vtkPolyData* input, const std::vector<Triangle>& scene)
{
  vtkNew<vtkRadiosityView> view;
  view->SetInputData(input);
  view->SetSize(200, 150);
  view->SetToneMappingTypeToClamp();
  view->SetExposure(0.25);
  const double position[3] = { 0.0, 0.0, 5.0 }, focal[3] = { 0, 0, 0 }, up[3] = { 0, 1, 0 };
  view->SetCamera(position, focal, up, 30.0);
  if (!view->UsesInterpolantMapper() || !view->Render())
  {
    std::cerr << "vtkRadiosityView did not take the interpolant path\n";
    return false;
  }
  const Vec3 centroid = Lerp3(scene[0], 1.0 / 3.0, 1.0 / 3.0);
  vtkRenderer* ren = view->GetRenderer();
  ren->SetWorldPoint(centroid[0], centroid[1], centroid[2], 1.0);
  ren->WorldToDisplay();
  double dp[3];
  ren->GetDisplayPoint(dp);
  const vtkIdType pixel = static_cast<vtkIdType>(dp[1]) * 200 + static_cast<vtkIdType>(dp[0]);
  const double peak = ReadPixels(view->GetRenderWindow())->GetComponent(pixel, 0);

  view->InterpolantRenderingOff();
  if (view->UsesInterpolantMapper() || !view->Render())
  {
    std::cerr << "vtkRadiosityView did not take the Gouraud path\n";
    return false;
  }
  const double flat = ReadPixels(view->GetRenderWindow())->GetComponent(pixel, 0);
  const double corner = Displayed(scene[0].Radiosity(0, 0)[0] / vtkMath::Pi() * 0.25, 0);
  const double top = Displayed(scene[0].Radiosity(1.0 / 3, 1.0 / 3)[0] / vtkMath::Pi() * 0.25, 0);
  std::cout << "vtkRadiosityView at the left centroid, red: interpolants " << peak
            << " (expected " << top << "), Gouraud " << flat << " (corners " << corner << ")\n";
  if (std::abs(peak - top) > 3.0 || std::abs(flat - corner) > 3.0 || peak - flat < 40.0)
  {
    std::cerr << "The two paths of vtkRadiosityView do not show the interior peak as expected\n";
    return false;
  }

  // The view refuses what the mapper refuses, naming the array.
  return ViewRefusesSixComponents(view, input, "QuadraticInterpolant");
}
}

int TestQuadraticInterpolantMapper(int argc, char* argv[])
{
  // Mesa's llvmpipe raises SIGFPE when VTK's driver enables FP exceptions.
  vtkFloatingPointExceptions::Disable();

  if (!RefusesNullInput(vtkQuadraticInterpolantMapper::ValidateInput))
  {
    return EXIT_FAILURE;
  }

  // Defaults, clamping setters, PrintSelf.
  {
    vtkNew<vtkQuadraticInterpolantMapper> mapper;
    if (mapper->GetExposure() != 1.0 || mapper->GetGamma() != 2.2 ||
      mapper->GetToneMapping() != vtkQuadraticInterpolantMapper::CLAMP)
    {
      std::cerr << "Unexpected defaults: Exposure " << mapper->GetExposure() << ", Gamma "
                << mapper->GetGamma() << ", ToneMapping " << mapper->GetToneMapping() << "\n";
      return EXIT_FAILURE;
    }
    mapper->SetExposure(-2.0);
    mapper->SetGamma(0.0);
    mapper->SetToneMapping(7);
    if (mapper->GetExposure() != 0.0 || mapper->GetGamma() != 0.1 ||
      mapper->GetToneMapping() != vtkQuadraticInterpolantMapper::EXPONENTIAL)
    {
      std::cerr << "Exposure, Gamma or ToneMapping not clamped\n";
      return EXIT_FAILURE;
    }
    std::ostringstream printed;
    mapper->Print(printed);
    if (printed.str().find("Exposure: 0") == std::string::npos ||
      printed.str().find("ToneMapping: Exponential") == std::string::npos ||
      printed.str().find("InterpolantArrayName: QuadraticInterpolant") == std::string::npos)
    {
      std::cerr << "PrintSelf is missing properties:\n" << printed.str();
      return EXIT_FAILURE;
    }
  }

  const std::vector<Triangle> scene = MakeScene();
  vtkSmartPointer<vtkPolyData> input = MakePolyData(scene);

  vtkNew<vtkQuadraticInterpolantMapper> mapper;
  mapper->SetInputData(input);
  ToneMappedWindow view(mapper, 400, 300);
  vtkActor* actor = view.Actor;
  vtkRenderer* renderer = view.Renderer;
  vtkToneMappingPass* toneMapping = view.ToneMapping;
  vtkRenderWindow* window = view.Window;

  if (!TestInvalidInput(window, mapper, input))
  {
    return EXIT_FAILURE;
  }

  // Radiance below 1 everywhere (the largest B in the scene is under 11
  // W/m^2): with the Clamp operator the displayed value is L^(1/2.2) itself,
  // so the comparison is as sensitive as 8 bits allow.
  const double exposure = 0.25;
  mapper->SetExposure(exposure);
  toneMapping->SetToneMappingType(vtkToneMappingPass::Clamp);
  if (!CheckPerspectiveCorrectPixels(renderer, window, scene, exposure))
  {
    return EXIT_FAILURE;
  }

  // Surface with edges: VTK adds a geometry shader, which the barycentrics
  // pass through; away from the edges the pixels are unchanged.
  actor->GetProperty()->EdgeVisibilityOn();
  actor->GetProperty()->SetEdgeColor(1.0, 1.0, 1.0);
  window->Render();
  if (!CheckPixels(renderer, window, scene, exposure, vtkToneMappingPass::Clamp, 3.0, nullptr))
  {
    return EXIT_FAILURE;
  }
  actor->GetProperty()->EdgeVisibilityOff();

  // Wireframe (thin and wide lines) and points: one texel block per OpenGL
  // primitive, laid out through the cell-to-cell map; something is drawn.
  struct Representation
  {
    int Type;
    double Size;
    const char* Name;
  };
  const Representation representations[] = { { VTK_WIREFRAME, 1.0, "wireframe" },
    { VTK_WIREFRAME, 4.0, "wide wireframe" }, { VTK_POINTS, 5.0, "points" } };
  for (const Representation& r : representations)
  {
    actor->GetProperty()->SetRepresentation(r.Type);
    actor->GetProperty()->SetLineWidth(r.Size);
    actor->GetProperty()->SetPointSize(r.Size);
    window->Render();
    vtkSmartPointer<vtkUnsignedCharArray> pixels = ReadPixels(window);
    vtkIdType lit = 0;
    for (vtkIdType i = 0; i < pixels->GetNumberOfTuples(); ++i)
    {
      lit += (pixels->GetComponent(i, 0) + pixels->GetComponent(i, 1) +
               pixels->GetComponent(i, 2)) > 30.0
        ? 1
        : 0;
    }
    std::cout << r.Name << ": " << lit << " pixels drawn\n";
    if (lit < 15)
    {
      std::cerr << "Nothing drawn in the " << r.Name << " representation\n";
      return EXIT_FAILURE;
    }
  }
  actor->GetProperty()->SetRepresentationToSurface();
  actor->GetProperty()->SetLineWidth(1.0);
  actor->GetProperty()->SetPointSize(1.0);

  if (!TestView(input, scene))
  {
    return EXIT_FAILURE;
  }

  // The mapper's own operators (for a view without the pass; here the pass
  // clamps): on HDR radiance (up to about 3) they must give what the pass's
  // operators give.
  mapper->SetExposure(1.0);
  toneMapping->SetToneMappingType(vtkToneMappingPass::Clamp);
  for (int op : { vtkQuadraticInterpolantMapper::REINHARD, vtkQuadraticInterpolantMapper::EXPONENTIAL })
  {
    mapper->SetToneMapping(op);
    window->Render();
    if (!CheckPixels(renderer, window, scene, 1.0, op, 3.0, nullptr))
    {
      std::cerr << "(the mapper's tone mapping " << op << ")\n";
      return EXIT_FAILURE;
    }
  }
  mapper->SetToneMapping(vtkQuadraticInterpolantMapper::CLAMP);

  // The baseline: HDR radiance (up to about 3) through Reinhard.
  toneMapping->SetToneMappingType(vtkToneMappingPass::Reinhard);
  window->Render();
  if (!CheckPixels(renderer, window, scene, 1.0, vtkToneMappingPass::Reinhard, 3.0, nullptr))
  {
    return EXIT_FAILURE;
  }

  const int retVal = vtkRegressionTestImage(window);
  return !retVal;
}
