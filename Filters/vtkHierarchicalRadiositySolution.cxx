#include "vtkHierarchicalRadiositySolution.h"

#include "vtkObjectFactory.h"

#include "Radiosity/Hierarchical/HierarchicalRadiosity.h"

vtkStandardNewMacro(vtkHierarchicalRadiositySolution);

vtkHierarchicalRadiositySolution::vtkHierarchicalRadiositySolution() = default;
vtkHierarchicalRadiositySolution::~vtkHierarchicalRadiositySolution() = default;

void vtkHierarchicalRadiositySolution::SetSolution(
  std::shared_ptr<const radiosity::HierarchicalRadiosity> solution)
{
  if (this->Solution != solution)
  {
    this->Solution = std::move(solution);
    this->Modified();
  }
}

void vtkHierarchicalRadiositySolution::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  if (!this->Solution)
  {
    os << indent << "Solution: (none)\n";
    return;
  }
  const radiosity::HierarchicalRadiosity& s = *this->Solution;
  os << indent << "Solution:\n";
  os << indent.GetNextIndent() << "Scene triangles: " << s.GetScene().Triangles.size() << "\n";
  os << indent.GetNextIndent() << "Nodes: " << s.Mesh().Elements().size() << "\n";
  os << indent.GetNextIndent() << "Links: " << s.Links().size() << "\n";
  os << indent.GetNextIndent() << "Leaves: " << s.Mesh().NumberOfLeaves() << "\n";
  os << indent.GetNextIndent() << "Link tolerance (W/m^2): " << s.GetLinkTolerance() << "\n";
}
