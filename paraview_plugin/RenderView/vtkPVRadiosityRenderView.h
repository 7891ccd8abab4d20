/**
 * @class   vtkPVRadiosityRenderView
 * @brief   ParaView's render view drawn through vtkRadiosityPass: the
 *          "Radiosity Render View"
 *
 * A vtkPVRenderView whose synchronized renderer draws with a
 * vtkRadiosityPass (installed as the view's render pass, inside ParaView's
 * camera pass, as the PanoramicProjectionView plugin installs its pass): the
 * visible opaque surface representations are solved by radiosity and drawn
 * per pixel with the method's mapper; translucent, wireframe and points
 * representations, 2D annotations and the orientation axes are drawn as the
 * render view draws them (vtkRadiosityPass's class documentation says what
 * is solved).
 *
 * Lights: only the view's scene lights are solved, the lights the Light
 * Inspector adds (the view's AdditionalLights, or `AddLight(view=...)` in
 * Python) whose coordinate space is Scene. ParaView's light kit, the
 * headlight and Camera lights move with the camera and are not part of the
 * solve; a view with no scene light (and no sky, no emissive `Emission`
 * array) is black.
 *
 * The solve's settings are view properties forwarded to the pass's filter
 * (Method, Tolerance, RadiosityLightScale, SkyModel, SkyRadiance, SkyUp),
 * and the display's (RadiosityExposure, RadiosityToneMapping) to the pass.
 * A solve runs at the render after what is shown, a light or a setting
 * changed (a camera move only redraws); its progress goes to ParaView's
 * progress bar (the filter is registered with the session's progress
 * handler).
 *
 * On MPI ranks (pvbatch or pvserver under mpirun): when the view renders
 * distributed (every rank draws its own pieces, IceT composites), the solve
 * gathers every rank's pieces and each rank draws the whole scene's solution
 * on its own (vtkRadiosityFilter's Controller); the view solves before
 * ParaView's render, on every rank, since IceT calls the pass only on the
 * ranks with something in view. When ParaView gathers the geometry onto one
 * process to render (small data), that process solves alone; a client of a
 * server that renders (remote rendering) solves nothing and shows the
 * server's image.
 */
#ifndef vtkPVRadiosityRenderView_h
#define vtkPVRadiosityRenderView_h

#include "RadiosityParaViewRenderViewModule.h" // For export macro
#include "vtkNew.h"                            // For members
#include "vtkPVRenderView.h"

class vtkRadiosityPass;

class RADIOSITYPARAVIEWRENDERVIEW_EXPORT vtkPVRadiosityRenderView : public vtkPVRenderView
{
public:
  static vtkPVRadiosityRenderView* New();
  vtkTypeMacro(vtkPVRadiosityRenderView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The solve's settings, forwarded to the pass's vtkRadiosityFilter.
  void SetMethod(int method);
  int GetMethod();
  void SetTolerance(double tolerance);
  double GetTolerance();
  void SetRadiosityLightScale(double scale);
  double GetRadiosityLightScale();
  void SetSkyModel(int model);
  int GetSkyModel();
  void SetSkyRadiance(double r, double g, double b);
  void SetSkyUp(double x, double y, double z);
  ///@}

  ///@{
  /// The display's settings, forwarded to the pass (redraw only).
  void SetRadiosityExposure(double exposure);
  double GetRadiosityExposure();
  void SetRadiosityToneMapping(int mode);
  int GetRadiosityToneMapping();
  void SetTwoSided(bool twoSided);
  ///@}

  /// How many solves the pass ran.
  int GetNumberOfSolves();

  /// The pass drawing the view's renderer.
  vtkRadiosityPass* GetRadiosityPass();

protected:
  vtkPVRadiosityRenderView();
  /// Solves on every rank (see the class doc), then renders as ParaView does.
  void Render(bool interactive, bool skip_rendering) override;
  ~vtkPVRadiosityRenderView() override;

  vtkNew<vtkRadiosityPass> RadiosityPass;

private:
  vtkPVRadiosityRenderView(const vtkPVRadiosityRenderView&) = delete;
  void operator=(const vtkPVRadiosityRenderView&) = delete;
};

#endif
