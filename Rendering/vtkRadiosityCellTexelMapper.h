/**
 * @class   vtkRadiosityCellTexelMapper
 * @brief   base of the radiosity mappers: a polydata mapper whose fragment
 *          shader reads per-cell data from a float texture buffer
 *
 * The radiosity mappers (vtkQuadraticInterpolantMapper,
 * vtkShepardSplatMapper, vtkVectorIrradianceMapper) carry per-cell floats
 * (coefficients, materials) that VTK's vertex buffers have no place for. A
 * subclass fills CellTexels (CellFloats floats per cell of the polydata
 * it draws, a multiple of 4), sets DrawnPolyData and DrawPiece when its
 * input is valid (in UpdateCameraShiftScale, before the draw), and reads the
 * texels in its fragment shader at CellTexelIndex(n) with the sampler named
 * by CellTexelUniform. This class lays the texels out per OpenGL primitive
 * through the superclass's cell-to-cell map (so the wireframe and points
 * representations work too), uploads them when they or the representation
 * change, binds them around the draw, and draws nothing for an input the
 * subclass refused. Lighting and textures do not apply.
 *
 * All of them write the radiance L = B / pi * Exposure encoded as
 * L^(1/Gamma) for a vtkToneMappingPass, which decodes it before its
 * operator: the fragment shader declares RadianceUniforms() and ends with
 * EncodedRadiance(); the uniforms are set here.
 */
#ifndef vtkRadiosityCellTexelMapper_h
#define vtkRadiosityCellTexelMapper_h

#include "RadiosityRenderingModule.h" // For export macro
#include "vtkNew.h" // For members
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkPolyData.h" // For members

#include <memory> // For members
#include <string> // For members
#include <vector> // For members

class vtkRadiosityTexelBuffer;
class vtkShaderProgram;

class RADIOSITYRENDERING_EXPORT vtkRadiosityCellTexelMapper : public vtkOpenGLPolyDataMapper
{
public:
  vtkAbstractTypeMacro(vtkRadiosityCellTexelMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Releases the texture buffer with the superclass's resources.
  void ReleaseGraphicsResources(vtkWindow* win) override;

  ///@{
  /**
   * Scale applied to the radiance B / pi (default 1), clamped to [0, 1e12].
   */
  vtkSetClampMacro(Exposure, double, 0.0, 1e12);
  vtkGetMacro(Exposure, double);
  ///@}

  ///@{
  /**
   * Gamma of the encoding of the fragment colour, L^(1/Gamma) (default 2.2,
   * which vtkToneMappingPass decodes before its operator). 1 writes the
   * linear radiance. Clamped to [0.1, 10].
   */
  vtkSetClampMacro(Gamma, double, 0.1, 10.0);
  vtkGetMacro(Gamma, double);
  ///@}

  /**
   * The tone mapping operator applied per fragment to the exposed radiance L,
   * before the 1/Gamma encoding: vtkToneMappingPass's global operators, for a
   * renderer without that pass (a ParaView view with its tone mapping off).
   * CLAMP (default) writes L itself, for a vtkToneMappingPass or a display
   * that clamps at 1; REINHARD writes L / (1 + L); EXPONENTIAL 1 - exp(-L).
   */
  enum ToneMappingOperator
  {
    CLAMP = 0,
    REINHARD = 1,
    EXPONENTIAL = 2
  };
  vtkSetClampMacro(ToneMapping, int, CLAMP, EXPONENTIAL);
  vtkGetMacro(ToneMapping, int);

  /**
   * The GLSL of the radiance encoding, shared with passes that draw the
   * radiance without this class's shaders: RadianceUniforms() declares the
   * uniforms radianceScale (Exposure / pi), inverseGamma and toneOperator and
   * defines RadianceDisplayFunction(), radianceDisplay(L), the encoded colour
   * of a radiance (for shaders whose uniforms are declared elsewhere, as
   * VTK's custom uniforms are); EncodedRadiance(radiosity) is the encoded
   * colour of a vec3 radiosity expression (W/m^2), negative parts cut;
   * SetRadianceUniforms sets the uniforms that `program` uses.
   */
  static std::string RadianceUniforms();
  static const char* RadianceDisplayFunction();
  static std::string EncodedRadiance(const std::string& radiosity);
  static void SetRadianceUniforms(
    vtkShaderProgram* program, double exposure, double gamma, int toneMapping);

  ///@{
  /**
   * Scalar colouring does not apply: the colour is the radiance. No scalars
   * are mapped (which also keeps the colour texture of
   * InterpolateScalarsBeforeMapping out of the shaders).
   */
  using Superclass::MapScalars;
  vtkUnsignedCharArray* MapScalars(double alpha) override;
  vtkUnsignedCharArray* MapScalars(double alpha, int& cellFlag) override;
  ///@}

protected:
  vtkRadiosityCellTexelMapper(const char* uniform, int floatsPerCell, const char* what);
  ~vtkRadiosityCellTexelMapper() override;

  ///@{
  /// Upload and bind the texels around the superclass's draw; nothing for a
  /// refused input.
  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceDraw(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;
  ///@}

  /// Binds the sampler uniform, and radianceScale (Exposure / pi) and
  /// inverseGamma when the shader uses them.
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  /// No lighting: sets nothing (except for vertices drawn by VertexVisibility).
  void SetLightingShaderParameters(
    vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  /// Textures do not apply: nothing to replace.
  void ReplaceShaderTCoord(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;

  /// GLSL: the index of the first texel of the current primitive's block.
  std::string CellTexelIndex() const;
  /// GLSL for the vertex shader: the declarations ModelPosition() needs,
  /// and the vertex's model coordinates. vertexMC holds them shifted and
  /// scaled when the VBO's shift-scale is on (ParaView turns it on); this
  /// undoes it (the uniforms are set here).
  static const char* ModelPositionDeclarations();
  static const char* ModelPosition();

  double Exposure = 1.0;
  double Gamma = 2.2;
  int ToneMapping = CLAMP;

  // Filled by the subclass.
  std::vector<float> CellTexels;
  vtkTimeStamp CellTexelsTime;
  vtkPolyData* DrawnPolyData = nullptr;
  bool DrawPiece = false;
  bool CellTexelsReady = false;

  const std::string CellTexelUniform;
  const int CellFloats;

private:
  vtkRadiosityCellTexelMapper(const vtkRadiosityCellTexelMapper&) = delete;
  void operator=(const vtkRadiosityCellTexelMapper&) = delete;

  const std::string What;
  std::unique_ptr<vtkRadiosityTexelBuffer> CellBuffer;
  vtkNew<vtkPolyData> NoScalars;
};

#endif
