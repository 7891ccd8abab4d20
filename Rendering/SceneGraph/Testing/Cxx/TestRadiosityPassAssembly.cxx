// vtkRadiosityPass on the parts of a vtkAssembly (PassTestScene plus an
// assembly in the back-left corner; hierarchical radiosity for the image,
// then progressive at a loose tolerance for the count of solves):
// - world placement: a part is solved where vtkAssembly draws it, by its
//   path's matrix (the outer assembly moved and turned, a nested assembly
//   moved, each part moved): the bounds of the gathered objects equal the
//   corners worked out by hand below, to 1e-8 m (measured 3.0e-9:
//   vtkCubeSource's points are floats);
// - re-solves: a redraw and a camera move do not solve (the assembly's
//   translucent part is drawn with its path's matrix poked in at every
//   render, which moves its MTime and rebuilds the assembly's paths); the
//   outer assembly moved, the nested one moved, the outer one hidden (its
//   parts leave the solve), shown again: one solve each;
// - the translucent part's own matrix is restored after each draw;
// - the image against a baseline: the solid parts drawn by the solution
//   (lit by the spot, casting shadows on the floor and the wall), the red
//   translucent part drawn by VTK over them.
#include "PassTestScene.h"

#include "vtkActorCollection.h"
#include "vtkAssembly.h"
#include "vtkCompositeDataSet.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkInformation.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiosityPass.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

#include <cmath>
#include <string>

namespace
{
vtkSmartPointer<vtkActor> Cube(double side, double r, double g, double b)
{
  vtkNew<vtkCubeSource> source;
  source->SetXLength(side);
  source->SetYLength(side);
  source->SetZLength(side);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  return actor;
}

/// The gathered object of `actor` (the block named after its index among
/// the renderer's actors), or null when it was not gathered.
vtkPolyData* Gathered(vtkRadiosityPass* pass, vtkRenderer* renderer, vtkActor* actor)
{
  vtkActorCollection* actors = renderer->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  int index = 0;
  while (vtkActor* a = actors->GetNextActor(it))
  {
    if (a == actor)
    {
      break;
    }
    ++index;
  }
  const std::string label = "actor " + std::to_string(index) + " ";
  auto* scene = vtkMultiBlockDataSet::SafeDownCast(pass->GetFilter()->GetInputDataObject(0, 0));
  for (unsigned int b = 0; scene && b < scene->GetNumberOfBlocks(); ++b)
  {
    const char* name = scene->GetMetaData(b)->Get(vtkCompositeDataSet::NAME());
    if (name && std::string(name).rfind(label, 0) == 0)
    {
      return vtkPolyData::SafeDownCast(scene->GetBlock(b));
    }
  }
  return nullptr;
}

bool BoundsAre(vtkPolyData* object, const double expected[6], const std::string& what)
{
  if (!object)
  {
    return PassTestScene::Check(false, what + ": not gathered");
  }
  double bounds[6];
  object->GetBounds(bounds);
  double worst = 0.0;
  for (int i = 0; i < 6; ++i)
  {
    worst = std::max(worst, std::fabs(bounds[i] - expected[i]));
  }
  std::cout << what << ": bounds (" << bounds[0] << ", " << bounds[1] << ") (" << bounds[2] << ", "
            << bounds[3] << ") (" << bounds[4] << ", " << bounds[5] << "), largest difference "
            << worst << " m\n";
  return PassTestScene::Check(worst <= 1e-8, what + ": bounds off by " + std::to_string(worst * 1e9) + " nm");
}
}

