// Checks of the cells and of the optional cell arrays the radiosity mappers
// read (SPEC.md: `Reflectance`, `Emission`, `ObjectId`), shared by the
// mappers; not wrapped.
#ifndef vtkRadiosityCellArrays_h
#define vtkRadiosityCellArrays_h

#include "vtkType.h"

#include <string>

class vtkPolyData;

namespace vtkRadiosityCellArrays
{
/**
 * Where a `Validate...(..., std::string* message)` writes why it refuses:
 * the caller's string, or a scratch one when the caller passed none;
 * cleared on construction.
 */
class Reason
{
public:
  explicit Reason(std::string* message)
    : Text(message ? *message : this->Scratch)
  {
    this->Text.clear();
  }
  Reason(const Reason&) = delete;
  Reason& operator=(const Reason&) = delete;

private:
  std::string Scratch;

public:
  std::string& Text;
};

/**
 * True when the cell array `name` is absent, or numeric with `components`
 * components and a tuple per cell; otherwise false with `message` naming the
 * array and what is wrong with it.
 */
bool CheckOptional(vtkPolyData* input, const char* name, int components, std::string& message);

/// "cell 12 is a vtkQuad (4 points)": the cell named by its VTK class.
std::string DescribeCell(vtkPolyData* input, vtkIdType cellId);

/**
 * True when `input` has polygons only (no vertices, lines or strips) and,
 * with `trianglesOnly`, no polygon but triangles; otherwise false with
 * `message` "Input <the first offending cell>" followed by `hint`, or
 * "No input polydata." when `input` is null.
 */
bool CheckPolygons(vtkPolyData* input, bool trianglesOnly, const std::string& hint, std::string& message);
}

#endif
