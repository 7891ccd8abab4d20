#include "vtkQuadraticInterpolantMapper.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkQuadraticInterpolantMapper);

namespace
{
const char* const InterpolantLayout = "RGB x (A, 2B, 2C, D, 2E, F)";
const char* const ThisMapper = "vtkQuadraticInterpolantMapper";
}

//------------------------------------------------------------------------------
vtkQuadraticInterpolantMapper::vtkQuadraticInterpolantMapper()
  : vtkRadiosityTriangleFieldMapper(
      GetInterpolantArrayName(), 6, InterpolantLayout, ThisMapper, "the quadratic interpolants")
{
}

//------------------------------------------------------------------------------
vtkQuadraticInterpolantMapper::~vtkQuadraticInterpolantMapper() = default;

//------------------------------------------------------------------------------
bool vtkQuadraticInterpolantMapper::ValidateInput(vtkPolyData* input, std::string* message)
{
  return ValidateField(input, GetInterpolantArrayName(), 6, InterpolantLayout, ThisMapper, message);
}

//------------------------------------------------------------------------------
std::string vtkQuadraticInterpolantMapper::FieldIrradianceGLSL() const
{
  // field0 .. field5: A, 2B, 2C, D, 2E, F (R(s,t) = A s^2 + 2B st + 2C s +
  // D t^2 + 2E t + F, Hardt & Teller eq. 1).
  return "  vec3 irradiance = field0*s*s + field1*s*t + field2*s + field3*t*t + field4*t + "
         "field5;\n";
}

//------------------------------------------------------------------------------
void vtkQuadraticInterpolantMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "InterpolantArrayName: " << GetInterpolantArrayName() << "\n";
}
