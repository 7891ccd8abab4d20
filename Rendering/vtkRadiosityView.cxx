#include "vtkRadiosityView.h"
#include "vtkIrradianceSamplesMapper.h"
#include "vtkQuadraticInterpolantMapper.h"
#include "vtkRadiosityWindowPNG.h"
#include "vtkShepardSplatMapper.h"
#include "vtkVectorIrradianceMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLRenderer.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkShaderProperty.h"
#include "vtkToneMappingPass.h"
#include "vtkUniforms.h"

#include <algorithm>
#include <cstring>
#include <string>

vtkStandardNewMacro(vtkRadiosityView);

namespace
{
// Names used in the shader replacements below.
const char* const RadiosityAttribute = "radiosityMC";
const char* const RadianceScaleUniform = "radianceScale";
}

//------------------------------------------------------------------------------
vtkRadiosityView::vtkRadiosityView()
{
  this->SetArrayName("Radiosity");

  // The plain OpenGL mapper: the radiosity values reach it as a generic vertex
  // attribute, not as scalars, so that nothing maps them through a lookup
  // table or clamps them to [0, 1].
  this->Mapper = vtkSmartPointer<vtkOpenGLPolyDataMapper>::New();
  this->Mapper->ScalarVisibilityOff();

  this->Actor = vtkSmartPointer<vtkActor>::New();
  this->Actor->SetMapper(this->Mapper);
  // Radiosity already is the light leaving the surface: no shading on top.
  this->Actor->GetProperty()->LightingOff();
  this->Actor->GetProperty()->SetInterpolationToGouraud();

  vtkShaderProperty* sp = this->Actor->GetShaderProperty();
  // Vertex stage: L = B / pi * Exposure per vertex; the rasterizer then
  // interpolates it linearly across each triangle (Gouraud on radiance).
  sp->AddVertexShaderReplacement("//VTK::Normal::Dec", true,
    "//VTK::Normal::Dec\n"
    "in vec3 radiosityMC;\n"
    "out vec3 radianceVSOutput;\n",
    false);
  sp->AddVertexShaderReplacement("//VTK::Normal::Impl", true,
    "//VTK::Normal::Impl\n"
    "  radianceVSOutput = radiosityMC * radianceScale;\n",
    false);
  // Fragment stage: overwrite whatever the lighting code wrote with the
  // radiance encoded as the radiosity mappers encode it (with their default
  // Gamma 2.2, which the tone mapping pass decodes before its operator, and
  // no operator of their own); the uniforms are custom ones, which VTK
  // declares.
  sp->AddFragmentShaderReplacement("//VTK::Normal::Dec", true,
    std::string("//VTK::Normal::Dec\n"
                "in vec3 radianceVSOutput;\n") +
      vtkRadiosityCellTexelMapper::RadianceDisplayFunction(),
    false);
  sp->AddFragmentShaderReplacement("//VTK::Light::Impl", true,
    "//VTK::Light::Impl\n"
    "  gl_FragData[0] = vec4(radianceDisplay(radianceVSOutput), 1.0);\n",
    false);
  vtkUniforms* fragment = sp->GetFragmentCustomUniforms();
  fragment->SetUniformf("inverseGamma", static_cast<float>(1.0 / 2.2));
  fragment->SetUniformi("toneOperator", vtkRadiosityCellTexelMapper::CLAMP);

  // The interpolant path: per-pixel evaluation of the quadratic interpolants.
  // Its actor carries none of the replacements above; only one of the two
  // actors is visible at a time.
  this->InterpolantMapper = vtkSmartPointer<vtkQuadraticInterpolantMapper>::New();
  this->InterpolantActor = vtkSmartPointer<vtkActor>::New();
  this->InterpolantActor->SetMapper(this->InterpolantMapper);
  this->InterpolantActor->GetProperty()->LightingOff();
  this->InterpolantActor->VisibilityOff();

  this->SplatMapper = vtkSmartPointer<vtkShepardSplatMapper>::New();
  this->SplatActor = vtkSmartPointer<vtkActor>::New();
  this->SplatActor->SetMapper(this->SplatMapper);
  this->SplatActor->VisibilityOff();

  this->VectorMapper = vtkSmartPointer<vtkVectorIrradianceMapper>::New();
  this->VectorActor = vtkSmartPointer<vtkActor>::New();
  this->VectorActor->SetMapper(this->VectorMapper);
  this->VectorActor->VisibilityOff();

  this->SamplesMapper = vtkSmartPointer<vtkIrradianceSamplesMapper>::New();
  this->SamplesActor = vtkSmartPointer<vtkActor>::New();
  this->SamplesActor->SetMapper(this->SamplesMapper);
  this->SamplesActor->VisibilityOff();

  this->Renderer = vtkSmartPointer<vtkOpenGLRenderer>::New();
  this->Renderer->SetBackground(0.0, 0.0, 0.0);
  this->Renderer->AddActor(this->Actor);
  this->Renderer->AddActor(this->InterpolantActor);
  this->Renderer->AddActor(this->SplatActor);
  this->Renderer->AddActor(this->VectorActor);
  this->Renderer->AddActor(this->SamplesActor);

  // The standard render steps (camera, lights, opaque, translucent, overlay)
  // draw into the tone mapping pass's float framebuffer, which keeps HDR.
  vtkNew<vtkRenderStepsPass> steps;
  this->ToneMappingPass = vtkSmartPointer<vtkToneMappingPass>::New();
  this->ToneMappingPass->SetDelegatePass(steps);
  // Exposure is applied in the vertex shader, so that it means the same for
  // every operator (vtkToneMappingPass uses its own only for some of them).
  this->ToneMappingPass->SetExposure(1.0f);
  vtkOpenGLRenderer::SafeDownCast(this->Renderer)->SetPass(this->ToneMappingPass);
}

