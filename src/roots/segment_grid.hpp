#pragma once
// A uniform grid over root-segment midpoints in compressed (CSR) form — the spatial index the OpenCL
// root-contact kernel walks: the segments of cell c are cell_segments[cell_start[c] .. cell_start[c+1]).
#include <vector>

#include <glm/vec3.hpp>

#include "roots/root_field_solver.hpp"

namespace heliostand::roots {

struct SegmentGrid {
  glm::dvec3 origin{0.0};     // min corner of the midpoints' bounding box
  double cell_size_m = 1.0;
  glm::ivec3 dims{1, 1, 1};
  double longest_half_m = 0.0;
  std::vector<int> cell_start;     // size cells + 1
  std::vector<int> cell_segments;  // segment indices, grouped by cell

  // Cells half the widest reach of a query (`widest_perception_radius_m` + the longest segment's half): a query
  // visits at most 5³ cells and skips those wholly outside its reach, which hugs the sphere more tightly than 3³
  // cells of a whole reach. The cells are made coarser when the grid would exceed `max_cells`.
  static SegmentGrid build(const SegmentList& segments, double widest_perception_radius_m,
                           std::size_t max_cells = std::size_t{1} << 22);
  glm::ivec3 cell_of(const glm::dvec3& point) const;  // clamped into the grid
  std::size_t cell_index(const glm::ivec3& cell) const;
};

}  // namespace heliostand::roots
