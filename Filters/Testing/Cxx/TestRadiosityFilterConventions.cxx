// VTK's conventions in Filters/ and Rendering/ (as vtkWindowedSincPolyDataFilter
// follows them): the scene filters name the input types they accept (any
// dataset, whose surface is the scene, or composite data arriving whole), so
// that the pipeline refuses anything else before RequestData; every boolean
// property has its On/Off pair; PrintSelf prints every property by its API name.
#include "FilterTestSupport.h"

#include "vtkAlgorithm.h"
#include "vtkCornellBoxSource.h"
#include "vtkExecutive.h"
#include "vtkFaceClusterHierarchyFilter.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationStringVectorKey.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkQuadraticInterpolantMapper.h"
#include "vtkRadiosityConvergenceChart.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiosityView.h"
#include "vtkShepardFieldProbe.h"
#include "vtkShepardSplatMapper.h"
#include "vtkTable.h"
#include "vtkTestErrorObserver.h"
#include "vtkVectorIrradianceMapper.h"

#include <algorithm>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

using FilterTestSupport::Check;

namespace
{
// Every name of `names` starts a line of `object`'s PrintSelf output as
// "Name:" (followed by its value, or by indented lines), at any indentation.
bool PrintsAll(vtkObject* object, std::initializer_list<const char*> names)
{
  std::ostringstream out;
  object->PrintSelf(out, vtkIndent());
  std::vector<std::string> lines;
  std::istringstream in(out.str());
  for (std::string line; std::getline(in, line);)
  {
    lines.push_back(line.substr(std::min(line.find_first_not_of(' '), line.size())));
  }
  bool ok = true;
  for (const char* name : names)
  {
    const std::string prefix = std::string(name) + ":";
    ok &= Check(std::any_of(lines.begin(), lines.end(),
                  [&](const std::string& line) { return line.rfind(prefix, 0) == 0; }),
      std::string(object->GetClassName()) + "::PrintSelf prints " + name);
  }
  return ok;
}

// Port 0 requires exactly vtkDataSet and vtkCompositeDataSet.
bool NamesSceneTypes(vtkAlgorithm* algorithm)
{
  vtkInformation* info = algorithm->GetInputPortInformation(0);
  vtkInformationStringVectorKey* key = vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE();
  const std::string what = std::string(algorithm->GetClassName()) + " input types";
  if (!Check(info->Length(key) == 2, what + ": two"))
  {
    return false;
  }
  return Check(std::string(info->Get(key, 0)) == "vtkDataSet" &&
      std::string(info->Get(key, 1)) == "vtkCompositeDataSet",
    what + ": vtkDataSet, vtkCompositeDataSet");
}
}

