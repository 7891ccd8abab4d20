// Frame rates of the project's displays (issue 22's render bench): frames
// per second and milliseconds per frame at 640 x 480, 1280 x 720 and
// 1920 x 1080 along a camera path, for
//   - the quadratic interpolant mapper on hierarchical radiosity's
//     discontinuity mesh (port 1),
//   - the vector irradiance mapper on face cluster radiosity's surface,
//   - the splat mapper on meshless radiosity's Shepard field (SURFACE_TEXELS,
//     its default),
//   - the irradiance samples mapper on progressive radiosity's elements (on
//     the bunny room face cluster radiosity's triangles, their samples),
//   - the Gouraud path: the point array `Radiosity` drawn by VTK's polydata
//     mapper (progressive radiosity's; on the bunny room face cluster
//     radiosity's, progressive radiosity not being run on 1.5M triangles),
//   - vtkRadiosityPass (face cluster radiosity) on the scene as actors,
// on the Cornell box, the office and, for the displays of the methods that
// solve it, the 1.5M-triangle bunny room. The five mappers are set up by
// vtkRadiosityPassDisplay, as the pass draws them (Reinhard, back faces
// culled), each alone in a renderer.
//
// Each scene is solved once per method (the solve's seconds reported, not
// part of any frame); then at each size a warm-up frame at the path's start
// and the path's frames, each timed from the camera move to the end of the
// drawing (Render() then WaitForCompletion(), i.e. glFinish): the camera
// moves 30% of the way to the focal point and back while it turns 15
// degrees left and right and 5 degrees up and down, ending where it
// started.
//
//   bench_render <output dir> [--quick] [--bunny index.js] [--frames N] [--png dir]
//                [--scene cornell|office|bunny]   (--scene: that scene alone)
//                [--culling]
//
// --culling: the splat mapper's exact per-pixel splats (Evaluation SPLATS)
// alone, without culling, with the view frustum's and with the frustum's
// and the occlusion queries' (Lehtinen et al. 2007, 6.2), on the Cornell
// box, the Cornell box from close in front of the tall block, and the
// office; 640 x 480 and 1280 x 720 only, 10 frames a size (--frames N), the
// fraction of the field's points culled averaged over the path; written to
// <output dir>/render-culling.md.
//
// Writes <output dir>/render.md. 60 frames a size, 30 on the bunny room
// (--frames: N everywhere). Quick (CI): the Cornell box only, 3 frames a
// size. --png writes each display's last 640 x 480 frame. Run under a
// display (Xvfb: llvmpipe); without one it says so and exits 77.
#include "BenchArguments.h"
#include "BenchRenderSupport.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRadiosityCellTexelMapper.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiosityPass.h"
#include "vtkRadiosityPassDisplay.h"
#include "vtkRadiositySceneConverter.h"
#include "vtkRadiosityView.h"
#include "vtkRadiosityWindowPNG.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShepardSplatMapper.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include "Radiosity/Scenes/BunnyScene.h"
#include "Radiosity/Scenes/OfficeScene.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iomanip>
#include <map>
#include <numeric>
#include <sstream>
#include <vector>

