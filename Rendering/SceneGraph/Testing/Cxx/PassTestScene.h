// The lit scene of the pass's tests, built from VTK sources: an open room
// (floor and two walls), a box moved and turned by its actor's transform, a
// sphere, a spot light from above and the sun through the open sides.
#ifndef PassTestScene_h
#define PassTestScene_h

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRadiosityPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"

#include <iostream>
#include <string>

namespace PassTestScene
{
struct Scene
{
  vtkSmartPointer<vtkActor> Floor, BackWall, LeftWall, Box, Ball;
  vtkSmartPointer<vtkSphereSource> BallSource;
  vtkSmartPointer<vtkLight> Spot, Sun;
};

inline vtkSmartPointer<vtkActor> Plane(vtkRenderer* renderer, const double origin[3],
  const double p1[3], const double p2[3], int resolution, double r, double g, double b)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(origin[0], origin[1], origin[2]);
  plane->SetPoint1(p1[0], p1[1], p1[2]);
  plane->SetPoint2(p2[0], p2[1], p2[2]);
  plane->SetResolution(resolution, resolution);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  renderer->AddActor(actor);
  return actor;
}

/// Builds the scene into `renderer` (scene lights only: no headlight).
inline Scene Build(vtkRenderer* renderer)
{
  Scene s;
  renderer->AutomaticLightCreationOff();
  const double floorOrigin[3] = { -2, -2, 0 }, floorP1[3] = { 2, -2, 0 }, floorP2[3] = { -2, 2, 0 };
  s.Floor = Plane(renderer, floorOrigin, floorP1, floorP2, 4, 0.8, 0.8, 0.8);
  // The walls face into the room (the right-hand normal of origin, p1, p2).
  const double backOrigin[3] = { -2, 2, 0 }, backP1[3] = { 2, 2, 0 }, backP2[3] = { -2, 2, 2.5 };
  s.BackWall = Plane(renderer, backOrigin, backP1, backP2, 3, 0.75, 0.35, 0.3);
  const double leftOrigin[3] = { -2, -2, 0 }, leftP1[3] = { -2, 2, 0 }, leftP2[3] = { -2, -2, 2.5 };
  s.LeftWall = Plane(renderer, leftOrigin, leftP1, leftP2, 3, 0.3, 0.65, 0.35);

  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(0.8);
  cube->SetYLength(0.8);
  cube->SetZLength(0.8);
  vtkNew<vtkPolyDataMapper> boxMapper;
  boxMapper->SetInputConnection(cube->GetOutputPort());
  s.Box = vtkSmartPointer<vtkActor>::New();
  s.Box->SetMapper(boxMapper);
  s.Box->SetPosition(0.8, 0.5, 0.4);
  s.Box->RotateZ(30.0);
  s.Box->GetProperty()->SetColor(0.85, 0.75, 0.3);
  renderer->AddActor(s.Box);

  s.BallSource = vtkSmartPointer<vtkSphereSource>::New();
  s.BallSource->SetCenter(-0.8, -0.4, 0.5);
  s.BallSource->SetRadius(0.5);
  s.BallSource->SetThetaResolution(12);
  s.BallSource->SetPhiResolution(8);
  vtkNew<vtkPolyDataMapper> ballMapper;
  ballMapper->SetInputConnection(s.BallSource->GetOutputPort());
  s.Ball = vtkSmartPointer<vtkActor>::New();
  s.Ball->SetMapper(ballMapper);
  s.Ball->GetProperty()->SetColor(0.35, 0.45, 0.85);
  renderer->AddActor(s.Ball);

  s.Spot = vtkSmartPointer<vtkLight>::New();
  s.Spot->SetLightTypeToSceneLight();
  s.Spot->SetPositional(true);
  s.Spot->SetPosition(0.2, 0.2, 2.4);
  s.Spot->SetFocalPoint(0.2, 0.2, 0.0);
  s.Spot->SetConeAngle(40.0);
  s.Spot->SetIntensity(4.0);
  renderer->AddLight(s.Spot);
  s.Sun = vtkSmartPointer<vtkLight>::New();
  s.Sun->SetLightTypeToSceneLight();
  s.Sun->SetPositional(false);
  s.Sun->SetPosition(2.0, -3.0, 4.0);
  s.Sun->SetFocalPoint(0.0, 0.0, 0.0);
  s.Sun->SetColor(1.0, 0.95, 0.85);
  s.Sun->SetIntensity(0.6);
  renderer->AddLight(s.Sun);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(3.6, -4.6, 3.0);
  camera->SetFocalPoint(-0.1, 0.3, 0.6);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetViewAngle(40.0);
  renderer->ResetCameraClippingRange();
  return s;
}

inline bool Check(bool ok, const std::string& what)
{
  if (!ok)
  {
    std::cerr << "FAILED: " << what << "\n";
  }
  return ok;
}

/// Renders `window`, adds `more` to `expected` and checks that the pass has
/// solved that many times in all and holds a solution.
inline bool RenderAndCountSolves(
  vtkRenderWindow* window, vtkRadiosityPass* pass, int& expected, int more, const std::string& what)
{
  window->Render();
  expected += more;
  const int solves = pass->GetNumberOfSolves();
  std::cout << what << ": " << solves << " solves (expected " << expected << ")\n";
  bool ok = Check(solves == expected,
    what + ": " + std::to_string(solves) + " solves, expected " + std::to_string(expected));
  ok &= Check(pass->HasSolution(), what + ": no solution");
  return ok;
}

/// Mean of the red, green and blue bytes of the window's left (half 0) or
/// right (half 1) half, each `width` x `height` pixels.
inline double MeanOfHalf(vtkRenderWindow* window, int half, int width, int height)
{
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetRGBACharPixelData(half * width, 0, half * width + width - 1, height - 1, 1, pixels);
  double sum = 0.0;
  for (vtkIdType i = 0; i < pixels->GetNumberOfTuples(); ++i)
  {
    sum += pixels->GetValue(4 * i) + pixels->GetValue(4 * i + 1) + pixels->GetValue(4 * i + 2);
  }
  return sum / (3.0 * pixels->GetNumberOfTuples());
}
}

#endif
