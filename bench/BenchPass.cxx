// vtkRadiosityPass on an ordinary renderer (issue 18's bench): the time to
// the first image (the scene gathered from the actors, solved, drawn) and
// the time per redraw after a camera move (no solve), at 1280 x 720, on the
// office (its spot as a vtkLight, the CIE overcast sky as the pass's) and on
// the 1.5M-triangle bunny room (its ceiling light as an `Emission` array).
// Each scene's objects become actors with vtkProperty colours; nothing here
// is radiosity-specific but the pass.
//
//   bench_pass <output dir> [--quick] [--bunny index.js]
//
// Writes <output dir>/pass.md. Quick: the office by meshless and
// progressive only. Run under a display (Xvfb: llvmpipe).
#include "BenchArguments.h"
#include "BenchRenderSupport.h"

#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiosityPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include "Radiosity/Scenes/BunnyScene.h"
#include "Radiosity/Scenes/OfficeScene.h"

#include <algorithm>
#include <fstream>
#include <functional>
#include <iomanip>
#include <vector>

namespace
{
struct Case
{
  std::string Scene;
  std::function<radiosity::Scene()> Make;
  int Method;
  double Position[3], Focal[3], Up[3];
};

struct Row
{
  std::string Scene, Method;
  std::size_t Triangles = 0;
  double FirstImage = 0.0, MedianRedraw = 0.0, WorstRedraw = 0.0;
  int Solves = 0;
};

Row Run(const Case& c, std::string& renderer)
{
  const radiosity::Scene scene = c.Make();
  vtkNew<vtkRenderWindow> window;
  window->SetSize(1280, 720);
  window->SetMultiSamples(0);
  vtkNew<vtkRenderer> ren;
  window->AddRenderer(ren);
  vtkNew<vtkRadiosityPass> pass;
  pass->SetMethod(c.Method);
  bench::SetUpPass(ren, pass, scene);
  vtkCamera* camera = ren->GetActiveCamera();
  camera->SetPosition(c.Position);
  camera->SetFocalPoint(c.Focal);
  camera->SetViewUp(c.Up);
  camera->SetViewAngle(60.0);
  ren->ResetCameraClippingRange();

  Row row;
  row.Scene = c.Scene;
  row.Method = vtkRadiosityFilter::GetMethodName(c.Method);
  row.Triangles = scene.Triangles.size();
  row.FirstImage = bench::TimedRender(window);
  renderer = bench::GlRenderer(window);
  std::vector<double> redraws;
  for (int i = 0; i < 30; ++i)
  {
    camera->Azimuth(1.0);
    ren->ResetCameraClippingRange();
    redraws.push_back(bench::TimedRender(window));
  }
  std::sort(redraws.begin(), redraws.end());
  row.MedianRedraw = redraws[redraws.size() / 2];
  row.WorstRedraw = redraws.back();
  row.Solves = pass->GetNumberOfSolves();
  std::cout << std::flush << row.Scene << " " << row.Method << ": first image " << row.FirstImage << " s, redraw "
            << 1e3 * row.MedianRedraw << " ms (worst " << 1e3 * row.WorstRedraw << "), " << row.Solves
            << " solve(s)" << std::endl;
  return row;
}
}

int main(int argc, char* argv[])
{
  BenchArguments args;
  if (!args.Parse(argc, argv))
  {
    return 2;
  }
  const auto office = [] { return radiosity::MakeOfficeScene(); };
  std::vector<Case> cases;
  const std::vector<int> officeMethods = args.Quick
    ? std::vector<int>{ vtkRadiosityFilter::Meshless, vtkRadiosityFilter::Progressive }
    : std::vector<int>{ vtkRadiosityFilter::Meshless, vtkRadiosityFilter::Progressive,
        vtkRadiosityFilter::FaceCluster, vtkRadiosityFilter::Hierarchical };
  for (int method : officeMethods)
  {
    cases.push_back({ "office", office, method, { 4.6, 3.7, 1.7 }, { 1.5, 0.3, 1.1 }, { 0, 0, 1 } });
  }
  if (!args.Quick && !args.BunnyJs.empty())
  {
    const std::string js = args.BunnyJs;
    const auto bunny = [js] { return radiosity::MakeBunnyRoomWithTriangles(radiosity::ReadNpmBunny(js), 1500000); };
    for (int method : { vtkRadiosityFilter::FaceCluster, vtkRadiosityFilter::Meshless })
    {
      cases.push_back({ "bunny room", bunny, method, { 1.8, 1.1, 0.2 }, { 1.0, 0.25, 1.0 }, { 0, 1, 0 } });
    }
  }
  std::vector<Row> rows;
  std::string gl;
  for (const Case& c : cases)
  {
    rows.push_back(Run(c, gl));
  }
  std::ofstream md(args.Directory + "/pass.md");
  args.WriteHeading(md, "vtkRadiosityPass: time to the first image and per redraw");
  md << "OpenGL renderer:" << gl << ". Window 1280 x 720. First image: the first `Render()` of a"
     << " renderer with the pass (the actors gathered through the scene graph, the solve at the"
     << " method's defaults, the first draw; `WaitForCompletion`). Redraw: 30 renders, each after"
     << " a 1 degree azimuth of the camera (no solve: the solves column stays 1).\n\n";
  md << "| scene | triangles | method | first image (s) | redraw median (ms) | redraw worst (ms) | solves |\n"
     << "|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows)
  {
    md << "| " << r.Scene << " | " << r.Triangles << " | " << r.Method << " | " << std::fixed
       << std::setprecision(2) << r.FirstImage << " | " << std::setprecision(1) << 1e3 * r.MedianRedraw
       << " | " << 1e3 * r.WorstRedraw << " | " << r.Solves << " |\n";
    md.unsetf(std::ios::fixed);
  }
  return 0;
}
