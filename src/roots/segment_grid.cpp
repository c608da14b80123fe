#include "roots/segment_grid.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace heliostand::roots {

SegmentGrid SegmentGrid::build(const SegmentList& segments, double widest_perception_radius_m, std::size_t max_cells) {
  SegmentGrid grid;
  glm::dvec3 low(0.0), high(0.0);
  segments.for_each([&](std::size_t s, const glm::dvec3& start, const glm::dvec3& end) {
    const glm::dvec3 middle = 0.5 * (start + end);
    low = s == 0 ? middle : glm::min(low, middle);
    high = s == 0 ? middle : glm::max(high, middle);
  });
  grid.longest_half_m = segments.longest_half_m();
  grid.origin = low;
  grid.cell_size_m = std::max(0.5 * (widest_perception_radius_m + grid.longest_half_m), 1e-6);
  auto dims_for = [&](double cell) { return glm::max(glm::ivec3(glm::floor((high - low) / cell)) + 1, glm::ivec3(1)); };
  grid.dims = dims_for(grid.cell_size_m);
  while (static_cast<std::size_t>(grid.dims.x) * grid.dims.y * grid.dims.z > max_cells) {
    grid.cell_size_m *= 1.5;
    grid.dims = dims_for(grid.cell_size_m);
  }

  // Counting sort of the segments by cell (cell indices fit an int: at most max_cells cells).
  const std::size_t cells = static_cast<std::size_t>(grid.dims.x) * grid.dims.y * grid.dims.z;
  std::vector<int> cell_of_segment(segments.size());
  grid.cell_start.assign(cells + 1, 0);
  segments.for_each([&](std::size_t s, const glm::dvec3& start, const glm::dvec3& end) {
    cell_of_segment[s] = static_cast<int>(grid.cell_index(grid.cell_of(0.5 * (start + end))));
    ++grid.cell_start[cell_of_segment[s] + 1];
  });
  for (std::size_t c = 0; c < cells; ++c) grid.cell_start[c + 1] += grid.cell_start[c];
  grid.cell_segments.resize(segments.size());
  std::vector<int> fill(grid.cell_start.begin(), grid.cell_start.end() - 1);
  for (std::size_t s = 0; s < segments.size(); ++s) grid.cell_segments[fill[cell_of_segment[s]]++] = static_cast<int>(s);
  return grid;
}

glm::ivec3 SegmentGrid::cell_of(const glm::dvec3& point) const {
  const glm::ivec3 cell(glm::floor((point - origin) / cell_size_m));
  return glm::clamp(cell, glm::ivec3(0), dims - 1);
}

std::size_t SegmentGrid::cell_index(const glm::ivec3& cell) const {
  return static_cast<std::size_t>(cell.x) + static_cast<std::size_t>(dims.x) * (cell.y + static_cast<std::size_t>(dims.y) * cell.z);
}

}  // namespace heliostand::roots
