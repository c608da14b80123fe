#include "crown_shape.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace heliostand {

namespace {

// Union-find over tip indices for the touching leaf balls.
int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

double largest_connected_fraction(const std::vector<CrownTip>& tips, double link) {
  const int n = static_cast<int>(tips.size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (glm::length(tips[i].position - tips[j].position) < link) parent[find_root(parent, i)] = find_root(parent, j);
  std::vector<int> size(n, 0);
  for (int i = 0; i < n; ++i) ++size[find_root(parent, i)];
  return static_cast<double>(*std::max_element(size.begin(), size.end())) / n;
}

double clark_evans(const std::vector<CrownTip>& tips) {
  const double area = top_view_hull_area(tips);
  if (tips.size() < 3 || area <= 0.0) return 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < tips.size(); ++i) {
    double nearest = std::numeric_limits<double>::max();
    for (std::size_t j = 0; j < tips.size(); ++j)
      if (i != j)
        nearest = std::min(nearest, std::hypot(tips[i].position.x - tips[j].position.x,
                                               tips[i].position.y - tips[j].position.y));
    sum += nearest;
  }
  const double density = tips.size() / area;
  return (sum / tips.size()) / (0.5 / std::sqrt(density));
}

}  // namespace

double top_view_hull_area(const std::vector<CrownTip>& tips) {
  // Andrew's monotone chain.
  std::vector<glm::dvec2> p;
  for (const CrownTip& t : tips) p.emplace_back(t.position.x, t.position.y);
  std::sort(p.begin(), p.end(), [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (p.size() < 3) return 0.0;
  auto cross = [](glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
  std::vector<glm::dvec2> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  double area = 0.0;
  for (std::size_t i = 0; i + 1 < k; ++i) area += hull[i].x * hull[i + 1].y - hull[i + 1].x * hull[i].y;
  return 0.5 * std::abs(area);
}

CrownShape measure_crown_shape(const std::vector<CrownTip>& tips, double leaf_ball_radius) {
  CrownShape s;
  if (tips.empty()) return s;
  s.connected = largest_connected_fraction(tips, 4.0 * leaf_ball_radius);
  int drooping = 0, up = 0;
  double low_x = std::numeric_limits<double>::max(), high_x = -low_x, low_y = low_x, high_y = -low_x;
  double low_z = low_x, high_z = -low_x;
  for (const CrownTip& t : tips) {
    const bool droops = t.position.z < t.branch_base_z;
    drooping += droops;
    up += droops && t.direction.z > 0.0;
    low_x = std::min(low_x, t.position.x), high_x = std::max(high_x, t.position.x);
    low_y = std::min(low_y, t.position.y), high_y = std::max(high_y, t.position.y);
    low_z = std::min(low_z, t.position.z), high_z = std::max(high_z, t.position.z);
  }
  s.drooping = static_cast<double>(drooping) / tips.size();
  s.tip_up = drooping > 0 ? static_cast<double>(up) / drooping : 0.0;
  s.evenness = clark_evans(tips);
  const double depth = high_z - low_z;
  s.width_over_depth = depth > 0.0 ? 0.5 * ((high_x - low_x) + (high_y - low_y)) / depth : 0.0;
  return s;
}

CrownShape mean_of(const std::vector<CrownShape>& all) {
  CrownShape m;
  const double n = static_cast<double>(all.size());
  for (const CrownShape& a : all) {
    m.connected += a.connected / n;
    m.tip_up += a.tip_up / n;
    m.drooping += a.drooping / n;
    m.evenness += a.evenness / n;
    m.width_over_depth += a.width_over_depth / n;
  }
  return m;
}

}  // namespace heliostand
