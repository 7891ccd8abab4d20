#include "vtkRadiosityRendererNode.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkAssembly.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkCompositeDataSet.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkInformationKey.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkPropCollection.h"
#include "vtkRadiosityActorNode.h"
#include "vtkRadiosityLightNode.h"
#include "vtkRadiosityPolyDataMapperNode.h"
#include "vtkRenderer.h"

#include <map>

vtkStandardNewMacro(vtkRadiosityRendererNode);

vtkInformationKeyMacro(vtkRadiosityRendererNode, METHOD, Integer);
vtkInformationKeyMacro(vtkRadiosityRendererNode, TOLERANCE, Double);
vtkInformationKeyMacro(vtkRadiosityRendererNode, LIGHT_SCALE, Double);
vtkInformationKeyMacro(vtkRadiosityRendererNode, SKY_MODEL, Integer);
vtkInformationKeyMacro(vtkRadiosityRendererNode, MAX_REFLECTANCE, Double);
vtkInformationKeyMacro(vtkRadiosityRendererNode, TWO_SIDED, Integer);
vtkInformationKeyMacro(vtkRadiosityRendererNode, EXPOSURE, Double);
vtkInformationKeyMacro(vtkRadiosityRendererNode, TONE_MAPPING, Integer);
vtkInformationKeyMacro(vtkRadiosityRendererNode, NUMBER_OF_SOLVES, Integer);

namespace
{
// A renderer's setting, or the pass's default when the renderer has none.
template <typename Key, typename Value>
Value ReadSetting(vtkRenderer* renderer, Key* key, Value fallback)
{
  vtkInformation* info = renderer ? renderer->GetInformation() : nullptr;
  return info && info->Has(key) ? static_cast<Value>(info->Get(key)) : fallback;
}
}

// The defaults are those of a new vtkRadiosityPass (its filter's: method
// Auto, tolerance 1e-3, LightScale pi, no sky).
int vtkRadiosityRendererNode::GetMethod(vtkRenderer* r)
{
  return ReadSetting(r, METHOD(), 0);
}
double vtkRadiosityRendererNode::GetTolerance(vtkRenderer* r)
{
  return ReadSetting(r, TOLERANCE(), 1e-3);
}
double vtkRadiosityRendererNode::GetLightScale(vtkRenderer* r)
{
  return ReadSetting(r, LIGHT_SCALE(), 3.14159265358979323846);
}
int vtkRadiosityRendererNode::GetSkyModel(vtkRenderer* r)
{
  return ReadSetting(r, SKY_MODEL(), 0);
}
double vtkRadiosityRendererNode::GetMaxReflectance(vtkRenderer* r)
{
  return ReadSetting(r, MAX_REFLECTANCE(), 0.95);
}
bool vtkRadiosityRendererNode::GetTwoSided(vtkRenderer* r)
{
  return ReadSetting(r, TWO_SIDED(), 0) != 0;
}
double vtkRadiosityRendererNode::GetExposure(vtkRenderer* r)
{
  return ReadSetting(r, EXPOSURE(), 1.0);
}
int vtkRadiosityRendererNode::GetToneMapping(vtkRenderer* r)
{
  return ReadSetting(r, TONE_MAPPING(), 0);
}
int vtkRadiosityRendererNode::GetNumberOfSolves(vtkRenderer* r)
{
  return ReadSetting(r, NUMBER_OF_SOLVES(), 0);
}

vtkRadiosityRendererNode::vtkRadiosityRendererNode()
  : SceneInput(vtkSmartPointer<vtkMultiBlockDataSet>::New())
  , SceneLights(vtkSmartPointer<vtkLightCollection>::New())
{
}

vtkRadiosityRendererNode::~vtkRadiosityRendererNode() = default;

void vtkRadiosityRendererNode::Synchronize(bool prepass)
{
  auto* renderer = vtkRenderer::SafeDownCast(this->GetRenderable());
  if (!renderer)
  {
    return;
  }
  if (!prepass)
  {
    this->Gather();
    return;
  }
  // Names for errors: the actor's index among the renderer's actors.
  std::map<vtkObject*, int> index;
  vtkActorCollection* actors = renderer->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  int i = 0;
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    index[actor] = i++;
  }
  // The parts of assemblies (which the renderer's actors include): the
  // path's concatenated matrix and whether the assembly is visible. A part
  // in several paths (one actor in two assemblies) is placed by the first.
  std::map<vtkObject*, std::pair<vtkMatrix4x4*, bool>> parts;
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator pit;
  props->InitTraversal(pit);
  while (vtkProp* prop = props->GetNextProp(pit))
  {
    if (auto* assembly = vtkAssembly::SafeDownCast(prop))
    {
      assembly->InitPathTraversal();
      while (vtkAssemblyPath* path = assembly->GetNextPath())
      {
        vtkAssemblyNode* leaf = path->GetLastNode();
        parts.emplace(leaf->GetViewProp(), std::make_pair(leaf->GetMatrix(), assembly->GetVisibility() != 0));
      }
    }
  }
  for (vtkViewNode* child : this->GetChildren())
  {
    if (auto* node = vtkRadiosityActorNode::SafeDownCast(child))
    {
      vtkObject* actor = node->GetRenderable();
      const auto found = index.find(actor);
      node->SetLabel("actor " + std::to_string(found == index.end() ? -1 : found->second) + " (" +
        actor->GetClassName() + ")");
      const auto part = parts.find(actor);
      if (part == parts.end())
      {
        node->SetAssemblyPath(nullptr, true);
      }
      else
      {
        node->SetAssemblyPath(part->second.first, part->second.second);
      }
    }
  }
}

