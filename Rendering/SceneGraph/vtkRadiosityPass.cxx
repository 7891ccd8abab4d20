#include "vtkRadiosityPass.h"

#include "vtkActor.h"
#include "vtkAssembly.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkHardwareSelector.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkMatrix4x4.h"
#include "vtkProp.h"
#include "vtkProp3D.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiosityPassDisplay.h"
#include "vtkRadiosityRankExchange.h"
#include "vtkRadiosityRendererNode.h"
#include "vtkRadiositySceneConverter.h"
#include "vtkRadiosityViewNodeFactory.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkViewNode.h"

#include "Radiosity/Common/Lights.h"

#include <algorithm>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkRadiosityPass);

vtkRadiosityPass::vtkRadiosityPass()
  : Filter(vtkSmartPointer<vtkRadiosityFilter>::New())
  , Factory(vtkSmartPointer<vtkRadiosityViewNodeFactory>::New())
  , Display(vtkSmartPointer<vtkRadiosityPassDisplay>::New())
  , DefaultPass(vtkSmartPointer<vtkRenderStepsPass>::New())
  , ProgressObserver(vtkSmartPointer<vtkCallbackCommand>::New())
{
  this->DelegatePass = this->DefaultPass;
  this->ProgressObserver->SetCallback(&vtkRadiosityPass::ForwardProgress);
  this->ProgressObserver->SetClientData(this);
  this->Filter->AddObserver(vtkCommand::ProgressEvent, this->ProgressObserver);
}

vtkRadiosityPass::~vtkRadiosityPass()
{
  this->Filter->RemoveObserver(this->ProgressObserver);
}

void vtkRadiosityPass::ForwardProgress(vtkObject*, unsigned long, void* self, void* data)
{
  static_cast<vtkRadiosityPass*>(self)->InvokeEvent(vtkCommand::ProgressEvent, data);
}

vtkRadiosityFilter* vtkRadiosityPass::GetFilter()
{
  return this->Filter;
}

vtkViewNodeFactory* vtkRadiosityPass::GetFactory()
{
  return this->Factory;
}

vtkRadiosityRendererNode* vtkRadiosityPass::GetSceneGraph()
{
  return this->SceneGraph;
}

vtkRadiosityPassDisplay* vtkRadiosityPass::GetDisplay()
{
  return this->Display;
}

bool vtkRadiosityPass::HasSolution() const
{
  return this->SceneGraph && this->SceneGraph->HasSolution() && this->Display->GetActor();
}

vtkMTimeType vtkRadiosityPass::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->Filter->GetMTime());
}

void vtkRadiosityPass::SetMethod(int method)
{
  this->Filter->SetMethod(method);
}
int vtkRadiosityPass::GetMethod()
{
  return this->Filter->GetMethod();
}
void vtkRadiosityPass::SetLightScale(double scale)
{
  this->Filter->SetLightScale(scale);
}
double vtkRadiosityPass::GetLightScale()
{
  return this->Filter->GetLightScale();
}
void vtkRadiosityPass::SetSkyModel(int model)
{
  this->Filter->SetSkyModel(model);
}
int vtkRadiosityPass::GetSkyModel()
{
  return this->Filter->GetSkyModel();
}
void vtkRadiosityPass::SetSkyRadiance(double r, double g, double b)
{
  this->Filter->SetSkyRadiance(r, g, b);
}
void vtkRadiosityPass::SetSkyRadiance(const double radiance[3])
{
  this->Filter->SetSkyRadiance(radiance[0], radiance[1], radiance[2]);
}
double* vtkRadiosityPass::GetSkyRadiance()
{
  return this->Filter->GetSkyRadiance();
}
void vtkRadiosityPass::SetSkyUp(double x, double y, double z)
{
  this->Filter->SetSkyUp(x, y, z);
}
void vtkRadiosityPass::SetSkyUp(const double up[3])
{
  this->Filter->SetSkyUp(up[0], up[1], up[2]);
}
double* vtkRadiosityPass::GetSkyUp()
{
  return this->Filter->GetSkyUp();
}

