// vtkRadiosityPass solves again exactly when it should (GetNumberOfSolves
// after each render of PassTestScene, progressive at a loose tolerance):
// - a redraw and a camera move: no solve; the Exposure of the display and
//   a translucent actor's colour: no solve;
// - a property (the box's colour), a light (the spot's intensity), an
//   actor's transform (the box moved), the input data (the sphere source's
//   radius), a filter setting (the method), the pass's MaxReflectance:
//   adding an actor, removing it: exactly one solve each; a headlight
//   added (it follows the camera): none;
// - progress: every solve invokes StartEvent, ProgressEvent with fractions
//   in [0, 1] ending at 1, and EndEvent on the pass;
// - bad input: a light with a NaN intensity and an actor with a NaN colour
//   fail UpdateSolution with an error naming the light ("scene light 0")
//   and the actor ("actor 4"), keep no solution, and the scene solves again
//   once they are repaired;
// - hardware selection (vtkHardwareSelector) still picks the solved actors;
// - the settings are readable from the renderer's information
//   (vtkRadiosityRendererNode's keys): method, tolerance, exposure, the
//   count of solves, each as the pass holds it after a render.
#include "PassTestScene.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkHardwareSelector.h"
#include "vtkProp.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiosityPass.h"
#include "vtkRadiosityRendererNode.h"
#include "vtkRenderWindow.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"
#include "vtkInformation.h"

#include <cmath>
#include <limits>
#include <string>

namespace
{
struct Events
{
  int Start = 0, Progress = 0, End = 0;
  double Last = -1.0;
  bool InRange = true;
};

void Count(vtkObject*, unsigned long event, void* client, void* data)
{
  auto* e = static_cast<Events*>(client);
  if (event == vtkCommand::StartEvent)
  {
    ++e->Start;
  }
  else if (event == vtkCommand::EndEvent)
  {
    ++e->End;
  }
  else if (event == vtkCommand::ProgressEvent)
  {
    ++e->Progress;
    e->Last = *static_cast<double*>(data);
    e->InRange &= e->Last >= 0.0 && e->Last <= 1.0;
  }
}

/// Collects the error messages of an object.
struct Errors : vtkCommand
{
  static Errors* New() { return new Errors; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    this->Text += static_cast<const char*>(data);
  }
  std::string Text;
};
}

