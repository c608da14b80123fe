#include "io/root_vtk.hpp"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include "io/vtk_named_array.hpp"
#include "io/vtk_time_series_writer.hpp"
#include "stand/root_zone.hpp"

namespace heliostand::roots {

vtkSmartPointer<vtkPolyData> root_polylines(std::span<const RootSystem* const> trees) {
  vtkIdType segments = 0;
  for (const RootSystem* tree : trees) segments += static_cast<vtkIdType>(tree->segments().size());
  // Two points per segment (not shared at branch nodes), so every point carries its own segment's radius.
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(2 * segments);
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  auto radius = sized_named_array<vtkDoubleArray>("radius", 2 * segments);
  auto type = sized_named_array<vtkIntArray>("type", 2 * segments);
  auto tree_id = sized_named_array<vtkIntArray>("tree_id", 2 * segments);
  auto age = sized_named_array<vtkFloatArray>("age", 2 * segments);
  auto path = sized_named_array<vtkIntArray>("path", 2 * segments);
  vtkIdType point = 0;
  for (const RootSystem* tree : trees)
    for (const RootSegment& segment : tree->segments()) {
      points->SetPoint(point, segment.start.x, segment.start.y, segment.start.z);
      points->SetPoint(point + 1, segment.end.x, segment.end.y, segment.end.z);
      const vtkIdType ends[2] = {point, point + 1};
      lines->InsertNextCell(2, ends);
      for (vtkIdType p : ends) {
        radius->SetValue(p, segment.radius_m);
        type->SetValue(p, index_of(segment.type));
        tree_id->SetValue(p, tree->tree_id());
        age->SetValue(p, static_cast<float>(tree->age_of(segment)));
        path->SetValue(p, segment.sector);
      }
      point += 2;
    }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetLines(lines);
  for (vtkDataArray* array : {static_cast<vtkDataArray*>(radius), static_cast<vtkDataArray*>(type),
                              static_cast<vtkDataArray*>(tree_id), static_cast<vtkDataArray*>(age),
                              static_cast<vtkDataArray*>(path)})
    data->GetPointData()->AddArray(array);
  data->GetPointData()->SetActiveScalars("radius");
  return data;
}

vtkSmartPointer<vtkImageData> soil_image(const SoilGrid& soil) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  const glm::ivec3 n = soil.vertex_counts();
  image->SetDimensions(n.x, n.y, n.z);
  const glm::dvec3 origin = soil.min_corner();
  image->SetOrigin(origin.x, origin.y, origin.z);
  const double spacing = soil.geometry().spacing_m;
  image->SetSpacing(spacing, spacing, spacing);
  // vtkImageData orders points x fastest, then y, then z — the soil grid's own vertex order.
  for (auto [field, name] : {std::pair{SoilField::moisture, "moisture"}, std::pair{SoilField::nutrient, "nutrient"}}) {
    const std::vector<double>& values = soil.values(field);
    auto array = sized_named_array<vtkDoubleArray>(name, static_cast<vtkIdType>(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i) array->SetValue(static_cast<vtkIdType>(i), values[i]);
    image->GetPointData()->AddArray(array);
  }
  image->GetPointData()->SetActiveScalars("moisture");
  return image;
}

}  // namespace heliostand::roots

namespace heliostand {

void add_root_blocks(VtkTimeSeriesWriter& writer, const RootZone& zone, int age_multiple) {
  writer.add_block({"roots",
                    [&zone](const StandSnapshot&) -> vtkSmartPointer<vtkDataObject> {
                      return roots::root_polylines(zone.living_roots());
                    },
                    age_multiple});
  writer.add_block({"soil",
                    [&zone](const StandSnapshot&) -> vtkSmartPointer<vtkDataObject> {
                      return roots::soil_image(zone.soil());
                    },
                    age_multiple});
}

}  // namespace heliostand
