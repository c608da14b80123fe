#pragma once
// Writes a hollow mesh as VTK XML PolyData (.vtp) with its per-vertex arrays, for ParaView.
#include <string>

#include "hollow/hollow_mesh.hpp"

namespace heliostand::hollow {

// Point arrays: part, callus_thickness_m, bark_shift_m, bark_lift_m, bark_line. Throws OutputFolderError
// (a std::runtime_error) naming the file and the reason when it cannot be written (io/vtk_write_check.hpp).
void write_vtp(const HollowMesh& mesh, const std::string& path);

}  // namespace heliostand::hollow
