#include "hollow/hollow_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <glm/geometric.hpp>

#include "geometry/angles.hpp"
#include "hollow/bark_flow.hpp"
#include "hollow/placement.hpp"
#include "hollow/stem_chart.hpp"
#include "hollow/wound_outline.hpp"
#include "io/input_error.hpp"

namespace heliostand::hollow {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// Largest angular step whose chord stays within `tolerance` of a circle of radius rho.
double angular_step(double rho, double tolerance) {
  if (rho <= tolerance) return 2.0 * pi / 16.0;
  return std::min(2.0 * std::acos(1.0 - tolerance / rho), 2.0 * pi / 16.0);
}

double max_stem_radius(const TrunkSurface& trunk) {
  double rho = 0.0;
  for (int i = 0; i <= 50; ++i) rho = std::max(rho, trunk.radius(trunk.tree_height() * i / 50.0));
  return rho;
}

// Stem rows (heights): every `patch_step` inside [lo, hi], coarser elsewhere (finer near a flaring collar),
// plus the given extra heights; up to just below the tip, which is closed by an apex vertex.
std::vector<double> stem_heights(const TrunkSurface& trunk, double lo, double hi, double patch_step,
                                 const std::vector<double>& extra) {
  std::vector<double> h;
  const double top = trunk.tree_height();
  const double collar = trunk.buttress().flare > 0.0 ? 3.0 * trunk.buttress().decay_height_m : 0.0;
  auto coarse_step = [&](double z) { return z < collar ? std::min(0.05, trunk.buttress().decay_height_m / 3.0) : 0.25; };
  for (double z = 0.0; z < lo - 1e-9; z += coarse_step(z)) h.push_back(z);
  const int n = std::max(1, static_cast<int>(std::ceil((hi - lo) / patch_step)));
  for (int i = 0; i <= n; ++i) h.push_back(lo + (hi - lo) * i / n);
  const double last = top - std::max(0.02 * top, 0.01);
  for (double z = hi + coarse_step(hi); z < last; z += coarse_step(z)) h.push_back(z);
  h.push_back(last);
  for (double z : extra) h.push_back(z);
  std::sort(h.begin(), h.end());
  std::vector<double> rows;
  for (double z : h) {
    if (!rows.empty() && z - rows.back() < 1e-6) continue;
    rows.push_back(z);
  }
  return rows;
}

// Mesh under construction, with the chart position of every vertex that lies on (or is lifted off) the stem.
struct Builder {
  HollowMesh mesh;
  std::vector<glm::dvec2> chart_xy;
  std::vector<bool> on_chart;
  std::vector<bool> frozen;  // edges between two frozen vertices are shared with unrefined faces: never split
  std::vector<bool> refinable_triangle;

  int add(const glm::dvec3& p, MeshPart part, bool chart, glm::dvec2 xy = {}, double shift = 0.0,
          double lift = 0.0, int line = -1, double thickness = 0.0) {
    mesh.vertices.push_back(p);
    mesh.part.push_back(static_cast<int>(part));
    mesh.callus_thickness_m.push_back(thickness);
    mesh.bark_shift_m.push_back(shift);
    mesh.bark_lift_m.push_back(lift);
    mesh.bark_line.push_back(line);
    chart_xy.push_back(xy);
    on_chart.push_back(chart);
    frozen.push_back(false);
    return static_cast<int>(mesh.vertices.size()) - 1;
  }
  void triangle(int a, int b, int c, bool refinable) {
    mesh.triangles.push_back({a, b, c});
    refinable_triangle.push_back(refinable);
  }
};

// Joins two chains that both run upwards (left chain on the left) with triangles, merging by height.
void zip(Builder& b, const std::vector<int>& left, const std::vector<int>& right) {
  std::size_t i = 0, j = 0;
  while (i + 1 < left.size() || j + 1 < right.size()) {
    const bool advance_left =
        j + 1 >= right.size() ||
        (i + 1 < left.size() && b.chart_xy[left[i + 1]].y <= b.chart_xy[right[j + 1]].y);
    if (advance_left) {
      b.triangle(left[i], right[j], left[i + 1], true);
      ++i;
    } else {
      b.triangle(left[i], right[j], right[j + 1], true);
      ++j;
    }
  }
}

// Everything the lift and the patch tests need about the hollow's surroundings.
struct Surroundings {
  const StemChart* chart;
  double patch_x, patch_up, patch_down;
  double callus_radius;
  const std::vector<glm::dvec2>* outline;
  std::vector<double> mean_radius;

