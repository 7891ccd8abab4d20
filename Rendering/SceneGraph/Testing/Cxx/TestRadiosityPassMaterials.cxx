// What the pass's scene graph gathers from VTK's actors (SPEC.md, "Scenes
// from VTK's scene graph"), read from the objects it hands the filter
// (GetSceneGraph()->GetSceneInput()), UpdateSolution only (no window):
// - Diffuse x DiffuseColor, and white clamped to MaxReflectance (0.95);
// - mapped scalar colours: cell colours per triangle, point colours
//   averaged per triangle (a quad's two triangles);
// - PBR: base colour x (1 - Metallic), EmissiveFactor x LightScale as the
//   emission, which lights the scene without any vtkLight;
// - Specular x SpecularColor and SpecularPower as Specular and Shininess;
// - the actor's matrix applied (a translated and mirrored quad keeps its
//   facing side: its triangles' normals still point up);
// - a composite mapper's blocks: a hidden block left out, a block colour
//   replacing the property's;
// - a wireframe actor and a headlight are not gathered;
// - an actor whose PropertyKeys set vtkRadiosityRendererNode::TWO_SIDED is
//   solved on both sides (the TwoSided array), the others on one;
// - Method Auto (the default) solves this glossy scene by face cluster
//   radiosity and draws it with the vector irradiance mapper;
// - textures: a classic texture (as vtkOBJImporter sets map_Kd), two texels
//   red and blue, clamped, bilinear, over a quad's texture coordinates
//   [0, 1]^2: its triangles' mean red worked out by hand (red falls
//   linearly from s = 1/4 to 3/4): 35/48 over the lower-left triangle,
//   13/48 over the upper-right, blue the rest; measured to 2.6e-4 (bound
//   5e-4, the n x n centroid rule); a PBR base colour texture and an
//   emissive texture (as vtkGLTFImporter sets them) of one sRGB texel each:
//   (128, 64, 255) -> (0.2158605, 0.0512695, 1 clamped to 0.95), and
//   (255, 128, 0) x EmissiveFactor 1 x LightScale pi, to 1e-6.
#include "vtkActor.h"
#include "vtkRadiosityPassDisplay.h"
#include "vtkVectorIrradianceMapper.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkDataArray.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolygon.h"
#include "vtkProperty.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiosityPass.h"
#include "vtkRadiosityRendererNode.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"
#include "vtkImageData.h"
#include "vtkFloatArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkViewNode.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <iostream>
#include <string>

namespace
{
bool Check(bool ok, const std::string& what)
{
  if (!ok)
  {
    std::cerr << "FAILED: " << what << "\n";
  }
  return ok;
}

/// A unit quad at height z facing +z (one polygon, four points).
vtkSmartPointer<vtkPolyData> Quad(double x0, double z)
{
  auto quad = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(x0, 0, z);
  points->InsertNextPoint(x0 + 1, 0, z);
  points->InsertNextPoint(x0 + 1, 1, z);
  points->InsertNextPoint(x0, 1, z);
  vtkNew<vtkCellArray> cells;
  const vtkIdType ids[4] = { 0, 1, 2, 3 };
  cells->InsertNextCell(4, ids);
  quad->SetPoints(points);
  quad->SetPolys(cells);
  return quad;
}

vtkActor* Add(vtkRenderer* renderer, vtkPolyData* data)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  vtkActor* actor = vtkActor::New();
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  actor->Delete();
  return actor;
}

/// A texture of `width` x 1 RGB texels.
vtkSmartPointer<vtkTexture> Texture(int width, const unsigned char* rgb, bool srgb)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(width, 1, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* texels = static_cast<unsigned char*>(image->GetScalarPointer());
  std::copy(rgb, rgb + 3 * width, texels);
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->InterpolateOn();
  texture->RepeatOff();
  texture->EdgeClampOn();
  texture->SetUseSRGBColorSpace(srgb);
  return texture;
}

