#include "roots/reference_root_field_solver.hpp"

#include <algorithm>

#include <flann/flann.hpp>
#include <glm/geometric.hpp>

#include "core/parallel_for.hpp"

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

// The year's k-d tree over segment midpoints (FLANN keeps pointers into `midpoints`, so they live together).
struct ReferenceRootFieldSolver::Index {
  double longest_half = 0.0;
  std::vector<double> midpoints;  // x y z per segment
  flann::KDTreeSingleIndex<flann::L2_Simple<double>> tree;

  explicit Index(const SegmentList& segments)
      : longest_half(segments.longest_half_m()),
        midpoints(midpoints_of(segments)),
        tree(flann::Matrix<double>(midpoints.data(), segments.size(), 3), flann::KDTreeSingleIndexParams(12)) {
    tree.buildIndex();
  }
  static std::vector<double> midpoints_of(const SegmentList& segments) {
    std::vector<double> midpoints;
    midpoints.reserve(3 * segments.size());
    segments.for_each([&](std::size_t, const glm::dvec3& start, const glm::dvec3& end) {
      const glm::dvec3 middle = 0.5 * (start + end);
      midpoints.insert(midpoints.end(), {middle.x, middle.y, middle.z});
    });
    return midpoints;
  }
};

ReferenceRootFieldSolver::ReferenceRootFieldSolver() = default;
ReferenceRootFieldSolver::~ReferenceRootFieldSolver() = default;

void ReferenceRootFieldSolver::begin_year(const RootFieldYear& year) {
  index_.reset();
  year_ = year;
  if (!year_.segments.empty()) index_ = std::make_unique<Index>(year_.segments);
}

void ReferenceRootFieldSolver::end_year() {
  index_.reset();
  year_ = {};
}

std::vector<RootFieldSample> ReferenceRootFieldSolver::query(std::span<const RootTipQuery> tips,
                                                             std::span<const glm::dvec3> probes, int probes_per_tip) {
  std::vector<RootFieldSample> samples(tips.size());
  const std::size_t per_tip = static_cast<std::size_t>(std::max(probes_per_tip, 0));
  // Blocks of apices on the worker threads: each sample is its own apex's, summed in the order one thread sums it
  // (the k-d tree is only read), so the answers do not depend on the threads.
  parallel_for_blocks(tips.size(), apices_per_block, [&](std::size_t from, std::size_t to) {
    if (year_.soil != nullptr && per_tip > 0)
      for (std::size_t t = from; t < to; ++t)
        samples[t].moisture_pull = moisture_pull(tips[t].position, tips[t].perception_radius_m,
                                                 probes.subspan(t * per_tip, per_tip), *year_.soil);
    if (index_)
      for (std::size_t t = from; t < to; ++t) samples[t] = with_contacts(tips[t], samples[t]);
  });
  return samples;
}

// The contact avoidance at one apex: every other segment whose nearest point lies inside the perception sphere.
RootFieldSample ReferenceRootFieldSolver::with_contacts(const RootTipQuery& tip, RootFieldSample sample) const {
  flann::SearchParams search;
  search.sorted = false;
  std::vector<std::vector<std::size_t>> found(1);
  std::vector<std::vector<double>> distances(1);
  double query_point[3] = {tip.position.x, tip.position.y, tip.position.z};
  const flann::Matrix<double> query(query_point, 1, 3);
  const double reach = tip.perception_radius_m + index_->longest_half;
  index_->tree.radiusSearch(query, found, distances, static_cast<float>(reach * reach * (1.0 + 1e-5) + 1e-9), search);
  for (std::size_t s : found[0]) {
    if (static_cast<int>(s) == tip.excluded[0] || static_cast<int>(s) == tip.excluded[1]) continue;
    const glm::dvec3 toward = nearest_point_on_segment(tip.position, year_.segments[s]) - tip.position;
    const double distance = glm::length(toward);
    if (distance >= tip.perception_radius_m || distance < touching_distance_m) continue;
    sample.contact_avoidance -= toward / distance;
    ++sample.contacts;
  }
  return sample;
}

}  // namespace heliostand::roots
