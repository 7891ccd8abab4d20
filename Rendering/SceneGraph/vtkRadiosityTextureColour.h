/**
 * @class   vtkRadiosityTextureColour
 * @brief   the mean colour of a texture over a triangle, for the
 *          reflectance (base colour) and emission the pass gathers
 *
 * A surface's colour texture (a glTF material's baseColorTexture and
 * emissiveTexture, which vtkGLTFImporter sets as the property's "albedoTex"
 * and "emissiveTex"; an OBJ's map_Kd, which vtkOBJImporter sets as the
 * actor's texture) multiplies its colour factor. A radiosity element has one
 * reflectance, so each triangle takes the texture's mean over the part of
 * the image its texture coordinates cover: the texture as VTK draws it
 * (bilinear, wrapped as the vtkTexture's Wrap says: clamped to the edge,
 * repeated, mirrored or the border colour; the image's row 0 at t = 0), decoded to linear values where the texture is in
 * the sRGB colour space (UseSRGBColorSpace, as glTF colour textures are),
 * averaged at the centroids of an n x n subdivision of the triangle, n = 8
 * per texel of the triangle's longest edge in texels (at least 8, at most
 * 64), so that a triangle covering a few texels is averaged to well under a
 * percent and a large one is not left to one sample.
 *
 * Images of unsigned char are read as [0, 255] (sRGB decoded or divided by
 * 255), other scalar types as linear values; 1 component is grey, 2 grey and
 * alpha, 3 RGB, 4 RGBA (alpha is not used: a translucent texel is not
 * solved differently).
 */
#ifndef vtkRadiosityTextureColour_h
#define vtkRadiosityTextureColour_h

#include "RadiosityRenderingSceneGraphModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for members

#include <string> // for std::string
#include <vector> // for std::vector

class vtkImageData;
class vtkTexture;

class RADIOSITYRENDERINGSCENEGRAPH_EXPORT vtkRadiosityTextureColour : public vtkObject
{
public:
  static vtkRadiosityTextureColour* New();
  vtkTypeMacro(vtkRadiosityTextureColour, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Reads the texture's image (its input, updated). Returns false with
   * `error` when it cannot be sampled: no image, an empty or 3D image, or
   * not 1 to 4 components, or a texel that is not finite or negative.
   */
  bool SetTexture(vtkTexture* texture, std::string& error);

  /// The mean linear colour over the triangle of texture coordinates `uv`.
  void TriangleMean(const double uv[3][2], double rgb[3]) const;

  /// The colour at texture coordinates (s, t), bilinear.
  void Sample(double s, double t, double rgb[3]) const;

  vtkGetMacro(Width, int);
  vtkGetMacro(Height, int);
  /// vtkTexture's wrap mode (ClampToEdge, Repeat, MirroredRepeat, ClampToBorder).
  vtkGetMacro(Wrap, int);
  vtkGetMacro(SRGB, bool);

protected:
  vtkRadiosityTextureColour();
  ~vtkRadiosityTextureColour() override;

private:
  vtkRadiosityTextureColour(const vtkRadiosityTextureColour&) = delete;
  void operator=(const vtkRadiosityTextureColour&) = delete;

  /// The texel (i, j), wrapped (the border colour outside for ClampToBorder).
  const double* Texel(int i, int j) const;

  int Width = 0;
  int Height = 0;
  int Wrap = 1;              ///< vtkTexture::Repeat
  double Border[3] = { 0.0, 0.0, 0.0 };
  bool SRGB = false;
  std::vector<double> Texels; ///< linear RGB, row by row from t = 0
};

#endif
