// Internal: a render window's back buffer written as PNG, shared by the
// view and the convergence chart.
#ifndef vtkRadiosityWindowPNG_h
#define vtkRadiosityWindowPNG_h

#include <string>

class vtkRenderWindow;

/// Whether `window` can be opened: an X window needs a display, and VTK
/// aborts or crashes without one. False with `error` naming DISPLAY and the
/// way out (xvfb-run) when there is none; true for other kinds of window.
bool vtkRadiosityCanOpenWindow(vtkRenderWindow* window, std::string& error);

/// Writes `window` (already rendered) to `fileName`; false with `error` set.
bool vtkRadiosityWriteWindowPNG(vtkRenderWindow* window, const char* fileName, std::string& error);

#endif
