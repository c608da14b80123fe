#pragma once
// Roots and soil as VTK data for the stand writer (ParaView):
//   root_polylines — one 2-point line per root segment; point data `radius` (m, for the Tube filter's
//                    "Vary Radius: By Absolute Scalar"), `type` (0 main, 1 lateral, 2 sinker, 3 fine),
//                    `tree_id`, `age` (years), `path` (0..7, −1 main root)
//   soil_image     — the soil grid as vtkImageData, point data `moisture`, `nutrient` (vertex values)
#include <span>

#include <vtkImageData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "roots/root_system.hpp"
#include "roots/soil_grid.hpp"

namespace heliostand::roots {

vtkSmartPointer<vtkPolyData> root_polylines(std::span<const RootSystem* const> trees);
vtkSmartPointer<vtkImageData> soil_image(const SoilGrid& soil);

}  // namespace heliostand::roots

namespace heliostand {

class RootZone;
class VtkTimeSeriesWriter;

// Adds the `roots` (segment polylines) and `soil` (vtkImageData) blocks of the stand's root zone to the years the
// writer writes whose stand age is a multiple of `age_multiple` (scenario key run.roots_output_interval).
void add_root_blocks(VtkTimeSeriesWriter& writer, const RootZone& zone, int age_multiple = 1);

}  // namespace heliostand
