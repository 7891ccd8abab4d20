// A float texture buffer of RGBA32F texels that a fragment shader reads with
// texelFetch, for data that has no place in VTK's vertex buffers: per-cell
// blocks laid out per OpenGL primitive (read at gl_PrimitiveID +
// PrimitiveIDOffset, as vtkOpenGLPolyDataMapper does for cell scalars), or
// per-splat records. Shared by the radiosity mappers; not wrapped.
#ifndef vtkRadiosityTexelBuffer_h
#define vtkRadiosityTexelBuffer_h

#include "vtkTimeStamp.h"
#include "vtkType.h"

#include <ostream>
#include <string>
#include <vector>

class vtkIndent;
class vtkOpenGLBufferObject;
class vtkOpenGLCellToVTKCellMap;
class vtkOpenGLRenderWindow;
class vtkPolyData;
class vtkTextureObject;
class vtkWindow;

class vtkRadiosityTexelBuffer
{
public:
  vtkRadiosityTexelBuffer() = default;
  ~vtkRadiosityTexelBuffer();
  vtkRadiosityTexelBuffer(const vtkRadiosityTexelBuffer&) = delete;
  vtkRadiosityTexelBuffer& operator=(const vtkRadiosityTexelBuffer&) = delete;

  /**
   * Uploads `floats` (a multiple of 4) as RGBA32F texels; false with `error`
   * set when the GPU cannot hold them (GL_MAX_TEXTURE_BUFFER_SIZE) or the
   * upload fails. `what` names the data in the error.
   */
  bool Upload(vtkOpenGLRenderWindow* window, const std::vector<float>& floats, const char* what,
    std::string& error);

  /**
   * Lays out `perCell` (floatsPerCell floats per VTK cell of `poly`, a
   * multiple of 4) once per OpenGL primitive drawn for `representation`,
   * through the mapper's cell-to-cell map, and uploads it.
   */
  bool UploadPerPrimitive(vtkOpenGLRenderWindow* window, vtkOpenGLCellToVTKCellMap* map,
    vtkPolyData* poly, int representation, const std::vector<float>& perCell, int floatsPerCell,
    const char* what, std::string& error);

  /// Whether the last upload is newer than `data` and was for `representation`.
  bool IsCurrent(const vtkTimeStamp& data, int representation) const;

  /// Binds the buffer to a free texture unit (Activate) and frees it.
  void Activate();
  void Deactivate();
  int GetTextureUnit() const;

  void ReleaseGraphicsResources(vtkWindow* window);
  void PrintSelf(std::ostream& os, vtkIndent indent) const;

private:
  vtkTextureObject* Texture = nullptr;
  vtkOpenGLBufferObject* Buffer = nullptr;
  vtkTimeStamp UploadTime;
  int Representation = -1;
  size_t Texels = 0;
};

#endif
