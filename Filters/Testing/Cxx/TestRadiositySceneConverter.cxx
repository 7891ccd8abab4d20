// Scene conversion: composite blocks as objects, ObjectId splitting, ignored
// cell types, TwoSided expansion and array shape errors.
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCornellBoxSource.h"
#include "vtkDoubleArray.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyData.h"
#include "vtkRadiositySceneConverter.h"

#include <iostream>

namespace
{
int failures = 0;
void Expect(bool ok, const std::string& what)
{
  if (!ok)
  {
    std::cerr << "FAILED: " << what << "\n";
    ++failures;
  }
}

vtkSmartPointer<vtkPolyData> Square(int res)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(res, res);
  plane->Update();
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->DeepCopy(plane->GetOutput());
  return pd;
}
}

int TestRadiositySceneConverter(int, char*[])
{
  radiosity::Scene scene;
  std::string error;
  std::vector<std::string> warnings;

  // Two blocks: two objects; quads triangulated; Reflectance defaulted with a warning.
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, Square(2));
  blocks->SetBlock(1, Square(3));
  Expect(vtkRadiositySceneConverter::ToScene(blocks, scene, error, warnings), "multiblock: " + error);
  Expect(scene.ObjectNames.size() == 2, "two blocks give two objects");
  Expect(scene.Triangles.size() == 2 * (4 + 9), "quads are triangulated");
  Expect(scene.ObjectIds.back() == 1, "the second block is object 1");
  Expect(!warnings.empty(), "missing Reflectance is warned about");

  // The Cornell box source's ObjectId splits one polydata into its 8 objects.
  vtkNew<vtkCornellBoxSource> box;
  box->Update();
  Expect(vtkRadiositySceneConverter::ToScene(box->GetOutput(), scene, error, warnings), error);
  Expect(scene.ObjectNames.size() == 8, "Cornell box has 8 objects");
  Expect(scene.ObjectNames[5] == "light", "object names are kept");

  // Lines are ignored with a warning; TwoSided doubles a triangle, reversed.
  auto pd = Square(1);
  vtkNew<vtkCellArray> lines;
  const vtkIdType line[2] = { 0, 1 };
  lines->InsertNextCell(2, line);
  pd->SetLines(lines);
  vtkNew<vtkIntArray> twoSided;
  twoSided->SetName("TwoSided");
  twoSided->SetNumberOfTuples(2); // one line cell, then one quad
  twoSided->SetValue(0, 0);
  twoSided->SetValue(1, 1);
  pd->GetCellData()->AddArray(twoSided);
  warnings.clear();
  Expect(vtkRadiositySceneConverter::ToScene(pd, scene, error, warnings), "two-sided: " + error);
  Expect(scene.Triangles.size() == 4, "a two-sided quad gives four triangles");
  Expect(scene.Normal(0).z == -scene.Normal(1).z || scene.Normal(0).z == -scene.Normal(2).z,
    "the copy faces the other way");
  bool lineWarning = false;
  for (const auto& w : warnings)
  {
    lineWarning = lineWarning || w.find("1 line") != std::string::npos;
  }
  Expect(lineWarning, "ignored lines are warned about");

  // A Reflectance array with 2 components is refused, naming the array.
  auto bad = Square(1);
  vtkNew<vtkDoubleArray> reflectance;
  reflectance->SetName("Reflectance");
  reflectance->SetNumberOfComponents(2);
  reflectance->SetNumberOfTuples(1);
  bad->GetCellData()->AddArray(reflectance);
  Expect(!vtkRadiositySceneConverter::ToScene(bad, scene, error, warnings), "2 components refused");
  Expect(error.find("Reflectance") != std::string::npos && error.find("2 components") != std::string::npos,
    "error names the array and its shape: " + error);
  if (failures > 0)
  {
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
