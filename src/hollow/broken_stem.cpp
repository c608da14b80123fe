#include "hollow/broken_stem.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "geometry/angles.hpp"
#include "hollow/callus.hpp"
#include "hollow/stem_mesh_builder.hpp"

namespace heliostand::hollow {

using namespace detail;

std::vector<InputProblem> validate(const BrokenStemSpec& s, const TrunkSurface& trunk) {
  std::vector<InputProblem> p;
  auto add = [&](const char* field, std::string reason) { p.push_back({"", 0, field, std::move(reason)}); };
  if (!std::isfinite(s.break_height_m) || s.break_height_m <= 0.0 || s.break_height_m >= 0.95 * trunk.tree_height()) {
    add("break_height_m", fmt::format("expected a height in (0, {:.3f}) m (below 95 % of the tree's {:.3f} m), got {}",
                                      0.95 * trunk.tree_height(), trunk.tree_height(), s.break_height_m));
    return p;
  }
  const double rho = trunk.radius(s.break_height_m);
  if (!std::isfinite(s.callus_radius_m) || s.callus_radius_m < seed_unit_m || s.callus_radius_m > rho / 4.0)
    add("callus_radius_m", fmt::format("expected r in [{}, stem radius/4 = {:.4f}] m, got {}", seed_unit_m, rho / 4.0,
                                       s.callus_radius_m));
  else if (!std::isfinite(s.bulge_m) || s.bulge_m < 0.0 || s.bulge_m > rho / 4.0 - s.callus_radius_m + 1e-12)
    add("bulge_m", fmt::format("expected I in [0, stem radius/4 − r = {:.4f}] m, got {}",
                               rho / 4.0 - s.callus_radius_m, s.bulge_m));
  if (!std::isfinite(s.break_tilt_m) || s.break_tilt_m < 0.0 || s.break_tilt_m > 2.0 * rho)
    add("break_tilt_m", fmt::format("expected a tilt in [0, stem diameter {:.3f}] m, got {}", 2.0 * rho, s.break_tilt_m));
  else if (s.break_height_m - s.break_tilt_m / 2.0 - 4.0 * s.callus_radius_m < 0.1)
    add("break_height_m", fmt::format("the rim's lowest point must stay 0.1 m plus four callus radii above the "
                                      "ground; raise the break or lower its tilt"));
  if (s.polygon_corners < 4 || s.polygon_corners > 36)
    add("polygon_corners", fmt::format("expected M in [4, 36], got {}", s.polygon_corners));
  if (!std::isfinite(s.bark_line_spacing_m) || s.bark_line_spacing_m < 0.002 || s.bark_line_spacing_m > rho)
    add("bark_line_spacing_m", fmt::format("expected l in [0.002, {:.3f}] m, got {}", rho, s.bark_line_spacing_m));
  if (!std::isfinite(s.bark_segment_m) || s.bark_segment_m < 0.002 || s.bark_segment_m > 0.5)
    add("bark_segment_m", fmt::format("expected q in [0.002, 0.5] m, got {}", s.bark_segment_m));
  if (!std::isfinite(s.outline_step_m) || s.outline_step_m < 0.0002 || s.outline_step_m > rho / 20.0)
    add("outline_step_m", fmt::format("expected a step in [0.0002, {:.4f}] m, got {}", rho / 20.0, s.outline_step_m));
  if (!std::isfinite(s.surface_tolerance_m) || s.surface_tolerance_m < 1e-5)
    add("surface_tolerance_m", fmt::format("expected a tolerance ≥ 1e-5 m, got {}", s.surface_tolerance_m));
  return p;
}

namespace {

// Height (chart y) of a closed chain that runs once around the stem, at chart x (periodic linear interpolation).
double chain_height(const std::vector<glm::dvec2>& chain, double x, double period) {
  const int n = static_cast<int>(chain.size());
  for (int i = 0; i < n; ++i) {
    const glm::dvec2 a = chain[i];
    glm::dvec2 b = chain[(i + 1) % n];
    if (b.x < a.x) b.x += period;
    double xx = x;
    while (xx < a.x) xx += period;
    while (xx >= a.x + period) xx -= period;
    if (xx <= b.x) return a.y + (b.y - a.y) * (xx - a.x) / std::max(b.x - a.x, 1e-15);
  }
  return chain.front().y;
}

// Joins two closed chains that run once around the stem in +x, `lower` below `upper`, merging by x.
void zip_around(Builder& b, const std::vector<int>& lower, const std::vector<int>& upper, double period) {
  auto unwrapped = [&](const std::vector<int>& chain) {
    std::vector<double> x;
    for (int v : chain) {
      double xv = b.chart_xy[v].x;
      while (!x.empty() && xv < x.back() - period / 2) xv += period;
      x.push_back(xv);
    }
    x.push_back(x.front() + period);
    return x;
  };
  const std::vector<double> xl = unwrapped(lower), xu = unwrapped(upper);
  const std::size_t nl = lower.size(), nu = upper.size();
  std::size_t i = 0, j = 0;
  while (i < nl || j < nu) {
    const bool advance_lower = j >= nu || (i < nl && xl[i + 1] <= xu[j + 1]);
    if (advance_lower) {
      b.triangle(lower[i], lower[(i + 1) % nl], upper[j % nu], true);
      ++i;
    } else {
      b.triangle(lower[i % nl], upper[(j + 1) % nu], upper[j], true);
      ++j;
    }
  }
}

}  // namespace

HollowModel build_broken_stem(const BrokenStemSpec& spec, const TrunkSurface& trunk, BuildOptions options) {
  if (auto problems = validate(spec, trunk); !problems.empty()) throw InputError(std::move(problems), "field");

  HollowModel model;
  const StemChart chart(trunk, spec.break_height_m, radians(spec.azimuth_deg));
  const double rho0 = chart.reference_radius();
  const double period = 2.0 * chart.half_round();
  model.chart_radius = rho0;
  model.patch_half_width = chart.half_round();

  // The rim, once around the stem in +x (so that the right of travel, where the roll's foot goes, is down):
  // an oblique cut, highest at the chart's centre.
  const int n = std::max(64, static_cast<int>(std::ceil(period / spec.outline_step_m)));
  for (int j = 0; j < n; ++j) {
    const double x = -chart.half_round() + period * j / n;
    model.outline_xy.push_back({x, 0.5 * spec.break_tilt_m * std::cos(x / rho0)});
  }
  HollowSpec roll;
  roll.width_m = period;
  roll.wound_height_m = std::max(spec.break_tilt_m, 4.0 * seed_unit_m);
  roll.callus_radius_m = spec.callus_radius_m;
  roll.bulge_m = spec.bulge_m;
  roll.polygon_corners = spec.polygon_corners;
  roll.outline_step_m = spec.outline_step_m;
  roll.seed = spec.seed;
  model.callus = build_callus(model.outline_xy, chart, roll, options.limit_callus);
  const Callus& callus = model.callus;

  std::vector<glm::dvec2> foot;
  for (const auto& ring : callus.rings) foot.push_back(ring.foot_xy);
  double foot_low = 1e9;
  for (const auto& f : foot) foot_low = std::min(foot_low, f.y);

  // Bark band below the rim: its rows start level at the band's foot and bend to follow the roll's foot,
  // so the last row runs parallel to the rim a quarter segment below it.
  const double band = std::max({spec.break_tilt_m, 4.0 * spec.callus_radius_m, 0.1});
  const double band_low = foot_low - band;  // chart y
  const double margin = 0.25 * spec.bark_segment_m;
  const int band_rows = std::max(2, static_cast<int>(std::ceil(band / spec.bark_segment_m)));
  const std::vector<double> below =
      stem_heights(trunk, spec.break_height_m + band_low, spec.break_height_m + band_low, 1.0, {},
                   spec.break_height_m + band_low);
  const int n_cols = std::max(16, static_cast<int>(std::ceil(period / spec.bark_line_spacing_m)));
  std::vector<double> cols(n_cols);
  for (int c = 0; c < n_cols; ++c) cols[c] = -chart.half_round() + period * c / n_cols;

  Surroundings around{&chart, chart.half_round(), 10.0, -band_low, spec.callus_radius_m, &model.outline_xy, {}};
  around.full_round = true;
  for (int j = 0; j < n; ++j) around.mean_radius.push_back(callus.mean_radius(j));

  Builder b;
  const int n_below = static_cast<int>(below.size());
  const int n_rows = n_below + band_rows;
  std::vector<std::vector<int>> grid(n_cols, std::vector<int>(n_rows));
  for (int c = 0; c < n_cols; ++c) {
    const double top = chain_height(foot, cols[c], period) - margin;
    for (int k = 0; k < n_rows; ++k) {
      double y;
      if (k < n_below) {
        y = below[k] - spec.break_height_m;
      } else {
        const double u = static_cast<double>(k - n_below + 1) / band_rows;
        y = band_low + (top - band_low) * u;
      }
      const glm::dvec2 xy{cols[c], y};
      const bool bark = k >= n_below - 1;
      const double lift = bark ? around.lift(xy) : 0.0;
      grid[c][k] = b.add(chart.point(xy, lift), bark ? MeshPart::bark : MeshPart::trunk, true, xy, 0.0, lift, c);
    }
  }
  add_grid_quads(b, grid);
  const auto corner = add_callus_corners(b, callus, chart, around);
  std::vector<int> top_row, foot_chain;
  for (int c = 0; c < n_cols; ++c) top_row.push_back(grid[c][n_rows - 1]);
  for (int j = 0; j < n; ++j) foot_chain.push_back(corner[j][0]);
  zip_around(b, top_row, foot_chain, period);

  add_roll(b, callus, corner);
  if (options.follow_convexity) model.refinement_passes = follow_convexity(b, around, spec.surface_tolerance_m);

  // Bark lines run straight: original and drawn positions coincide.
  model.bark.x = cols;
  model.bark.spacing = period / n_cols;
  for (int k = n_below - 1; k < n_rows; ++k) model.bark.y.push_back(b.chart_xy[grid[0][k]].y);
  model.bark.X.assign(n_cols, {});
  for (int c = 0; c < n_cols; ++c)
    for (int k = n_below - 1; k < n_rows; ++k) model.bark.X[c].push_back(b.chart_xy[grid[c][k]].x);
  model.mesh = std::move(b.mesh);
  return model;
}

}  // namespace heliostand::hollow
