#include "vtkRadiosityCellArrays.h"

#include "vtkCellData.h"
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
