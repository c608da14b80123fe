#include "roots/reference_root_field_solver.hpp"

#include <algorithm>

#include <flann/flann.hpp>
#include <glm/geometric.hpp>

namespace heliostand::roots {

glm::dvec3 nearest_point_on_segment(const glm::dvec3& point, const RootSegmentLine& segment) {
  const glm::dvec3 axis = segment.end - segment.start;
  const double length2 = glm::dot(axis, axis);
  const double t = length2 > 0.0 ? std::clamp(glm::dot(point - segment.start, axis) / length2, 0.0, 1.0) : 0.0;
  return segment.start + t * axis;
}

glm::dvec3 moisture_pull(const glm::dvec3& apex, double perception_radius_m, std::span<const glm::dvec3> probes,
                         const SoilGrid& soil) {
  glm::dvec3 pull(0.0);
  for (const glm::dvec3& probe : probes) {
    const double length = glm::length(probe);
    if (length <= 0.0) continue;
    pull += (probe / length) * soil.moisture(apex + perception_radius_m * probe);
  }
  return pull;
}

std::vector<RootFieldSample> ReferenceRootFieldSolver::solve(const RootFieldInput& input) {
  std::vector<RootFieldSample> samples(input.tips.size());
  const std::size_t probes = static_cast<std::size_t>(std::max(input.probes_per_tip, 0));
  if (input.soil != nullptr && probes > 0)
    for (std::size_t t = 0; t < input.tips.size(); ++t)
      samples[t].moisture_pull = moisture_pull(input.tips[t].position, input.tips[t].perception_radius_m,
                                               input.probes.subspan(t * probes, probes), *input.soil);
  if (input.segments.empty()) return samples;

  std::vector<double> midpoints;
  midpoints.reserve(3 * input.segments.size());
  double longest_half = 0.0;
  for (const RootSegmentLine& segment : input.segments) {
    const glm::dvec3 middle = 0.5 * (segment.start + segment.end);
    midpoints.insert(midpoints.end(), {middle.x, middle.y, middle.z});
    longest_half = std::max(longest_half, 0.5 * glm::length(segment.end - segment.start));
  }
  const flann::Matrix<double> points(midpoints.data(), input.segments.size(), 3);
  flann::KDTreeSingleIndex<flann::L2_Simple<double>> index(points, flann::KDTreeSingleIndexParams(12));
  index.buildIndex();
  flann::SearchParams search;
  search.sorted = false;

  std::vector<std::vector<std::size_t>> found(1);
  std::vector<std::vector<double>> distances(1);
  for (std::size_t t = 0; t < input.tips.size(); ++t) {
    const RootTipQuery& tip = input.tips[t];
    double query_point[3] = {tip.position.x, tip.position.y, tip.position.z};
    const flann::Matrix<double> query(query_point, 1, 3);
    const double reach = tip.perception_radius_m + longest_half;
    index.radiusSearch(query, found, distances, static_cast<float>(reach * reach * (1.0 + 1e-5) + 1e-9), search);
    RootFieldSample& sample = samples[t];
    for (std::size_t s : found[0]) {
      if (static_cast<int>(s) == tip.excluded[0] || static_cast<int>(s) == tip.excluded[1]) continue;
      const glm::dvec3 toward = nearest_point_on_segment(tip.position, input.segments[s]) - tip.position;
      const double distance = glm::length(toward);
      if (distance >= tip.perception_radius_m || distance < touching_distance_m) continue;
      sample.contact_avoidance -= toward / distance;
      ++sample.contacts;
    }
  }
  return samples;
}

}  // namespace heliostand::roots
