#include "hollow/wound_outline.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace heliostand::hollow {

namespace {
constexpr std::array<double, 6> binomial5{1, 5, 10, 10, 5, 1};
constexpr std::array<double, 5> binomial4{1, 4, 6, 4, 1};
}  // namespace

ControlPoints right_control_points(double w, double h) {
  return {glm::dvec2{0.0, -h / 2}, {w / 4, -h / 2}, {w / 2, -h / 4}, {w / 2, 0.0}, {w / 4, h / 2}, {0.0, h / 2}};
}

ControlPoints left_control_points(double w, double h) {
  ControlPoints p = right_control_points(w, h);
  for (auto& q : p) q.x = -q.x;
  return p;
}

glm::dvec2 bezier5(const ControlPoints& p, double t) {
  glm::dvec2 sum{0.0};
  for (int i = 0; i <= 5; ++i) sum += binomial5[i] * std::pow(t, i) * std::pow(1.0 - t, 5 - i) * p[i];
  return sum;
}

glm::dvec2 bezier5_derivative(const ControlPoints& p, double t) {
  glm::dvec2 sum{0.0};
  for (int i = 0; i <= 4; ++i) sum += binomial4[i] * std::pow(t, i) * std::pow(1.0 - t, 4 - i) * (p[i + 1] - p[i]);
  return 5.0 * sum;
}

std::vector<double> arc_length_parameters(const ControlPoints& p, double step) {
  std::vector<double> ts{0.0};
  double t = 0.0;
  while (true) {
    // |K′| vanishes nowhere on these curves (P0 ≠ P1), but guard the division anyway.
    const double speed = std::max(glm::length(bezier5_derivative(p, t)), 1e-12);
    t += step / speed;
    if (t >= 1.0) break;
    ts.push_back(t);
  }
  // Close on the end point; a sliver of a last step would give two nearly coincident vertices.
  if (ts.size() > 1 && glm::length(bezier5(p, 1.0) - bezier5(p, ts.back())) < 0.5 * step) ts.pop_back();
  ts.push_back(1.0);
  return ts;
}

std::vector<glm::dvec2> sample_outline(double width, double height, double step) {
  const ControlPoints right = right_control_points(width, height);
  const ControlPoints left = left_control_points(width, height);
  std::vector<glm::dvec2> loop;
  for (double t : arc_length_parameters(right, step)) loop.push_back(bezier5(right, t));
  const std::vector<double> tl = arc_length_parameters(left, step);
  // Down the left curve, leaving out its ends: they are the apexes already on the right curve.
  for (auto it = tl.rbegin() + 1; it + 1 != tl.rend(); ++it) loop.push_back(bezier5(left, *it));
  return loop;
}

int top_vertex(const std::vector<glm::dvec2>& loop) {
  return static_cast<int>(std::max_element(loop.begin(), loop.end(),
                                           [](auto& a, auto& b) { return a.y < b.y; }) - loop.begin());
}

int bottom_vertex(const std::vector<glm::dvec2>& loop) {
  return static_cast<int>(std::min_element(loop.begin(), loop.end(),
                                           [](auto& a, auto& b) { return a.y < b.y; }) - loop.begin());
}

std::vector<glm::dvec2> outward_normals(const std::vector<glm::dvec2>& loop, double period) {
  const int n = static_cast<int>(loop.size());
  std::vector<glm::dvec2> normals(n);
  for (int j = 0; j < n; ++j) {
    glm::dvec2 step = loop[(j + 1) % n] - loop[(j + n - 1) % n];
    if (period > 0.0) step.x = std::remainder(step.x, period);
    const glm::dvec2 tangent = glm::normalize(step);
    normals[j] = {tangent.y, -tangent.x};  // right of the direction of travel = outside for a CCW loop
  }
  return normals;
}

}  // namespace heliostand::hollow