void vtkRadiosityRendererNode::Gather()
{
  this->SceneInput = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  this->SceneLights = vtkSmartPointer<vtkLightCollection>::New();
  this->GatherError.clear();
  this->GatherWarnings.clear();
  this->Gathered.clear();
  this->CurrentSignature.clear();
  this->NumberOfTriangles = 0;
  unsigned int block = 0;
  for (vtkViewNode* child : this->GetChildren())
  {
    if (auto* actorNode = vtkRadiosityActorNode::SafeDownCast(child))
    {
      vtkRadiosityPolyDataMapperNode* mapperNode = actorNode->GetMapperNode();
      if (!actorNode->GetSolvable() || !mapperNode)
      {
        continue;
      }
      if (!mapperNode->GetError().empty() && this->GatherError.empty())
      {
        this->GatherError = mapperNode->GetError();
      }
      this->GatherWarnings.insert(this->GatherWarnings.end(), mapperNode->GetWarnings().begin(),
        mapperNode->GetWarnings().end());
      if (mapperNode->GetObjects().empty() && mapperNode->GetError().empty())
      {
        continue; // nothing to solve (no polygons): drawn as VTK draws it
      }
      this->Gathered.insert(vtkProp::SafeDownCast(actorNode->GetRenderable()));
      this->CurrentSignature.emplace_back(actorNode->GetRenderable(), mapperNode->GetConversionTime());
      for (const vtkRadiosityPolyDataMapperNode::Object& object : mapperNode->GetObjects())
      {
        this->SceneInput->SetBlock(block, object.Data);
        this->SceneInput->GetMetaData(block)->Set(vtkCompositeDataSet::NAME(), object.Name.c_str());
        this->NumberOfTriangles += object.Data->GetNumberOfCells();
        ++block;
      }
    }
  }
  // The lights in the renderer's order (the order of its light collection).
  vtkLightCollection* lights = vtkRenderer::SafeDownCast(this->GetRenderable())->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    auto* node = vtkRadiosityLightNode::SafeDownCast(this->GetViewNodeFor(light));
    if (node && node->GetSolved())
    {
      this->SceneLights->AddItem(light);
      this->CurrentSignature.emplace_back(light, node->GetSceneMTime());
    }
  }
}

vtkMultiBlockDataSet* vtkRadiosityRendererNode::GetSceneInput()
{
  return this->SceneInput;
}

vtkLightCollection* vtkRadiosityRendererNode::GetSceneLights()
{
  return this->SceneLights;
}

vtkPolyData* vtkRadiosityRendererNode::GetSolutionSurface()
{
  return this->SolutionSurface;
}

vtkPolyData* vtkRadiosityRendererNode::GetSolutionProduct()
{
  return this->SolutionProduct;
}

bool vtkRadiosityRendererNode::IsGathered(vtkProp* prop) const
{
  return this->Gathered.count(prop) > 0;
}

void vtkRadiosityRendererNode::SetSolution(vtkPolyData* surface, vtkPolyData* product,
  const Signature& signature, vtkMTimeType filterTime)
{
  this->SolutionSurface = vtkSmartPointer<vtkPolyData>::New();
  this->SolutionSurface->ShallowCopy(surface);
  this->SolutionProduct = vtkSmartPointer<vtkPolyData>::New();
  if (product)
  {
    this->SolutionProduct->ShallowCopy(product);
  }
  this->SolvedSignature = signature;
  this->SolvedFilterTime = filterTime;
  this->Solved = true;
}

void vtkRadiosityRendererNode::ClearSolution(const Signature& signature, vtkMTimeType filterTime)
{
  this->SolutionSurface = nullptr;
  this->SolutionProduct = nullptr;
  this->SolvedSignature = signature;
  this->SolvedFilterTime = filterTime;
  this->Solved = true;
}

bool vtkRadiosityRendererNode::IsSolvedFor(const Signature& signature, vtkMTimeType filterTime) const
{
  return this->Solved && signature == this->SolvedSignature && filterTime <= this->SolvedFilterTime;
}

void vtkRadiosityRendererNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaxReflectance: " << this->MaxReflectance << "\n";
  os << indent << "LightScale: " << this->LightScale << "\n";
  os << indent << "TwoSided: " << (this->TwoSided ? "On" : "Off") << "\n";
  os << indent << "Objects: " << this->SceneInput->GetNumberOfBlocks() << " ("
     << this->NumberOfTriangles << " triangles) of " << this->Gathered.size() << " actors\n";
  os << indent << "SceneLights: " << this->SceneLights->GetNumberOfItems() << "\n";
  os << indent << "GatherError: " << (this->GatherError.empty() ? "(none)" : this->GatherError) << "\n";
  os << indent << "GatherWarnings: " << this->GatherWarnings.size() << "\n";
  os << indent << "Signature: " << this->CurrentSignature.size() << " entries\n";
  os << indent << "Solution: "
     << (this->SolutionSurface ? std::to_string(this->SolutionSurface->GetNumberOfCells()) + " cells"
                               : std::string("(none)"))
     << "\n";
}
