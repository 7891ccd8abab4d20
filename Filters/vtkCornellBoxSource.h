/**
 * @class   vtkCornellBoxSource
 * @brief   the Cornell box as polydata with its materials
 *
 * The measured Cornell box (Cornell University Program of Computer Graphics),
 * in metres, with its two blocks, the common RGB reflectances and the light's
 * emission as cell data (`Reflectance`, `Emission`, `Specular`, `Shininess`),
 * one `ObjectId` per wall, block and light, and their names in the field data
 * array `ObjectNames`. The geometry is radiosity::MakeCornellBox.
 */
#ifndef vtkCornellBoxSource_h
#define vtkCornellBoxSource_h

#include "vtkPolyDataAlgorithm.h"
#include "RadiosityFiltersModule.h" // for export macro

class RADIOSITYFILTERS_EXPORT vtkCornellBoxSource : public vtkPolyDataAlgorithm
{
public:
  static vtkCornellBoxSource* New();
  vtkTypeMacro(vtkCornellBoxSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Scales the light's emission (1: radiance (17, 12, 4), exitance pi times
   * that). Clamped to [0, 1e12].
   */
  vtkSetClampMacro(LightScale, double, 0.0, 1e12);
  vtkGetMacro(LightScale, double);
  ///@}

  /// The camera of the Cornell box data (eye, focal point, view up, view angle in degrees).
  static void GetCamera(double position[3], double focalPoint[3], double viewUp[3], double& angle);

protected:
  vtkCornellBoxSource();
  ~vtkCornellBoxSource() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double LightScale = 1.0;

private:
  vtkCornellBoxSource(const vtkCornellBoxSource&) = delete;
  void operator=(const vtkCornellBoxSource&) = delete;
};

#endif
