#include "geometry/planting_rows.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "geometry/angles.hpp"
#include "geometry/neighbourhood.hpp"

namespace heliostand {
namespace {

constexpr double least_agreement = 0.5;  // mean resultant length of the nearest-neighbour directions
constexpr int refinements = 2;

double folded_deg(double azimuth_deg) {
  double folded = std::fmod(azimuth_deg, 180.0);
  if (folded < 0) folded += 180.0;
  return folded >= 180.0 ? 0.0 : folded;
}

struct Direction {
  double azimuth_deg = 0;
  double agreement = 0;  // 1: every nearest neighbour along it; 0: no common direction
};

Direction nearest_neighbour_direction(std::span<const glm::dvec2> positions) {
  const Neighbourhood stems(positions, StandEdges{});
  double c = 0, s = 0;
  int count = 0;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const auto nearest = stems.nearest(i);
    if (!nearest) continue;
    const glm::dvec2 along = positions[nearest->stem] - positions[i];
    const double doubled = 2.0 * std::atan2(along.y, along.x);
    c += std::cos(doubled);
    s += std::sin(doubled);
    ++count;
  }
  if (count == 0) return {};
  return {folded_deg(degrees(std::atan2(s, c) / 2.0)), std::hypot(c, s) / count};
}

// Across the rows, pointing north for rows within 45° of east–west, else east: rows are numbered from the south or
// from the west whichever way the direction was folded (0.4° and 179.6° are the same rows).
glm::dvec2 across_rows(double azimuth_deg) {
  glm::dvec2 normal{-std::sin(radians(azimuth_deg)), std::cos(radians(azimuth_deg))};
  const bool east_west = std::abs(normal.y) >= std::abs(normal.x);
  if (east_west ? normal.y < 0 : normal.x < 0) normal = -normal;
  return normal;
}

std::vector<double> offsets_across(std::span<const glm::dvec2> positions, double azimuth_deg) {
  const glm::dvec2 normal = across_rows(azimuth_deg);
  std::vector<double> offsets;
  for (const glm::dvec2 p : positions) offsets.push_back(p.x * normal.x + p.y * normal.y);
  return offsets;
}

struct Bands {
  std::vector<int> row_of;
  std::vector<double> low, high;  // offset range of each band
};

Bands cut_into_bands(const std::vector<double>& offsets, double tolerance_m) {
  std::vector<std::size_t> order(offsets.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return offsets[a] < offsets[b]; });
  Bands bands;
  bands.row_of.resize(offsets.size());
  for (std::size_t k : order) {
    if (bands.low.empty() || offsets[k] > bands.low.back() + tolerance_m) {
      bands.low.push_back(offsets[k]);
      bands.high.push_back(offsets[k]);
    }
    bands.high.back() = offsets[k];
    bands.row_of[k] = static_cast<int>(bands.low.size()) - 1;
  }
  return bands;
}

// The principal axis of the stems' scatter about their own row's centre, pooled over the rows.
double common_row_direction(std::span<const glm::dvec2> positions, const Bands& bands, double fallback_deg) {
  const std::size_t rows = bands.low.size();
  std::vector<glm::dvec2> sum(rows, glm::dvec2(0.0));
  std::vector<int> members(rows, 0);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    sum[bands.row_of[i]] += positions[i];
    ++members[bands.row_of[i]];
  }
  double sxx = 0, syy = 0, sxy = 0;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const int row = bands.row_of[i];
    const glm::dvec2 d = positions[i] - sum[row] / static_cast<double>(members[row]);
    sxx += d.x * d.x;
    syy += d.y * d.y;
    sxy += d.x * d.y;
  }
  if (sxx + syy <= 0) return fallback_deg;
  return folded_deg(degrees(0.5 * std::atan2(2.0 * sxy, sxx - syy)));
}

std::string separation_problem(const Bands& bands, double azimuth_deg, double tolerance_m) {
  if (bands.low.size() < 2)
    return fmt::format("the trees stand in a single row along {:.1f}°: there is no other row to keep", azimuth_deg);
  for (std::size_t r = 0; r + 1 < bands.low.size(); ++r) {
    const double gap = bands.low[r + 1] - bands.high[r];
    if (gap < tolerance_m)
      return fmt::format("the trees are not in rows along {:.1f}°: across that direction, the band from {:.2f} m to "
                         "{:.2f} m is only {:.2f} m from the next one (rows must be bands at most row_tolerance_m = "
                         "{:g} m wide, at least that far apart)",
                         azimuth_deg, bands.low[r], bands.high[r], gap, tolerance_m);
  }
  return {};
}

}  // namespace

PlantingRowsFound find_planting_rows(std::span<const glm::dvec2> positions, std::optional<double> azimuth_deg,
                                     double tolerance_m) {
  if (positions.size() < 2) return {std::nullopt, "fewer than two trees: there are no rows"};
  double azimuth = 0;
  if (azimuth_deg) {
    azimuth = folded_deg(*azimuth_deg);
  } else {
    const Direction found = nearest_neighbour_direction(positions);
    if (found.agreement < least_agreement)
      return {std::nullopt,
              fmt::format("no row direction: the trees' nearest neighbours point along several directions "
                          "(agreement {:.2f}, at least {:g} needed; a square planting?); give row_azimuth_deg",
                          found.agreement, least_agreement)};
    azimuth = found.azimuth_deg;
  }
  Bands bands = cut_into_bands(offsets_across(positions, azimuth), tolerance_m);
  for (int k = 0; k < refinements && !azimuth_deg; ++k) {
    azimuth = common_row_direction(positions, bands, azimuth);
    bands = cut_into_bands(offsets_across(positions, azimuth), tolerance_m);
  }
  if (auto problem = separation_problem(bands, azimuth, tolerance_m); !problem.empty()) return {std::nullopt, problem};
  return {PlantingRows{azimuth, bands.row_of, static_cast<int>(bands.low.size())}, {}};
}

}  // namespace heliostand
