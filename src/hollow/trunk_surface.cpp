#include "hollow/trunk_surface.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace heliostand::hollow {

TrunkSurface::TrunkSurface(std::function<double(double)> radius_m, double tree_height_m, Buttress buttress)
    : radius_m_(std::move(radius_m)), tree_height_(tree_height_m), buttress_(buttress) {}

TrunkSurface TrunkSurface::seed001_taper(double tree_height_m, double crown_base_m, Buttress buttress) {
  // The two fits disagree by ~2 % at the crown base; a surface needs no step there, so the below-crown fit
  // is scaled to meet the in-crown one at the crown base (documented in docs/hollows.md).
  auto in_crown = [](double depth) { return 2.245 * std::pow(depth, 0.951); };
  auto below_crown = [](double depth) { return 3.336 * std::pow(depth, 0.771); };
  const double base_depth = std::max(tree_height_m - crown_base_m, 0.0);
  const double match = base_depth > 0.0 ? in_crown(base_depth) / below_crown(base_depth) : 1.0;
  auto radius = [=](double h) {
    const double depth = std::max(tree_height_m - h, 0.0);  // H − h, metres below the top
    const double diameter_cm = h >= crown_base_m ? in_crown(depth) : match * below_crown(depth);
    return diameter_cm / 200.0;  // cm diameter → m radius
  };
  return TrunkSurface(radius, tree_height_m, buttress);
}

double TrunkSurface::taper_radius(double h) const { return std::max(radius_m_(h), 0.0); }

double TrunkSurface::flare_factor(double h) const {
  if (buttress_.flare <= 0.0 || buttress_.decay_height_m <= 0.0) return 1.0;
  return 1.0 + buttress_.flare * std::exp(-std::max(h, 0.0) / buttress_.decay_height_m);
}

double TrunkSurface::radius(double h) const { return taper_radius(h) * flare_factor(h); }

double TrunkSurface::radius_slope(double h) const {
  const double dh = 1e-4;
  const double lo = std::max(h - dh, 0.0);
  const double hi = std::min(h + dh, tree_height_);
  if (hi <= lo) return 0.0;
  return (radius(hi) - radius(lo)) / (hi - lo);
}

glm::dvec3 TrunkSurface::point(double h, double azimuth, double lift) const {
  const double rho = radius(h);
  const glm::dvec3 on_surface{rho * std::cos(azimuth), rho * std::sin(azimuth), h};
  if (lift == 0.0) return on_surface;
  return on_surface + lift * outward_normal(h, azimuth);
}

glm::dvec3 TrunkSurface::outward_normal(double h, double azimuth) const {
  // Surface of revolution (ρ(h) cos φ, ρ(h) sin φ, h): normal ∝ (cos φ, sin φ, −ρ'(h)).
  return glm::normalize(glm::dvec3{std::cos(azimuth), std::sin(azimuth), -radius_slope(h)});
}

double TrunkSurface::outside(const glm::dvec3& p) const {
  const double h = std::clamp(p.z, 0.0, tree_height_);
  return std::hypot(p.x, p.y) - radius(h);
}

glm::dvec3 TrunkSurface::cross_surface(const glm::dvec3& inside, const glm::dvec3& beyond) const {
  glm::dvec3 far = beyond;
  // A point of the outline plane can lie inside a flaring stem: walk on along the ray until outside.
  for (int i = 0; i < 60 && outside(far) <= 0.0; ++i) far = inside + 2.0 * (far - inside);
  glm::dvec3 lo = inside, hi = far;
  for (int i = 0; i < 80; ++i) {
    const glm::dvec3 mid = 0.5 * (lo + hi);
    (outside(mid) > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace heliostand::hollow
