// Internal: a render window's back buffer written as PNG, shared by the
// view and the convergence chart.
#ifndef vtkRadiosityWindowPNG_h
#define vtkRadiosityWindowPNG_h

#include <string>

class vtkRenderWindow;

/// Writes `window` (already rendered) to `fileName`; false with `error` set.
bool vtkRadiosityWriteWindowPNG(vtkRenderWindow* window, const char* fileName, std::string& error);

#endif
