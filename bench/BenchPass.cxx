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

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiosityPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include "Radiosity/Scenes/BunnyScene.h"
#include "Radiosity/Scenes/OfficeScene.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <functional>
#include <iomanip>
#include <sstream>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

double Since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// One actor per object of `scene`: its triangles, DiffuseColor its
/// reflectance, an `Emission` cell array where it emits.
void AddActors(vtkRenderer* renderer, const radiosity::Scene& scene)
{
  const int objects = static_cast<int>(std::max<std::size_t>(1, scene.ObjectNames.size()));
  for (int object = 0; object < objects; ++object)
  {
    std::vector<vtkIdType> remap(scene.Points.size(), -1);
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    vtkNew<vtkCellArray> triangles;
    vtkNew<vtkDoubleArray> emission;
    emission->SetName("Emission");
    emission->SetNumberOfComponents(3);
    bool emits = false;
    radiosity::RGB colour(0.0);
    for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
    {
      if (scene.ObjectIds[t] != object)
      {
        continue;
      }
      vtkIdType ids[3];
      for (int k = 0; k < 3; ++k)
      {
        const std::uint32_t v = scene.Triangles[t].V[k];
        if (remap[v] < 0)
        {
          const radiosity::Vec3& p = scene.Points[v];
          remap[v] = points->InsertNextPoint(p.x, p.y, p.z);
        }
        ids[k] = remap[v];
      }
      triangles->InsertNextCell(3, ids);
      const radiosity::Material& m = scene.Materials[t];
      emission->InsertNextTuple3(m.Emission.r, m.Emission.g, m.Emission.b);
      emits = emits || radiosity::MaxComponent(m.Emission) > 0.0;
      colour = m.Reflectance;
    }
    if (triangles->GetNumberOfCells() == 0)
    {
      continue;
    }
    vtkNew<vtkPolyData> data;
    data->SetPoints(points);
    data->SetPolys(triangles);
    if (emits)
    {
      data->GetCellData()->AddArray(emission);
    }
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(data);
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(colour.r, colour.g, colour.b);
    renderer->AddActor(actor);
  }
}

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

std::string GlRenderer(vtkRenderWindow* window)
{
  std::istringstream in(window->ReportCapabilities());
  std::string line;
  while (std::getline(in, line))
  {
    if (line.find("OpenGL renderer string") != std::string::npos)
    {
      return line.substr(line.find(':') + 1);
    }
  }
  return " (unknown)";
}

Row Run(const Case& c, std::string& renderer)
{
  const radiosity::Scene scene = c.Make();
  vtkNew<vtkRenderWindow> window;
  window->SetSize(1280, 720);
  window->SetMultiSamples(0);
  vtkNew<vtkRenderer> ren;
  window->AddRenderer(ren);
  AddActors(ren, scene);
  vtkNew<vtkRadiosityPass> pass;
  pass->SetMethod(c.Method);
  pass->SetLightScale(1.0); // vtkLight Intensity in W/sr
  for (const radiosity::Light& l : scene.Lighting.Lights)
  {
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPositional(true);
    light->SetPosition(l.Position.x, l.Position.y, l.Position.z);
    const radiosity::Vec3 to = l.Position + l.Direction;
    light->SetFocalPoint(to.x, to.y, to.z);
    light->SetConeAngle(l.OuterConeAngle * 180.0 / radiosity::Pi);
    light->SetIntensity(l.Intensity.r);
    ren->AddLight(light);
  }
  if (scene.Lighting.SkyLight.Enabled())
  {
    const radiosity::Sky& sky = scene.Lighting.SkyLight;
    pass->SetSkyModel(vtkRadiosityFilter::SkyCieOvercast);
    pass->SetSkyRadiance(sky.Radiance.r, sky.Radiance.g, sky.Radiance.b);
    pass->SetSkyUp(sky.Up.x, sky.Up.y, sky.Up.z);
  }
  ren->SetPass(pass);
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
  const Clock::time_point start = Clock::now();
  window->Render();
  window->WaitForCompletion();
  row.FirstImage = Since(start);
  renderer = GlRenderer(window);
  std::vector<double> redraws;
  for (int i = 0; i < 30; ++i)
  {
    camera->Azimuth(1.0);
    ren->ResetCameraClippingRange();
    const Clock::time_point t = Clock::now();
    window->Render();
    window->WaitForCompletion();
    redraws.push_back(Since(t));
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
