#include "vtkMeshlessRadiositySolution.h"

#include "vtkObjectFactory.h"

#include "Radiosity/Meshless/MeshlessRadiosity.h"

vtkStandardNewMacro(vtkMeshlessRadiositySolution);

vtkMeshlessRadiositySolution::vtkMeshlessRadiositySolution() = default;
vtkMeshlessRadiositySolution::~vtkMeshlessRadiositySolution() = default;

void vtkMeshlessRadiositySolution::SetSolution(
  std::shared_ptr<const radiosity::MeshlessRadiosity> solution)
{
  if (this->Solution != solution)
  {
    this->Solution = std::move(solution);
    this->Modified();
  }
}

void vtkMeshlessRadiositySolution::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  if (!this->Solution)
  {
    os << indent << "Solution: (none)\n";
    return;
  }
  const radiosity::MeshlessRadiosity& s = *this->Solution;
  const radiosity::MeshlessStatistics& t = s.Statistics();
  os << indent << "Solution:\n";
  os << indent.GetNextIndent() << "Scene triangles: " << s.GetScene().Triangles.size() << "\n";
  os << indent.GetNextIndent() << "Samples generated: " << t.SamplesGenerated << "\n";
  os << indent.GetNextIndent() << "Samples gathered to: " << t.SamplesGatheredTo << "\n";
  os << indent.GetNextIndent() << "Levels: " << t.Levels << "\n";
}