/// Quad(x0, 0) with texture coordinates (0, 0), (1, 0), (1, 1), (0, 1).
vtkSmartPointer<vtkPolyData> TexturedQuad(double x0)
{
  auto quad = Quad(x0, 0);
  vtkNew<vtkFloatArray> st;
  st->SetName("TCoords");
  st->SetNumberOfComponents(2);
  st->InsertNextTuple2(0, 0);
  st->InsertNextTuple2(1, 0);
  st->InsertNextTuple2(1, 1);
  st->InsertNextTuple2(0, 1);
  quad->GetPointData()->SetTCoords(st);
  return quad;
}

/// The gathered block named `name`, or null.
vtkPolyData* Block(vtkRadiosityPass* pass, const std::string& name)
{
  vtkMultiBlockDataSet* blocks = pass->GetSceneGraph()->GetSceneInput();
  for (unsigned int b = 0; b < blocks->GetNumberOfBlocks(); ++b)
  {
    if (blocks->HasMetaData(b) && name == blocks->GetMetaData(b)->Get(vtkCompositeDataSet::NAME()))
    {
      return vtkPolyData::SafeDownCast(blocks->GetBlock(b));
    }
  }
  return nullptr;
}

bool Near(const double* a, double r, double g, double b)
{
  return std::fabs(a[0] - r) < 1e-6 && std::fabs(a[1] - g) < 1e-6 && std::fabs(a[2] - b) < 1e-6;
}

std::string Str(const double* v)
{
  return "(" + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " + std::to_string(v[2]) + ")";
}
}

