#include "light/far_field_margin.hpp"

#include <algorithm>
#include <cmath>

namespace heliostand {
namespace {

bool outermost_cells_empty(const FarField& far) {
  const VoxelGrid& grid = far.grid();
  const auto& density = far.density();
  for (int z = 0; z < grid.dims.z; ++z)
    for (int y = 0; y < grid.dims.y; ++y)
      for (int x = 0; x < grid.dims.x; ++x) {
        const bool outermost = x == 0 || y == 0 || x == grid.dims.x - 1 || y == grid.dims.y - 1;
        if (outermost && density[grid.index(x, y, z)] != 0.0) return false;
      }
  return true;
}

}  // namespace

int sweep_margin_cells(const FarField& far, std::span<const SkyPatch> patches) {
  const VoxelGrid& grid = far.grid();
  if (!grid.periodic && !outermost_cells_empty(far)) return 0;
  // A layer's lookups lie between start_distance() and start_distance() + reach along the patch's direction
  // (reach: to the next layer's mid-plane); the last layer's stop within half a reach, where the ray leaves the
  // grid's top or bottom. A lookup's upper corner is one cell further on.
  double farthest = 0.0;
  for (const auto& patch : patches) {
    const glm::dvec3& n = patch.direction;
    const double along = far.start_distance() + grid.cell.z / std::abs(n.z);
    farthest = std::max({farthest, along * std::abs(n.x) / grid.cell.x, along * std::abs(n.y) / grid.cell.y});
  }
  return std::min(sweep_margin_cap, static_cast<int>(std::ceil(farthest)) + 1);
}

std::vector<float> density_with_margin(const FarField& far, int margin) {
  const VoxelGrid& grid = far.grid();
  const int row = grid.dims.x + 2 * margin, rows = grid.dims.y + 2 * margin;
  std::vector<float> padded(std::size_t(row) * rows * grid.dims.z, 0.0f);
  for (int z = 0; z < grid.dims.z; ++z)
    for (int y = -margin; y < grid.dims.y + margin; ++y)
      for (int x = -margin; x < grid.dims.x + margin; ++x) {
        const bool inside = x >= 0 && y >= 0 && x < grid.dims.x && y < grid.dims.y;
        if (!inside && !grid.periodic) continue;  // zeros (the outermost cells are empty)
        const double sigma = far.density()[grid.index(wrap_cell(x, grid.dims.x), wrap_cell(y, grid.dims.y), z)];
        padded[(std::size_t(z) * rows + (y + margin)) * row + (x + margin)] = static_cast<float>(sigma);
      }
  return padded;
}

}  // namespace heliostand