namespace
{
constexpr int Sizes[3][2] = { { 640, 480 }, { 1280, 720 }, { 1920, 1080 } };

enum Kind
{
  Interpolants,
  VectorIrradiance,
  Splats,
  Samples,
  Gouraud,
  Pass,
  ExactSplats ///< SPLATS, with Display::Culling
};

enum CullingMode
{
  NoCulling,
  FrustumCulling,
  OcclusionCulling
};

struct Display
{
  Kind Which;
  const char* Name;
  const char* Path; ///< vtkRadiosityPassDisplay::GetPathName of its actor
  int Method;       ///< the method whose solution it draws
  int BigMethod;    ///< on the big scene; -1: not run there
  int Culling = -1; ///< ExactSplats: a CullingMode
};

const Display Displays[] = {
  { Interpolants, "quadratic interpolants", "interpolants", vtkRadiosityFilter::Hierarchical, -1 },
  { VectorIrradiance, "vector irradiance", "vector irradiance", vtkRadiosityFilter::FaceCluster,
    vtkRadiosityFilter::FaceCluster },
  { Splats, "Shepard splats", "splats", vtkRadiosityFilter::Meshless, vtkRadiosityFilter::Meshless },
  { Samples, "element samples", "irradiance samples", vtkRadiosityFilter::Progressive,
    vtkRadiosityFilter::FaceCluster },
  { Gouraud, "Gouraud", "radiosity per vertex", vtkRadiosityFilter::Progressive,
    vtkRadiosityFilter::FaceCluster },
  { Pass, "vtkRadiosityPass", "vector irradiance", vtkRadiosityFilter::FaceCluster,
    vtkRadiosityFilter::FaceCluster },
};

const Display CullingDisplays[] = {
  { ExactSplats, "SPLATS, no culling", "splats", vtkRadiosityFilter::Meshless,
    vtkRadiosityFilter::Meshless, NoCulling },
  { ExactSplats, "SPLATS, frustum", "splats", vtkRadiosityFilter::Meshless,
    vtkRadiosityFilter::Meshless, FrustumCulling },
  { ExactSplats, "SPLATS, frustum + occlusion", "splats", vtkRadiosityFilter::Meshless,
    vtkRadiosityFilter::Meshless, OcclusionCulling },
};

struct SceneCase
{
  std::string Name;
  std::function<radiosity::Scene()> Make;
  bool Big;   ///< only the displays with a BigMethod
  int Frames; ///< of the path at each size
  double Position[3], Focal[3], Up[3], ViewAngle, Exposure;
};

/// The camera at t in [0, 1] along the path (t = 0 and 1: the scene's view).
void PlaceCamera(vtkCamera* camera, const SceneCase& s, double t)
{
  const double forward = 0.3 * std::sin(radiosity::Pi * t);
  double p[3], f[3];
  for (int k = 0; k < 3; ++k)
  {
    const double step = forward * (s.Focal[k] - s.Position[k]);
    p[k] = s.Position[k] + step;
    f[k] = s.Focal[k] + step;
  }
  camera->SetPosition(p);
  camera->SetFocalPoint(f);
  camera->SetViewUp(s.Up);
  camera->SetViewAngle(s.ViewAngle);
  camera->Yaw(15.0 * std::sin(2.0 * radiosity::Pi * t));
  camera->Pitch(5.0 * std::sin(4.0 * radiosity::Pi * t));
  camera->OrthogonalizeViewUp();
}

/// The fraction of the window's pixels brighter than 8 of 255 in some channel.
double LitFraction(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkUnsignedCharArray* rgb =
    vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
  if (!rgb || rgb->GetNumberOfTuples() == 0)
  {
    return 0.0;
  }
  vtkIdType lit = 0;
  const unsigned char* v = rgb->GetPointer(0);
  for (vtkIdType i = 0; i < rgb->GetNumberOfTuples(); ++i, v += 3)
  {
    lit += std::max({ v[0], v[1], v[2] }) > 8 ? 1 : 0;
  }
  return static_cast<double>(lit) / static_cast<double>(rgb->GetNumberOfTuples());
}

struct Solved
{
  vtkSmartPointer<vtkRadiosityFilter> Filter;
  double Seconds = 0.0;
};

/// One scene's input and its solutions by method, each solved once.
class Solutions
{
public:
  explicit Solutions(const radiosity::Scene& scene)
    : Scene(scene)
    , Input(vtkRadiositySceneConverter::FromScene(scene))
  {
  }

