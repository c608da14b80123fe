#include "hollow/stem_chart.hpp"

#include <cmath>

#include "geometry/angles.hpp"

namespace heliostand::hollow {

StemChart::StemChart(const TrunkSurface& trunk, double centre_height_m, double azimuth_rad)
    : trunk_(&trunk), h0_(centre_height_m), phi0_(azimuth_rad), rho0_(trunk.radius(centre_height_m)) {}

double StemChart::half_round() const { return pi * rho0_; }

glm::dvec3 StemChart::point(glm::dvec2 xy, double lift) const {
  return trunk_->point(height_of(xy.y), azimuth_of(xy.x), lift);
}

glm::dvec3 StemChart::normal(glm::dvec2 xy) const {
  return trunk_->outward_normal(height_of(xy.y), azimuth_of(xy.x));
}

glm::dvec2 StemChart::chart_of(const glm::dvec3& p) const {
  double dphi = std::atan2(p.y, p.x) - phi0_;
  dphi = std::remainder(dphi, 2.0 * pi);  // into (−π, π]: the hollow's front is x = 0
  return {dphi * rho0_, p.z - h0_};
}

}  // namespace heliostand::hollow
