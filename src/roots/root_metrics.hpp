#pragma once
// Measured quantities of root systems: what the seed-003 demonstrations show in figures, as numbers
// (validation/roots/), and rooting-depth profiles to compare with Jackson et al. (1996).
#include <functional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "roots/root_segment.hpp"

namespace heliostand::roots {

using SegmentFilter = std::function<bool(const RootSegment&)>;

// Root-length-weighted centroid of the segments' midpoints (zero if there is no length).
glm::dvec3 length_centroid(std::span<const RootSegment> segments, const SegmentFilter& keep = {});

// Root-length-weighted mean depth of the midpoints below `surface_z`.
double mean_depth(std::span<const RootSegment> segments, double surface_z, const SegmentFilter& keep = {});

// Mean distance from each kept segment's midpoint to the nearest midpoint of another kept segment that
// is not attached to it (shares no end point): how far apart a tree's roots grow.
double mean_nearest_root_distance(std::span<const RootSegment> segments, const SegmentFilter& keep = {});

// Fraction of root quantity (length, or volume π r² L when `by_volume`) above each depth (m) in `depths`.
std::vector<double> cumulative_fraction_above(std::span<const RootSegment> segments, double surface_z,
                                              std::span<const double> depths, bool by_volume);

}  // namespace heliostand::roots