void vtkRadiosityPass::SetDelegatePass(vtkRenderPass* pass)
{
  vtkRenderPass* next = pass ? pass : this->DefaultPass.GetPointer();
  if (this->DelegatePass != next)
  {
    this->DelegatePass = next;
    this->Modified();
  }
}

vtkRenderPass* vtkRadiosityPass::GetDelegatePass()
{
  return this->DelegatePass;
}

namespace
{
/// The i-th scene light handed to the filter, as the renderer holds it.
std::string LightLabel(vtkRenderer* renderer, vtkLight* light, int sceneIndex)
{
  int index = 0;
  vtkCollectionSimpleIterator it;
  renderer->GetLights()->InitTraversal(it);
  while (vtkLight* l = renderer->GetLights()->GetNextLight(it))
  {
    if (l == light)
    {
      break;
    }
    ++index;
  }
  return "scene light " + std::to_string(sceneIndex) + " (light " + std::to_string(index) +
    " of the renderer's lights, " + light->GetClassName() + ")";
}
}

bool vtkRadiosityPass::UpdateSolution(vtkRenderer* renderer)
{
  if (!renderer)
  {
    vtkErrorMacro("UpdateSolution: no renderer");
    return false;
  }
  if (!this->SceneGraph || this->SceneGraph->GetRenderable() != renderer)
  {
    vtkViewNode* node = this->Factory->CreateNode(renderer);
    this->SceneGraph.TakeReference(vtkRadiosityRendererNode::SafeDownCast(node));
    if (!this->SceneGraph)
    {
      if (node)
      {
        node->Delete();
      }
      vtkErrorMacro("UpdateSolution: no scene-graph node for " << renderer->GetClassName());
      return false;
    }
    this->Display->Clear();
  }
  vtkRadiosityRendererNode* graph = this->SceneGraph;
  this->PublishSettings(renderer);
  graph->SetMaxReflectance(this->MaxReflectance);
  graph->SetLightScale(this->Filter->GetLightScale());
  graph->SetTwoSided(this->TwoSided);
  graph->Traverse(vtkViewNode::build);
  graph->Traverse(vtkViewNode::synchronize);

  const vtkRadiosityRendererNode::Signature signature = graph->GetSignature();
  // Distributed (the filter's controller: ParaView's ranks, each rendering
  // its own actors): the ranks solve together or not at all, whichever
  // rank's actors changed, since the solve gathers every rank's piece.
  vtkMultiProcessController* controller = this->Filter->GetController();
  const bool distributed = controller && controller->GetNumberOfProcesses() > 1;
  bool solved = graph->IsSolvedFor(signature, this->Filter->GetMTime());
  if (distributed)
  {
    solved = !vtkRadiosityRankExchange::AnyRank(controller, !solved);
  }
  if (solved)
  {
    return graph->HasSolution();
  }

  // Something changed: solve again (or fail), and keep no half solution.
  this->Display->Clear();
  std::string error = graph->GetGatherError();
  vtkLightCollection* lights = graph->GetSceneLights();
  if (error.empty())
  {
    // Each light on its own, so that the error names it as the renderer holds it.
    int i = 0;
    vtkCollectionSimpleIterator it;
    lights->InitTraversal(it);
    while (vtkLight* light = lights->GetNextLight(it))
    {
      radiosity::LightSet one;
      one.Lights.push_back(vtkRadiositySceneConverter::ToLight(light, this->Filter->GetLightScale()));
      try
      {
        radiosity::ValidateLights(one);
      }
      catch (const std::exception& e)
      {
        error = LightLabel(renderer, light, i) + ": " + e.what();
        break;
      }
      ++i;
    }
  }
  // A rank may hold no actor of a distributed scene; the filter refuses a
  // scene empty on every rank.
  if (error.empty() && !distributed && graph->GetSceneInput()->GetNumberOfBlocks() == 0)
  {
    error = "the renderer has no solvable actor (visible, opaque, surface representation, with "
            "polygons)";
  }
  if (distributed)
  {
    // One rank's bad light fails every rank, before the filter's collectives.
    error = vtkRadiosityRankExchange::AgreeOnError(controller, error);
  }
  this->Filter->SetInputData(graph->GetSceneInput());
  this->Filter->SetLights(lights);
  if (error.empty())
  {
    for (const std::string& w : graph->GetGatherWarnings())
    {
      vtkWarningMacro(<< w);
    }
    ++this->NumberOfSolves;
    this->InvokeEvent(vtkCommand::StartEvent, nullptr);
    this->Filter->Update();
    if (!this->Filter->GetLastError().empty())
    {
      error = this->Filter->GetLastError();
    }
    else
    {
      vtkPolyData* surface = this->Filter->GetOutput(0);
      vtkPolyData* product = this->Filter->GetOutput(1);
      vtkSmartPointer<vtkPolyData> materials;
      if (this->Filter->GetResolvedMethod() == vtkRadiosityFilter::FaceCluster)
      {
        materials = vtkRadiositySceneConverter::FromScene(this->Filter->GetScene());
      }
      graph->SetSolution(surface, product, signature, this->Filter->GetMTime());
      // Distributed: a rank that holds none of the scene's triangles has
      // nothing of the solution to draw (not an error).
      const bool nothingHere = distributed && surface->GetNumberOfCells() == 0;
      if (!nothingHere && !this->Display->SetSolution(
            graph->GetSolutionSurface(), graph->GetSolutionProduct(), materials, error))
      {
        error = "the solution cannot be drawn: " + error;
      }
    }
    const double one = 1.0;
    this->InvokeEvent(vtkCommand::ProgressEvent, const_cast<double*>(&one));
    this->InvokeEvent(vtkCommand::EndEvent, nullptr);
  }
  this->PublishSettings(renderer); // the count of solves
  if (!error.empty())
  {
    this->Display->Clear();
    graph->ClearSolution(signature, this->Filter->GetMTime());
    vtkErrorMacro("cannot solve the renderer's scene: " << error);
    return false;
  }
  return true;
}

