#include "hollow/mesh_checks.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <glm/vec2.hpp>

namespace heliostand::hollow {

ManifoldReport check_manifold(const std::vector<glm::dvec3>& vertices,
                              const std::vector<std::array<int, 3>>& triangles, double min_area) {
  ManifoldReport report;
  // For each undirected edge: how often it is used, and the net count of its two directions.
  std::map<std::pair<int, int>, std::pair<int, int>> uses;
  for (const auto& t : triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0] ||
        0.5 * glm::length(glm::cross(vertices[t[1]] - vertices[t[0]], vertices[t[2]] - vertices[t[0]])) < min_area) {
      ++report.degenerate_triangles;
    }
    for (int e = 0; e < 3; ++e) {
      const int a = t[e], b = t[(e + 1) % 3];
      auto& u = uses[{std::min(a, b), std::max(a, b)}];
      ++u.first;
      u.second += a < b ? 1 : -1;
    }
  }
  report.edges = static_cast<int>(uses.size());
  for (const auto& [edge, u] : uses) {
    if (u.first == 1) ++report.boundary_edges;
    else if (u.first > 2) ++report.non_manifold_edges;
    else if (u.second != 0) ++report.inconsistent_edges;  // both triangles run the edge the same way
  }
  return report;
}

namespace {

constexpr double plane_epsilon = 1e-10;  // m: distances below this count as "on the plane"

// Interval of the line of plane intersection covered by one triangle (Möller's "compute intervals").
bool interval(const double p[3], const double d[3], double& lo, double& hi) {
  int alone;
  if (d[0] * d[1] > 0) alone = 2;
  else if (d[0] * d[2] > 0) alone = 1;
  else if (d[1] * d[2] > 0 || d[0] != 0) alone = 0;
  else if (d[1] != 0) alone = 1;
  else if (d[2] != 0) alone = 2;
  else return false;  // coplanar
  const int j = (alone + 1) % 3, k = (alone + 2) % 3;
  const double t1 = p[alone] + (p[j] - p[alone]) * d[alone] / (d[alone] - d[j]);
  const double t2 = p[alone] + (p[k] - p[alone]) * d[alone] / (d[alone] - d[k]);
  lo = std::min(t1, t2);
  hi = std::max(t1, t2);
  return true;
}

double cross2(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

bool segments_cross(glm::dvec2 p, glm::dvec2 q, glm::dvec2 r, glm::dvec2 s) {
  const double d1 = cross2(q - p, r - p), d2 = cross2(q - p, s - p);
  const double d3 = cross2(s - r, p - r), d4 = cross2(s - r, q - r);
  return d1 * d2 <= 0 && d3 * d4 <= 0 &&
         std::max(p.x, q.x) >= std::min(r.x, s.x) && std::max(r.x, s.x) >= std::min(p.x, q.x) &&
         std::max(p.y, q.y) >= std::min(r.y, s.y) && std::max(r.y, s.y) >= std::min(p.y, q.y);
}

bool inside_triangle(glm::dvec2 p, const glm::dvec2 t[3]) {
  const double a = cross2(t[1] - t[0], p - t[0]), b = cross2(t[2] - t[1], p - t[1]), c = cross2(t[0] - t[2], p - t[2]);
  return (a >= 0 && b >= 0 && c >= 0) || (a <= 0 && b <= 0 && c <= 0);
}

bool coplanar_intersect(const glm::dvec3& n, const glm::dvec3 a[3], const glm::dvec3 b[3]) {
  // Drop the axis along which the normal is largest and work in the remaining two.
  const glm::dvec3 m = glm::abs(n);
  const int drop = m.x >= m.y && m.x >= m.z ? 0 : (m.y >= m.z ? 1 : 2);
  auto flat = [drop](const glm::dvec3& v) {
    return drop == 0 ? glm::dvec2{v.y, v.z} : drop == 1 ? glm::dvec2{v.x, v.z} : glm::dvec2{v.x, v.y};
  };
  glm::dvec2 p[3], q[3];
  for (int i = 0; i < 3; ++i) p[i] = flat(a[i]), q[i] = flat(b[i]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (segments_cross(p[i], p[(i + 1) % 3], q[j], q[(j + 1) % 3])) return true;
  return inside_triangle(p[0], q) || inside_triangle(q[0], p);
}

}  // namespace

bool triangles_intersect(const glm::dvec3& a0, const glm::dvec3& a1, const glm::dvec3& a2,
                         const glm::dvec3& b0, const glm::dvec3& b1, const glm::dvec3& b2) {
  const glm::dvec3 a[3] = {a0, a1, a2}, b[3] = {b0, b1, b2};
  const glm::dvec3 n2 = glm::cross(b1 - b0, b2 - b0);
  const glm::dvec3 n1 = glm::cross(a1 - a0, a2 - a0);
  if (glm::length(n1) == 0.0 || glm::length(n2) == 0.0) return false;  // degenerate: reported elsewhere
  const glm::dvec3 u2 = glm::normalize(n2), u1 = glm::normalize(n1);
  double da[3], db[3];
  for (int i = 0; i < 3; ++i) {
    da[i] = glm::dot(u2, a[i] - b0);
    if (std::abs(da[i]) < plane_epsilon) da[i] = 0;
    db[i] = glm::dot(u1, b[i] - a0);
    if (std::abs(db[i]) < plane_epsilon) db[i] = 0;
  }
  if ((da[0] > 0 && da[1] > 0 && da[2] > 0) || (da[0] < 0 && da[1] < 0 && da[2] < 0)) return false;
  if ((db[0] > 0 && db[1] > 0 && db[2] > 0) || (db[0] < 0 && db[1] < 0 && db[2] < 0)) return false;
  if (da[0] == 0 && da[1] == 0 && da[2] == 0) return coplanar_intersect(u1, a, b);
  // Project onto the axis along which the line of intersection D = n1 × n2 is largest.
  const glm::dvec3 d = glm::abs(glm::cross(u1, u2));
  const int axis = d.x >= d.y && d.x >= d.z ? 0 : (d.y >= d.z ? 1 : 2);
  double pa[3], pb[3];
  for (int i = 0; i < 3; ++i) pa[i] = a[i][axis], pb[i] = b[i][axis];
  double lo_a, hi_a, lo_b, hi_b;
  if (!interval(pa, da, lo_a, hi_a) || !interval(pb, db, lo_b, hi_b)) return coplanar_intersect(u1, a, b);
  return hi_a >= lo_b && hi_b >= lo_a;
}

IntersectionReport find_self_intersections(const std::vector<glm::dvec3>& vertices,
                                           const std::vector<std::array<int, 3>>& triangles, int limit) {
  IntersectionReport report;
  const int n = static_cast<int>(triangles.size());
  if (n < 2) return report;
  std::vector<glm::dvec3> lo(n), hi(n);
  std::vector<double> extent(n);
  glm::dvec3 world_lo{1e300}, world_hi{-1e300};
  for (int t = 0; t < n; ++t) {
    const auto& v = triangles[t];
    lo[t] = glm::min(vertices[v[0]], glm::min(vertices[v[1]], vertices[v[2]]));
    hi[t] = glm::max(vertices[v[0]], glm::max(vertices[v[1]], vertices[v[2]]));
    const glm::dvec3 size = hi[t] - lo[t];
    extent[t] = std::max({size.x, size.y, size.z});
    world_lo = glm::min(world_lo, lo[t]);
    world_hi = glm::max(world_hi, hi[t]);
  }
  // Cells twice the median triangle size; triangles spanning very many cells are tested against all others
  // by bounding box instead (the long stem faces far from the hollow).
  std::vector<double> sorted = extent;
  std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
  const double cell = std::max(2.0 * sorted[n / 2], 1e-6);
  auto cell_of = [&](const glm::dvec3& p) { return glm::ivec3(glm::floor((p - world_lo) / cell)); };
  auto cell_key = [](glm::ivec3 c) {
    return (static_cast<long long>(c.x) * 73856093LL) ^ (static_cast<long long>(c.y) * 19349663LL) ^
           (static_cast<long long>(c.z) * 83492791LL);
  };
  std::unordered_map<long long, std::vector<int>> cells;
  std::vector<int> big;
  for (int t = 0; t < n; ++t) {
    const glm::ivec3 a = cell_of(lo[t]), b = cell_of(hi[t]);
    const long long count = static_cast<long long>(b.x - a.x + 1) * (b.y - a.y + 1) * (b.z - a.z + 1);
    if (count > 512) { big.push_back(t); continue; }
    for (int x = a.x; x <= b.x; ++x)
      for (int y = a.y; y <= b.y; ++y)
        for (int z = a.z; z <= b.z; ++z) cells[cell_key({x, y, z})].push_back(t);
  }
  auto shares_vertex = [&](int s, int t) {
    for (int i : triangles[s])
      for (int j : triangles[t])
        if (i == j) return true;
    return false;
  };
  auto boxes_overlap = [&](int s, int t) {
    return glm::all(glm::lessThanEqual(lo[s], hi[t])) && glm::all(glm::lessThanEqual(lo[t], hi[s]));
  };
  auto test = [&](int s, int t) {
    if (!boxes_overlap(s, t) || shares_vertex(s, t)) return;
    ++report.pairs_tested;
    const auto& u = triangles[s];
    const auto& v = triangles[t];
    if (triangles_intersect(vertices[u[0]], vertices[u[1]], vertices[u[2]], vertices[v[0]], vertices[v[1]],
                            vertices[v[2]])) {
      ++report.count;
      if (static_cast<int>(report.intersecting.size()) < limit) report.intersecting.push_back({s, t});
    }
  };
  for (const auto& [key, members] : cells) {
    for (std::size_t i = 0; i < members.size(); ++i) {
      for (std::size_t j = i + 1; j < members.size(); ++j) {
        const int s = members[i], t = members[j];
        // Test each pair once: in the first cell (lowest corner) their cell ranges share.
        const glm::ivec3 first = glm::max(cell_of(lo[s]), cell_of(lo[t]));
        if (cell_key(first) != key) continue;
        test(s, t);
      }
    }
  }
  std::vector<bool> is_big(n, false);
  for (int s : big) is_big[s] = true;
  for (int s : big)
    for (int t = 0; t < n; ++t)
      if (t != s && (!is_big[t] || t > s)) test(s, t);
  return report;
}

}  // namespace heliostand::hollow
