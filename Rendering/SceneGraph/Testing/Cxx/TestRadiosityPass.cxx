// vtkRadiosityPass on an ordinary VTK scene (PassTestScene: an open room,
// a box moved and turned by its actor's transform, a sphere, a spot and the
// sun as vtkLights): left progressive refinement (radiosity per vertex),
// right hierarchical radiosity with discontinuity meshing (quadratic
// interpolants per pixel), each renderer with a pass of its own, the same
// actors and lights. A translucent sphere (Opacity 0.4) in front of the box,
// a wireframe box over the sphere and a 2D text actor are not solved but
// drawn with the solution by the delegate pass. Checked
// against the baseline image, and each half must show light (its mean
// brighter than 20 of 255) and both methods must agree on the mean within
// 15% (they solve the same scene).
#include "PassTestScene.h"

#include "vtkActorCollection.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiosityPass.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"

#include <cmath>

namespace
{
constexpr int Width = 320, Height = 260;
}

int TestRadiosityPass(int argc, char* argv[])
{
  vtkFloatingPointExceptions::Disable(); // llvmpipe and Embree trip them (DESIGN.md)
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(2 * Width, Height);
  const int methods[2] = { vtkRadiosityFilter::Progressive, vtkRadiosityFilter::Hierarchical };
  vtkNew<vtkRenderer> renderers[2];
  vtkNew<vtkRadiosityPass> passes[2];
  PassTestScene::Scene scene = PassTestScene::Build(renderers[0]);

  vtkNew<vtkSphereSource> glassSource;
  glassSource->SetCenter(0.9, -0.9, 0.35);
  glassSource->SetRadius(0.3);
  vtkNew<vtkPolyDataMapper> glassMapper;
  glassMapper->SetInputConnection(glassSource->GetOutputPort());
  vtkNew<vtkActor> glass;
  glass->SetMapper(glassMapper);
  glass->GetProperty()->SetColor(1.0, 1.0, 1.0);
  glass->GetProperty()->SetOpacity(0.4);
  renderers[0]->AddActor(glass);
  vtkNew<vtkCubeSource> cageSource;
  cageSource->SetCenter(-0.8, -0.4, 0.5);
  cageSource->SetXLength(1.1);
  cageSource->SetYLength(1.1);
  cageSource->SetZLength(1.1);
  vtkNew<vtkPolyDataMapper> cageMapper;
  cageMapper->SetInputConnection(cageSource->GetOutputPort());
  vtkNew<vtkActor> cage;
  cage->SetMapper(cageMapper);
  cage->GetProperty()->SetRepresentationToWireframe();
  cage->GetProperty()->SetColor(1.0, 1.0, 0.0);
  cage->GetProperty()->LightingOff();
  renderers[0]->AddActor(cage);

  for (int i = 0; i < 2; ++i)
  {
    if (i == 1)
    {
      vtkActorCollection* actors = renderers[0]->GetActors();
      vtkCollectionSimpleIterator it;
      actors->InitTraversal(it);
      while (vtkActor* a = actors->GetNextActor(it))
      {
        renderers[1]->AddActor(a);
      }
      renderers[1]->AutomaticLightCreationOff();
      renderers[1]->AddLight(scene.Spot);
      renderers[1]->AddLight(scene.Sun);
      renderers[1]->SetActiveCamera(renderers[0]->GetActiveCamera());
    }
    renderers[i]->SetViewport(0.5 * i, 0.0, 0.5 * (i + 1), 1.0);
    vtkNew<vtkTextActor> label;
    label->SetInput(vtkRadiosityFilter::GetMethodName(methods[i]));
    label->SetPosition(8, 8);
    label->GetTextProperty()->SetFontSize(18);
    label->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
    renderers[i]->AddViewProp(label);
    passes[i]->SetMethod(methods[i]);
    passes[i]->GetFilter()->SetNumberOfThreads(2);
    passes[i]->GetFilter()->SetMaxSubdivisionLevels(1); // progressive's quadtrees: seconds, not a minute
    renderers[i]->SetPass(passes[i]);
    window->AddRenderer(renderers[i]);
  }
  window->Render();

  bool ok = true;
  double means[2];
  for (int i = 0; i < 2; ++i)
  {
    vtkRadiosityFilter* filter = passes[i]->GetFilter();
    ok &= PassTestScene::Check(passes[i]->GetNumberOfSolves() == 1 && passes[i]->HasSolution(),
      std::string(vtkRadiosityFilter::GetMethodName(methods[i])) + ": no solution");
    means[i] = PassTestScene::MeanOfHalf(window, i, Width, Height);
    std::cout << vtkRadiosityFilter::GetMethodName(methods[i]) << ": "
              << filter->GetScene().Triangles.size() << " scene triangles, "
              << filter->GetOutput(0)->GetNumberOfCells() << " solution cells, "
              << filter->GetStatistics().SolveSeconds << " s, mean pixel " << means[i] << "\n";
    ok &= PassTestScene::Check(means[i] > 20.0,
      std::string(vtkRadiosityFilter::GetMethodName(methods[i])) + " is dark: mean " +
        std::to_string(means[i]));
  }
  ok &= PassTestScene::Check(std::fabs(means[0] - means[1]) < 0.15 * means[0],
    "the methods disagree: means " + std::to_string(means[0]) + " and " + std::to_string(means[1]));

  const int result = vtkRegressionTestImage(window);
  return ok && result != vtkRegressionTester::FAILED ? EXIT_SUCCESS : EXIT_FAILURE;
}
