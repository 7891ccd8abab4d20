// vtkRadiosityFilter's lights: the vtkLights, the scene lights, the
// LIGHTS.json file and the sky, gathered and validated for a request.
#include "vtkRadiosityFilter.h"

#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkRadiositySceneConverter.h"

#include "Radiosity/Common/Lights.h"

#include <sstream>
#include <string>

void vtkRadiosityFilter::AddLight(vtkLight* light)
{
  if (light && !this->Lights->IsItemPresent(light))
  {
    this->Lights->AddItem(light);
    this->Modified();
  }
}

void vtkRadiosityFilter::SetLights(vtkLightCollection* lights)
{
  this->Lights->RemoveAllItems();
  if (lights)
  {
    vtkCollectionSimpleIterator it;
    lights->InitTraversal(it);
    while (vtkLight* light = lights->GetNextLight(it))
    {
      this->Lights->AddItem(light);
    }
  }
  this->Modified();
}

vtkLightCollection* vtkRadiosityFilter::GetLights()
{
  return this->Lights;
}

void vtkRadiosityFilter::RemoveAllLights()
{
  if (this->Lights->GetNumberOfItems() > 0)
  {
    this->Lights->RemoveAllItems();
    this->Modified();
  }
}

void vtkRadiosityFilter::SetSceneLights(const radiosity::LightSet& lights)
{
  *this->SceneLights = lights;
  this->Modified();
}

vtkMTimeType vtkRadiosityFilter::GetMTime()
{
  vtkMTimeType time = std::max(this->Superclass::GetMTime(), this->Lights->GetMTime());
  vtkCollectionSimpleIterator it;
  this->Lights->InitTraversal(it);
  while (vtkLight* light = this->Lights->GetNextLight(it))
  {
    time = std::max(time, light->GetMTime());
  }
  return time;
}

const char* vtkRadiosityFilter::GetSkyModelName(int model)
{
  switch (model)
  {
    case SkyNone:
      return "none";
    case SkyUniform:
      return "uniform";
    case SkyCieOvercast:
      return "cie-overcast";
    default:
      return "unknown";
  }
}

radiosity::LightSet vtkRadiosityFilter::GatherLights() const
{
  using radiosity::LightSet;
  using radiosity::SceneError;
  LightSet all;
  std::string skyFrom;
  const auto addSky = [&all, &skyFrom](const radiosity::Sky& sky, const std::string& from)
  {
    if (sky.Model == radiosity::SkyModel::None)
    {
      return;
    }
    if (!skyFrom.empty())
    {
      throw SceneError(from + ": a second sky (the first from " + skyFrom +
        "; a scene has at most one)");
    }
    skyFrom = from;
    all.SkyLight = sky;
  };
  if (this->LightsFileName && *this->LightsFileName)
  {
    // Throws naming the file, the light's index and the field.
    const LightSet file = radiosity::ReadLightsFile(this->LightsFileName);
    all.Lights = file.Lights;
    addSky(file.SkyLight, std::string("LightsFileName ") + this->LightsFileName);
  }
  {
    LightSet scene = *this->SceneLights;
    try
    {
      radiosity::ValidateLights(scene);
    }
    catch (const SceneError& e)
    {
      throw SceneError(std::string("scene lights (SetSceneLights): ") + e.what());
    }
    all.Lights.insert(all.Lights.end(), scene.Lights.begin(), scene.Lights.end());
    addSky(scene.SkyLight, "the sky of SetSceneLights");
  }
  {
    LightSet vtk;
    std::vector<bool> on;
    vtkCollectionSimpleIterator it;
    this->Lights->InitTraversal(it);
    while (vtkLight* light = this->Lights->GetNextLight(it))
    {
      vtk.Lights.push_back(vtkRadiositySceneConverter::ToLight(light, this->LightScale));
      on.push_back(light->GetSwitch() != 0);
    }
    try
    {
      radiosity::ValidateLights(vtk);
    }
    catch (const SceneError& e)
    {
      // "light i (type): field ..." of the core, i the index among AddLight's lights.
      throw SceneError(std::string("vtkLights (AddLight, SetLights): ") + e.what());
    }
    for (std::size_t i = 0; i < vtk.Lights.size(); ++i)
    {
      if (on[i])
      {
        all.Lights.push_back(vtk.Lights[i]);
      }
    }
  }
  if (this->SkyModel != SkyNone)
  {
    radiosity::Sky sky;
    sky.Model = this->SkyModel == SkyUniform ? radiosity::SkyModel::Uniform
                                             : radiosity::SkyModel::CieOvercast;
    sky.Radiance = radiosity::RGB(this->SkyRadiance[0], this->SkyRadiance[1], this->SkyRadiance[2]);
    sky.Up = radiosity::Vec3(this->SkyUp[0], this->SkyUp[1], this->SkyUp[2]);
    LightSet check;
    check.SkyLight = sky;
    try
    {
      radiosity::ValidateLights(check);
    }
    catch (const SceneError& e)
    {
      throw SceneError(std::string("SkyModel ") + GetSkyModelName(this->SkyModel) +
        " (SkyRadiance, SkyUp): " + e.what());
    }
    addSky(check.SkyLight, std::string("SkyModel ") + GetSkyModelName(this->SkyModel));
  }
  return all;
}
