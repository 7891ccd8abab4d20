#include "vtkIrradianceSamplesMapper.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkIrradianceSamplesMapper);

namespace
{
const char* const SamplesLayout = "RGB at the cell's three points, then at its centroid";
const char* const ThisMapper = "vtkIrradianceSamplesMapper";
}

//------------------------------------------------------------------------------
vtkIrradianceSamplesMapper::vtkIrradianceSamplesMapper()
  : vtkRadiosityTriangleFieldMapper(
      GetSamplesArrayName(), 4, SamplesLayout, ThisMapper, "the irradiance samples")
{
}

//------------------------------------------------------------------------------
vtkIrradianceSamplesMapper::~vtkIrradianceSamplesMapper() = default;

//------------------------------------------------------------------------------
bool vtkIrradianceSamplesMapper::ValidateInput(vtkPolyData* input, std::string* message)
{
  return ValidateField(input, GetSamplesArrayName(), 4, SamplesLayout, ThisMapper, message);
}

//------------------------------------------------------------------------------
std::string vtkIrradianceSamplesMapper::FieldIrradianceGLSL() const
{
  // field0..2 at the corners, field3 at the centroid, where u s t = 1/27.
  return "  float u = 1.0 - s - t;\n"
         "  vec3 irradiance = u*field0 + s*field1 + t*field2 +\n"
         "    27.0*u*s*t*(field3 - (field0 + field1 + field2)/3.0);\n";
}

//------------------------------------------------------------------------------
void vtkIrradianceSamplesMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SamplesArrayName: " << GetSamplesArrayName() << "\n";
}