int TestRadiosityPassMaterials(int, char*[])
{
  vtkFloatingPointExceptions::Disable();
  vtkNew<vtkRenderer> renderer;
  renderer->AutomaticLightCreationOff();
  bool ok = true;

  // actor 0: Diffuse 0.5 x DiffuseColor (0.8, 0.6, 0.4), glossy.
  vtkActor* plain = Add(renderer, Quad(0, 0));
  plain->GetProperty()->SetDiffuseColor(0.8, 0.6, 0.4);
  plain->GetProperty()->SetDiffuse(0.5);
  plain->GetProperty()->SetSpecular(0.3);
  plain->GetProperty()->SetSpecularColor(1.0, 0.5, 1.0);
  plain->GetProperty()->SetSpecularPower(20.0);
  // actor 1: white, clamped to 0.95.
  Add(renderer, Quad(2, 0))->GetProperty()->SetColor(1, 1, 1);
  // actor 2: cell colours (direct RGB scalars).
  auto cellColoured = Quad(4, 0);
  vtkNew<vtkUnsignedCharArray> cellRgb;
  cellRgb->SetNumberOfComponents(3);
  cellRgb->InsertNextTuple3(51, 102, 204);
  cellColoured->GetCellData()->SetScalars(cellRgb);
  Add(renderer, cellColoured);
  // actor 3: point colours, averaged per triangle.
  auto pointColoured = Quad(6, 0);
  vtkNew<vtkUnsignedCharArray> pointRgb;
  pointRgb->SetNumberOfComponents(3);
  pointRgb->InsertNextTuple3(255, 0, 0);
  pointRgb->InsertNextTuple3(0, 255, 0);
  pointRgb->InsertNextTuple3(0, 0, 255);
  pointRgb->InsertNextTuple3(0, 0, 0);
  pointColoured->GetPointData()->SetScalars(pointRgb);
  Add(renderer, pointColoured);
  // actor 4: PBR, half metallic, emissive: the only emitter of the scene.
  // Facing down from z = 2 over actor 0: turned about x and moved.
  vtkActor* pbr = Add(renderer, Quad(0, 2));
  pbr->RotateX(180.0);
  pbr->SetPosition(0.0, 1.0, 4.0);
  pbr->GetProperty()->SetInterpolationToPBR();
  pbr->GetProperty()->SetColor(0.6, 0.6, 0.8);
  pbr->GetProperty()->SetMetallic(0.5);
  pbr->GetProperty()->SetEmissiveFactor(0.5, 0.25, 0.0);
  // actor 5: mirrored (scale -1 in x) and moved up 1.
  vtkActor* mirrored = Add(renderer, Quad(0, 0));
  mirrored->SetScale(-1.0, 1.0, 1.0);
  mirrored->SetPosition(0.0, 0.0, 1.0);
  // actor 6: composite, block 0 hidden, block 1 coloured.
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, Quad(8, 0));
  blocks->SetBlock(1, Quad(10, 0));
  vtkNew<vtkCompositePolyDataMapper2> compositeMapper;
  compositeMapper->SetInputDataObject(blocks);
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  compositeMapper->SetCompositeDataDisplayAttributes(attributes);
  attributes->SetBlockVisibility(blocks->GetBlock(0), false);
  const double blockColour[3] = { 0.2, 0.4, 0.6 };
  attributes->SetBlockColor(blocks->GetBlock(1), blockColour);
  vtkNew<vtkActor> composite;
  composite->SetMapper(compositeMapper);
  renderer->AddActor(composite);
  // actor 7: wireframe, not gathered; and a headlight, not solved.
  Add(renderer, Quad(12, 0))->GetProperty()->SetRepresentationToWireframe();
  vtkNew<vtkLight> headlight;
  headlight->SetLightTypeToHeadlight();
  renderer->AddLight(headlight);
  // actor 8: a classic texture, red | blue, white property.
  const unsigned char redBlue[6] = { 255, 0, 0, 0, 0, 255 };
  vtkActor* textured = Add(renderer, TexturedQuad(14));
  textured->GetProperty()->SetColor(1, 1, 1);
  textured->SetTexture(Texture(2, redBlue, false));
  // actor 9: PBR base colour and emissive textures, one sRGB texel each.
  const unsigned char baseTexel[3] = { 128, 64, 255 }, emissiveTexel[3] = { 255, 128, 0 };
  vtkActor* pbrTextured = Add(renderer, TexturedQuad(16));
  pbrTextured->GetProperty()->SetInterpolationToPBR();
  pbrTextured->GetProperty()->SetColor(1, 1, 1);
  pbrTextured->GetProperty()->SetMetallic(0.0);
  pbrTextured->GetProperty()->SetBaseColorTexture(Texture(1, baseTexel, true));
  pbrTextured->GetProperty()->SetEmissiveFactor(1.0, 1.0, 1.0);
  pbrTextured->GetProperty()->SetEmissiveTexture(Texture(1, emissiveTexel, true));
  // actor 10: two-sided by its own PropertyKeys (a glTF doubleSided material).
  vtkActor* twoSided = Add(renderer, Quad(18, 0));
  vtkNew<vtkInformation> keys;
  keys->Set(vtkRadiosityRendererNode::TWO_SIDED(), 1);
  twoSided->SetPropertyKeys(keys);

  vtkNew<vtkRadiosityPass> pass;
  pass->SetMethod(vtkRadiosityFilter::Progressive);
  pass->GetFilter()->SetTolerance(1e-2);
  pass->GetFilter()->SetNumberOfThreads(2);
  if (!Check(pass->UpdateSolution(renderer), "UpdateSolution failed"))
  {
    return EXIT_FAILURE;
  }
  vtkRadiosityRendererNode* graph = pass->GetSceneGraph();
  std::cout << graph->GetSceneInput()->GetNumberOfBlocks() << " objects, "
            << graph->GetNumberOfTriangles() << " triangles, "
            << graph->GetSceneLights()->GetNumberOfItems() << " scene lights\n";
  ok &= Check(graph->GetSceneInput()->GetNumberOfBlocks() == 10, "10 objects expected");
  // The two-sided actor: its quad's two triangles and their reversed twins
  // (TwoSided 1), the one-sided ones without the array.
  if (vtkPolyData* b = Block(pass, "actor 10 (vtkOpenGLActor)"))
  {
    vtkDataArray* sides = b->GetCellData()->GetArray("TwoSided");
    ok &= Check(sides && sides->GetTuple1(0) == 1.0, "actor 10 is not marked TwoSided");
  }
  else
  {
    ok &= Check(false, "no object 'actor 10 (vtkOpenGLActor)'");
  }
  ok &= Check(!Block(pass, "actor 0 (vtkOpenGLActor)")->GetCellData()->GetArray("TwoSided"),
    "actor 0 was made two-sided");
  ok &= Check(graph->GetSceneLights()->GetNumberOfItems() == 0, "the headlight was gathered");

  const auto reflectance = [&](const std::string& name, vtkIdType cell) -> const double*
  {
    vtkPolyData* block = Block(pass, name);
    static const double none[3] = { -1, -1, -1 };
    if (!block || cell >= block->GetNumberOfCells())
    {
      std::cerr << "no object " << name << " cell " << cell << "\n";
      return none;
    }
    return block->GetCellData()->GetArray("Reflectance")->GetTuple3(cell);
  };
  const double* r = reflectance("actor 0 (vtkOpenGLActor)", 0);
  ok &= Check(Near(r, 0.4, 0.3, 0.2), "Diffuse x DiffuseColor: " + Str(r));
  if (vtkPolyData* b = Block(pass, "actor 0 (vtkOpenGLActor)"))
  {
    const double* s = b->GetCellData()->GetArray("Specular")->GetTuple3(0);
    ok &= Check(Near(s, 0.3, 0.15, 0.3), "Specular x SpecularColor: " + Str(s));
    ok &= Check(b->GetCellData()->GetArray("Shininess")->GetTuple1(0) == 20.0, "Shininess");
    ok &= Check(b->GetNumberOfCells() == 2, "the quad is not two triangles");
  }
  r = reflectance("actor 1 (vtkOpenGLActor)", 0);
  ok &= Check(Near(r, 0.95, 0.95, 0.95), "white clamped to 0.95: " + Str(r));
  r = reflectance("actor 2 (vtkOpenGLActor)", 1);
  ok &= Check(Near(r, 0.2, 0.4, 0.8), "cell colours: " + Str(r));
  // vtkTriangleFilter splits the quad of red, green, blue and black points
  // into (0, 1, 3) and (1, 2, 3).
  const double* r0 = reflectance("actor 3 (vtkOpenGLActor)", 0);
  ok &= Check(Near(r0, 1.0 / 3, 1.0 / 3, 0.0), "point colours of triangle 0: " + Str(r0));
  const double* r1 = reflectance("actor 3 (vtkOpenGLActor)", 1);
  ok &= Check(Near(r1, 0.0, 1.0 / 3, 1.0 / 3), "point colours of triangle 1: " + Str(r1));
  r = reflectance("actor 4 (vtkOpenGLActor)", 0);
  ok &= Check(Near(r, 0.3, 0.3, 0.4), "PBR base colour x (1 - metallic): " + Str(r));
  if (vtkPolyData* b = Block(pass, "actor 4 (vtkOpenGLActor)"))
  {
    const double* e = b->GetCellData()->GetArray("Emission")->GetTuple3(0);
    const double pi = 3.14159265358979323846;
    ok &= Check(Near(e, 0.5 * pi, 0.25 * pi, 0.0), "EmissiveFactor x LightScale: " + Str(e));
  }
  if (vtkPolyData* b = Block(pass, "actor 5 (vtkOpenGLActor)"))
  {
    double bounds[6];
    b->GetBounds(bounds);
    ok &= Check(bounds[0] == -1.0 && bounds[1] == 0.0 && bounds[4] == 1.0 && bounds[5] == 1.0,
      "the mirrored actor's world bounds");
    double n[3];
    vtkPolygon::ComputeNormal(b->GetPoints(), 3, b->GetCell(0)->GetPointIds()->GetPointer(0), n);
    ok &= Check(n[2] > 0.99, "the mirrored quad faces " + Str(n) + ", not up");
  }
  else
  {
    ok &= Check(false, "no mirrored object");
  }
  ok &= Check(!Block(pass, "actor 6 (vtkOpenGLActor) block 1"), "the hidden block was gathered");
  r = reflectance("actor 6 (vtkOpenGLActor) block 2", 0);
  ok &= Check(Near(r, 0.2, 0.4, 0.6), "the block colour: " + Str(r));
  ok &= Check(!Block(pass, "actor 7 (vtkOpenGLActor)"), "the wireframe actor was gathered");
  // Textures: the triangles (0, 1, 3) and (1, 2, 3) of the quad.
  // (copies: the array's GetTuple3 returns one buffer)
  double t0[3], t1[3];
  r = reflectance("actor 8 (vtkOpenGLActor)", 0);
  std::copy(r, r + 3, t0);
  r = reflectance("actor 8 (vtkOpenGLActor)", 1);
  std::copy(r, r + 3, t1);
  r0 = t0;
  r1 = t1;
  const double lowerLeft = 35.0 / 48.0, upperRight = 13.0 / 48.0;
  const double textureError = std::max({ std::fabs(r0[0] - lowerLeft), std::fabs(r0[2] - upperRight),
    std::fabs(r1[0] - upperRight), std::fabs(r1[2] - lowerLeft), std::fabs(r0[1]), std::fabs(r1[1]) });
  std::cout << "texture means " << Str(r0) << " and " << Str(r1) << ": off by " << textureError << "\n";
  ok &= Check(textureError < 5e-4, "texture means " + Str(r0) + " and " + Str(r1) + ", expected (" +
      std::to_string(lowerLeft) + ", 0, " + std::to_string(upperRight) + ") and the reverse");
  for (vtkIdType c = 0; c < 2; ++c)
  {
    r = reflectance("actor 9 (vtkOpenGLActor)", c);
    ok &= Check(Near(r, 0.21586050011389926, 0.05126945837404324, 0.95),
      "PBR base colour texture (sRGB): " + Str(r));
    if (vtkPolyData* b = Block(pass, "actor 9 (vtkOpenGLActor)"))
    {
      const double* e = b->GetCellData()->GetArray("Emission")->GetTuple3(c);
      const double pi = 3.14159265358979323846;
      ok &= Check(Near(e, pi, 0.21586050011389926 * pi, 0.0), "emissive texture x LightScale: " + Str(e));
    }
  }

  // Lit by the emissive PBR quad alone: the floor quads below receive light.
  const radiosity::SolverStatistics& statistics = pass->GetFilter()->GetStatistics();
  vtkDataArray* irradiance = pass->GetFilter()->GetOutput()->GetCellData()->GetArray("Irradiance");
  double range[2] = { 0, 0 };
  if (irradiance)
  {
    irradiance->GetRange(range, 0);
  }
  std::cout << "solved in " << statistics.SolveSeconds << " s, largest red irradiance " << range[1]
            << " W/m^2\n";
  ok &= Check(range[1] > 0.0, "the emissive PBR surface lights nothing");

  // Every node prints (PrintSelf of the pass, its filter and scene graph).
  std::ostringstream printed;
  pass->Print(printed);
  for (vtkViewNode* child : graph->GetChildren())
  {
    child->Print(printed);
    for (vtkViewNode* grandchild : child->GetChildren())
    {
      grandchild->Print(printed);
    }
  }
  ok &= Check(printed.str().find("NumberOfSolves: 1") != std::string::npos &&
      printed.str().find("Solvable: wireframe") != std::string::npos,
    "PrintSelf");

  // Method Auto, the pass's default: actor 0 is glossy, so face cluster
  // radiosity (radiosity::ChooseMethod), drawn by the vector irradiance
  // mapper that shows the glossy part.
  vtkNew<vtkRadiosityPass> chosen;
  chosen->GetFilter()->SetNumberOfThreads(2);
  ok &= Check(chosen->GetMethod() == vtkRadiosityFilter::Auto, "the pass's default method is Auto");
  ok &= Check(chosen->UpdateSolution(renderer), "Auto: UpdateSolution failed");
  ok &= Check(chosen->GetFilter()->GetResolvedMethod() == vtkRadiosityFilter::FaceCluster &&
      chosen->GetFilter()->GetMethodChoice().find("glossy") != std::string::npos,
    std::string("Auto chose ") + vtkRadiosityFilter::GetMethodName(chosen->GetFilter()->GetResolvedMethod()) +
      " (" + chosen->GetFilter()->GetMethodChoice() + ")");
  vtkActor* drawn = chosen->GetDisplay()->GetActor();
  ok &= Check(drawn && vtkVectorIrradianceMapper::SafeDownCast(drawn->GetMapper()),
    "Auto's face cluster solution is not drawn by the vector irradiance mapper");
  std::ostringstream chosenPrinted;
  chosen->Print(chosenPrinted);
  ok &= Check(chosenPrinted.str().find("ResolvedMethod: facecluster") != std::string::npos, "PrintSelf: ResolvedMethod");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