  /// Null (with `error`) when the solve failed.
  const Solved* Get(int method, std::string& error)
  {
    auto found = this->ByMethod.find(method);
    if (found != this->ByMethod.end())
    {
      return &found->second;
    }
    Solved s;
    s.Filter = vtkSmartPointer<vtkRadiosityFilter>::New();
    s.Filter->SetMethod(method);
    s.Filter->SetInputData(this->Input);
    s.Filter->SetSceneLights(this->Scene.Lighting);
    const bench::Clock::time_point start = bench::Clock::now();
    s.Filter->Update();
    s.Seconds = bench::Since(start);
    if (!s.Filter->GetLastError().empty())
    {
      error = s.Filter->GetLastError();
      return nullptr;
    }
    return &(this->ByMethod[method] = s);
  }

  const radiosity::Scene& Scene;
  vtkSmartPointer<vtkPolyData> Input; ///< the materials, for Specular
  std::map<int, Solved> ByMethod;
};

struct SizeRow
{
  int Width = 0, Height = 0, Frames = 0;
  double Warmup = 0.0, Median = 0.0, Mean = 0.0, Worst = 0.0, Lit = 0.0;
  double Culled = 0.0, Occluded = 0.0; ///< ExactSplats: mean fractions of the points
};

struct Row
{
  std::string Scene, Display, Method;
  std::size_t Triangles = 0;
  double Solve = 0.0;     ///< the filter's solve; the pass: its first image (gather, solve, draw)
  double FirstDraw = 0.0; ///< the first frame at 640 x 480 (uploads, shaders, texels)
  int Solves = 0;         ///< the pass's solves over every frame
  SizeRow Sizes[3];
};

/// Sets `window` up for display `d` of the scene (a solution drawn by
/// `display`, or the pass on the scene's actors). False with `error` when
/// the solve failed or drew through another path.
bool SetUp(const Display& d, int method, const SceneCase& sc, Solutions& solutions,
  vtkRenderer* ren, vtkRadiosityPassDisplay* display, vtkRadiosityPass* pass, Row& row,
  std::string& error)
{
  row.Method = vtkRadiosityFilter::GetMethodName(method);
  if (d.Which == Pass)
  {
    pass->SetMethod(method);
    pass->SetExposure(sc.Exposure);
    pass->SetToneMapping(vtkRadiosityCellTexelMapper::REINHARD);
    bench::SetUpPass(ren, pass, solutions.Scene);
    return true;
  }
  const Solved* solved = solutions.Get(method, error);
  if (!solved)
  {
    return false;
  }
  row.Solve = solved->Seconds;
  vtkPolyData* surface = solved->Filter->GetOutput(0);
  vtkPolyData* product = solved->Filter->GetOutput(1);
  vtkNew<vtkPolyData> vertices;
  if (d.Which == Gouraud || d.Which == Samples)
  {
    // No product, no irradiance vectors; Gouraud: the point array Radiosity
    // only, no samples either.
    vertices->ShallowCopy(surface);
    vertices->GetPointData()->RemoveArray("IrradianceVector");
    if (d.Which == Gouraud)
    {
      vertices->GetCellData()->RemoveArray("IrradianceSamples");
    }
    surface = vertices;
    product = nullptr;
  }
  display->SetExposure(sc.Exposure);
  display->SetToneMapping(vtkRadiosityCellTexelMapper::REINHARD);
  if (!display->SetSolution(surface, product, solutions.Input, error))
  {
    return false;
  }
  if (std::string(display->GetPathName()) != d.Path)
  {
    error = std::string("drawn by the path '") + display->GetPathName() + "', not '" + d.Path + "'";
    return false;
  }
  ren->AddActor(display->GetActor());
  if (d.Which == ExactSplats)
  {
    vtkShepardSplatMapper* splats = display->GetSplatMapper();
    splats->SetEvaluationToSplats();
    splats->SetCulling(d.Culling != NoCulling);
    splats->SetOcclusionQueries(d.Culling == OcclusionCulling);
  }
  return true;
}

bool Run(const Display& d, int method, const SceneCase& sc, Solutions& solutions, int frames,
  int sizes, const std::string& pngDir, Row& row, std::string& gl, std::string& error)
{
  row.Scene = sc.Name;
  row.Display = d.Name;
  row.Triangles = solutions.Scene.Triangles.size();
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(0.0, 0.0, 0.0);
  window->AddRenderer(ren);
  vtkNew<vtkRadiosityPassDisplay> display;
  vtkNew<vtkRadiosityPass> pass;
  if (!SetUp(d, method, sc, solutions, ren, display, pass, row, error))
  {
    return false;
  }
  vtkCamera* camera = ren->GetActiveCamera();
  for (int s = 0; s < sizes; ++s)
  {
    SizeRow& out = row.Sizes[s];
    out.Width = Sizes[s][0];
    out.Height = Sizes[s][1];
    out.Frames = frames;
    window->SetSize(out.Width, out.Height);
    PlaceCamera(camera, sc, 0.0);
    ren->ResetCameraClippingRange();
    out.Warmup = bench::TimedRender(window);
    if (s == 0)
    {
      row.FirstDraw = out.Warmup;
      gl = bench::GlRenderer(window);
      if (d.Which == Pass)
      {
        row.Solve = out.Warmup;
        if (std::string(pass->GetDisplay()->GetPathName()) != d.Path)
        {
          error = std::string("the pass drew through '") + pass->GetDisplay()->GetPathName() + "'";
          return false;
        }
      }
    }
    std::vector<double> times;
    vtkShepardSplatMapper* splats = display->GetSplatMapper();
    for (int i = 1; i <= frames; ++i)
    {
      const bench::Clock::time_point start = bench::Clock::now();
      PlaceCamera(camera, sc, static_cast<double>(i) / frames);
      ren->ResetCameraClippingRange();
      window->Render();
      window->WaitForCompletion();
      times.push_back(bench::Since(start));
      if (d.Which == ExactSplats)
      {
        const double all = static_cast<double>(splats->GetNumberOfSplattedPoints() +
          splats->GetNumberOfFrustumCulledPoints() + splats->GetNumberOfOcclusionCulledPoints());
        out.Culled += (1.0 - splats->GetNumberOfSplattedPoints() / std::max(1.0, all)) / frames;
        out.Occluded += splats->GetNumberOfOcclusionCulledPoints() / std::max(1.0, all) / frames;
      }
    }
    out.Mean = std::accumulate(times.begin(), times.end(), 0.0) / times.size();
    std::sort(times.begin(), times.end());
    out.Median = times.size() % 2 ? times[times.size() / 2]
                                  : 0.5 * (times[times.size() / 2 - 1] + times[times.size() / 2]);
    out.Worst = times.back();
    out.Lit = LitFraction(window);
    const int* size = window->GetSize();
    if (size[0] != out.Width || size[1] != out.Height)
    {
      error = "the window is " + std::to_string(size[0]) + " x " + std::to_string(size[1]);
      return false;
    }
    std::cout << sc.Name << ", " << d.Name << " (" << row.Method << "), " << out.Width << " x "
              << out.Height << ": " << std::fixed << std::setprecision(1) << 1e3 * out.Median
              << " ms median, " << 1e3 * out.Mean << " mean, " << 1e3 * out.Worst << " worst, "
              << 1.0 / out.Mean << " fps, " << std::setprecision(0) << 100.0 * out.Lit << "% lit";
    if (d.Which == ExactSplats)
    {
      std::cout << ", " << std::setprecision(1) << 100.0 * out.Culled << "% of the points culled ("
                << 100.0 * out.Occluded << "% by occlusion)";
    }
    std::cout << std::defaultfloat << std::endl;
    if (s == 0 && !pngDir.empty())
    {
      std::string name = sc.Name + "-" + d.Name + ".png";
      std::replace(name.begin(), name.end(), ' ', '_');
      std::string pngError;
      if (!vtkRadiosityWriteWindowPNG(window, (pngDir + "/" + name).c_str(), pngError))
      {
        std::cerr << pngError << std::endl;
      }
    }
  }
  row.Solves = d.Which == Pass ? pass->GetNumberOfSolves() : 0;
  return true;
}

std::string LoadAverage()
{
  std::ifstream in("/proc/loadavg");
  std::string one, five, fifteen;
  in >> one >> five >> fifteen;
  return one.empty() ? "(unknown)" : one + " " + five + " " + fifteen;
}

void WriteMarkdown(std::ostream& md, const BenchArguments& args, const std::vector<Row>& rows,
  const std::string& gl, const std::string& command, const std::string& loadBefore,
  const std::string& loadAfter, double seconds, bool culling)
{
  args.WriteHeading(md,
    culling ? "Frame rates of the splat mapper's exact splats, with and without culling"
            : "Frame rates of the displays along a camera path");
  md << "OpenGL renderer:" << gl << ". Load average (1, 5, 15 min) " << loadBefore
     << " at the start, " << loadAfter << " at the end; " << std::fixed << std::setprecision(0)
     << seconds << " s in all. Command: `" << command << "`.\n\n";
  md << "A frame: the camera moved along the path, `Render()`, `WaitForCompletion()` (glFinish),"
     << " on an X window (Xvfb) without multisampling; each size starts with an untimed frame. fps"
     << " = 1000 / mean ms. Lit: the pixels of the last frame (the path's start) above 8/255.\n\n";
  md << "| scene | display | 640 x 480 fps | 1280 x 720 fps | 1920 x 1080 fps |"
     << (culling ? " culled (occluded) at 640 x 480 |\n|---|---|---|---|---|---|\n"
                 : "\n|---|---|---|---|---|\n");
  for (const Row& r : rows)
  {
    md << "| " << r.Scene << " | " << r.Display << " |";
    for (const SizeRow& s : r.Sizes)
    {
      if (s.Frames == 0)
      {
        md << " - |";
        continue;
      }
      md << " " << std::setprecision(s.Mean > 0.1 ? 2 : 1) << 1.0 / s.Mean << " |";
    }
    if (culling)
    {
      md << " " << std::setprecision(1) << 100.0 * r.Sizes[0].Culled << "% ("
         << 100.0 * r.Sizes[0].Occluded << "%) |";
    }
    md << "\n";
  }
  md << "\n| scene | triangles | display | method | solve (s) | first draw (s) | size | frames |"
     << " median (ms) | mean (ms) | worst (ms) | fps | lit |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows)
  {
    for (const SizeRow& s : r.Sizes)
    {
      if (s.Frames == 0)
      {
        continue;
      }
      md << "| " << r.Scene << " | " << r.Triangles << " | " << r.Display << " | " << r.Method
         << " | " << std::setprecision(2) << r.Solve << " | " << r.FirstDraw << " | " << s.Width
         << " x " << s.Height << " | " << s.Frames << " | " << std::setprecision(1) << 1e3 * s.Median
         << " | " << 1e3 * s.Mean << " | " << 1e3 * s.Worst << " | " << std::setprecision(s.Mean > 0.1 ? 2 : 1)
         << 1.0 / s.Mean << " | " << std::setprecision(0) << 100.0 * s.Lit << "% |\n";
    }
  }
  md << std::defaultfloat << "\nSolve: vtkRadiosityFilter's `Update()` at the method's defaults"
     << " (one per scene and method, shared by the displays of that method); for vtkRadiosityPass"
     << " its first image (the actors gathered, solved, drawn at 640 x 480). First draw: the first"
     << " frame at 640 x 480 (buffers, shaders, the splat mapper's surface texels).";
  bool passSolvedOnce = true;
  for (const Row& r : rows)
  {
    passSolvedOnce = passSolvedOnce && (r.Display != "vtkRadiosityPass" || r.Solves == 1);
  }
  md << (passSolvedOnce ? " The pass solved once per scene over all its frames.\n" : "\n");
}
}

