// vtkFaceClusterHierarchyFilter on the subdivided Cornell box: nested
// ClusterId<L> arrays (one root per object at level 0), the hierarchy in the
// output's information and shared with a second filter on the same scene,
// rebuilt for another ShapeWeight, bad input refused. The image shows the
// clusters of level 4 in flat colours against a baseline.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCornellBoxSource.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFaceClusterHierarchyFilter.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkInformation.h"
#include "vtkLinearSubdivisionFilter.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTestErrorObserver.h"
#include "vtkExecutive.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include "Radiosity/FaceCluster/FaceClusterHierarchy.h"

#include "FilterTestSupport.h"

#include <iostream>
#include <map>
#include <set>
#include <string>

using FilterTestSupport::Check;

int TestFaceClusterHierarchyFilter(int argc, char* argv[])
{
  vtkFloatingPointExceptions::Disable();
  bool ok = true;
  vtkNew<vtkCornellBoxSource> box;
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(box->GetOutputPort());
  vtkNew<vtkLinearSubdivisionFilter> subdivide;
  subdivide->SetNumberOfSubdivisions(3);
  subdivide->SetInputConnection(triangles->GetOutputPort());
  subdivide->Update();
  vtkPolyData* scene = subdivide->GetOutput();

  vtkNew<vtkFaceClusterHierarchyFilter> clusters;
  clusters->SetInputData(scene);
  clusters->SetNumberOfLevels(7);
  clusters->Update();
  vtkPolyData* out = clusters->GetOutput();
  ok &= Check(clusters->GetLastError().empty(), "no error: " + clusters->GetLastError());
  ok &= Check(out->GetNumberOfCells() == scene->GetNumberOfCells(), "one tuple per input cell");
  auto hierarchy = clusters->GetHierarchy();
  ok &= Check(hierarchy && !clusters->GetReused(), "built, not reused");
  if (!ok)
  {
    return EXIT_FAILURE;
  }
  std::cout << scene->GetNumberOfCells() << " triangles: " << hierarchy->NumberOfClusters()
            << " clusters, depth " << hierarchy->MaximumDepth() << ", "
            << hierarchy->BuildSeconds() << " s\n";

  // Level 0: one root per object (8 in the Cornell box); each level nests in
  // the one above; the number of clusters grows with the level.
  vtkDataArray* objects = out->GetCellData()->GetArray("ObjectId");
  std::size_t previousCount = 0;
  for (int level = 0; level < 7; ++level)
  {
    vtkDataArray* ids = out->GetCellData()->GetArray(("ClusterId" + std::to_string(level)).c_str());
    ok &= Check(ids != nullptr, "ClusterId" + std::to_string(level));
    if (!ids)
    {
      return EXIT_FAILURE;
    }
    std::map<vtkIdType, vtkIdType> parentOf;
    std::map<vtkIdType, int> objectOf;
    std::set<vtkIdType> distinct;
    vtkDataArray* above =
      level > 0 ? out->GetCellData()->GetArray(("ClusterId" + std::to_string(level - 1)).c_str()) : nullptr;
    for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
    {
      const auto id = static_cast<vtkIdType>(ids->GetComponent(c, 0));
      ok &= Check(id >= 0, "every triangle is clustered");
      distinct.insert(id);
      const int object = static_cast<int>(objects->GetComponent(c, 0));
      ok &= Check(objectOf.emplace(id, object).first->second == object, "clusters stay in their object");
      if (above)
      {
        const auto up = static_cast<vtkIdType>(above->GetComponent(c, 0));
        ok &= Check(parentOf.emplace(id, up).first->second == up, "levels nest");
      }
    }
    std::cout << "level " << level << ": " << distinct.size() << " clusters\n";
    ok &= Check(level > 0 || distinct.size() == 8, "one root per object");
    ok &= Check(distinct.size() >= previousCount, "finer levels have more clusters");
    previousCount = distinct.size();
    if (!ok)
    {
      return EXIT_FAILURE;
    }
  }
  ok &= Check(previousCount > 100, "the hierarchy reaches small clusters by level 6");

  // The same scene again: the same hierarchy, not rebuilt; another shape
  // weight builds another.
  vtkNew<vtkFaceClusterHierarchyFilter> again;
  again->SetInputData(scene);
  again->Update();
  ok &= Check(again->GetReused() && again->GetHierarchy() == hierarchy, "second build reused");
  again->SetShapeWeight(2.0);
  again->Update();
  ok &= Check(!again->GetReused() && again->GetHierarchy() != hierarchy, "other options rebuilt");

  // Bad input: a one-component Reflectance, named in the error.
  vtkNew<vtkPolyData> bad;
  bad->DeepCopy(scene);
  vtkNew<vtkDoubleArray> grey;
  grey->SetName("Reflectance");
  grey->SetNumberOfTuples(bad->GetNumberOfCells());
  grey->Fill(0.5);
  bad->GetCellData()->AddArray(grey);
  vtkNew<vtkTest::ErrorObserver> observer;
  vtkNew<vtkFaceClusterHierarchyFilter> refused;
  refused->AddObserver(vtkCommand::ErrorEvent, observer);
  refused->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, observer); // the failed request
  refused->SetInputData(bad);
  refused->Update();
  ok &= Check(observer->GetError() && refused->GetLastError().find("Reflectance") != std::string::npos &&
      refused->GetOutput()->GetNumberOfCells() == 0 && !refused->GetHierarchy(),
    "bad Reflectance refused: '" + refused->GetLastError() + "'");

  // Flat colours per cluster of level 4 (a hash of the id).
  vtkDataArray* level4 = out->GetCellData()->GetArray("ClusterId4");
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("Colours");
  colours->SetNumberOfComponents(3);
  colours->SetNumberOfTuples(out->GetNumberOfCells());
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    auto h = static_cast<unsigned>(level4->GetComponent(c, 0)) * 2654435761u;
    colours->SetTuple3(c, 60 + (h >> 8) % 190, 60 + (h >> 16) % 190, 60 + (h >> 24) % 190);
  }
  vtkNew<vtkPolyData> coloured;
  coloured->ShallowCopy(out);
  coloured->GetCellData()->SetScalars(colours);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(coloured);
  mapper->SetScalarModeToUseCellData();
  mapper->SetColorModeToDirectScalars();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  double position[3], focal[3], up[3], angle;
  vtkCornellBoxSource::GetCamera(position, focal, up, angle);
  renderer->GetActiveCamera()->SetPosition(position);
  renderer->GetActiveCamera()->SetFocalPoint(focal);
  renderer->GetActiveCamera()->SetViewUp(up);
  renderer->GetActiveCamera()->SetViewAngle(angle);
  renderer->ResetCameraClippingRange();
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetOffScreenRendering(1);
  window->SetSize(400, 400);
  window->AddRenderer(renderer);
  window->Render();
  if (!ok)
  {
    return EXIT_FAILURE;
  }
  const int result = vtkRegressionTestImage(window);
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
