#include "vtkFaceClusterHierarchy.h"

#include "vtkObjectFactory.h"

#include "Radiosity/FaceCluster/FaceClusterHierarchy.h"

vtkStandardNewMacro(vtkFaceClusterHierarchy);

vtkFaceClusterHierarchy::vtkFaceClusterHierarchy() = default;
vtkFaceClusterHierarchy::~vtkFaceClusterHierarchy() = default;

void vtkFaceClusterHierarchy::SetHierarchy(
  std::shared_ptr<const radiosity::FaceClusterHierarchy> hierarchy)
{
  this->Hierarchy = std::move(hierarchy);
  this->Modified();
}

void vtkFaceClusterHierarchy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  if (!this->Hierarchy)
  {
    os << indent << "Hierarchy: (none)\n";
    return;
  }
  const radiosity::FaceClusterHierarchy& h = *this->Hierarchy;
  os << indent << "Hierarchy: " << h.NumberOfTriangles() << " triangles, "
     << h.NumberOfClusters() << " clusters, " << h.Roots().size() << " roots, depth "
     << h.MaximumDepth() << ", " << h.MemoryBytes() << " bytes, built in " << h.BuildSeconds()
     << " s\n";
}
