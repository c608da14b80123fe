#include "roots/root_system.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "geometry/angles.hpp"
#include "geometry/compass_sector.hpp"
#include "rng/random_stream.hpp"
#include "roots/root_direction.hpp"

namespace heliostand::roots {

RootSystem::RootSystem(int tree_id, const glm::dvec3& collar, RootParameters parameters, int planting_year)
    : tree_id_(tree_id), collar_(collar), parameters_(std::move(parameters)), year_(planting_year) {
  parameters_.validate();
  const RootTypeParameters& tap = parameters_.of(RootType::main);
  RootSegment first;
  first.start = collar;
  first.end = collar + tap.elongation_m_per_year * gravity_direction;
  first.radius_m = tap.radius_m;
  first.type = RootType::main;
  first.birth_year = first.axis_birth_year = planting_year;
  first.id = next_id_++;
  first.growing = true;
  segments_.push_back(first);
}

std::vector<RootBud> RootSystem::buds(int year, std::uint64_t seed) const {
  std::vector<RootBud> result;
  const bool crowded = static_cast<int>(segments_.size()) >= parameters_.max_segments;
  const double mean_bonus = std::accumulate(branching_bonus_.begin(), branching_bonus_.end(), 0.0) / path_count;
  for (int s = 0; s < static_cast<int>(segments_.size()); ++s) {
    const RootSegment& apex = segments_[s];
    if (!apex.alive) continue;
    RandomStream random(seed, {static_cast<std::uint64_t>(tree_id_), static_cast<std::uint64_t>(year), organ_root_bud, apex.id});
    if (!apex.growing) {
      if (!crowded) sprout_fine_roots(s, random, result);
      continue;
    }
    const RootTypeParameters& own = parameters_.of(apex.type);
    const glm::dvec3 heading = apex.direction();
    auto random_horizontal = [&random] {
      const double azimuth = random.uniform(0.0, 2.0 * pi);
      return glm::dvec3(std::cos(azimuth), std::sin(azimuth), 0.0);
    };
    int ordinal = 0;
    RootBud continuation{s, apex.type, true, ordinal++, rotate_within_range(heading, own.continuation_angle_deg, random),
                         random_horizontal()};
    result.push_back(continuation);
    if (crowded) continue;
    const double bonus = apex.sector == no_sector ? mean_bonus : branching_bonus_[apex.sector];
    for (RootType child : all_root_types) {
      const double base = own.branching_frequency[index_of(child)];
      if (!may_branch_into(apex.type, child) || base <= 0.0) continue;  // the coupling never switches on a rule
      if (child != RootType::fine && apex.order + 1 > parameters_.max_woody_order) continue;
      const double expected = std::max(0.0, base + bonus);
      const int count = static_cast<int>(expected) + (random.chance(expected - std::floor(expected)) ? 1 : 0);
      for (int n = 0; n < count; ++n)
        result.push_back({s, child, false, ordinal++,
                          rotate_within_range(heading, parameters_.of(child).branching_angle_deg, random),
                          random_horizontal()});
    }
  }
  return result;
}

void RootSystem::sprout_fine_roots(int s, RandomStream& random, std::vector<RootBud>& buds) const {
  const RootSegment& segment = segments_[s];
  const double base = parameters_.of(segment.type).fine_root_sprouting_per_year;
  if (base <= 0.0 || !may_branch_into(segment.type, RootType::fine)) return;
  // The coupling scales sprouting instead of adding to it, so that one path bonus does not start
  // thousands of fine roots along an old framework.
  const double bonus = segment.sector == no_sector ? 0.0 : branching_bonus_[segment.sector];
  const double expected = std::max(0.0, base * (1.0 + bonus));
  const int count = static_cast<int>(expected) + (random.chance(expected - std::floor(expected)) ? 1 : 0);
  for (int n = 0; n < count; ++n) {
    const double azimuth = random.uniform(0.0, 2.0 * pi);
    buds.push_back({s, RootType::fine, false, n + 1,
                    rotate_within_range(segment.direction(), parameters_.of(RootType::fine).branching_angle_deg, random),
                    glm::dvec3(std::cos(azimuth), std::sin(azimuth), 0.0)});
  }
}

glm::dvec3 keep_in_soil(const glm::dvec3& start, const glm::dvec3& direction, double length, const SoilGrid& soil,
                        double min_depth_m) {
  glm::dvec3 low = soil.min_corner();
  glm::dvec3 high = soil.max_corner();
  high.z = std::max(low.z, soil.surface_z() - min_depth_m);
  glm::dvec3 heading = direction;
  const glm::dvec3 end = start + length * heading;
  for (int axis = 0; axis < 3; ++axis)
    if ((end[axis] > high[axis] && heading[axis] > 0.0) || (end[axis] < low[axis] && heading[axis] < 0.0))
      heading[axis] = -heading[axis];
  return glm::clamp(start + length * heading, low, high);
}

void RootSystem::add_segment(const RootBud& bud, const glm::dvec3& direction, int year, const SoilGrid& soil) {
  RootSegment& from = segments_.at(bud.from_segment);
  const RootTypeParameters& type = parameters_.of(bud.type);
  RootSegment segment;
  segment.start = from.end;
  segment.end = keep_in_soil(from.end, glm::normalize(direction), type.elongation_m_per_year, soil,
                             parameters_.min_depth_m);
  segment.radius_m = type.radius_m;
  segment.type = bud.type;
  segment.birth_year = year;
  segment.axis_birth_year = bud.continuation ? from.axis_birth_year : year;
  segment.parent = bud.from_segment;
  segment.order = bud.continuation ? from.order : from.order + 1;
  segment.id = next_id_++;
  segment.growing = true;
  if (bud.type == RootType::main) segment.sector = no_sector;
  else if (from.sector != no_sector) segment.sector = from.sector;
  else segment.sector = compass_sector_of(segment.end - segment.start);
  if (bud.continuation) from.growing = false;  // the apex moves on
  segments_.push_back(segment);  // invalidates `from`
}

int RootSystem::finish_year(int year) {
  year_ = year;
  for (RootSegment& segment : segments_) {
    const RootTypeParameters& type = parameters_.of(segment.type);
    // An axis started in year Y has formed its segments of years Y .. year: growth_years of them at most.
    if (segment.growing && year - segment.axis_birth_year + 1 >= type.growth_years) segment.growing = false;
    if (age_of(segment) > type.lifespan_years) segment.alive = false;
  }
  const std::size_t before = segments_.size();
  remove_dead_and_compact();
  return static_cast<int>(before - segments_.size());
}

void RootSystem::remove_dead_and_compact() {
  // Parents always precede their children, so one forward pass carries death down every subtree.
  std::vector<int> new_index(segments_.size(), -1);
  int kept_count = 0;
  for (std::size_t s = 0; s < segments_.size(); ++s) {
    const RootSegment& segment = segments_[s];
    if (segment.parent >= 0 && new_index[segment.parent] < 0) continue;
    if (segment.alive) new_index[s] = kept_count++;
  }
  // Exactly as many as are kept: the year's new segments may have doubled the list's capacity.
  std::vector<RootSegment> kept;
  kept.reserve(static_cast<std::size_t>(kept_count));
  for (std::size_t s = 0; s < segments_.size(); ++s) {
    if (new_index[s] < 0) continue;
    kept.push_back(segments_[s]);
    if (kept.back().parent >= 0) kept.back().parent = new_index[kept.back().parent];
  }
  segments_ = std::move(kept);
}

int RootSystem::prune(const RootPruning& rule) {
  for (RootSegment& segment : segments_) {
    if (segment.type == RootType::main) continue;  // pruning cuts paths, never the tap root
    if (rule.sector != no_sector && segment.sector != rule.sector) continue;
    const double depth = collar_.z - segment.end.z;
    const double distance = glm::length(glm::dvec2(segment.end.x - collar_.x, segment.end.y - collar_.y));
    if (depth >= rule.min_depth_m && distance >= rule.min_distance_m) segment.alive = false;
  }
  const std::size_t before = segments_.size();
  remove_dead_and_compact();
  return static_cast<int>(before - segments_.size());
}

double RootSystem::uptake_capacity(const RootSegment& segment) const {
  return parameters_.of(segment.type).absorptive_weight * segment.length() *
         std::exp(-age_of(segment) / parameters_.uptake_decay_years);
}

std::array<double, path_count> RootSystem::uptake_capacity_by_path() const {
  std::array<double, path_count> by_path{};
  for (const RootSegment& segment : segments_) {
    const double capacity = uptake_capacity(segment);
    if (segment.sector == no_sector)
      for (double& path : by_path) path += capacity / path_count;
    else
      by_path[segment.sector] += capacity;
  }
  return by_path;
}

std::array<double, path_count> RootSystem::available_uptake_by_path(const SoilGrid& soil) const {
  std::array<double, path_count> by_path{};
  for (const RootSegment& segment : segments_) {
    const double capacity = uptake_capacity(segment);
    if (capacity < 1e-12) continue;
    const double available = capacity * soil.moisture(segment.end) * soil.nutrient(segment.end);
    if (segment.sector == no_sector)
      for (double& path : by_path) path += available / path_count;
    else
      by_path[segment.sector] += available;
  }
  return by_path;
}

std::vector<SoilGrid::DepletionShares> RootSystem::uptake_shares(const SoilGrid& soil) const {
  std::vector<SoilGrid::DepletionShares> shares;
  for (const RootSegment& segment : segments_) {
    const double fraction = parameters_.uptake_rate_per_m * uptake_capacity(segment);
    if (fraction < 1e-9) continue;  // old, lignified roots
    shares.push_back(soil.depletion_shares(segment.end, fraction));
  }
  return shares;
}

double RootSystem::take_up(SoilGrid& soil, std::span<const SoilGrid::DepletionShares> shares) {
  double taken = 0.0;
  for (const SoilGrid::DepletionShares& segment : shares) {
    taken += soil.deplete(SoilField::moisture, segment);
    soil.deplete(SoilField::nutrient, segment);
  }
  return taken;
}

double RootSystem::take_up(SoilGrid& soil) const { return take_up(soil, uptake_shares(soil)); }

double RootSystem::total_length_m() const {
  double total = 0.0;
  for (const RootSegment& segment : segments_) total += segment.length();
  return total;
}

}  // namespace heliostand::roots