void vtkRadiosityPass::PublishSettings(vtkRenderer* renderer)
{
  vtkInformation* info = renderer->GetInformation();
  using Node = vtkRadiosityRendererNode;
  info->Set(Node::METHOD(), this->Filter->GetMethod());
  info->Set(Node::TOLERANCE(), this->Filter->GetTolerance());
  info->Set(Node::LIGHT_SCALE(), this->Filter->GetLightScale());
  info->Set(Node::SKY_MODEL(), this->Filter->GetSkyModel());
  info->Set(Node::MAX_REFLECTANCE(), this->MaxReflectance);
  info->Set(Node::TWO_SIDED(), this->TwoSided ? 1 : 0);
  info->Set(Node::EXPOSURE(), this->Exposure);
  info->Set(Node::TONE_MAPPING(), this->ToneMapping);
  info->Set(Node::NUMBER_OF_SOLVES(), this->NumberOfSolves);
}

void vtkRadiosityPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  vtkRenderer* renderer = s->GetRenderer();
  if (vtkHardwareSelector* selector = renderer->GetSelector())
  {
    // Hardware selection: the renderer's own props, drawn by the selector as
    // a renderer without a pass has them drawn (camera, clear, the selector's
    // passes over the props); no solve.
    renderer->GetActiveCamera()->Render(renderer);
    renderer->Clear();
    this->NumberOfRenderedProps =
      selector->Render(renderer, s->GetPropArray(), s->GetPropArrayCount());
    return;
  }
  if (this->SolveOnRender)
  {
    this->UpdateSolution(renderer);
  }
  const bool solved = this->HasSolution();
  std::vector<vtkProp*> props;
  std::vector<vtkProp3D*> poked;
  props.reserve(s->GetPropArrayCount() + 1);
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    auto* assembly = vtkAssembly::SafeDownCast(prop);
    if (solved && assembly && this->AddUnsolvedParts(assembly, props, poked))
    {
      continue;
    }
    if (!solved || !this->SceneGraph->IsGathered(prop))
    {
      props.push_back(prop);
    }
  }
  if (solved)
  {
    this->Display->SetExposure(this->Exposure);
    this->Display->SetToneMapping(this->ToneMapping);
    this->Display->Update();
    props.push_back(this->Display->GetActor());
  }
  vtkRenderState state(renderer);
  state.SetPropArrayAndCount(props.data(), static_cast<int>(props.size()));
  state.SetFrameBuffer(s->GetFrameBuffer());
  this->DelegatePass->Render(&state);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  for (vtkProp3D* part : poked)
  {
    part->PokeMatrix(nullptr);
  }
}