int TestRadiosityFilterConventions(int, char*[])
{
  vtkFloatingPointExceptions::Disable();
  bool ok = true;

  // 1. Input types.
  vtkNew<vtkRadiosityFilter> radiosity;
  vtkNew<vtkFaceClusterHierarchyFilter> clusters;
  ok &= NamesSceneTypes(radiosity);
  ok &= NamesSceneTypes(clusters);

  // A table is refused by the pipeline's type check: RequestData never runs.
  for (vtkAlgorithm* algorithm : { static_cast<vtkAlgorithm*>(radiosity.Get()),
         static_cast<vtkAlgorithm*>(clusters.Get()) })
  {
    const std::string name = algorithm->GetClassName();
    vtkNew<vtkTest::ErrorObserver> errors;
    algorithm->AddObserver(vtkCommand::ErrorEvent, errors);
    algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
    vtkNew<vtkTable> table;
    algorithm->SetInputDataObject(0, table);
    algorithm->Update();
    ok &= Check(errors->GetError(), name + ": a vtkTable input reports an error");
    ok &= Check(errors->GetErrorMessage().find("vtkTable") != std::string::npos &&
        errors->GetErrorMessage().find("is required") != std::string::npos,
      name + ": the pipeline names the required type, got '" + errors->GetErrorMessage() + "'");
    const std::string lastError = algorithm == radiosity.Get() ? radiosity->GetLastError()
                                                               : clusters->GetLastError();
    ok &= Check(lastError.empty(), name + ": RequestData did not run, LastError '" + lastError + "'");
    algorithm->RemoveAllObservers();
    algorithm->GetExecutive()->RemoveAllObservers();
  }

  // Image data is a dataset: it still reaches ToScene (its outer surface).
  {
    vtkNew<vtkTest::ErrorObserver> errors;
    radiosity->AddObserver(vtkCommand::ErrorEvent, errors);
    radiosity->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
    radiosity->AddObserver(vtkCommand::WarningEvent, errors); // surface, grey, no emitter
    vtkNew<vtkImageData> image;
    image->SetDimensions(2, 2, 2);
    radiosity->SetInputData(image);
    radiosity->SetMaxIterations(10);
    radiosity->Update();
    ok &= Check(errors->GetErrorMessage().find("is required") == std::string::npos,
      "vtkImageData passes the pipeline's type check, got '" + errors->GetErrorMessage() + "'");
    ok &= Check(!radiosity->GetLastError().empty() || radiosity->GetOutput()->GetNumberOfCells() > 0,
      "vtkImageData reaches RequestData");
    radiosity->RemoveAllObservers();
    radiosity->GetExecutive()->RemoveAllObservers();
  }

  // A multiblock scene arrives whole: one polydata output, not one per block.
  {
    vtkNew<vtkCornellBoxSource> box;
    box->Update();
    vtkNew<vtkMultiBlockDataSet> scene;
    scene->SetNumberOfBlocks(1);
    scene->SetBlock(0, box->GetOutput());
    radiosity->SetInputData(scene);
    radiosity->SetMaxIterations(10);
    radiosity->Update();
    ok &= Check(radiosity->GetLastError().empty(),
      "a multiblock scene solves: '" + radiosity->GetLastError() + "'");
    ok &= Check(vtkPolyData::SafeDownCast(radiosity->GetOutputDataObject(0)) != nullptr &&
        radiosity->GetOutput()->GetNumberOfCells() > 0,
      "a multiblock scene gives one polydata output");
  }

  // 2. Boolean properties.
  radiosity->OvershootingOff();
  ok &= Check(!radiosity->GetOvershooting(), "OvershootingOff");
  radiosity->OvershootingOn();
  ok &= Check(radiosity->GetOvershooting(), "OvershootingOn");
  radiosity->DiscontinuityMeshingOff();
  radiosity->ConformingBoundariesOff();
  ok &= Check(!radiosity->GetDiscontinuityMeshing() && !radiosity->GetConformingBoundaries(),
    "DiscontinuityMeshingOff, ConformingBoundariesOff");
  radiosity->DiscontinuityMeshingOn();
  radiosity->ConformingBoundariesOn();
  ok &= Check(radiosity->GetDiscontinuityMeshing() && radiosity->GetConformingBoundaries(),
    "DiscontinuityMeshingOn, ConformingBoundariesOn");
  // The clustering mode: clamped to its three values, named in PrintSelf.
  ok &= Check(radiosity->GetClustering() == vtkRadiosityFilter::ClusteringAuto, "Clustering: auto by default");
  radiosity->SetClustering(7);
  ok &= Check(radiosity->GetClustering() == vtkRadiosityFilter::ClusteringAuto, "SetClustering(7) clamps to auto");
  radiosity->SetClusteringToOff();
  ok &= Check(radiosity->GetClustering() == vtkRadiosityFilter::ClusteringOff &&
      std::string(vtkRadiosityFilter::GetClusteringName(radiosity->GetClustering())) == "off",
    "SetClusteringToOff");
  radiosity->SetClusteringToOn();
  ok &= Check(radiosity->GetClustering() == vtkRadiosityFilter::ClusteringOn, "SetClusteringToOn");
  radiosity->SetClusteringToAuto();
  vtkNew<vtkRadiosityView> view;
  view->InterpolantRenderingOff();
  view->OffScreenOff();
  ok &= Check(!view->GetInterpolantRendering() && !view->GetOffScreen(),
    "InterpolantRenderingOff, OffScreenOff");
  view->InterpolantRenderingOn();
  view->OffScreenOn();
  ok &= Check(view->GetInterpolantRendering() && view->GetOffScreen(),
    "InterpolantRenderingOn, OffScreenOn");
  vtkNew<vtkRadiosityConvergenceChart> chart;
  chart->LogTimeOn();
  ok &= Check(chart->GetLogTime(), "LogTimeOn");
  chart->LogTimeOff();
  ok &= Check(!chart->GetLogTime(), "LogTimeOff");

  // 3. PrintSelf.
  ok &= PrintsAll(radiosity, { "Method", "ResolvedMethod", "MethodChoice", "Tolerance", "MaxIterations", "MaxTime",
                               "NumberOfThreads", "Overshooting", "ShooterElementSize",
                               "InitialElementSize", "MaxSubdivisionLevels",
                               "SubdivisionThreshold", "FormFactorTolerance", "VisibilitySamples",
                               "IndirectVisibilitySamples", "LinkTolerance", "MinElementSize",
                               "MaxRefinementRounds", "Clustering", "PointRadius", "PointLevels", "GatherRays",
                               "VariationThreshold", "SolidAngleThreshold", "IrradianceBasis",
                               "RadiosityBasis", "TransferTolerance", "MaxBisections",
                               "MaxMemory", "DiscontinuityMeshing", "MaxDiscontinuitiesPerLeaf", "Controller",
                               "MinDiscontinuityWeight", "ConformingBoundaries", "Solver",
                               "ErrorReference", "StatusCallback" });
  ok &= PrintsAll(clusters, { "NumberOfLevels", "ShapeWeight" });
  vtkNew<vtkCornellBoxSource> box;
  ok &= PrintsAll(box, { "LightScale" });
  vtkNew<vtkShepardFieldProbe> probe;
  ok &= PrintsAll(probe, { "Source", "MaxLevel" });
  ok &= PrintsAll(view, { "InputData", "ArrayName", "InterpolantRendering", "ShepardField",
                          "Exposure", "ToneMappingType", "Size", "OffScreen", "Camera",
                          "RenderWindow" });
  ok &= PrintsAll(chart, { "TimeColumn", "Title", "LogTime", "Inputs", "Columns" });
  vtkNew<vtkQuadraticInterpolantMapper> interpolants;
  ok &= PrintsAll(interpolants, { "Exposure", "Gamma", "ToneMapping" });
  vtkNew<vtkVectorIrradianceMapper> vectors;
  ok &= PrintsAll(vectors, { "Exposure", "Gamma", "ToneMapping" });
  vtkNew<vtkShepardSplatMapper> splats;
  ok &= PrintsAll(splats, { "Exposure", "Gamma", "ToneMapping", "Field", "Passes", "Width",
                            "Height" });

  if (!ok)
  {
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