int main(int argc, char* argv[])
{
  BenchArguments args;
  if (!args.Parse(argc, argv))
  {
    return 2;
  }
  int frames = 0; // each scene's own

  std::string pngDir, only;
  bool culling = false;
  std::string command = "bench_render";
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    command += " " + a;
    if (a == "--frames" && i + 1 < argc)
    {
      frames = std::max(1, std::atoi(argv[i + 1]));
    }
    else if (a == "--png" && i + 1 < argc)
    {
      pngDir = argv[i + 1];
    }
    else if (a == "--scene" && i + 1 < argc)
    {
      only = argv[i + 1];
    }
    else if (a == "--culling")
    {
      culling = true;
    }
  }
  std::string why;
  if (!vtkRadiosityView::CanOpenWindow(why))
  {
    std::cerr << "bench_render: " << why << std::endl;
    return 77;
  }
  std::vector<SceneCase> scenes;
  const radiosity::CornellCamera cornell;
  scenes.push_back({ "cornell", [] { return radiosity::MakeCornellBox(); }, false, args.Quick ? 3 : 60,
    { cornell.Position[0], cornell.Position[1], cornell.Position[2] }, { 0.278, 0.273, 0.28 },
    { 0, 1, 0 }, cornell.ViewAngle, 1.0 });
  if (culling)
  {
    // In front of the tall block, looking at the back wall past it.
    scenes.push_back({ "cornell close-up", [] { return radiosity::MakeCornellBox(); }, false,
      args.Quick ? 3 : 10, { 0.37, 0.17, 0.08 }, { 0.37, 0.17, 0.559 }, { 0, 1, 0 }, 50.0, 1.0 });
    scenes.front().Frames = args.Quick ? 3 : 10;
  }
  if (!args.Quick)
  {
    scenes.push_back({ "office", [] { return radiosity::MakeOfficeScene(); }, false, 60,
      { 4.6, 3.7, 1.7 }, { 1.5, 0.3, 1.1 }, { 0, 0, 1 }, 60.0, 0.02 });
    if (!args.BunnyJs.empty())
    {
      const std::string js = args.BunnyJs;
      scenes.push_back({ "bunny room",
        [js] { return radiosity::MakeBunnyRoomWithTriangles(radiosity::ReadNpmBunny(js), 1500000); },
        true, 30, { 1.8, 1.1, 0.2 }, { 1.0, 0.25, 1.0 }, { 0, 1, 0 }, 60.0, 1.0 });
    }
  }
  const std::string loadBefore = LoadAverage();
  const bench::Clock::time_point start = bench::Clock::now();
  std::vector<Row> rows;
  std::string gl;
  for (const SceneCase& sc : scenes)
  {
    if (!only.empty() && sc.Name.compare(0, only.size(), only) != 0)
    {
      continue;
    }
    const radiosity::Scene scene = sc.Make();
    Solutions solutions(scene);
    std::vector<Display> displays(std::begin(Displays), std::end(Displays));
    if (culling)
    {
      displays.assign(std::begin(CullingDisplays), std::end(CullingDisplays));
    }
    for (const Display& d : displays)
    {
      const int method = sc.Big ? d.BigMethod : d.Method;
      if (method < 0)
      {
        continue;
      }
      Row row;
      std::string error;
      // The exact splats take seconds a frame on llvmpipe: two sizes.
      const int sceneFrames = culling && sc.Name == "office" ? 10 : sc.Frames;
      if (!Run(d, method, sc, solutions, frames > 0 ? frames : sceneFrames, culling ? 2 : 3, pngDir,
            row, gl, error))
      {
        std::cerr << "bench_render: " << sc.Name << ", " << d.Name << ": " << error << std::endl;
        return 1;
      }
      rows.push_back(row);
    }
  }
  std::ofstream md(args.Directory + (culling ? "/render-culling.md" : "/render.md"));
  WriteMarkdown(
    md, args, rows, gl, command, loadBefore, LoadAverage(), bench::Since(start), culling);
  return md ? 0 : 1;
}
