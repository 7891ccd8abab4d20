#include "vtkRadiosityWindowPNG.h"

#include "vtkErrorCode.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"
#include "vtkWindowToImageFilter.h"

#include <cstdlib>

#if RADIOSITY_HAVE_X11
#include <X11/Xlib.h>
#endif

bool vtkRadiosityCanOpenWindow(vtkRenderWindow* window, std::string& error)
{
#if RADIOSITY_HAVE_X11
  if (window && window->IsA("vtkXOpenGLRenderWindow") && !window->GetGenericDisplayId())
  {
    Display* display = XOpenDisplay(nullptr);
    if (!display)
    {
      const char* name = std::getenv("DISPLAY");
      error = std::string("cannot render: no X display could be opened (DISPLAY='") +
        (name ? name : "") + "'); run under xvfb-run -a, or set DISPLAY to an X server";
      return false;
    }
    XCloseDisplay(display);
  }
#else
  (void)window;
  (void)error;
#endif
  return true;
}

bool vtkRadiosityWriteWindowPNG(vtkRenderWindow* window, const char* fileName, std::string& error)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(fileName);
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  if (writer->GetErrorCode() != vtkErrorCode::NoError)
  {
    error = std::string("Could not write PNG image '") + fileName +
      "': " + vtkErrorCode::GetStringFromErrorCode(writer->GetErrorCode());
    return false;
  }
  return true;
}
