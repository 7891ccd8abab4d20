// vtkRadiosityPass with relighting (Lehtinen et al. 2007, section 6.5;
// vtkRadiosityFilter Relighting through GetFilter()), meshless and face
// cluster: the first render solves and precomputes the transfer (keeps the
// transfer couplings); moving the spot and dimming the sun relights instead
// of solving, and the relit picture equals a fresh solve's of the same
// lights, drawn by another pass in another window.
#include "PassTestScene.h"

#include "vtkDataArray.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRadiosityFilter.h"
#include "vtkRadiosityPass.h"
#include "vtkRenderWindow.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
constexpr int Width = 320, Height = 260;

/// The pass's window on PassTestScene, by `method` (meshless at 3 levels).
struct PassWindow
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRadiosityPass> Pass;
  PassTestScene::Scene Scene;
  explicit PassWindow(int method)
  {
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(Width, Height);
    this->Window->AddRenderer(this->Renderer);
    this->Scene = PassTestScene::Build(this->Renderer);
    this->Pass->SetMethod(method);
    this->Pass->GetFilter()->SetNumberOfThreads(2);
    this->Pass->GetFilter()->SetPointLevels(3);
    this->Renderer->SetPass(this->Pass);
  }
  /// The spot moved across the floor and turned, the sun dimmed and warmer.
  void MoveLights()
  {
    this->Scene.Spot->SetPosition(-0.3, 0.5, 2.2);
    this->Scene.Spot->SetFocalPoint(-0.4, 0.6, 0.0);
    this->Scene.Spot->SetColor(1.0, 0.85, 0.7);
    this->Scene.Sun->SetIntensity(0.3);
  }
};

bool StartsWith(const std::string& text, const std::string& prefix)
{
  return text.compare(0, prefix.size(), prefix) == 0;
}

/// Relit against fresh, by `method`: the largest irradiance difference
/// relative to the peak and the worst pixel channel must be within the bounds.
bool RelitEqualsFresh(int method, double valueBound, int pixelBound)
{
  const std::string name = vtkRadiosityFilter::GetMethodName(method);
  std::cout << name << ":\n";
  bool ok = true;
  int expected = 0;
  PassWindow relit(method);
  relit.Pass->GetFilter()->RelightingOn();
  ok &= PassTestScene::RenderAndCountSolves(relit.Window, relit.Pass, expected, 1, "first render");
  const std::string first = relit.Pass->GetFilter()->GetRelightingStatus();
  std::cout << "first render: " << first << "\n";
  ok &= PassTestScene::Check(StartsWith(first, "precomputed: "), name + ": the first render precomputes: " + first);

  relit.MoveLights();
  ok &= PassTestScene::RenderAndCountSolves(relit.Window, relit.Pass, expected, 1, "lights moved");
  const std::string second = relit.Pass->GetFilter()->GetRelightingStatus();
  std::cout << "lights moved: " << second << "\n";
  ok &= PassTestScene::Check(StartsWith(second, "relit: "), name + ": moved lights are relit: " + second);
  vtkNew<vtkUnsignedCharArray> relitPixels, freshPixels;
  relit.Window->GetPixelData(0, 0, Width - 1, Height - 1, 1, relitPixels);

  PassWindow fresh(method);
  fresh.MoveLights();
  int freshSolves = 0;
  ok &= PassTestScene::RenderAndCountSolves(fresh.Window, fresh.Pass, freshSolves, 1, "a fresh solve");
  fresh.Window->GetPixelData(0, 0, Width - 1, Height - 1, 1, freshPixels);

  // The solutions: the surfaces' irradiance, relative to the peak.
  vtkDataArray* a = relit.Pass->GetFilter()->GetOutput()->GetPointData()->GetArray("Irradiance");
  vtkDataArray* b = fresh.Pass->GetFilter()->GetOutput()->GetPointData()->GetArray("Irradiance");
  ok &= PassTestScene::Check(a && b && a->GetNumberOfTuples() == b->GetNumberOfTuples() && a->GetNumberOfTuples() > 0,
    "both passes have a surface with Irradiance");
  double peak = 0.0, worstValue = 0.0;
  for (vtkIdType i = 0; a && b && i < std::min(a->GetNumberOfTuples(), b->GetNumberOfTuples()); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      peak = std::max(peak, std::fabs(b->GetComponent(i, c)));
      worstValue = std::max(worstValue, std::fabs(a->GetComponent(i, c) - b->GetComponent(i, c)));
    }
  }
  int worstPixel = 0;
  double meanPixel = 0.0;
  for (vtkIdType i = 0; i < relitPixels->GetNumberOfValues(); ++i)
  {
    worstPixel = std::max(worstPixel, std::abs(int(relitPixels->GetValue(i)) - int(freshPixels->GetValue(i))));
    meanPixel += freshPixels->GetValue(i);
  }
  meanPixel /= std::max<vtkIdType>(1, freshPixels->GetNumberOfValues());
  std::cout << "relit against a fresh solve: irradiance " << worstValue / std::max(peak, 1e-300)
            << " of the peak, worst pixel channel " << worstPixel << " of 255; mean pixel " << meanPixel << "\n";
  ok &= PassTestScene::Check(meanPixel > 20.0, name + ": the picture is dark");
  ok &= PassTestScene::Check(
    peak > 0 && worstValue <= valueBound * peak, name + ": the relit irradiance is not a fresh solve's");
  ok &= PassTestScene::Check(worstPixel <= pixelBound, name + ": the relit picture is not a fresh solve's");
  return ok;
}
}

int TestRadiosityPassRelighting(int, char*[])
{
  vtkFloatingPointExceptions::Disable(); // llvmpipe and Embree trip them (DESIGN.md)
  // Measured, meshless: irradiance 5.5e-9 of the peak (27 receivers the
  // moved spot's oracle wants gathered and added to the transfer), worst
  // pixel channel 0 of 255; relit in 55 ms. Face cluster: 0 and 0 (the
  // same oracle over the same transfer couplings; 66,054 of 183,250 pairs
  // new to the moved spot), relit in 2.4 s.
  bool ok = RelitEqualsFresh(vtkRadiosityFilter::Meshless, 0.01, 2);
  ok &= RelitEqualsFresh(vtkRadiosityFilter::FaceCluster, 1e-12, 0);
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
