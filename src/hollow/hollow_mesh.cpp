#include "hollow/hollow_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <glm/geometric.hpp>

#include "geometry/angles.hpp"
#include "hollow/bark_flow.hpp"
#include "hollow/stem_mesh_builder.hpp"
#include "hollow/placement.hpp"
#include "hollow/stem_chart.hpp"
#include "hollow/wound_outline.hpp"
#include "io/input_error.hpp"

namespace heliostand::hollow {

namespace {
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
}  // namespace

using namespace detail;

HollowModel build_hollow(const HollowSpec& spec, const TrunkSurface& trunk, BuildOptions options) {
  if (auto problems = validate(spec, trunk); !problems.empty()) throw InputError(std::move(problems), "field");

  HollowModel model;
  const StemChart chart(trunk, spec.height_m, radians(spec.azimuth_deg));
  model.chart_radius = chart.reference_radius();
  const std::vector<glm::dvec2> plane_loop = sample_outline(spec.width_m, spec.wound_height_m, spec.outline_step_m);
  model.outline_xy = place_outline(plane_loop, chart, spec.placement);
  model.callus = build_callus(model.outline_xy, chart, spec, options.limit_callus);
  const Callus& callus = model.callus;
  const int rings = static_cast<int>(callus.rings.size());

  std::vector<glm::dvec2> foot_loop;
  for (const auto& ring : callus.rings) foot_loop.push_back(ring.foot_xy);
  const WoundProfile profile(foot_loop);

  // The bark patch: the seed's 2W × 2H, widened where the callus needs room for the flow to stay one-to-one.
  const double half_round = chart.half_round();
  const double patch_x = std::min(half_round, std::max(spec.width_m, 2.5 * profile.max_reach()));
  // Vertically the patch must hold the callus foot with room to spare (flat wounds: H is less than the roll).
  const double patch_up = std::min(std::max(spec.wound_height_m, 1.5 * profile.y_max()),
                                   0.95 * trunk.tree_height() - spec.height_m);
  const double patch_down = std::min(std::max(spec.wound_height_m, -1.5 * profile.y_min()), spec.height_m);
  model.patch_half_width = patch_x;
  const BarkFlow flow(profile, patch_x);

  Surroundings around{&chart, patch_x, patch_up, patch_down, spec.callus_radius_m, &model.outline_xy, {}};
  for (int j = 0; j < rings; ++j) around.mean_radius.push_back(callus.mean_radius(j));

  // Columns: bark lines a spacing ≈ l apart across the patch (x = 0 is the split line), then the back of the
  // stem at a spacing whose chords stay within the tolerance.
  const int half_lines = std::max(2, static_cast<int>(std::ceil(patch_x / spec.bark_line_spacing_m)));
  const double dx = patch_x / half_lines;
  std::vector<double> cols;
  for (int j = -half_lines; j <= half_lines; ++j) cols.push_back(j * dx);
  const bool wraps = patch_x >= half_round - 1e-12;
  if (wraps) cols.pop_back();  // x = +πρ0 is x = −πρ0
  const int mid = half_lines;
  const int first_back = static_cast<int>(cols.size());
  if (!wraps) {
    const double back = 2.0 * half_round - 2.0 * patch_x;
    const double step = chart.reference_radius() *
                        angular_step(max_stem_radius(trunk), spec.surface_tolerance_m);
    const int n_back = std::max(2, static_cast<int>(std::ceil(back / step)));
    for (int i = 1; i < n_back; ++i) cols.push_back(patch_x + back * i / n_back);
  }
  const int n_cols = static_cast<int>(cols.size());

  // Rows (chart y): regular ones plus the wound rows where the callus foot's reach changes.
  std::vector<double> extra;
  for (double y : wound_rows(profile, 0.1 * dx)) extra.push_back(y + spec.height_m);
  const double h_lo = spec.height_m - patch_down, h_hi = spec.height_m + patch_up;
  std::vector<double> heights = stem_heights(trunk, h_lo, h_hi, spec.bark_segment_m, extra);
  // No row may sit exactly on the foot's apexes (the split line would touch the foot there).
  const double keep_off = 1e-4 * (profile.y_max() - profile.y_min());
  std::erase_if(heights, [&](double h) {
    const double y = h - spec.height_m;
    return std::abs(y - profile.y_min()) < keep_off || std::abs(y - profile.y_max()) < keep_off;
  });
  const int n_rows = static_cast<int>(heights.size());
  std::vector<double> rows(n_rows);
  for (int k = 0; k < n_rows; ++k) rows[k] = heights[k] - spec.height_m;

  // The wound's reach on either side, once per row (the flow needs it for every line).
  std::vector<double> reach_left(n_rows), reach_right(n_rows);
  for (int k = 0; k < n_rows; ++k) reach_left[k] = profile.left_reach(rows[k]), reach_right[k] = profile.right_reach(rows[k]);

  Builder b;
  std::vector<std::vector<int>> grid(n_cols, std::vector<int>(n_rows, -1));
  for (int c = 0; c < n_cols; ++c) {
    for (int k = 0; k < n_rows; ++k) {
      const double y = rows[k];
      const bool cut = c == mid && y > profile.y_min() && y < profile.y_max();
      if (cut) continue;  // the split line's fibres are cut by the wound
      const bool patch = around.in_patch({cols[c], y});
      const double x = patch && c < first_back ? flow.displaced(cols[c], reach_left[k], reach_right[k]) : cols[c];
      const double lift = patch ? around.lift({x, y}) : 0.0;
      grid[c][k] = b.add(chart.point({x, y}, lift), patch ? MeshPart::bark : MeshPart::trunk, true, {x, y},
                         x - cols[c], lift, c);
    }
  }
  const int apex = b.add({0.0, 0.0, trunk.tree_height()}, MeshPart::trunk, false);
  for (int c = 0; c < n_cols; ++c) b.frozen[grid[c][n_rows - 1]] = true;  // shared with the tip's fan

  // Callus corners; corner 0 (the foot) is on the chart and lifted with the bark it joins.
  std::vector<std::vector<int>> corner(rings);
  for (int j = 0; j < rings; ++j) {
    const CallusRing& ring = callus.rings[j];
    for (int m = 0; m <= callus.lip_corner; ++m) {
      if (m == 0) {
        const double lift = around.lift(ring.foot_xy);
        const glm::dvec3 foot = chart.point(ring.foot_xy, lift);
        corner[j].push_back(b.add(foot, MeshPart::callus, true, ring.foot_xy, 0.0, lift, -1,
                                  glm::length(foot - ring.centre)));
        b.frozen.back() = true;
      } else {
        corner[j].push_back(b.add(ring.corners[m], MeshPart::callus, false, {}, 0.0, 0.0, -1, ring.radius[m]));
      }
    }
  }

  // Stem and bark quads, leaving out those that touch the cut split line.
  for (int c = 0; c < n_cols; ++c) {
    const int c2 = (c + 1) % n_cols;
    for (int k = 0; k + 1 < n_rows; ++k) {
      const int v00 = grid[c][k], v10 = grid[c2][k], v11 = grid[c2][k + 1], v01 = grid[c][k + 1];
      if (v00 < 0 || v10 < 0 || v11 < 0 || v01 < 0) continue;
      b.triangle(v00, v10, v11, true);
      b.triangle(v00, v11, v01, true);
    }
    b.triangle(grid[c][n_rows - 1], grid[c2][n_rows - 1], apex, false);
  }

  // The two strips beside the wound: bark line left of the split ↔ left half of the callus foot, and the
  // right half ↔ the bark line right of the split (the seed's eq. 3.17 joins, as a height-ordered zip).
  int k_lo = 0, k_hi = n_rows - 1;
  for (int k = 0; k < n_rows; ++k) {
    if (rows[k] < profile.y_min()) k_lo = k;
    if (rows[k] > profile.y_max()) { k_hi = k; break; }
  }
  const int bottom = profile.bottom_index(), top = profile.top_index();
  std::vector<int> left_col, right_col, left_foot{grid[mid][k_lo]}, right_foot{grid[mid][k_lo]};
  for (int k = k_lo; k <= k_hi; ++k) {
    left_col.push_back(grid[mid - 1][k]);
    right_col.push_back(grid[mid + 1][k]);
  }
  for (int j = bottom;; j = (j + rings - 1) % rings) { left_foot.push_back(corner[j][0]); if (j == top) break; }
  for (int j = bottom;; j = (j + 1) % rings) { right_foot.push_back(corner[j][0]); if (j == top) break; }
  left_foot.push_back(grid[mid][k_hi]);
  right_foot.push_back(grid[mid][k_hi]);
  zip(b, left_col, left_foot);
  zip(b, right_foot, right_col);

  // The callus roll: quads between consecutive polygons, from the foot over the top into the wound.
  for (int j = 0; j < rings; ++j) {
    const int j2 = (j + 1) % rings;
    for (int m = 0; m < callus.lip_corner; ++m) {
      b.triangle(corner[j][m], corner[j2][m], corner[j2][m + 1], false);
      b.triangle(corner[j][m], corner[j2][m + 1], corner[j][m + 1], false);
    }
  }

  if (options.follow_convexity) model.refinement_passes = follow_convexity(b, around, spec.surface_tolerance_m);

  // The bark lines as the seed would draw them (patch columns and rows only).
  BarkLines& lines = model.bark;
  lines.split_column = 0;
  lines.spacing = dx;
  for (int c = 0; c < first_back; ++c) lines.x.push_back(cols[c]);
  std::vector<int> patch_rows;
  for (int k = 0; k < n_rows; ++k)
    if (rows[k] >= -patch_down - 1e-9 && rows[k] <= patch_up + 1e-9) lines.y.push_back(rows[k]), patch_rows.push_back(k);
  for (int c = 0; c < first_back; ++c) {
    if (cols[c] == 0.0) lines.split_column = static_cast<int>(lines.X.size());
    std::vector<double> X;
    for (int k : patch_rows) {
      const bool cut = cols[c] == 0.0 && rows[k] > profile.y_min() && rows[k] < profile.y_max();
      X.push_back(cut ? nan : flow.displaced(cols[c], reach_left[k], reach_right[k]));
    }
    lines.X.push_back(std::move(X));
  }
  model.mesh = std::move(b.mesh);
  return model;
}

HollowMesh build_trunk_mesh(const TrunkSurface& trunk, double tolerance_m) {
  const double rho = max_stem_radius(trunk);
  const int n_cols = std::max(8, static_cast<int>(std::ceil(2.0 * pi / angular_step(rho, tolerance_m))));
  const std::vector<double> heights = stem_heights(trunk, 0.0, 0.0, 1.0, {});
  Builder b;
  const int n_rows = static_cast<int>(heights.size());
  std::vector<std::vector<int>> grid(n_cols, std::vector<int>(n_rows));
  for (int c = 0; c < n_cols; ++c)
    for (int k = 0; k < n_rows; ++k)
      grid[c][k] = b.add(trunk.point(heights[k], 2.0 * pi * c / n_cols), MeshPart::trunk, false, {}, 0, 0, c);
  const int apex = b.add({0.0, 0.0, trunk.tree_height()}, MeshPart::trunk, false);
  for (int c = 0; c < n_cols; ++c) {
    const int c2 = (c + 1) % n_cols;
    for (int k = 0; k + 1 < n_rows; ++k) {
      b.triangle(grid[c][k], grid[c2][k], grid[c2][k + 1], false);
      b.triangle(grid[c][k], grid[c2][k + 1], grid[c][k + 1], false);
    }
    b.triangle(grid[c][n_rows - 1], grid[c2][n_rows - 1], apex, false);
  }
  return std::move(b.mesh);
}

}  // namespace heliostand::hollow
