// What the render benchmarks (bench_pass, bench_render) share: a scene as
// actors for vtkRadiosityPass (one actor per object, its lights as vtkLights
// and its sky as the pass's), and the OpenGL renderer string of a window.
#ifndef BenchRenderSupport_h
#define BenchRenderSupport_h

#include "vtkActor.h"
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

#include "Radiosity/Common/Scene.h"

#include <algorithm>
#include <chrono>
#include <sstream>
#include <string>
#include <vector>

namespace bench
{
using Clock = std::chrono::steady_clock;

/// Seconds since `start`.
inline double Since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Seconds of one `Render()` of `window` until its drawing completed (glFinish).
inline double TimedRender(vtkRenderWindow* window)
{
  const Clock::time_point start = Clock::now();
  window->Render();
  window->WaitForCompletion();
  return Since(start);
}

/// One actor per object of `scene`: its triangles, DiffuseColor its
/// reflectance, an `Emission` cell array where it emits.
inline void AddActors(vtkRenderer* renderer, const radiosity::Scene& scene)
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

/// `scene` on `renderer` for `pass`: its objects as actors (AddActors), its
/// spot and point lights as scene vtkLights (Intensity in W/sr: LightScale
/// 1), its CIE overcast sky as the pass's; the pass set on the renderer.
inline void SetUpPass(vtkRenderer* renderer, vtkRadiosityPass* pass, const radiosity::Scene& scene)
{
  AddActors(renderer, scene);
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
    renderer->AddLight(light);
  }
  if (scene.Lighting.SkyLight.Enabled())
  {
    const radiosity::Sky& sky = scene.Lighting.SkyLight;
    pass->SetSkyModel(vtkRadiosityFilter::SkyCieOvercast);
    pass->SetSkyRadiance(sky.Radiance.r, sky.Radiance.g, sky.Radiance.b);
    pass->SetSkyUp(sky.Up.x, sky.Up.y, sky.Up.z);
  }
  renderer->SetPass(pass);
}

/// The "OpenGL renderer string" of `window`'s capabilities (after a render).
inline std::string GlRenderer(vtkRenderWindow* window)
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
} // namespace bench

#endif
