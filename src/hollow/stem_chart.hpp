#pragma once
// Coordinates on the stem around a hollow: x = arc length along the circumference at the hollow's centre
// radius ρ0 (counter-clockwise seen from above), y = height above the hollow's centre. Everything of a
// hollow (outline, callus foot, bark lines, the stem grid) is laid out in these coordinates and mapped onto
// the surface at the end, which lets a wound wrap as far around the stem as the chart goes (our extension
// of the seed's single tangent plane).
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "hollow/trunk_surface.hpp"

namespace heliostand::hollow {

class StemChart {
 public:
  StemChart(const TrunkSurface& trunk, double centre_height_m, double azimuth_rad);

  double reference_radius() const { return rho0_; }
  double centre_height() const { return h0_; }
  double azimuth0() const { return phi0_; }
  double half_round() const;  // x of the back of the stem (π ρ0)
  double height_of(double y) const { return h0_ + y; }
  double azimuth_of(double x) const { return phi0_ + x / rho0_; }

  glm::dvec3 point(glm::dvec2 xy, double lift = 0.0) const;
  glm::dvec3 normal(glm::dvec2 xy) const;
  glm::dvec2 chart_of(const glm::dvec3& p) const;  // inverse of point() for points on the surface
  const TrunkSurface& trunk() const { return *trunk_; }

 private:
  const TrunkSurface* trunk_;
  double h0_, phi0_, rho0_;
};

}  // namespace heliostand::hollow