int TestRadiosityPassAssembly(int argc, char* argv[])
{
  vtkFloatingPointExceptions::Disable(); // llvmpipe and Embree trip them (DESIGN.md)
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(320, 260);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  PassTestScene::Build(renderer);

  // The outer assembly at (-1.2, 1.2, 0), turned 90 degrees about z:
  // (x, y, z) -> (-1.2 - y, 1.2 + x, z).
  vtkNew<vtkAssembly> outer;
  outer->SetPosition(-1.2, 1.2, 0.0);
  outer->RotateZ(90.0);
  // Part A, a 0.4 m cube at (0.5, 0, 0.2) in the assembly: x in [0.3, 0.7],
  // y in [-0.2, 0.2], z in [0, 0.4] -> world x in [-1.4, -1.0], y in
  // [1.5, 1.9], z in [0, 0.4].
  vtkSmartPointer<vtkActor> partA = Cube(0.4, 0.85, 0.85, 0.8);
  partA->SetPosition(0.5, 0.0, 0.2);
  outer->AddPart(partA);
  // The nested assembly at (0.5, -0.6, 0) in the outer one, with part C, a
  // 0.2 m cube at (0, 0, 0.1): x in [0.4, 0.6], y in [-0.7, -0.5], z in
  // [0, 0.2] in the outer assembly -> world x in [-0.7, -0.5], y in
  // [1.6, 1.8], z in [0, 0.2].
  vtkNew<vtkAssembly> inner;
  inner->SetPosition(0.5, -0.6, 0.0);
  vtkSmartPointer<vtkActor> partC = Cube(0.2, 0.3, 0.5, 0.9);
  partC->SetPosition(0.0, 0.0, 0.1);
  inner->AddPart(partC);
  outer->AddPart(inner);
  // Part D, translucent: drawn by VTK, not solved.
  vtkSmartPointer<vtkActor> partD = Cube(0.25, 1.0, 0.1, 0.1);
  partD->SetPosition(0.0, -0.3, 0.7);
  partD->GetProperty()->SetOpacity(0.5);
  outer->AddPart(partD);
  renderer->AddViewProp(outer);

  // The camera on the back-left corner.
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.9, -1.2, 1.9);
  camera->SetFocalPoint(-1.0, 1.4, 0.3);
  camera->SetViewAngle(40.0);
  renderer->ResetCameraClippingRange();

  vtkNew<vtkRadiosityPass> pass;
  pass->SetMethod(vtkRadiosityFilter::Hierarchical); // sharp shadows for the image
  pass->GetFilter()->SetNumberOfThreads(2);
  renderer->SetPass(pass);

  bool ok = true;
  int expected = 0;
  const auto step = [&](const std::string& what, int more)
  {
    ok &= PassTestScene::RenderAndCountSolves(window, pass, expected, more, what);
    // D's own matrix back after the draw: its position only.
    vtkMatrix4x4* own = partD->GetMatrix();
    ok &= PassTestScene::Check(own->GetElement(0, 3) == 0.0 && own->GetElement(1, 3) == -0.3 &&
        own->GetElement(2, 3) == 0.7 && own->GetElement(0, 0) == 1.0,
      what + ": the translucent part's own matrix was not restored");
  };

  step("first render", 1);
  const double boundsA[6] = { -1.4, -1.0, 1.5, 1.9, 0.0, 0.4 };
  const double boundsC[6] = { -0.7, -0.5, 1.6, 1.8, 0.0, 0.2 };
  ok &= BoundsAre(Gathered(pass, renderer, partA), boundsA, "part A");
  ok &= BoundsAre(Gathered(pass, renderer, partC), boundsC, "part C (nested)");
  ok &= PassTestScene::Check(Gathered(pass, renderer, partD) == nullptr, "the translucent part was solved");

  // The image: the parts in place, D drawn over them.
  const int result = vtkRegressionTestImage(window);
  ok &= result != vtkRegressionTester::FAILED;

  // Progressive, coarse and loose from here: the rest counts solves.
  pass->SetMethod(vtkRadiosityFilter::Progressive);
  pass->GetFilter()->SetTolerance(2e-2);
  pass->GetFilter()->SetInitialElementSize(0.125);
  pass->GetFilter()->SetMaxSubdivisionLevels(0);
  step("progressive, coarse settings", 1);
  step("redraw", 0);
  renderer->GetActiveCamera()->Azimuth(15.0);
  step("camera moved", 0);
  outer->SetPosition(-1.2, 1.0, 0.0); // everything 0.2 m towards -y
  step("outer assembly moved", 1);
  const double movedA[6] = { -1.4, -1.0, 1.3, 1.7, 0.0, 0.4 };
  ok &= BoundsAre(Gathered(pass, renderer, partA), movedA, "part A after the outer move");
  inner->SetPosition(0.5, -0.5, 0.0); // C 0.1 m towards -x in the world
  step("nested assembly moved", 1);
  const double movedC[6] = { -0.8, -0.6, 1.4, 1.6, 0.0, 0.2 };
  ok &= BoundsAre(Gathered(pass, renderer, partC), movedC, "part C after the nested move");
  outer->VisibilityOff();
  step("outer assembly hidden", 1);
  ok &= PassTestScene::Check(Gathered(pass, renderer, partA) == nullptr &&
      Gathered(pass, renderer, partC) == nullptr,
    "the hidden assembly's parts were solved");
  outer->VisibilityOn();
  step("outer assembly shown", 1);
  step("redraw", 0);
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
