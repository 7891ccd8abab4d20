#include "vtkRadiosityTexelBuffer.h"

#include "vtkCellArray.h"
#include "vtkIndent.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLCellToVTKCellMap.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPolyData.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <sstream>

vtkRadiosityTexelBuffer::~vtkRadiosityTexelBuffer()
{
  if (this->Texture)
  {
    this->Texture->Delete();
  }
  if (this->Buffer)
  {
    this->Buffer->Delete();
  }
}

bool vtkRadiosityTexelBuffer::Upload(vtkOpenGLRenderWindow* window,
  const std::vector<float>& floats, const char* what, std::string& error)
{
  const size_t texels = floats.size() / 4;
  GLint maxTexels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
  std::ostringstream os;
  if (texels == 0 || texels > static_cast<size_t>(maxTexels))
  {
    os << "Cannot draw " << what << ": " << texels
       << " RGBA32F texels, GL_MAX_TEXTURE_BUFFER_SIZE is " << maxTexels << ".";
    error = os.str();
    return false;
  }
  if (!this->Texture)
  {
    this->Texture = vtkTextureObject::New();
    this->Buffer = vtkOpenGLBufferObject::New();
    this->Buffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
  }
  this->Texture->SetContext(window);
  if (!this->Buffer->Upload(floats, vtkOpenGLBufferObject::TextureBuffer) ||
    !this->Texture->CreateTextureBuffer(
      static_cast<unsigned int>(texels), 4, VTK_FLOAT, this->Buffer))
  {
    os << "Cannot create the texture buffer of " << what << " (" << texels
       << " RGBA32F texels).";
    error = os.str();
    return false;
  }
  vtkOpenGLStaticCheckErrorMacro("failed after uploading a texel buffer");
  this->Texels = texels;
  this->UploadTime.Modified();
  return true;
}

bool vtkRadiosityTexelBuffer::UploadPerPrimitive(vtkOpenGLRenderWindow* window,
  vtkOpenGLCellToVTKCellMap* map, vtkPolyData* poly, int representation,
  const std::vector<float>& perCell, int floatsPerCell, const char* what, std::string& error)
{
  // One block per OpenGL primitive: a triangle in the surface representation,
  // an edge in wireframe, a corner in points (the superclass's map, as for
  // cell scalars).
  vtkCellArray* prims[4] = { poly->GetVerts(), poly->GetLines(), poly->GetPolys(),
    poly->GetStrips() };
  map->Update(prims, representation, poly->GetPoints());
  const size_t primitives = map->GetSize();
  const size_t cells = perCell.size() / floatsPerCell;
  std::vector<float> texels(primitives * floatsPerCell);
  for (size_t i = 0; i < primitives; ++i)
  {
    const size_t cell = static_cast<size_t>(map->GetValue(i));
    if (cell >= cells)
    {
      std::ostringstream os;
      os << "OpenGL primitive " << i << " maps to cell " << cell << " of " << cells << ".";
      error = os.str();
      return false;
    }
    std::copy_n(perCell.data() + cell * floatsPerCell, floatsPerCell,
      texels.data() + i * floatsPerCell);
  }
  if (!this->Upload(window, texels, what, error))
  {
    return false;
  }
  this->Representation = representation;
  return true;
}

bool vtkRadiosityTexelBuffer::IsCurrent(const vtkTimeStamp& data, int representation) const
{
  return this->Texture && this->Texture->GetHandle() != 0 && this->UploadTime > data &&
    this->Representation == representation;
}

void vtkRadiosityTexelBuffer::Activate()
{
  this->Texture->Activate();
}

void vtkRadiosityTexelBuffer::Deactivate()
{
  this->Texture->Deactivate();
}

int vtkRadiosityTexelBuffer::GetTextureUnit() const
{
  return this->Texture ? this->Texture->GetTextureUnit() : -1;
}

void vtkRadiosityTexelBuffer::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(window);
  }
  if (this->Buffer)
  {
    this->Buffer->ReleaseGraphicsResources();
  }
  this->Representation = -1;
  this->Texels = 0;
}

void vtkRadiosityTexelBuffer::PrintSelf(std::ostream& os, vtkIndent indent) const
{
  os << indent << "Texels: " << this->Texels << " RGBA32F"
     << (this->Texture && this->Texture->GetHandle() != 0 ? " (on the GPU)" : " (not uploaded)")
     << ", representation " << this->Representation << "\n";
}
