#include "hollow/bark_flow.hpp"

#include <algorithm>
#include <cmath>

#include "hollow/hollow_spec.hpp"
#include "hollow/wound_outline.hpp"

namespace heliostand::hollow {

WoundProfile::WoundProfile(std::vector<glm::dvec2> loop) : loop_(std::move(loop)) {
  bottom_ = bottom_vertex(loop_);
  top_ = top_vertex(loop_);
  y_min_ = loop_[bottom_].y;
  y_max_ = loop_[top_].y;
}

namespace {
// x where the loop's edges cross the horizontal line at height y.
template <class Pick>
double crossing(const std::vector<glm::dvec2>& loop, double y, double start, Pick pick) {
  double best = start;
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec2 a = loop[i], b = loop[(i + 1) % n];
    if ((a.y - y) * (b.y - y) > 0.0 || a.y == b.y) continue;
    const double x = a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y);
    best = pick(best, x);
  }
  return best;
}
}  // namespace

double WoundProfile::left_reach(double y) const {
  if (y <= y_min_ || y >= y_max_) return 0.0;
  return std::max(0.0, -crossing(loop_, y, 0.0, [](double a, double b) { return std::min(a, b); }));
}

double WoundProfile::right_reach(double y) const {
  if (y <= y_min_ || y >= y_max_) return 0.0;
  return std::max(0.0, crossing(loop_, y, 0.0, [](double a, double b) { return std::max(a, b); }));
}

double WoundProfile::max_reach() const {
  double reach = 0.0;
  for (const auto& p : loop_) reach = std::max(reach, std::abs(p.x));
  return reach;
}

BarkFlow::BarkFlow(const WoundProfile& profile, double patch_half_width)
    : profile_(&profile), half_width_(patch_half_width) {
  // dX/dx = 1 − k·w/P·(1 − s)^(k−1) ≥ 1 − k·w/P: keep k·w ≤ 0.8 P (order kept, ≥ 20 % of the spacing left).
  // A quadratic fade where the wound is narrow relative to the patch, linear at the widest wounds.
  const double reach = std::max(profile.max_reach(), 1e-9);
  exponent_ = std::clamp(0.8 * half_width_ / reach, 1.0, 2.0);
}

double BarkFlow::displaced(double x, double y) const {
  if (x == 0.0) return 0.0;
  return displaced(x, x < 0.0 ? profile_->left_reach(y) : 0.0, x > 0.0 ? profile_->right_reach(y) : 0.0);
}

double BarkFlow::displaced(double x, double left_reach, double right_reach) const {
  if (x == 0.0) return 0.0;
  const double s = std::min(std::abs(x) / half_width_, 1.0);
  const double reach = x < 0.0 ? left_reach : right_reach;
  const double shift = reach * std::pow(1.0 - s, exponent_);
  return x < 0.0 ? x - shift : x + shift;
}

std::vector<double> wound_rows(const WoundProfile& profile, double reach_step) {
  std::vector<double> candidates;
  for (const auto& p : profile.loop()) candidates.push_back(p.y);
  std::sort(candidates.begin(), candidates.end());
  std::vector<double> rows;
  const double span = profile.y_max() - profile.y_min();
  const double keep_off = 1e-4 * span;  // rows exactly at the apexes would touch the foot's end vertices
  double last_left = 0.0, last_right = 0.0, last_y = profile.y_min();
  for (double y : candidates) {
    if (y <= profile.y_min() + keep_off || y >= profile.y_max() - keep_off) continue;
    if (y - last_y < keep_off) continue;
    const double left = profile.left_reach(y), right = profile.right_reach(y);
    if (std::abs(left - last_left) > reach_step || std::abs(right - last_right) > reach_step) {
      rows.push_back(y);
      last_left = left, last_right = right, last_y = y;
    }
  }
  return rows;
}

double seed_bark_lift(double mean_callus_radius, double callus_radius, double distance) {
  const double seed_lift = seed_unit_m * seed_unit_m * (mean_callus_radius / (2.0 * callus_radius)) /
                           std::max(distance, 1e-9);
  return std::min(seed_lift, 0.5 * callus_radius);
}

}  // namespace heliostand::hollow
