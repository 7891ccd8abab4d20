#include "vtkCornellBoxSource.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkRadiositySceneConverter.h"

#include "Radiosity/Scenes/SceneGenerators.h"

vtkStandardNewMacro(vtkCornellBoxSource);

vtkCornellBoxSource::vtkCornellBoxSource()
{
  this->SetNumberOfInputPorts(0);
}

void vtkCornellBoxSource::GetCamera(
  double position[3], double focalPoint[3], double viewUp[3], double& angle)
{
  for (int i = 0; i < 3; ++i)
  {
    position[i] = radiosity::CornellCamera::Position[i];
    focalPoint[i] = radiosity::CornellCamera::FocalPoint[i];
    viewUp[i] = i == 1 ? 1.0 : 0.0;
  }
  angle = radiosity::CornellCamera::ViewAngle;
}

int vtkCornellBoxSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  radiosity::Scene scene = radiosity::MakeCornellBox();
  for (auto& m : scene.Materials)
  {
    m.Emission *= this->LightScale;
  }
  output->ShallowCopy(vtkRadiositySceneConverter::FromScene(scene));
  return 1;
}

void vtkCornellBoxSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightScale: " << this->LightScale << "\n";
}
