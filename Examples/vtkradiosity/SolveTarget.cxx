#include "SolveTarget.h"

#include "SolveCommon.h"

#include "vtkDataObject.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiosityPass.h"

#include <algorithm>
#include <stdexcept>

namespace solve
{
SolveTarget::SolveTarget(vtkDataObject* input)
  : OwnFilter(vtkSmartPointer<vtkRadiosityFilter>::New())
{
  this->OwnFilter->SetInputData(input);
}

SolveTarget::SolveTarget(radiosity::cli::ImportedScene& imported, double maxReflectance)
  : Pass(vtkSmartPointer<vtkRadiosityPass>::New())
  , Imported(&imported)
{
  this->Pass->SetMaxReflectance(maxReflectance);
  this->Pass->SetLightScale(imported.LightScale);
}

SolveTarget::~SolveTarget() = default;

vtkRadiosityFilter* SolveTarget::Filter() const
{
  return this->Pass ? this->Pass->GetFilter() : this->OwnFilter.Get();
}

void SolveTarget::SetMethod(int method)
{
  if (this->Pass)
  {
    this->Pass->SetMethod(method);
  }
  this->Filter()->SetMethod(method);
}

void SolveTarget::SetTwoSided()
{
  if (this->Pass)
  {
    this->Pass->SetTwoSided(true);
  }
}

void SolveTarget::Update()
{
  if (!this->Pass)
  {
    this->OwnFilter->Update();
    return;
  }
  const std::string& file = this->Imported->File;
  // The pass reports through vtkErrorMacro and vtkWarningMacro: collected
  // here (the caller turned VTK's global display off for the filter's).
  radiosity::cli::VtkMessages messages;
  const int display = vtkObject::GetGlobalWarningDisplay();
  vtkObject::GlobalWarningDisplayOn();
  const bool solved = this->Pass->UpdateSolution(this->Imported->Renderer);
  vtkObject::SetGlobalWarningDisplay(display);
  this->Warnings.clear();
  const std::vector<std::string>& own = this->Filter()->GetWarnings();
  for (const std::string& w : messages.Warnings())
  {
    // The filter's own warnings are printed with the filter's.
    if (std::find(own.begin(), own.end(), w) == own.end())
    {
      this->Warnings.push_back(file + ": " + w);
    }
  }
  if (solved || !this->Filter()->GetLastError().empty())
  {
    return; // the filter's error, if any, is the caller's to report
  }
  // The pass refused the gathered scene before solving it: bad input.
  std::string why = messages.Errors().empty() ? std::string("vtkRadiosityPass could not solve it")
                                              : messages.Errors().front();
  const std::string prefix = "cannot solve the renderer's scene: ";
  if (why.compare(0, prefix.size(), prefix) == 0)
  {
    why = why.substr(prefix.size());
  }
  throw BadInput(file + ": " + why);
}

const radiosity::cli::ViewCamera* SolveTarget::Camera() const
{
  return this->Imported && this->Imported->HasCamera ? &this->Imported->Camera : nullptr;
}

radiosity::LightSet SolveTarget::SceneLights(const radiosity::LightSet& lights) const
{
  radiosity::LightSet all = lights;
  if (this->Imported)
  {
    for (const radiosity::Light& l : this->Imported->ExtraLights.Lights)
    {
      all.Lights.push_back(l);
    }
  }
  return all;
}

nlohmann::json SolveTarget::ImportReport() const
{
  if (!this->Imported)
  {
    return nullptr;
  }
  const radiosity::cli::ImportedScene& s = *this->Imported;
  nlohmann::json camera = nullptr;
  if (s.HasCamera)
  {
    const radiosity::cli::ViewCamera& c = s.Camera;
    camera = { { "position", { c.Position[0], c.Position[1], c.Position[2] } },
      { "focal_point", { c.FocalPoint[0], c.FocalPoint[1], c.FocalPoint[2] } },
      { "view_up", { c.ViewUp[0], c.ViewUp[1], c.ViewUp[2] } }, { "view_angle_deg", c.ViewAngle } };
  }
  return { { "importer", s.Importer }, { "path", "vtkRadiosityPass::UpdateSolution" },
    { "surface_actors", s.Actors }, { "polygons", s.Polygons }, { "file_lights", s.FileLights }, { "file_lights_left_out", s.LightsLeftOut },
    { "lights_solved_from_file_values", s.ExtraLights.Lights.size() },
    { "light_scale", s.LightScale }, { "camera", camera } };
}
}
