#include "vtkPVRadiosityRenderView.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCommunicator.h"
#include "vtkDataObject.h"
#include "vtkMapper.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPVProgressHandler.h"
#include "vtkPVSession.h"
#include "vtkProcessModule.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiosityPass.h"
#include "vtkRenderer.h"

vtkStandardNewMacro(vtkPVRadiosityRenderView);

vtkPVRadiosityRenderView::vtkPVRadiosityRenderView()
{
  // The pass draws inside ParaView's camera pass; its own delegate (a
  // vtkRenderStepsPass) draws the solution and the props not solved.
  this->SynchronizedRenderers->SetRenderPass(this->RadiosityPass);
  vtkRadiosityFilter* filter = this->RadiosityPass->GetFilter();
  filter->SetProgressText("Radiosity solve");
  // Progress of a solve reaches the progress bar as a filter's does.
  if (vtkPVSession* session = this->GetSession())
  {
    if (vtkPVProgressHandler* handler = session->GetProgressHandler())
    {
      handler->RegisterProgressEvent(filter, 0);
    }
  }
}

vtkPVRadiosityRenderView::~vtkPVRadiosityRenderView()
{
  this->SynchronizedRenderers->SetRenderPass(nullptr);
}

void vtkPVRadiosityRenderView::Render(bool interactive, bool skip_rendering)
{
  // Distributed rendering: every rank holds its own pieces and the solve is
  // a collective over the ranks (IceT would call the pass's Render on the
  // ranks with something in view only, so the solve runs here, where every
  // rank is). Otherwise this process holds all that is drawn: a local solve.
  const bool distributed = interactive ? this->GetUseDistributedRenderingForLODRender()
                                       : this->GetUseDistributedRenderingForRender();
  vtkMultiProcessController* global = vtkMultiProcessController::GetGlobalController();
  const bool ranks = distributed && global && global->GetNumberOfProcesses() > 1;
  // A client of a server that renders (remote rendering) shows the server's
  // image: it holds no geometry and solves nothing.
  const bool client = distributed && vtkProcessModule::GetProcessType() == vtkProcessModule::PROCESS_CLIENT;
  this->RadiosityPass->GetFilter()->SetController(ranks ? global : nullptr);
  this->RadiosityPass->SetSolveOnRender(!ranks && !client);
  // A view that shows nothing on any rank yet (the renders before the data
  // of a Show arrives) has nothing to solve.
  int shown = 0;
  vtkActorCollection* actors = this->GetRenderer()->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    vtkMapper* mapper = actor->GetMapper();
    vtkDataObject* data = mapper ? mapper->GetInputDataObject(0, 0) : nullptr;
    if (actor->GetVisibility() && data && data->GetNumberOfElements(vtkDataObject::CELL) > 0)
    {
      shown = 1;
      break;
    }
  }
  if (ranks)
  {
    int any = 0;
    global->AllReduce(&shown, &any, 1, vtkCommunicator::MAX_OP);
    shown = any;
  }
  if (ranks && !client && shown && !skip_rendering)
  {
    this->RadiosityPass->UpdateSolution(this->GetRenderer());
  }
  this->Superclass::Render(interactive, skip_rendering);
}

vtkRadiosityPass* vtkPVRadiosityRenderView::GetRadiosityPass()
{
  return this->RadiosityPass;
}

void vtkPVRadiosityRenderView::SetMethod(int method)
{
  this->RadiosityPass->SetMethod(method);
}

int vtkPVRadiosityRenderView::GetMethod()
{
  return this->RadiosityPass->GetMethod();
}

void vtkPVRadiosityRenderView::SetTolerance(double tolerance)
{
  this->RadiosityPass->GetFilter()->SetTolerance(tolerance);
}

double vtkPVRadiosityRenderView::GetTolerance()
{
  return this->RadiosityPass->GetFilter()->GetTolerance();
}

void vtkPVRadiosityRenderView::SetRadiosityLightScale(double scale)
{
  this->RadiosityPass->SetLightScale(scale);
}

double vtkPVRadiosityRenderView::GetRadiosityLightScale()
{
  return this->RadiosityPass->GetLightScale();
}

void vtkPVRadiosityRenderView::SetSkyModel(int model)
{
  this->RadiosityPass->SetSkyModel(model);
}

int vtkPVRadiosityRenderView::GetSkyModel()
{
  return this->RadiosityPass->GetSkyModel();
}

void vtkPVRadiosityRenderView::SetSkyRadiance(double r, double g, double b)
{
  this->RadiosityPass->SetSkyRadiance(r, g, b);
}

void vtkPVRadiosityRenderView::SetSkyUp(double x, double y, double z)
{
  this->RadiosityPass->SetSkyUp(x, y, z);
}

void vtkPVRadiosityRenderView::SetRadiosityExposure(double exposure)
{
  this->RadiosityPass->SetExposure(exposure);
}

double vtkPVRadiosityRenderView::GetRadiosityExposure()
{
  return this->RadiosityPass->GetExposure();
}

void vtkPVRadiosityRenderView::SetRadiosityToneMapping(int mode)
{
  this->RadiosityPass->SetToneMapping(mode);
}

int vtkPVRadiosityRenderView::GetRadiosityToneMapping()
{
  return this->RadiosityPass->GetToneMapping();
}

void vtkPVRadiosityRenderView::SetTwoSided(bool twoSided)
{
  this->RadiosityPass->SetTwoSided(twoSided);
}

int vtkPVRadiosityRenderView::GetNumberOfSolves()
{
  return this->RadiosityPass->GetNumberOfSolves();
}

void vtkPVRadiosityRenderView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RadiosityPass:\n";
  this->RadiosityPass->PrintSelf(os, indent.GetNextIndent());
}
