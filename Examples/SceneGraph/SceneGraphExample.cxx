// vtkRadiosityPass on an ordinary VTK scene: a room with a few shapes from
// VTK sources, a spot light and the sun as vtkLights, solved by radiosity
// and drawn per pixel, written as a PNG.
//
//   SceneGraphExample [OUT.png] [meshless|progressive|hierarchical|facecluster]
//
// Meshless by default (about 20 s on 2 loaded cores at 800 x 600;
// progressive and face cluster about 15 s, hierarchical with its
// discontinuity mesh about 3 minutes).
// Nothing here is radiosity-specific but the pass: the actors, properties,
// transforms, lights and camera are what any VTK application has.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkConeSource.h"
#include "vtkCubeSource.h"
#include "vtkCylinderSource.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiosityPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkWindowToImageFilter.h"

#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>

namespace
{
vtkActor* AddActor(vtkRenderer* renderer, vtkAlgorithm* source, double r, double g, double b)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkActor* actor = vtkActor::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  renderer->AddActor(actor);
  actor->Delete(); // the renderer keeps it
  return actor;
}

/// A wall from `origin` along p1 and p2 (facing along (p1 - o) x (p2 - o)).
void AddWall(vtkRenderer* renderer, const double o[3], const double p1[3], const double p2[3],
  double r, double g, double b)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(o[0], o[1], o[2]);
  plane->SetPoint1(p1[0], p1[1], p1[2]);
  plane->SetPoint2(p2[0], p2[1], p2[2]);
  plane->SetResolution(4, 4);
  AddActor(renderer, plane, r, g, b);
}

int MethodOf(const char* name)
{
  for (int m = vtkRadiosityFilter::Progressive; m <= vtkRadiosityFilter::FaceCluster; ++m)
  {
    if (std::strcmp(name, vtkRadiosityFilter::GetMethodName(m)) == 0)
    {
      return m;
    }
  }
  return -1;
}
}

int main(int argc, char* argv[])
{
  const std::string output = argc > 1 ? argv[1] : "scenegraph.png";
  const int method = argc > 2 ? MethodOf(argv[2]) : vtkRadiosityFilter::Meshless;
  if (method < 0)
  {
    std::cerr << "unknown method " << argv[2]
              << " (progressive, hierarchical, meshless or facecluster)\n";
    return 2;
  }

  vtkNew<vtkRenderer> renderer;
  renderer->AutomaticLightCreationOff(); // the scene's own lights, no headlight
  // The room, 4 m x 4 m x 2.6 m, open to the front and above (the sun comes in).
  const double o[3] = { -2, -2, 0 }, x[3] = { 2, -2, 0 }, y[3] = { -2, 2, 0 };
  AddWall(renderer, o, x, y, 0.8, 0.78, 0.72); // floor
  const double b0[3] = { -2, 2, 0 }, b1[3] = { 2, 2, 0 }, b2[3] = { -2, 2, 2.6 };
  AddWall(renderer, b0, b1, b2, 0.75, 0.75, 0.75); // back wall
  const double l0[3] = { -2, -2, 0 }, l1[3] = { -2, 2, 0 }, l2[3] = { -2, -2, 2.6 };
  AddWall(renderer, l0, l1, l2, 0.75, 0.3, 0.25); // left wall, red
  const double r0[3] = { 2, 2, 0 }, r1[3] = { 2, -2, 0 }, r2[3] = { 2, 2, 2.6 };
  AddWall(renderer, r0, r1, r2, 0.3, 0.6, 0.35); // right wall, green

  // A few shapes: a turned box, a sphere, a cylinder and a cone.
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(0.9);
  cube->SetYLength(0.9);
  cube->SetZLength(1.2);
  vtkActor* box = AddActor(renderer, cube, 0.85, 0.8, 0.7);
  box->SetPosition(0.8, 0.8, 0.6);
  box->RotateZ(25.0);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(-0.9, 0.2, 0.45);
  sphere->SetRadius(0.45);
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(12);
  AddActor(renderer, sphere, 0.3, 0.4, 0.85);
  vtkNew<vtkCylinderSource> cylinder;
  cylinder->SetRadius(0.25);
  cylinder->SetHeight(0.8);
  cylinder->SetResolution(16);
  vtkActor* column = AddActor(renderer, cylinder, 0.9, 0.75, 0.3);
  column->RotateX(90.0); // VTK's cylinder stands along y
  column->SetPosition(0.3, -0.8, 0.4);
  vtkNew<vtkConeSource> cone;
  cone->SetRadius(0.3);
  cone->SetHeight(0.7);
  cone->SetResolution(16);
  vtkActor* top = AddActor(renderer, cone, 0.8, 0.8, 0.8);
  top->RotateY(-90.0); // pointing up
  top->SetPosition(-0.6, -1.0, 0.35);

  // A spot from the ceiling's height and the sun (directional, from the front right).
  vtkNew<vtkLight> spot;
  spot->SetLightTypeToSceneLight();
  spot->SetPositional(true);
  spot->SetPosition(-0.3, 0.3, 2.5);
  spot->SetFocalPoint(-0.3, 0.3, 0.0);
  spot->SetConeAngle(45.0);
  spot->SetColor(1.0, 0.9, 0.75);
  spot->SetIntensity(4.0);
  renderer->AddLight(spot);
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(3.0, -4.0, 5.0);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  sun->SetIntensity(0.5);
  renderer->AddLight(sun);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, -6.5, 2.2);
  camera->SetFocalPoint(0.0, 0.3, 0.9);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetViewAngle(45.0);
  renderer->ResetCameraClippingRange();

  // The one radiosity-specific line: the pass, with its method.
  vtkNew<vtkRadiosityPass> pass;
  pass->SetMethod(method);
  renderer->SetPass(pass);

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(800, 600);
  window->AddRenderer(renderer);
  window->Render();
  if (!pass->HasSolution())
  {
    std::cerr << "the scene was not solved\n";
    return 1;
  }
  std::cout << vtkRadiosityFilter::GetMethodName(method) << ": "
            << pass->GetFilter()->GetScene().Triangles.size() << " triangles, "
            << pass->GetFilter()->GetStatistics().SolveSeconds << " s\n";

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(output.c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  std::cout << "wrote " << output << "\n";
  return 0;
}
