// vtkRadiosityFilter's Method Auto, the default (radiosity::ChooseMethod):
// the matte Cornell box is solved by clustered hierarchical radiosity and
// discontinuity-meshed, the same box with a glossy wall by face cluster
// radiosity (vector irradiance for the glossy display), a matte scene of
// more than 2048 triangles by meshless radiosity, each exactly as the
// method asked for by name solves it; GetMethodChoice says why; a method
// asked for by name is used as it is; Clustering Off is still honoured.
#include "vtkCellData.h"
#include "vtkCornellBoxSource.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiositySceneConverter.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"

#include "FilterTestSupport.h"

#include "Radiosity/Hierarchical/HierarchicalRadiosity.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>

using FilterTestSupport::Check;
using FilterTestSupport::RelativeDifference;

namespace
{
std::string ProductKind(vtkRadiosityFilter* filter)
{
  auto kind = vtkStringArray::SafeDownCast(filter->GetOutput(1)->GetFieldData()->GetAbstractArray("ProductKind"));
  return kind && kind->GetNumberOfValues() > 0 ? kind->GetValue(0) : std::string("(none)");
}

/// `input` solved with Auto and with `named`: the method chosen, the product
/// kind, and the two outputs equal (the same solver with the same settings).
bool ChoosesAndMatches(vtkPolyData* input, int named, const std::string& kind, const std::string& why)
{
  bool ok = true;
  vtkNew<vtkRadiosityFilter> chosen;
  chosen->SetInputData(input);
  ok &= Check(chosen->GetResolvedMethod() == vtkRadiosityFilter::Auto, "resolved: Auto before any request");
  chosen->Update();
  const std::string name = vtkRadiosityFilter::GetMethodName(named);
  ok &= Check(chosen->GetLastError().empty(), name + ": " + chosen->GetLastError());
  ok &= Check(chosen->GetMethod() == vtkRadiosityFilter::Auto, name + ": Method stays Auto");
  ok &= Check(chosen->GetResolvedMethod() == named,
    std::string("auto chose ") + vtkRadiosityFilter::GetMethodName(chosen->GetResolvedMethod()) + ", expected " + name);
  ok &= Check(ProductKind(chosen) == kind, name + ": product " + ProductKind(chosen) + ", expected " + kind);
  ok &= Check(chosen->GetMethodChoice().find(why) != std::string::npos,
    name + ": the choice '" + chosen->GetMethodChoice() + "' does not say '" + why + "'");
  std::ostringstream printed;
  chosen->Print(printed);
  ok &= Check(printed.str().find("ResolvedMethod: " + name) != std::string::npos &&
      printed.str().find(chosen->GetMethodChoice()) != std::string::npos,
    name + ": PrintSelf shows the resolved method and why");

  vtkNew<vtkRadiosityFilter> byName;
  byName->SetInputData(input);
  byName->SetMethod(named);
  if (named == vtkRadiosityFilter::Hierarchical)
  {
    byName->SetClusteringToOn(); // what Auto's hierarchical does at any size
  }
  byName->Update();
  ok &= Check(byName->GetResolvedMethod() == named && byName->GetMethodChoice().empty(),
    name + " by name: resolved as itself, no choice to explain");
  const double difference = RelativeDifference(chosen->GetOutput(), byName->GetOutput());
  std::cout << name << ": auto against by name, largest irradiance difference " << difference << " of the peak\n";
  ok &= Check(difference <= 1e-12, name + ": auto's solution differs from the named method's by " +
      std::to_string(difference) + " of the peak");
  return ok;
}
}

int TestRadiosityFilterAutoMethod(int, char*[])
{
  vtkFloatingPointExceptions::Disable();
  bool ok = true;

  // 1. The matte Cornell box (32 triangles): clustered hierarchical
  //    radiosity, discontinuity-meshed.
  vtkNew<vtkCornellBoxSource> box;
  box->Update();
  vtkPolyData* cornell = box->GetOutput();
  ok &= ChoosesAndMatches(cornell, vtkRadiosityFilter::Hierarchical, "DiscontinuityMesh", "32 triangles, at most 2048");
  {
    vtkNew<vtkRadiosityFilter> filter;
    filter->SetInputData(cornell);
    filter->Update();
    ok &= Check(filter->GetHierarchicalSolution() && filter->GetHierarchicalSolution()->Clustered(),
      "auto's hierarchical radiosity is clustered on the 32-triangle box");
    filter->SetClusteringToOff();
    filter->Update();
    ok &= Check(filter->GetHierarchicalSolution() && !filter->GetHierarchicalSolution()->Clustered(),
      "Clustering Off is honoured under Method Auto");
  }

  // 2. The same box with one glossy wall: face cluster radiosity, whose
  //    vector irradiance the glossy display needs.
  vtkNew<vtkPolyData> glossy;
  glossy->DeepCopy(cornell);
  vtkNew<vtkDoubleArray> specular;
  specular->SetName("Specular");
  specular->SetNumberOfComponents(3);
  specular->SetNumberOfTuples(glossy->GetNumberOfCells());
  specular->Fill(0.0);
  specular->SetTuple3(3, 0.3, 0.3, 0.3);
  glossy->GetCellData()->AddArray(specular);
  ok &= ChoosesAndMatches(glossy, vtkRadiosityFilter::FaceCluster, "LeafClusters", "1 of the 32 triangles");

  // 3. A matte closed room of 2,352 triangles: meshless radiosity.
  vtkSmartPointer<vtkPolyData> room =
    vtkRadiositySceneConverter::FromScene(radiosity::MakeClosedCube(1.0, 14, 0.5, 1.0));
  ok &= ChoosesAndMatches(room, vtkRadiosityFilter::Meshless, "ShepardField", "2352 triangles, more than 2048");

  // 4. A method by name is used as it is, whatever the scene.
  {
    vtkNew<vtkRadiosityFilter> filter;
    filter->SetInputData(room);
    filter->SetMethodToProgressive();
    filter->SetMaxIterations(20);
    filter->Update();
    ok &= Check(filter->GetResolvedMethod() == vtkRadiosityFilter::Progressive && filter->GetMethodChoice().empty(),
      "Progressive by name on 2,352 triangles stays progressive");
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
