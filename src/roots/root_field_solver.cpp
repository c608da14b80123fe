#include "roots/root_field_solver.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

namespace heliostand::roots {

RootSegmentLine SegmentList::operator[](std::size_t i) const {
  // Parts are in index order: the last part whose first index is <= i holds it.
  const auto part = std::upper_bound(parts_.begin(), parts_.end(), i,
                                     [](std::size_t index, const Part& p) { return index < p.first; }) - 1;
  const std::size_t j = i - part->first;
  return {at(part->start, part->stride, j), at(part->end, part->stride, j)};
}

double SegmentList::longest_half_m() const {
  double longest = 0.0;
  for_each([&](std::size_t, const glm::dvec3& start, const glm::dvec3& end) {
    longest = std::max(longest, 0.5 * glm::length(end - start));
  });
  return longest;
}

std::vector<RootFieldSample> RootFieldSolver::solve(const RootFieldInput& input) {
  RootFieldYear year;
  year.segments = SegmentList(input.segments);
  year.soil = input.soil;
  for (const RootTipQuery& tip : input.tips)
    year.widest_perception_radius_m = std::max(year.widest_perception_radius_m, tip.perception_radius_m);
  begin_year(year);
  std::vector<RootFieldSample> samples = query(input.tips, input.probes, input.probes_per_tip);
  end_year();
  return samples;
}

}  // namespace heliostand::roots
