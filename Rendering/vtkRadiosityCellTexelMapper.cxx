#include "vtkRadiosityCellTexelMapper.h"

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
  if (cellBO.Program->IsUniformUsed("radianceScale"))
  {
    // Lambertian surfaces: L = B / pi.
    cellBO.Program->SetUniformf("radianceScale", static_cast<float>(this->Exposure / vtkMath::Pi()));
  }
  if (cellBO.Program->IsUniformUsed("inverseGamma"))
  {
    cellBO.Program->SetUniformf("inverseGamma", static_cast<float>(1.0 / this->Gamma));
  }
}

const char* vtkRadiosityCellTexelMapper::RadianceUniforms()
{
  return "uniform float radianceScale;\n"
         "uniform float inverseGamma;\n";
}

std::string vtkRadiosityCellTexelMapper::EncodedRadiance(const std::string& radiosity)
{
  return "pow(max((" + radiosity + ") * radianceScale, vec3(0.0)), vec3(inverseGamma))";
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
  os << indent << "CellTexelUniform: " << this->CellTexelUniform << "\n";
  os << indent << "CellFloats: " << this->CellFloats << "\n";
  os << indent << "Cells: " << this->CellTexels.size() / std::max(this->CellFloats, 1) << "\n";
  os << indent << "DrawPiece: " << (this->DrawPiece ? "true" : "false") << "\n";
  os << indent << "CellTexelsReady: " << (this->CellTexelsReady ? "true" : "false") << "\n";
  os << indent << "CellBuffer:\n";
  this->CellBuffer->PrintSelf(os, indent.GetNextIndent());
}
