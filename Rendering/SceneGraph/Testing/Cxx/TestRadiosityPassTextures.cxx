// Colour textures in a file nobody here wrote: assimp's glTF 2.0 sample
// BoxTextured (Debian's assimp-testmodels; the test is skipped without it),
// a cube whose material is white with a baseColorTexture (the Cesium logo,
// 211 x 211, sRGB) and whose faces' texture coordinates run over s in
// [0, 6]. Imported by vtkGLTFImporter into a renderer, lit by a scene light,
// gathered by vtkRadiosityPass (UpdateSolution only, no window).
//
// Each triangle's reflectance must be the texture's mean over it, as VTK
// draws the texture: the reference here is computed another way, by
// counting: the decoded texels at the nearest texel of every point of a
// 240 x 240 barycentric grid over the triangle (the pass averages bilinear
// samples at the centroids of an n x n subdivision). VTK 9.2's importer
// clamps the texture to its edge (the file asks for mirrored repeat in s),
// so the ten triangles past s = 1 take the edge column's grey (0.7157, equal
// to the counted to 1e-6). Measured: largest difference 3.6e-3 over the 12
// triangles, on the two over the logo (nearest texels against bilinear
// across its sharp edges; bound 5e-3); without the texture every triangle
// would be the white base colour clamped to 0.95.
#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCellData.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkGLTFImporter.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkMapper.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiosityPass.h"
#include "vtkRadiosityRendererNode.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>

namespace
{
double Decode(double c)
{
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
}

int TestRadiosityPassTextures(int, char*[])
{
  vtkFloatingPointExceptions::Disable();
  const char* file = "/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf";
  if (!std::ifstream(file).good())
  {
    std::cout << "skipped: " << file << " is missing (Debian package assimp-testmodels)\n";
    return 125; // VTK_SKIP_RETURN_CODE
  }
  vtkNew<vtkRenderWindow> window; // the importer's target; never rendered
  vtkNew<vtkGLTFImporter> importer;
  importer->SetFileName(file);
  importer->SetRenderWindow(window);
  importer->Update();
  vtkRenderer* renderer = importer->GetRenderer();
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(1.0, 2.0, 3.0);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(sun);

  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  vtkActor* box = actors->GetNextActor();
  vtkTexture* texture = box ? box->GetProperty()->GetTexture("albedoTex") : nullptr;
  if (!box || !texture || !texture->GetInput())
  {
    std::cerr << "FAILED: the importer gave no actor with a base colour texture\n";
    return EXIT_FAILURE;
  }

  vtkNew<vtkRadiosityPass> pass;
  pass->SetMethod(vtkRadiosityFilter::Progressive);
  pass->GetFilter()->SetNumberOfThreads(2);
  if (!pass->UpdateSolution(renderer))
  {
    std::cerr << "FAILED: UpdateSolution\n";
    return EXIT_FAILURE;
  }
  vtkMultiBlockDataSet* blocks = pass->GetSceneGraph()->GetSceneInput();
  auto* gathered = blocks->GetNumberOfBlocks() == 1 ? vtkPolyData::SafeDownCast(blocks->GetBlock(0)) : nullptr;
  if (!gathered)
  {
    std::cerr << "FAILED: one object expected, " << blocks->GetNumberOfBlocks() << " gathered\n";
    return EXIT_FAILURE;
  }

  // The reference: the triangles of the actor's input as the pass takes
  // them (vtkTriangleFilter, the same order), the texels decoded by hand.
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(box->GetMapper()->GetInputDataObject(0, 0));
  triangles->Update();
  vtkPolyData* input = triangles->GetOutput();
  vtkDataArray* st = input->GetPointData()->GetTCoords();
  vtkImageData* image = texture->GetInput();
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* texels = image->GetPointData()->GetScalars();
  const bool clamped = texture->GetWrap() == vtkTexture::ClampToEdge;
  std::cout << "texture " << dims[0] << " x " << dims[1] << ", " << texels->GetNumberOfComponents()
            << " components, sRGB " << texture->GetUseSRGBColorSpace() << ", wrap " << texture->GetWrap()
            << "; " << input->GetNumberOfCells() << " triangles\n";
  if (!st || !clamped || input->GetNumberOfCells() != gathered->GetNumberOfCells())
  {
    std::cerr << "FAILED: no texture coordinates, a wrap other than VTK 9.2's ClampToEdge, or "
              << gathered->GetNumberOfCells() << " triangles gathered\n";
    return EXIT_FAILURE;
  }
  vtkDataArray* reflectance = gathered->GetCellData()->GetArray("Reflectance");
  const int grid = 240;
  double worst = 0.0;
  bool white = false;
  for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
  {
    const vtkIdType* ids;
    vtkIdType n;
    input->GetCellPoints(c, n, ids);
    double mean[3] = { 0.0, 0.0, 0.0 };
    int count = 0;
    for (int i = 0; i <= grid; ++i)
    {
      for (int j = 0; i + j <= grid; ++j)
      {
        const double b1 = double(i) / grid, b2 = double(j) / grid, b0 = 1.0 - b1 - b2;
        const double s = b0 * st->GetComponent(ids[0], 0) + b1 * st->GetComponent(ids[1], 0) +
          b2 * st->GetComponent(ids[2], 0);
        const double t = b0 * st->GetComponent(ids[0], 1) + b1 * st->GetComponent(ids[1], 1) +
          b2 * st->GetComponent(ids[2], 1);
        const int x = std::clamp(static_cast<int>(std::floor(s * dims[0])), 0, dims[0] - 1);
        const int y = std::clamp(static_cast<int>(std::floor(t * dims[1])), 0, dims[1] - 1);
        for (int k = 0; k < 3; ++k)
        {
          mean[k] += Decode(texels->GetComponent(y * dims[0] + x, k) / 255.0);
        }
        ++count;
      }
    }
    double got[3];
    reflectance->GetTuple(c, got);
    double d = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      mean[k] /= count;
      d = std::max(d, std::fabs(got[k] - std::min(mean[k], 0.95)));
    }
    white |= got[0] == 0.95 && got[1] == 0.95 && got[2] == 0.95;
    worst = std::max(worst, d);
    std::cout << "triangle " << c << ": (" << got[0] << ", " << got[1] << ", " << got[2]
              << "), counted (" << mean[0] << ", " << mean[1] << ", " << mean[2] << ")\n";
  }
  std::cout << "largest difference " << worst << " (bound 5e-3)\n";
  bool ok = worst < 5e-3;
  if (!ok)
  {
    std::cerr << "FAILED: the texture means differ from the counted ones by " << worst << "\n";
  }
  if (white)
  {
    std::cerr << "FAILED: a triangle is the clamped white base colour: the texture was not read\n";
    ok = false;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
