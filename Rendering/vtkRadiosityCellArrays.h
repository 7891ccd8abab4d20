// Checks of the optional cell arrays the radiosity mappers read (SPEC.md:
// `Reflectance`, `Emission`, `ObjectId`), shared by the mappers; not wrapped.
#ifndef vtkRadiosityCellArrays_h
#define vtkRadiosityCellArrays_h

#include <string>

class vtkPolyData;

namespace vtkRadiosityCellArrays
{
/**
 * True when the cell array `name` is absent, or numeric with `components`
 * components and a tuple per cell; otherwise false with `message` naming the
 * array and what is wrong with it.
 */
bool CheckOptional(vtkPolyData* input, const char* name, int components, std::string& message);
}

#endif
