#include "roots/segment_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/parallel_for.hpp"

namespace heliostand::roots {

namespace {

// The midpoints' bounding box and the longest segment's half, each part (a tree's list) by its own thread: minima
// and maxima do not depend on the order they are taken in.
struct SegmentExtent {
  glm::dvec3 low{std::numeric_limits<double>::infinity()};
  glm::dvec3 high{-std::numeric_limits<double>::infinity()};
  double longest_half_m = 0.0;
};

SegmentExtent extent_of(const SegmentList& segments) {
  std::vector<SegmentExtent> of_part(segments.part_count());
  parallel_for(of_part.size(), [&](std::size_t part) {
    SegmentExtent& extent = of_part[part];
    segments.for_each_of_part(part, [&](std::size_t, const glm::dvec3& start, const glm::dvec3& end) {
      const glm::dvec3 middle = 0.5 * (start + end);
      extent.low = glm::min(extent.low, middle);
      extent.high = glm::max(extent.high, middle);
      extent.longest_half_m = std::max(extent.longest_half_m, 0.5 * glm::length(end - start));
    });
  });
  SegmentExtent whole;
  for (const SegmentExtent& part : of_part) {
    whole.low = glm::min(whole.low, part.low);
    whole.high = glm::max(whole.high, part.high);
    whole.longest_half_m = std::max(whole.longest_half_m, part.longest_half_m);
  }
  if (segments.empty()) whole.low = whole.high = glm::dvec3(0.0);
  return whole;
}

}  // namespace

SegmentGrid SegmentGrid::build(const SegmentList& segments, double widest_perception_radius_m, std::size_t max_cells) {
  SegmentGrid grid;
  const SegmentExtent extent = extent_of(segments);
  const glm::dvec3 low = extent.low, high = extent.high;
  grid.longest_half_m = extent.longest_half_m;
  grid.origin = low;
  grid.cell_size_m = std::max(0.5 * (widest_perception_radius_m + grid.longest_half_m), 1e-6);
  auto dims_for = [&](double cell) { return glm::max(glm::ivec3(glm::floor((high - low) / cell)) + 1, glm::ivec3(1)); };
  grid.dims = dims_for(grid.cell_size_m);
  while (static_cast<std::size_t>(grid.dims.x) * grid.dims.y * grid.dims.z > max_cells) {
    grid.cell_size_m *= 1.5;
    grid.dims = dims_for(grid.cell_size_m);
  }

  // Counting sort of the segments by cell (cell indices fit an int: at most max_cells cells). Each segment's cell is
  // found by its part's thread; counting and placing stay in index order, so a cell lists its segments by index.
  const std::size_t cells = static_cast<std::size_t>(grid.dims.x) * grid.dims.y * grid.dims.z;
  std::vector<int> cell_of_segment(segments.size());
  parallel_for(segments.part_count(), [&](std::size_t part) {
    segments.for_each_of_part(part, [&](std::size_t s, const glm::dvec3& start, const glm::dvec3& end) {
      cell_of_segment[s] = static_cast<int>(grid.cell_index(grid.cell_of(0.5 * (start + end))));
    });
  });
  grid.cell_start.assign(cells + 1, 0);
  for (int cell : cell_of_segment) ++grid.cell_start[cell + 1];
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
