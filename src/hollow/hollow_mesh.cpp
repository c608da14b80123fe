#include "hollow/hollow_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/angles.hpp"
#include "hollow/bark_flow.hpp"
#include "hollow/placement.hpp"
#include "hollow/stem_chart.hpp"
#include "hollow/stem_mesh_builder.hpp"
#include "hollow/wound_outline.hpp"
#include "core/input_error.hpp"

namespace heliostand::hollow {

using namespace detail;

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// The bark patch around the wound (chart units): the seed's 2W × 2H, widened where the callus needs room for
// the flow to stay one-to-one, and tall enough to hold the callus foot of a flat wound.
struct Patch {
  double half_width, up, down;
};

Patch bark_patch(const HollowSpec& spec, const TrunkSurface& trunk, const StemChart& chart, const WoundProfile& foot) {
  return {std::min(chart.half_round(), std::max(spec.width_m, 2.5 * foot.max_reach())),
          std::min(std::max(spec.wound_height_m, 1.5 * foot.y_max()), 0.95 * trunk.tree_height() - spec.height_m),
          std::min(std::max(spec.wound_height_m, -1.5 * foot.y_min()), spec.height_m)};
}

// Stem columns (chart x): bark lines about l apart across the patch, x = 0 being the split line through the
// wound's top vertex, then the back of the stem at a spacing whose chords stay within the tolerance.
struct Columns {
  std::vector<double> x;
  int split = 0;       // index of x = 0
  int first_back = 0;  // first column behind the patch
  double spacing = 0;
};

Columns stem_columns(const HollowSpec& spec, const TrunkSurface& trunk, const StemChart& chart, double patch_x) {
  Columns cols;
  const int half_lines = std::max(2, static_cast<int>(std::ceil(patch_x / spec.bark_line_spacing_m)));
  cols.spacing = patch_x / half_lines;
  for (int j = -half_lines; j <= half_lines; ++j) cols.x.push_back(j * cols.spacing);
  cols.split = half_lines;
  const bool wraps = patch_x >= chart.half_round() - 1e-12;
  if (wraps) cols.x.pop_back();  // x = +πρ0 is x = −πρ0
  cols.first_back = static_cast<int>(cols.x.size());
  if (!wraps) {
    const double back = 2.0 * chart.half_round() - 2.0 * patch_x;
    const double step = chart.reference_radius() * angular_step(max_stem_radius(trunk), spec.surface_tolerance_m);
    const int n_back = std::max(2, static_cast<int>(std::ceil(back / step)));
    for (int i = 1; i < n_back; ++i) cols.x.push_back(patch_x + back * i / n_back);
  }
  return cols;
}

// Stem rows (chart y): regular ones, plus the wound rows where the callus foot's reach changes, none exactly
// on the foot's apexes (the split line would touch the foot there).
// Only rows inside the band are kept; the band's edges are rows themselves (unless the band reaches the tip).
std::vector<double> stem_rows(const HollowSpec& spec, const TrunkSurface& trunk, const WoundProfile& foot,
                              const Patch& patch, double spacing, const StemBand& band) {
  std::vector<double> extra;
  for (double y : wound_rows(foot, 0.1 * spacing)) extra.push_back(y + spec.height_m);
  if (band.lo > 0.0) extra.push_back(band.lo);
  if (!band.reaches_tip()) extra.push_back(band.hi);
  std::vector<double> heights = stem_heights(trunk, spec.height_m - patch.down, spec.height_m + patch.up,
                                             spec.bark_segment_m, extra);
  // stem_heights() merges rows closer than 1e-6 m: the edge row may be a neighbour that close to the edge.
  std::erase_if(heights, [&band](double h) { return h < band.lo - 1e-6 || h > band.hi + 1e-6; });
  const double keep_off = 1e-4 * (foot.y_max() - foot.y_min());
  std::vector<double> rows;
  for (double h : heights) {
    const double y = h - spec.height_m;
    if (std::abs(y - foot.y_min()) >= keep_off && std::abs(y - foot.y_max()) >= keep_off) rows.push_back(y);
  }
  return rows;
}

bool cut_by_wound(double x, double y, const WoundProfile& foot) { return x == 0.0 && y > foot.y_min() && y < foot.y_max(); }

// The two strips beside the wound: the bark line left of the split ↔ the left half of the callus foot, and the
// right half ↔ the bark line right of the split (the seed's eq. 3.17 joins, as a height-ordered zip). Each
// foot half is closed below and above by the split line's last vertices before and after the wound.
void join_wound_strips(Builder& b, const std::vector<std::vector<int>>& grid, int split,
                       const std::vector<double>& rows, const WoundProfile& foot,
                       const std::vector<std::vector<int>>& corner) {
  const int n_rows = static_cast<int>(rows.size());
  const int rings = static_cast<int>(corner.size());
  int below = 0, above = n_rows - 1;
  for (int k = 0; k < n_rows; ++k) {
    if (rows[k] < foot.y_min()) below = k;
    if (rows[k] > foot.y_max()) { above = k; break; }
  }
  std::vector<int> left_line, right_line, left_foot{grid[split][below]}, right_foot{grid[split][below]};
  for (int k = below; k <= above; ++k) {
    left_line.push_back(grid[split - 1][k]);
    right_line.push_back(grid[split + 1][k]);
  }
  const int bottom = foot.bottom_index(), top = foot.top_index();
  for (int j = bottom;; j = (j + rings - 1) % rings) {
    left_foot.push_back(corner[j][0]);
    if (j == top) break;
  }
  for (int j = bottom;; j = (j + 1) % rings) {
    right_foot.push_back(corner[j][0]);
    if (j == top) break;
  }
  left_foot.push_back(grid[split][above]);
  right_foot.push_back(grid[split][above]);
  zip(b, left_line, left_foot);
  zip(b, right_foot, right_line);
}

}  // namespace

