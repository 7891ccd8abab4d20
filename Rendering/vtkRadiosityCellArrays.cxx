#include "vtkRadiosityCellArrays.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellTypes.h"
#include "vtkDataArray.h"
#include "vtkPolyData.h"

#include <sstream>

bool vtkRadiosityCellArrays::CheckOptional(
  vtkPolyData* input, const char* name, int components, std::string& message)
{
  vtkCellData* cd = input->GetCellData();
  if (!cd->GetAbstractArray(name))
  {
    return true;
  }
  vtkDataArray* array = cd->GetArray(name);
  std::ostringstream os;
  if (!array)
  {
    os << "Cell array '" << name << "' is not numeric.";
  }
  else if (array->GetNumberOfComponents() != components)
  {
    os << "Cell array '" << name << "' has " << array->GetNumberOfComponents() << " components, "
       << components << (components == 3 ? " (RGB)" : "") << " expected.";
  }
  else if (array->GetNumberOfTuples() < input->GetNumberOfCells())
  {
    os << "Cell array '" << name << "' has " << array->GetNumberOfTuples() << " tuples for "
       << input->GetNumberOfCells() << " cells.";
  }
  else
  {
    return true;
  }
  message = os.str();
  return false;
}

std::string vtkRadiosityCellArrays::DescribeCell(vtkPolyData* input, vtkIdType cellId)
{
  std::ostringstream os;
  const char* type = vtkCellTypes::GetClassNameFromTypeId(input->GetCellType(cellId));
  const vtkIdType points = input->GetCellSize(cellId);
  os << "cell " << cellId << " is a " << (type ? type : "cell of unknown type") << " (" << points
     << (points == 1 ? " point" : " points") << ")";
  return os.str();
}

bool vtkRadiosityCellArrays::CheckPolygons(
  vtkPolyData* input, bool trianglesOnly, const std::string& hint, std::string& message)
{
  if (!input)
  {
    message = "No input polydata.";
    return false;
  }
  // VTK numbers vertices first, then lines, polys and strips: a vertex or
  // line, if any, is cell 0, and the first strip follows the polys.
  const vtkIdType polys = input->GetNumberOfPolys();
  vtkIdType offending = -1;
  if (input->GetNumberOfVerts() > 0 || input->GetNumberOfLines() > 0)
  {
    offending = 0;
  }
  else if (trianglesOnly)
  {
    vtkCellArray* cells = input->GetPolys();
    for (vtkIdType i = 0; i < polys && offending < 0; ++i)
    {
      offending = cells->GetCellSize(i) == 3 ? -1 : i;
    }
  }
  if (offending < 0 && input->GetNumberOfStrips() > 0)
  {
    offending = polys;
  }
  if (offending < 0)
  {
    return true;
  }
  message = "Input " + DescribeCell(input, offending) + hint;
  return false;
}