bool vtkRadiosityPass::AddUnsolvedParts(
  vtkAssembly* assembly, std::vector<vtkProp*>& props, std::vector<vtkProp3D*>& poked)
{
  // Whether any part was solved: else the assembly draws itself as usual.
  std::vector<std::pair<vtkProp3D*, vtkMatrix4x4*>> parts;
  bool anySolved = false;
  assembly->InitPathTraversal();
  while (vtkAssemblyPath* path = assembly->GetNextPath())
  {
    vtkAssemblyNode* leaf = path->GetLastNode();
    auto* part = vtkProp3D::SafeDownCast(leaf->GetViewProp());
    if (!part)
    {
      continue;
    }
    if (this->SceneGraph->IsGathered(part))
    {
      anySolved = true;
    }
    else if (part->GetVisibility())
    {
      parts.emplace_back(part, leaf->GetMatrix());
    }
  }
  if (!anySolved)
  {
    return false;
  }
  // The others are drawn as vtkAssembly draws them: each with its path's
  // matrix poked in for the draw (restored after it, in Render).
  for (const auto& part : parts)
  {
    if (std::find(poked.begin(), poked.end(), part.first) != poked.end())
    {
      continue; // one actor in two paths: drawn once
    }
    part.first->PokeMatrix(part.second);
    poked.push_back(part.first);
    props.push_back(part.first);
  }
  return true;
}

void vtkRadiosityPass::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Display->ReleaseGraphicsResources(window);
  this->DefaultPass->ReleaseGraphicsResources(window);
  if (this->DelegatePass != this->DefaultPass)
  {
    this->DelegatePass->ReleaseGraphicsResources(window);
  }
}

void vtkRadiosityPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Method: " << vtkRadiosityFilter::GetMethodName(this->Filter->GetMethod()) << "\n";
  os << indent << "ResolvedMethod: " << vtkRadiosityFilter::GetMethodName(this->Filter->GetResolvedMethod()) << "\n";
  os << indent << "MaxReflectance: " << this->MaxReflectance << "\n";
  os << indent << "TwoSided: " << (this->TwoSided ? "On" : "Off") << "\n";
  os << indent << "SolveOnRender: " << (this->SolveOnRender ? "On" : "Off") << "\n";
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "ToneMapping: " << this->ToneMapping << "\n";
  os << indent << "NumberOfSolves: " << this->NumberOfSolves << "\n";
  os << indent << "HasSolution: " << (this->HasSolution() ? "true" : "false") << "\n";
  os << indent << "Display: " << this->Display->GetPathName() << "\n";
  os << indent << "DelegatePass: " << this->DelegatePass.GetPointer()
     << (this->DelegatePass == this->DefaultPass ? " (default vtkRenderStepsPass)" : "") << "\n";
  os << indent << "Filter:\n";
  this->Filter->PrintSelf(os, indent.GetNextIndent());
  os << indent << "SceneGraph: ";
  if (this->SceneGraph)
  {
    os << "\n";
    this->SceneGraph->PrintSelf(os, indent.GetNextIndent());
  }
  else
  {
    os << "(none)\n";
  }
}
