#pragma once
// Whether a surface is closed: the edges of a polygonal surface that do not join exactly two of its cells
// (vtkFeatureEdges' boundary and non-manifold edges). A closed surface has none.
#include <vtkPolyData.h>
#include <vtkType.h>

namespace heliostand {

vtkIdType open_edges(vtkPolyData& surface);

}  // namespace heliostand
