#include "vtkRadiosityCellTexelMapper.h"

#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"

#include "vtkMath.h"

#include "vtkActor.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkProperty.h"
#include "vtkRadiosityTexelBuffer.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"

#include <algorithm>

vtkRadiosityCellTexelMapper::vtkRadiosityCellTexelMapper(
  const char* uniform, int floatsPerCell, const char* what)
  : CellTexelUniform(uniform)
  , CellFloats(floatsPerCell)
  , What(what)
  , CellBuffer(new vtkRadiosityTexelBuffer)
{
  // The colour is the radiance: never map scalars through a lookup table.
  this->ScalarVisibilityOff();
}

vtkRadiosityCellTexelMapper::~vtkRadiosityCellTexelMapper() = default;

std::string vtkRadiosityCellTexelMapper::CellTexelIndex() const
{
  return std::to_string(this->CellFloats / 4) + " * (gl_PrimitiveID + PrimitiveIDOffset)";
}

void vtkRadiosityCellTexelMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* actor)
{
  this->CellTexelsReady = false;
  if (!this->DrawPiece || !this->DrawnPolyData)
  {
    return;
  }
  // Builds the VBO/IBOs (and the superclass's cell-to-cell map).
  this->Superclass::RenderPieceStart(ren, actor);
  const int representation = actor->GetProperty()->GetRepresentation();
  std::string error;
  this->CellTexelsReady = this->CellBuffer->IsCurrent(this->CellTexelsTime, representation) ||
    this->CellBuffer->UploadPerPrimitive(static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow()),
      this->CellCellMap, this->DrawnPolyData, representation, this->CellTexels, this->CellFloats,
      this->What.c_str(), error);
  if (!this->CellTexelsReady)
  {
    vtkErrorMacro(<< error);
    return;
  }
  this->CellBuffer->Activate();
}

void vtkRadiosityCellTexelMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* actor)
{
  if (this->DrawPiece && this->CellTexelsReady)
  {
    this->Superclass::RenderPieceDraw(ren, actor);
  }
}

void vtkRadiosityCellTexelMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* actor)
{
  if (!this->DrawPiece || !this->DrawnPolyData)
  {
    return;
  }
  if (this->CellTexelsReady)
  {
    this->CellBuffer->Deactivate();
  }
  this->Superclass::RenderPieceFinish(ren, actor);
}

void vtkRadiosityCellTexelMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, actor);
  if (this->CellTexelsReady && cellBO.Program->IsUniformUsed(this->CellTexelUniform.c_str()))
  {
    cellBO.Program->SetUniformi(this->CellTexelUniform.c_str(), this->CellBuffer->GetTextureUnit());
  }
  SetRadianceUniforms(cellBO.Program, this->Exposure, this->Gamma, this->ToneMapping);
  if (cellBO.Program->IsUniformUsed("vertexShiftMC"))
  {
    // The VBO stores (x - shift) * scale.
    float shift[3] = { 0.0f, 0.0f, 0.0f };
    float scale[3] = { 1.0f, 1.0f, 1.0f };
    vtkOpenGLVertexBufferObject* vbo = this->VBOs->GetVBO("vertexMC");
    if (vbo && vbo->GetCoordShiftAndScaleEnabled())
    {
      for (int i = 0; i < 3; ++i)
      {
        shift[i] = static_cast<float>(vbo->GetShift()[i]);
        scale[i] = static_cast<float>(vbo->GetScale()[i]);
      }
    }
    cellBO.Program->SetUniform3f("vertexShiftMC", shift);
    cellBO.Program->SetUniform3f("vertexScaleMC", scale);
  }
}

const char* vtkRadiosityCellTexelMapper::ModelPositionDeclarations()
{
  return "uniform vec3 vertexShiftMC;\nuniform vec3 vertexScaleMC;\n";
}

const char* vtkRadiosityCellTexelMapper::ModelPosition()
{
  return "(vertexMC.xyz / vertexScaleMC + vertexShiftMC)";
}

std::string vtkRadiosityCellTexelMapper::RadianceUniforms()
{
  return std::string("uniform float radianceScale;\n"
                     "uniform float inverseGamma;\n"
                     "uniform int toneOperator;\n") +
    RadianceDisplayFunction();
}

const char* vtkRadiosityCellTexelMapper::RadianceDisplayFunction()
{
  // The operators are vtkToneMappingPass's (Reinhard; Exponential with its
  // coefficient 1, the exposure being applied before).
  return "vec3 radianceDisplay(vec3 radiance)\n"
         "{\n"
         "  vec3 l = max(radiance, vec3(0.0));\n"
         "  if (toneOperator == 1) { l = l / (l + vec3(1.0)); }\n"
         "  else if (toneOperator == 2) { l = vec3(1.0) - exp(-l); }\n"
         "  return pow(l, vec3(inverseGamma));\n"
         "}\n";
}

std::string vtkRadiosityCellTexelMapper::EncodedRadiance(const std::string& radiosity)
{
  return "radianceDisplay((" + radiosity + ") * radianceScale)";
}

void vtkRadiosityCellTexelMapper::SetRadianceUniforms(
  vtkShaderProgram* program, double exposure, double gamma, int toneMapping)
{
  if (program->IsUniformUsed("radianceScale"))
  {
    // Lambertian surfaces: L = B / pi.
    program->SetUniformf("radianceScale", static_cast<float>(exposure / vtkMath::Pi()));
  }
  if (program->IsUniformUsed("inverseGamma"))
  {
    program->SetUniformf("inverseGamma", static_cast<float>(1.0 / gamma));
  }
  if (program->IsUniformUsed("toneOperator"))
  {
    program->SetUniformi("toneOperator", toneMapping);
  }
}

vtkUnsignedCharArray* vtkRadiosityCellTexelMapper::MapScalars(double alpha)
{
  int cellFlag = 0;
  return this->MapScalars(alpha, cellFlag);
}

vtkUnsignedCharArray* vtkRadiosityCellTexelMapper::MapScalars(double alpha, int& cellFlag)
{
  // An input without scalars: this also clears any colours left from before.
  return this->Superclass::MapScalars(this->NoScalars, alpha, cellFlag);
}

void vtkRadiosityCellTexelMapper::SetLightingShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  if (this->DrawingVertices)
  {
    this->Superclass::SetLightingShaderParameters(cellBO, ren, actor);
  }
}

void vtkRadiosityCellTexelMapper::ReplaceShaderTCoord(
  std::map<vtkShader::Type, vtkShader*>, vtkRenderer*, vtkActor*)
{
}

void vtkRadiosityCellTexelMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  this->CellBuffer->ReleaseGraphicsResources(win);
  this->CellTexelsReady = false;
  this->Superclass::ReleaseGraphicsResources(win);
}

void vtkRadiosityCellTexelMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "Gamma: " << this->Gamma << "\n";
  os << indent << "ToneMapping: "
     << (this->ToneMapping == REINHARD       ? "Reinhard"
            : this->ToneMapping == EXPONENTIAL ? "Exponential"
                                               : "Clamp")
     << "\n";
  os << indent << "CellTexelUniform: " << this->CellTexelUniform << "\n";
  os << indent << "CellFloats: " << this->CellFloats << "\n";
  os << indent << "Cells: " << this->CellTexels.size() / std::max(this->CellFloats, 1) << "\n";
  os << indent << "DrawPiece: " << (this->DrawPiece ? "true" : "false") << "\n";
  os << indent << "CellTexelsReady: " << (this->CellTexelsReady ? "true" : "false") << "\n";
  os << indent << "CellBuffer:\n";
  this->CellBuffer->PrintSelf(os, indent.GetNextIndent());
}
