#include "io/open_edges.hpp"

#include <vtkFeatureEdges.h>
#include <vtkSmartPointer.h>

namespace heliostand {

vtkIdType open_edges(vtkPolyData& surface) {
  auto edges = vtkSmartPointer<vtkFeatureEdges>::New();
  edges->SetInputData(&surface);
  edges->BoundaryEdgesOn();     // on one cell only: a hole
  edges->NonManifoldEdgesOn();  // on three or more: a fin or a seam
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  edges->Update();
  return edges->GetOutput()->GetNumberOfCells();
}

}  // namespace heliostand