  double wrapped(double x) const { return std::remainder(x, 2.0 * chart->half_round()); }
  bool in_patch(glm::dvec2 xy) const {
    return std::abs(wrapped(xy.x)) <= patch_x + 1e-9 && xy.y >= -patch_down - 1e-9 && xy.y <= patch_up + 1e-9;
  }
  // Eq. 3.18 with a window that brings the rise to zero at the patch border, where the bark meets the stem.
  double lift(glm::dvec2 xy) const {
    if (!in_patch(xy)) return 0.0;
    const double x = wrapped(xy.x);
    const double s = std::max(std::abs(x) / patch_x, xy.y >= 0.0 ? xy.y / patch_up : -xy.y / patch_down);
    if (s >= 1.0) return 0.0;
    double nearest = 1e30;
    int j_near = 0;
    for (std::size_t j = 0; j < outline->size(); ++j) {
      const double d = glm::length((*outline)[j] - glm::dvec2{x, xy.y});
      if (d < nearest) nearest = d, j_near = static_cast<int>(j);
    }
    return seed_bark_lift(mean_radius[j_near], callus_radius, nearest) * (1.0 - s) * (1.0 - s);
  }
};

// Splits stem/bark edges whose midpoint is further than `tolerance` from the (lifted) surface, so that faces
// follow the stem's convexity; the split decision is per edge, so neighbouring faces stay conforming.
int follow_convexity(Builder& b, const Surroundings& around, double tolerance) {
  const double round = 2.0 * around.chart->half_round();
  int passes = 0;
  for (int pass = 0; pass < 10; ++pass) {
    std::map<std::pair<int, int>, int> midpoint;
    auto key = [](int a, int c) { return std::make_pair(std::min(a, c), std::max(a, c)); };
    for (std::size_t t = 0; t < b.mesh.triangles.size(); ++t) {
      if (!b.refinable_triangle[t]) continue;
      const auto tri = b.mesh.triangles[t];
      for (int e = 0; e < 3; ++e) {
        const int p = tri[e], q = tri[(e + 1) % 3];
        if ((b.frozen[p] && b.frozen[q]) || midpoint.count(key(p, q))) continue;
        // Edges a few tolerances long are as flat as they need to be (and a step in the taper cannot be cured).
        if (glm::length(b.mesh.vertices[p] - b.mesh.vertices[q]) < 4.0 * tolerance) continue;
        glm::dvec2 xp = b.chart_xy[p], xq = b.chart_xy[q];
        if (xq.x - xp.x > round / 2) xq.x -= round;  // across the seam at the back of the stem
        if (xp.x - xq.x > round / 2) xq.x += round;
        const glm::dvec2 mid = 0.5 * (xp + xq);
        const double lift = around.lift(mid);
        const glm::dvec3 on_surface = around.chart->point(mid, lift);
        if (glm::length(on_surface - 0.5 * (b.mesh.vertices[p] + b.mesh.vertices[q])) <= tolerance) continue;
        const MeshPart part = around.in_patch(mid) ? MeshPart::bark : MeshPart::trunk;
        const int line = b.mesh.bark_line[p] == b.mesh.bark_line[q] ? b.mesh.bark_line[p] : -1;
        midpoint[key(p, q)] = b.add(on_surface, part, true, mid,
                                    0.5 * (b.mesh.bark_shift_m[p] + b.mesh.bark_shift_m[q]), lift, line);
      }
    }
    if (midpoint.empty()) break;
    ++passes;
    std::vector<std::array<int, 3>> triangles;
    std::vector<bool> refinable;
    auto emit = [&](int a, int c, int d, bool r) { triangles.push_back({a, c, d}); refinable.push_back(r); };
    for (std::size_t t = 0; t < b.mesh.triangles.size(); ++t) {
      const auto tri = b.mesh.triangles[t];
      if (!b.refinable_triangle[t]) { emit(tri[0], tri[1], tri[2], false); continue; }
      int m[3];
      int splits = 0;
      for (int e = 0; e < 3; ++e) {
        auto it = midpoint.find(key(tri[e], tri[(e + 1) % 3]));
        m[e] = it == midpoint.end() ? -1 : it->second;
        splits += m[e] >= 0;
      }
      if (splits == 0) { emit(tri[0], tri[1], tri[2], true); continue; }
      if (splits == 3) {
        emit(tri[0], m[0], m[2], true); emit(m[0], tri[1], m[1], true);
        emit(m[2], m[1], tri[2], true); emit(m[0], m[1], m[2], true);
        continue;
      }
      // Rotate so that edge 0 (v0→v1) is split; with two splits, edge 1 or edge 2 is the other one.
      int r = 0;
      while (m[r] < 0 || (splits == 2 && m[(r + 2) % 3] >= 0)) ++r;
      const int v0 = tri[r], v1 = tri[(r + 1) % 3], v2 = tri[(r + 2) % 3];
      const int m01 = m[r], m12 = m[(r + 1) % 3];
      if (splits == 1) {
        emit(v0, m01, v2, true); emit(m01, v1, v2, true);
      } else {  // edges v0v1 and v1v2 split
        emit(m01, v1, m12, true); emit(v0, m01, m12, true); emit(v0, m12, v2, true);
      }
    }
    b.mesh.triangles = std::move(triangles);
    b.refinable_triangle = std::move(refinable);
  }
  return passes;
}

}  // namespace

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

  Builder b;
  std::vector<std::vector<int>> grid(n_cols, std::vector<int>(n_rows, -1));
  for (int c = 0; c < n_cols; ++c) {
    for (int k = 0; k < n_rows; ++k) {
      const double y = rows[k];
      const bool cut = c == mid && y > profile.y_min() && y < profile.y_max();
      if (cut) continue;  // the split line's fibres are cut by the wound
      const bool patch = around.in_patch({cols[c], y});
      const double x = patch && c < first_back ? flow.displaced(cols[c], y) : cols[c];
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
  for (int k = 0; k < n_rows; ++k)
    if (rows[k] >= -patch_down - 1e-9 && rows[k] <= patch_up + 1e-9) lines.y.push_back(rows[k]);
  for (int c = 0; c < first_back; ++c) {
    if (cols[c] == 0.0) lines.split_column = static_cast<int>(lines.X.size());
    std::vector<double> X;
    for (double y : lines.y) {
      const bool cut = cols[c] == 0.0 && y > profile.y_min() && y < profile.y_max();
      X.push_back(cut ? nan : flow.displaced(cols[c], y));
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
