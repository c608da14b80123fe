#include "roots/root_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "geometry/angles.hpp"

namespace heliostand::roots {

namespace {
bool kept(const SegmentFilter& keep, const RootSegment& segment) { return !keep || keep(segment); }
glm::dvec3 midpoint(const RootSegment& segment) { return 0.5 * (segment.start + segment.end); }
}  // namespace

glm::dvec3 length_centroid(std::span<const RootSegment> segments, const SegmentFilter& keep) {
  glm::dvec3 sum(0.0);
  double total = 0.0;
  for (const RootSegment& segment : segments) {
    if (!kept(keep, segment)) continue;
    sum += segment.length() * midpoint(segment);
    total += segment.length();
  }
  return total > 0.0 ? sum / total : glm::dvec3(0.0);
}

double mean_depth(std::span<const RootSegment> segments, double surface_z, const SegmentFilter& keep) {
  return surface_z - length_centroid(segments, keep).z;
}

double mean_nearest_root_distance(std::span<const RootSegment> segments, const SegmentFilter& keep) {
  std::vector<const RootSegment*> chosen;
  for (const RootSegment& segment : segments)
    if (kept(keep, segment)) chosen.push_back(&segment);
  auto attached = [](const RootSegment& a, const RootSegment& b) {
    constexpr double same = 1e-9;
    return glm::length(a.start - b.start) < same || glm::length(a.start - b.end) < same ||
           glm::length(a.end - b.start) < same || glm::length(a.end - b.end) < same;
  };
  double sum = 0.0;
  int counted = 0;
  for (const RootSegment* a : chosen) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const RootSegment* b : chosen)
      if (a != b && !attached(*a, *b)) nearest = std::min(nearest, glm::length(midpoint(*a) - midpoint(*b)));
    if (std::isfinite(nearest)) {
      sum += nearest;
      ++counted;
    }
  }
  return counted > 0 ? sum / counted : 0.0;
}

std::vector<double> cumulative_fraction_above(std::span<const RootSegment> segments, double surface_z,
                                              std::span<const double> depths, bool by_volume) {
  // Each segment's quantity is spread evenly along its depth interval.
  std::vector<double> above(depths.size(), 0.0);
  double total = 0.0;
  for (const RootSegment& segment : segments) {
    const double amount = by_volume ? pi * segment.radius_m * segment.radius_m * segment.length() : segment.length();
    total += amount;
    const double top = surface_z - std::max(segment.start.z, segment.end.z);
    const double bottom = surface_z - std::min(segment.start.z, segment.end.z);
    for (std::size_t d = 0; d < depths.size(); ++d) {
      if (bottom <= depths[d]) above[d] += amount;
      else if (top < depths[d]) above[d] += amount * (depths[d] - top) / (bottom - top);
    }
  }
  if (total > 0.0)
    for (double& fraction : above) fraction /= total;
  return above;
}

}  // namespace heliostand::roots