//------------------------------------------------------------------------------
vtkRadiosityView::~vtkRadiosityView()
{
  this->SetArrayName(nullptr);
}

//------------------------------------------------------------------------------
void vtkRadiosityView::SetInputData(vtkPolyData* input)
{
  if (this->Input != input)
  {
    this->Input = input;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkPolyData* vtkRadiosityView::GetInputData()
{
  return this->Input;
}

//------------------------------------------------------------------------------
void vtkRadiosityView::SetSize(int width, int height)
{
  width = std::min(std::max(width, 1), 16384);
  height = std::min(std::max(height, 1), 16384);
  if (this->Size[0] != width || this->Size[1] != height)
  {
    this->Size[0] = width;
    this->Size[1] = height;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkRadiosityView::SetCamera(
  const double position[3], const double focalPoint[3], const double viewUp[3], double viewAngle)
{
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  camera->SetPosition(position);
  camera->SetFocalPoint(focalPoint);
  camera->SetViewUp(viewUp);
  camera->SetViewAngle(std::min(std::max(viewAngle, 0.01), 179.0));
  camera->OrthogonalizeViewUp();
  this->CameraSet = true;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkRadiosityView::ResetCamera()
{
  this->CameraSet = false;
  this->Modified();
}

//------------------------------------------------------------------------------
vtkRenderer* vtkRadiosityView::GetRenderer()
{
  return this->Renderer;
}

//------------------------------------------------------------------------------
vtkRenderWindow* vtkRadiosityView::GetRenderWindow()
{
  if (!this->RenderWindow)
  {
    vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::New();
    window->SetOffScreenRendering(this->OffScreen ? 1 : 0);
    // Multisampling would blend HDR samples before tone mapping and makes
    // images depend on the driver: keep one sample per pixel.
    window->SetMultiSamples(0);
    window->SetSize(this->Size);
    this->SetRenderWindow(window);
  }
  return this->RenderWindow;
}

//------------------------------------------------------------------------------
void vtkRadiosityView::SetRenderWindow(vtkRenderWindow* window)
{
  if (this->RenderWindow == window)
  {
    return;
  }
  if (this->RenderWindow)
  {
    this->RenderWindow->RemoveRenderer(this->Renderer);
  }
  this->RenderWindow = window;
  if (window)
  {
    window->AddRenderer(this->Renderer);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkRadiosityView::SetShepardField(vtkPolyData* field)
{
  if (this->ShepardField != field)
  {
    this->ShepardField = field;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkPolyData* vtkRadiosityView::GetShepardField()
{
  return this->ShepardField;
}

//------------------------------------------------------------------------------
bool vtkRadiosityView::UsesSplatMapper()
{
  return this->InterpolantRendering && this->ShepardField && this->ArrayName &&
    strcmp(this->ArrayName, "Radiosity") == 0;
}

//------------------------------------------------------------------------------
bool vtkRadiosityView::UsesVectorIrradianceMapper()
{
  return !this->UsesSplatMapper() && !this->UsesInterpolantMapper() && this->InterpolantRendering &&
    this->Input && this->ArrayName && strcmp(this->ArrayName, "Radiosity") == 0 &&
    this->Input->GetPointData()->GetAbstractArray("IrradianceVector") != nullptr;
}

//------------------------------------------------------------------------------
bool vtkRadiosityView::UsesInterpolantMapper()
{
  return !this->UsesSplatMapper() && this->InterpolantRendering && this->Input && this->ArrayName &&
    strcmp(this->ArrayName, "Radiosity") == 0 &&
    this->Input->GetCellData()->GetAbstractArray(
      vtkQuadraticInterpolantMapper::GetInterpolantArrayName()) != nullptr;
}

//------------------------------------------------------------------------------
bool vtkRadiosityView::UsesIrradianceSamplesMapper()
{
  return !this->UsesSplatMapper() && !this->UsesInterpolantMapper() &&
    !this->UsesVectorIrradianceMapper() && this->InterpolantRendering && this->Input &&
    this->ArrayName && strcmp(this->ArrayName, "Radiosity") == 0 &&
    this->Input->GetCellData()->GetAbstractArray(
      vtkIrradianceSamplesMapper::GetSamplesArrayName()) != nullptr;
}

//------------------------------------------------------------------------------
bool vtkRadiosityView::CheckInput()
{
  const char* name = this->ArrayName ? this->ArrayName : "";
  if (!this->Input)
  {
    vtkErrorMacro("No input polydata: call SetInputData first.");
    return false;
  }
  if (!*name)
  {
    vtkErrorMacro("No array name set: call SetArrayName (default \"Radiosity\").");
    return false;
  }
  if (this->Input->GetNumberOfPoints() == 0 || this->Input->GetNumberOfPolys() == 0)
  {
    vtkErrorMacro("Input has no polygons to draw (" << this->Input->GetNumberOfPoints()
                                                    << " points, "
                                                    << this->Input->GetNumberOfPolys()
                                                    << " polygons).");
    return false;
  }
  if (this->UsesSplatMapper())
  {
    std::string message;
    if (!vtkShepardSplatMapper::ValidateSurface(this->Input, &message) ||
      !vtkShepardSplatMapper::ValidateField(this->ShepardField, &message))
    {
      vtkErrorMacro(<< message);
      return false;
    }
    return true;
  }
  if (this->UsesVectorIrradianceMapper())
  {
    std::string message;
    if (!vtkVectorIrradianceMapper::ValidateInput(this->Input, &message))
    {
      vtkErrorMacro(<< message);
      return false;
    }
    return true;
  }
  if (this->UsesInterpolantMapper())
  {
    std::string message;
    if (!vtkQuadraticInterpolantMapper::ValidateInput(this->Input, &message))
    {
      vtkErrorMacro(<< message);
      return false;
    }
    return true;
  }
  if (this->UsesIrradianceSamplesMapper())
  {
    std::string message;
    if (!vtkIrradianceSamplesMapper::ValidateInput(this->Input, &message))
    {
      vtkErrorMacro(<< message);
      return false;
    }
    return true;
  }
  vtkPointData* pd = this->Input->GetPointData();
  vtkDataArray* array = pd->GetArray(name);
  if (!array)
  {
    if (pd->GetAbstractArray(name))
    {
      vtkErrorMacro("Point array '" << name << "' is not numeric.");
    }
    else if (this->Input->GetCellData()->GetArray(name))
    {
      vtkErrorMacro("No point array '" << name
                                       << "' (there is a cell array of that name: "
                                          "interpolate it to the points first).");
    }
    else
    {
      vtkErrorMacro("No point array '" << name << "' on the input.");
    }
    return false;
  }
  if (array->GetNumberOfComponents() != 3)
  {
    vtkErrorMacro("Point array '" << name << "' has " << array->GetNumberOfComponents()
                                  << " components, 3 (RGB, W/m^2) expected.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkRadiosityView::UpdatePipeline()
{
  this->ToneMappingPass->SetToneMappingType(this->ToneMappingType);
  const bool splats = this->UsesSplatMapper();
  const bool interpolants = this->UsesInterpolantMapper();
  const bool vectors = this->UsesVectorIrradianceMapper();
  const bool samples = this->UsesIrradianceSamplesMapper();
  this->SplatActor->SetVisibility(splats);
  this->InterpolantActor->SetVisibility(interpolants);
  this->VectorActor->SetVisibility(vectors);
  this->SamplesActor->SetVisibility(samples);
  this->Actor->SetVisibility(!interpolants && !splats && !vectors && !samples);
  if (samples)
  {
    this->SamplesMapper->SetInputData(this->Input);
    this->SamplesMapper->SetExposure(this->Exposure);
    return;
  }
  if (vectors)
  {
    this->VectorMapper->SetInputData(this->Input);
    this->VectorMapper->SetExposure(this->Exposure);
    return;
  }
  if (splats)
  {
    this->SplatMapper->SetInputData(this->Input);
    this->SplatMapper->SetFieldData(this->ShepardField);
    this->SplatMapper->SetExposure(this->Exposure);
    return;
  }
  if (interpolants)
  {
    this->InterpolantMapper->SetInputData(this->Input);
    this->InterpolantMapper->SetExposure(this->Exposure);
    return;
  }
  this->Mapper->SetInputData(this->Input);
  // Remapped at every render: the array name may have changed, and the
  // mapping is cheap; the mapper rebuilds its buffers only when needed.
  this->Mapper->RemoveAllVertexAttributeMappings();
  this->Mapper->MapDataArrayToVertexAttribute(
    RadiosityAttribute, this->ArrayName, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  // Lambertian surfaces: radiance L = B / pi.
  this->Actor->GetShaderProperty()->GetVertexCustomUniforms()->SetUniformf(
    RadianceScaleUniform, static_cast<float>(this->Exposure / vtkMath::Pi()));
}

//------------------------------------------------------------------------------
bool vtkRadiosityView::Render()
{
  if (!this->CheckInput())
  {
    return false;
  }
  this->UpdatePipeline();
  vtkRenderWindow* window = this->GetRenderWindow();
  std::string why;
  if (!vtkRadiosityCanOpenWindow(window, why))
  {
    vtkErrorMacro(<< why);
    return false;
  }
  window->SetSize(this->Size);
  if (!this->CameraSet)
  {
    // Frame the input once; later changes to the camera are the caller's.
    this->Renderer->ResetCamera(this->Input->GetBounds());
    this->CameraSet = true;
  }
  window->Render();
  return true;
}

//------------------------------------------------------------------------------
bool vtkRadiosityView::CanOpenWindow(std::string& why)
{
  vtkNew<vtkRenderWindow> window; // the factory's kind; nothing is opened
  return vtkRadiosityCanOpenWindow(window, why);
}

//------------------------------------------------------------------------------
bool vtkRadiosityView::WritePNG(const char* fileName)
{
  if (!fileName || !*fileName)
  {
    vtkErrorMacro("No file name given for the PNG image.");
    return false;
  }
  if (!this->Render())
  {
    return false;
  }
  std::string error;
  if (!vtkRadiosityWriteWindowPNG(this->GetRenderWindow(), fileName, error))
  {
    vtkErrorMacro(<< error);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkRadiosityView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "InputData: " << this->Input.GetPointer() << "\n";
  os << indent << "ArrayName: " << (this->ArrayName ? this->ArrayName : "(none)") << "\n";
  os << indent << "InterpolantRendering: " << (this->InterpolantRendering ? "On" : "Off") << "\n";
  os << indent << "UsesInterpolantMapper: " << (this->UsesInterpolantMapper() ? "true" : "false")
     << "\n";
  os << indent << "ShepardField: " << this->ShepardField.GetPointer() << "\n";
  os << indent << "UsesIrradianceSamplesMapper: "
     << (this->UsesIrradianceSamplesMapper() ? "true" : "false") << "\n";
  os << indent << "UsesSplatMapper: " << (this->UsesSplatMapper() ? "true" : "false") << "\n";
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "ToneMappingType: " << this->ToneMappingType << "\n";
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << "\n";
  os << indent << "OffScreen: " << (this->OffScreen ? "On" : "Off") << "\n";
  os << indent << "CameraSet: " << (this->CameraSet ? "true" : "false") << "\n";
  if (vtkCamera* camera = this->Renderer ? this->Renderer->GetActiveCamera() : nullptr)
  {
    const double* p = camera->GetPosition();
    const double* f = camera->GetFocalPoint();
    const double* u = camera->GetViewUp();
    os << indent << "Camera: position (" << p[0] << ", " << p[1] << ", " << p[2]
       << "), focal point (" << f[0] << ", " << f[1] << ", " << f[2] << "), view up (" << u[0]
       << ", " << u[1] << ", " << u[2] << "), view angle " << camera->GetViewAngle()
       << (this->CameraSet ? "" : " (framed at the next render)") << "\n";
  }
  os << indent << "Renderer: " << this->Renderer.GetPointer() << "\n";
  os << indent << "RenderWindow: " << this->RenderWindow.GetPointer() << "\n";
  os << indent << "ToneMappingPass: " << this->ToneMappingPass.GetPointer() << "\n";
  os << indent << "InterpolantMapper: " << this->InterpolantMapper.GetPointer() << "\n";
  os << indent << "SplatMapper: " << this->SplatMapper.GetPointer() << "\n";
  os << indent << "VectorMapper: " << this->VectorMapper.GetPointer() << "\n";
  os << indent << "UsesVectorIrradianceMapper: " << (this->UsesVectorIrradianceMapper() ? "true" : "false")
     << "\n";
}