PatchBounds detail::patch_bounds(const HollowSpec& spec, const TrunkSurface& trunk) {
  // The callus foot lies r · flare across the stem from the rim (callus.cpp), and the rim within ±H/2 of the
  // centre (cylindrical placement; the tangent-plane projection can push it a little further where a
  // flaring stem bulges through the plane, hence the margin); the flare is largest at the hollow's lowest point.
  const double lowest = std::max(spec.height_m - spec.wound_height_m / 2.0, 0.0);
  const double rim = (spec.placement == Placement::cylindrical ? 0.5 : 0.6) * spec.wound_height_m;
  const double foot_reach = rim + spec.callus_radius_m * trunk.flare_factor(lowest);
  const double half = std::max(spec.wound_height_m, 1.5 * foot_reach);
  return {spec.height_m - std::min(half, spec.height_m),
          spec.height_m + std::min(half, 0.95 * trunk.tree_height() - spec.height_m)};
}

HollowModel detail::build_hollow_band(const HollowSpec& spec, const TrunkSurface& trunk, BuildOptions options,
                                      const StemBand& band) {
  if (auto problems = validate(spec, trunk); !problems.empty()) throw InputError(std::move(problems), "field");

  HollowModel model;
  const StemChart chart(trunk, spec.height_m, radians(spec.azimuth_deg));
  model.chart_radius = chart.reference_radius();
  const auto plane_loop = sample_outline(spec.width_m, spec.wound_height_m, spec.outline_step_m);
  model.outline_xy = place_outline(plane_loop, chart, spec.placement);
  model.callus = build_callus(model.outline_xy, chart, spec, options.limit_callus);

  std::vector<glm::dvec2> foot_loop;
  for (const auto& ring : model.callus.rings) foot_loop.push_back(ring.foot_xy);
  const WoundProfile foot(foot_loop);
  const Patch patch = bark_patch(spec, trunk, chart, foot);
  if (spec.height_m - patch.down < band.lo || spec.height_m + patch.up > band.hi)
    throw std::logic_error("hollow: bark patch outside its stem band (patch_bounds must bound bark_patch)");
  model.patch_half_width = patch.half_width;
  const BarkFlow flow(foot, patch.half_width);
  Surroundings around{&chart, patch.half_width, patch.up, patch.down, spec.callus_radius_m, &model.outline_xy, {}};
  for (std::size_t j = 0; j < model.callus.rings.size(); ++j) around.mean_radius.push_back(model.callus.mean_radius(j));

  const Columns cols = stem_columns(spec, trunk, chart, patch.half_width);
  const std::vector<double> rows = stem_rows(spec, trunk, foot, patch, cols.spacing, band);
  const int n_cols = static_cast<int>(cols.x.size()), n_rows = static_cast<int>(rows.size());
  // The wound's reach on either side, once per row (the flow needs it for every line).
  std::vector<double> reach_left(n_rows), reach_right(n_rows);
  for (int k = 0; k < n_rows; ++k) reach_left[k] = foot.left_reach(rows[k]), reach_right[k] = foot.right_reach(rows[k]);
  auto line_position = [&](int c, int k) {
    const bool in_patch = c < cols.first_back && around.in_patch({cols.x[c], rows[k]});
    return in_patch ? flow.displaced(cols.x[c], reach_left[k], reach_right[k]) : cols.x[c];
  };

  Builder b;
  std::vector<std::vector<int>> grid(n_cols, std::vector<int>(n_rows, -1));
  for (int c = 0; c < n_cols; ++c) {
    for (int k = 0; k < n_rows; ++k) {
      if (cut_by_wound(cols.x[c], rows[k], foot)) continue;  // the split line's fibres are cut by the wound
      const glm::dvec2 xy{line_position(c, k), rows[k]};
      const bool bark = around.in_patch(xy);
      const double lift = bark ? around.lift(xy) : 0.0;
      grid[c][k] = b.add(chart.point(xy, lift), bark ? MeshPart::bark : MeshPart::trunk, true, xy,
                         xy.x - cols.x[c], lift, c);
    }
  }
  if (band.reaches_tip()) close_tip(b, grid, trunk.tree_height());
  const auto corner = add_callus_corners(b, model.callus, chart, around);
  add_grid_quads(b, grid);
  join_wound_strips(b, grid, cols.split, rows, foot, corner);
  add_roll(b, model.callus, corner);
  if (options.follow_convexity) model.refinement_passes = follow_convexity(b, around, spec.surface_tolerance_m);

  // The bark lines as the seed draws them: patch columns and rows only, NaN where the split line is cut.
  BarkLines& lines = model.bark;
  lines.spacing = cols.spacing;
  lines.split_column = cols.split;
  std::vector<int> patch_rows;
  for (int k = 0; k < n_rows; ++k)
    if (rows[k] >= -patch.down - 1e-9 && rows[k] <= patch.up + 1e-9) lines.y.push_back(rows[k]), patch_rows.push_back(k);
  for (int c = 0; c < cols.first_back; ++c) {
    lines.x.push_back(cols.x[c]);
    std::vector<double> X;
    for (int k : patch_rows) X.push_back(cut_by_wound(cols.x[c], rows[k], foot) ? nan : line_position(c, k));
    lines.X.push_back(std::move(X));
  }
  model.mesh = std::move(b.mesh);
  return model;
}

HollowModel build_hollow(const HollowSpec& spec, const TrunkSurface& trunk, BuildOptions options) {
  return build_hollow_band(spec, trunk, options, StemBand{});
}

HollowMesh build_trunk_mesh(const TrunkSurface& trunk, double tolerance_m) {
  const double rho = max_stem_radius(trunk);
  const int n_cols = std::max(8, static_cast<int>(std::ceil(2.0 * pi / angular_step(rho, tolerance_m))));
  const std::vector<double> heights = stem_heights(trunk, 0.0, 0.0, 1.0, {});
  Builder b;
  std::vector<std::vector<int>> grid(n_cols, std::vector<int>(heights.size()));
  for (int c = 0; c < n_cols; ++c)
    for (std::size_t k = 0; k < heights.size(); ++k)
      grid[c][k] = b.add(trunk.point(heights[k], 2.0 * pi * c / n_cols), MeshPart::trunk, false, {}, 0, 0, c);
  close_tip(b, grid, trunk.tree_height());
  add_grid_quads(b, grid);
  return std::move(b.mesh);
}

}  // namespace heliostand::hollow
