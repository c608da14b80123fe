#include "hollow/stem_mesh_builder.hpp"

#include <algorithm>
#include <map>

#include <glm/geometric.hpp>

#include "geometry/angles.hpp"
#include "hollow/bark_flow.hpp"

namespace heliostand::hollow::detail {

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

std::vector<double> stem_heights(const TrunkSurface& trunk, double lo, double hi, double patch_step,
                                 const std::vector<double>& extra, double top_row) {
  std::vector<double> h;
  const double top = trunk.tree_height();
  const double collar = trunk.buttress().flare > 0.0 ? 3.0 * trunk.buttress().decay_height_m : 0.0;
  auto coarse_step = [&](double z) { return z < collar ? std::min(0.05, trunk.buttress().decay_height_m / 3.0) : 0.25; };
  for (double z = 0.0; z < lo - 1e-9; z += coarse_step(z)) h.push_back(z);
  const int n = std::max(1, static_cast<int>(std::ceil((hi - lo) / patch_step)));
  for (int i = 0; i <= n; ++i) h.push_back(lo + (hi - lo) * i / n);
  const double last = top_row >= 0.0 ? top_row : top - std::max(0.02 * top, 0.01);
  for (double z = hi + coarse_step(hi); z < last; z += coarse_step(z)) h.push_back(z);
  h.push_back(last);
  for (double z : extra) h.push_back(z);
  std::erase_if(h, [last](double z) { return z > last; });
  std::sort(h.begin(), h.end());
  std::vector<double> rows;
  for (double z : h) {
    if (!rows.empty() && z - rows.back() < 1e-6) continue;
    rows.push_back(z);
  }
  return rows;
}

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

double Surroundings::lift(glm::dvec2 xy) const {
  if (!in_patch(xy)) return 0.0;
  const double x = wrapped(xy.x);
  const double across = full_round ? 0.0 : std::abs(x) / patch_x;
  const double s = std::max(across, xy.y >= 0.0 ? xy.y / patch_up : -xy.y / patch_down);
  if (s >= 1.0) return 0.0;
  // Nearest rim vertex: every 16th vertex first, then the neighbourhood of the best one (the rim is sampled
  // every millimetre, the bark lies centimetres away, so the coarse pass cannot miss the right stretch).
  const int n = static_cast<int>(outline->size());
  auto distance_to = [&](int j) {
    const glm::dvec2& v = (*outline)[((j % n) + n) % n];
    return glm::length(glm::dvec2{wrapped(v.x - x), v.y - xy.y});
  };
  constexpr int stride = 16;
  double nearest = 1e30;
  int j_near = 0;
  for (int j = 0; j < n; j += stride)
    if (const double d = distance_to(j); d < nearest) nearest = d, j_near = j;
  const int coarse = j_near;
  for (int j = coarse - stride; j <= coarse + stride; ++j)
    if (const double d = distance_to(j); d < nearest) nearest = d, j_near = ((j % n) + n) % n;
  return seed_bark_lift(mean_radius[j_near], callus_radius, nearest) * (1.0 - s) * (1.0 - s);
}

void add_grid_quads(Builder& b, const std::vector<std::vector<int>>& grid) {
  const int n_cols = static_cast<int>(grid.size());
  for (int c = 0; c < n_cols; ++c) {
    const int c2 = (c + 1) % n_cols;
    for (std::size_t k = 0; k + 1 < grid[c].size(); ++k) {
      const int v00 = grid[c][k], v10 = grid[c2][k], v11 = grid[c2][k + 1], v01 = grid[c][k + 1];
      if (v00 < 0 || v10 < 0 || v11 < 0 || v01 < 0) continue;
      b.triangle(v00, v10, v11, true);
      b.triangle(v00, v11, v01, true);
    }
  }
}

void close_tip(Builder& b, const std::vector<std::vector<int>>& grid, double tree_height) {
  const int apex = b.add({0.0, 0.0, tree_height}, MeshPart::trunk, false);
  const int n_cols = static_cast<int>(grid.size());
  for (int c = 0; c < n_cols; ++c) {
    const int top = grid[c].back(), next = grid[(c + 1) % n_cols].back();
    b.frozen[top] = true;  // shared with the unrefined fan
    b.triangle(top, next, apex, false);
  }
}

std::vector<std::vector<int>> add_callus_corners(Builder& b, const Callus& callus, const StemChart& chart,
                                                 const Surroundings& around) {
  std::vector<std::vector<int>> corner(callus.rings.size());
  for (std::size_t j = 0; j < callus.rings.size(); ++j) {
    const CallusRing& ring = callus.rings[j];
    const double lift = around.lift(ring.foot_xy);
    const glm::dvec3 foot = chart.point(ring.foot_xy, lift);
    corner[j].push_back(b.add(foot, MeshPart::callus, true, ring.foot_xy, 0.0, lift, -1, glm::length(foot - ring.centre)));
    b.frozen.back() = true;  // foot edges are shared with the unrefined roll
    for (int m = 1; m <= callus.lip_corner; ++m)
      corner[j].push_back(b.add(ring.corners[m], MeshPart::callus, false, {}, 0.0, 0.0, -1, ring.radius[m]));
  }
  return corner;
}

void add_roll(Builder& b, const Callus& callus, const std::vector<std::vector<int>>& corner) {
  const int rings = static_cast<int>(corner.size());
  for (int j = 0; j < rings; ++j) {
    const int j2 = (j + 1) % rings;
    for (int m = 0; m < callus.lip_corner; ++m) {
      b.triangle(corner[j][m], corner[j2][m], corner[j2][m + 1], false);
      b.triangle(corner[j][m], corner[j2][m + 1], corner[j][m + 1], false);
    }
  }
}

}  // namespace heliostand::hollow::detail
