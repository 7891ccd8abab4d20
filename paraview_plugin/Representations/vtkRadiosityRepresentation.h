/**
 * @class   vtkRadiosityRepresentation
 * @brief   ParaView's surface representation drawn by one of the radiosity
 *          mappers (a vtkRadiosityCellTexelMapper)
 *
 * The base of the representations "Radiosity Quadratic Interpolants",
 * "Vector Irradiance (glossy)" and "Meshless Field Splats": ParaView's
 * surface representation (vtkGeometryRepresentationWithFaces, so that every
 * property of the Surface representation keeps its meaning) whose mapper is
 * replaced by the subclass's radiosity mapper.
 *
 * ParaView delivers the geometry to the mapper as a vtkMultiBlockDataSet;
 * the radiosity mappers draw a vtkPolyData. At render time this class hands
 * the mapper the delivered polydata (its polydata blocks appended when there
 * are several), so the mapper sees the filter's cells in their order, with
 * their point order and cell arrays.
 *
 * The display parameters are the mapper's: Exposure (the scale of the
 * radiance B / pi), ToneMapping (the mapper's own operator, for a view
 * whose tone mapping is off; Clamp to leave it to the view's) and Gamma (the
 * encoding; 2.2 is what the view's tone mapping decodes).
 *
 * Level of detail is suppressed: ParaView's decimated LOD geometry loses
 * the per-cell layout the mappers read (a quadratic interpolant is tied to
 * its triangle's corners), so the full geometry is drawn while interacting.
 * Scalar colouring and lighting do not apply: the colour is the radiance.
 *
 * @sa vtkQuadraticInterpolantRepresentation, vtkVectorIrradianceRepresentation,
 *     vtkShepardSplatRepresentation, vtkRadiosityCellTexelMapper
 */

#ifndef vtkRadiosityRepresentation_h
#define vtkRadiosityRepresentation_h

#include "RadiosityParaViewRepresentationsModule.h" // For export macro
#include "vtkGeometryRepresentationWithFaces.h"
#include "vtkNew.h"       // For members
#include "vtkPolyData.h" // For members

class vtkRadiosityCellTexelMapper;

class RADIOSITYPARAVIEWREPRESENTATIONS_EXPORT vtkRadiosityRepresentation
  : public vtkGeometryRepresentationWithFaces
{
public:
  vtkTypeMacro(vtkRadiosityRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Forwarded to the mappers (vtkRadiosityCellTexelMapper): the exposure,
   * clamped to [0, 1e12] (default 1); the tone mapping operator, 0 Clamp,
   * 1 Reinhard, 2 Exponential (default 0); the encoding gamma, clamped to
   * [0.1, 10] (default 2.2).
   */
  void SetExposure(double exposure);
  double GetExposure();
  void SetToneMapping(int toneMapping);
  int GetToneMapping();
  void SetGamma(double gamma);
  double GetGamma();
  ///@}

  /**
   * Level of detail stays suppressed (see the class description).
   */
  void SetSuppressLOD(bool) override { this->Superclass::SetSuppressLOD(true); }

  /**
   * Hands the mapper the delivered surface before the render.
   */
  int ProcessViewRequest(vtkInformationRequestKey* request_type, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

protected:
  /**
   * Takes over `mapper` and a second instance of its class for the LOD
   * actor; called by the subclass's constructor.
   */
  explicit vtkRadiosityRepresentation(vtkRadiosityCellTexelMapper* mapper);
  ~vtkRadiosityRepresentation() override;

  vtkRadiosityCellTexelMapper* GetRadiosityMapper();

  /**
   * The polydata of a delivered piece: the piece itself, its only polydata
   * block, or its polydata blocks appended into `Appended`; an empty
   * polydata when there is none.
   */
  vtkPolyData* DeliveredSurface(vtkDataObject* piece);

  /// Given to a mapper that has nothing to draw.
  vtkNew<vtkPolyData> Empty;

private:
  vtkRadiosityRepresentation(const vtkRadiosityRepresentation&) = delete;
  void operator=(const vtkRadiosityRepresentation&) = delete;

  vtkNew<vtkPolyData> Appended;
};

#endif