int TestRadiosityPassResolve(int, char*[])
{
  vtkFloatingPointExceptions::Disable();
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(160, 120);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  PassTestScene::Scene scene = PassTestScene::Build(renderer);
  vtkNew<vtkActor> glass;
  {
    vtkNew<vtkSphereSource> source;
    source->SetCenter(0.9, -0.9, 0.35);
    source->SetRadius(0.3);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(source->GetOutputPort());
    glass->SetMapper(mapper);
    glass->GetProperty()->SetOpacity(0.4);
    renderer->AddActor(glass);
  }
  vtkNew<vtkRadiosityPass> pass;
  pass->SetMethod(vtkRadiosityFilter::Progressive);
  // Coarse and loose: this test counts solves, it does not measure them.
  pass->GetFilter()->SetTolerance(2e-2);
  pass->GetFilter()->SetInitialElementSize(0.125);
  pass->GetFilter()->SetMaxSubdivisionLevels(0);
  pass->GetFilter()->SetNumberOfThreads(2);
  renderer->SetPass(pass);
  Events events;
  vtkNew<vtkCallbackCommand> counter;
  counter->SetCallback(Count);
  counter->SetClientData(&events);
  for (unsigned long e : { vtkCommand::StartEvent, vtkCommand::ProgressEvent, vtkCommand::EndEvent })
  {
    pass->AddObserver(e, counter);
  }
  vtkNew<Errors> errors;
  pass->AddObserver(vtkCommand::ErrorEvent, errors);
  pass->GetFilter()->AddObserver(vtkCommand::ErrorEvent, errors);

  bool ok = true;
  int expected = 0;
  const auto step = [&](const std::string& what, int more)
  { ok &= PassTestScene::RenderAndCountSolves(window, pass, expected, more, what); };

  step("first render", 1);
  ok &= PassTestScene::Check(events.Start == 1 && events.End == 1 && events.Progress >= 2 &&
      events.InRange && events.Last == 1.0,
    "progress of the first solve: " + std::to_string(events.Start) + " starts, " +
      std::to_string(events.Progress) + " progress events (last " + std::to_string(events.Last) +
      "), " + std::to_string(events.End) + " ends");
  step("redraw", 0);
  renderer->GetActiveCamera()->Azimuth(25.0);
  renderer->GetActiveCamera()->Elevation(10.0);
  renderer->ResetCameraClippingRange();
  step("camera moved", 0);
  pass->SetExposure(1.5);
  step("exposure", 0);
  glass->GetProperty()->SetColor(0.2, 0.9, 0.2);
  step("translucent actor's colour", 0);
  scene.Box->GetProperty()->SetColor(0.3, 0.8, 0.6);
  step("box colour", 1);
  scene.Spot->SetIntensity(3.0);
  step("spot intensity", 1);
  scene.Box->SetPosition(0.6, 0.6, 0.4);
  step("box moved", 1);
  scene.BallSource->SetRadius(0.45);
  step("sphere source radius", 1);
  pass->SetMethod(vtkRadiosityFilter::Auto);
  step("method", 1);
  pass->SetMaxReflectance(0.7); // the box's 0.8 now clamped: converted and solved again
  step("MaxReflectance", 1);
  vtkNew<vtkLight> headlight; // moves with the camera: not part of the solve
  headlight->SetLightTypeToHeadlight();
  renderer->AddLight(headlight);
  renderer->GetActiveCamera()->Azimuth(-10.0);
  step("a headlight added, the camera moved", 0);
  vtkNew<vtkActor> extra;
  {
    vtkNew<vtkCubeSource> source;
    source->SetCenter(-1.2, 1.2, 0.2);
    source->SetXLength(0.4);
    source->SetYLength(0.4);
    source->SetZLength(0.4);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(source->GetOutputPort());
    extra->SetMapper(mapper);
  }
  renderer->AddActor(extra);
  step("an actor added", 1);
  renderer->RemoveActor(extra);
  step("the actor removed", 1);
  step("redraw", 0);
  {
    // The settings as the renderer's information holds them (a fresh
    // renderer reads the defaults).
    using Node = vtkRadiosityRendererNode;
    vtkNew<vtkRenderer> other;
    ok &= PassTestScene::Check(Node::GetMethod(renderer) == vtkRadiosityFilter::Auto &&
        Node::GetTolerance(renderer) == 2e-2 && Node::GetExposure(renderer) == 1.5 &&
        Node::GetMaxReflectance(renderer) == 0.7 && Node::GetNumberOfSolves(renderer) == expected &&
        renderer->GetInformation()->Has(Node::METHOD()) && !other->GetInformation()->Has(Node::METHOD()) &&
        Node::GetTolerance(other) == 1e-3 && Node::GetNumberOfSolves(other) == 0,
      "renderer information: method " + std::to_string(Node::GetMethod(renderer)) + ", tolerance " +
        std::to_string(Node::GetTolerance(renderer)) + ", exposure " +
        std::to_string(Node::GetExposure(renderer)) + ", solves " +
        std::to_string(Node::GetNumberOfSolves(renderer)) + " (expected " + std::to_string(expected) + ")");
    pass->SetExposure(2.5);
    window->Render();
    ok &= PassTestScene::Check(Node::GetExposure(renderer) == 2.5 &&
        Node::GetNumberOfSolves(renderer) == expected,
      "renderer information after an exposure change: " + std::to_string(Node::GetExposure(renderer)));
    pass->SetExposure(1.5);
  }
  ok &= PassTestScene::Check(events.Start == expected && events.End == expected,
    "a StartEvent and an EndEvent per solve: " + std::to_string(events.Start) + " and " +
      std::to_string(events.End) + " for " + std::to_string(expected) + " solves");

  // Bad input: named, no solution kept, solved again once repaired.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto failing = [&](const std::string& what, const std::string& name)
  {
    errors->Text.clear();
    const bool solved = pass->UpdateSolution(renderer);
    ++expected;
    ok &= PassTestScene::Check(!solved && !pass->HasSolution(), what + ": solved anyway");
    ok &= PassTestScene::Check(errors->Text.find(name) != std::string::npos,
      what + ": the error does not name '" + name + "': " + errors->Text);
    std::cout << what << ": " << errors->Text << "\n";
    window->Render(); // the actors drawn as VTK draws them; no retry
    ok &= PassTestScene::Check(pass->GetNumberOfSolves() <= expected, what + ": retried");
    expected = pass->GetNumberOfSolves();
  };
  scene.Spot->SetIntensity(nan);
  failing("NaN light intensity", "scene light 0");
  scene.Spot->SetIntensity(3.0);
  step("light repaired", 1);
  scene.Ball->GetProperty()->SetColor(nan, 0.5, 0.5);
  failing("NaN actor colour", "actor 4");
  scene.Ball->GetProperty()->SetColor(0.35, 0.45, 0.85);
  step("colour repaired", 1);

  // Hardware selection draws the renderer's own props.
  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(renderer);
  selector->SetArea(0, 0, 159, 119);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
  vtkSmartPointer<vtkSelection> selection;
  selection.TakeReference(selector->Select());
  bool floorPicked = false;
  for (unsigned int i = 0; selection && i < selection->GetNumberOfNodes(); ++i)
  {
    vtkInformation* properties = selection->GetNode(i)->GetProperties();
    if (properties->Has(vtkSelectionNode::PROP()) &&
      properties->Get(vtkSelectionNode::PROP()) == scene.Floor.GetPointer())
    {
      floorPicked = true;
    }
  }
  std::cout << "hardware selection: " << (selection ? selection->GetNumberOfNodes() : 0)
            << " nodes, floor " << (floorPicked ? "picked" : "not picked") << "\n";
  ok &= PassTestScene::Check(floorPicked, "hardware selection does not pick the floor");
  ok &= PassTestScene::Check(pass->GetNumberOfSolves() == expected, "selection solved again");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
