#pragma once
// The stem as a surface of revolution: a radius for every height (the taper), optionally widened near the
// ground by a buttress flare (root collar). Hollows are laid onto this surface.
//
// Local tree frame: stem base at the origin, z up, azimuth measured counter-clockwise from +x (east).
#include <functional>

#include <glm/vec3.hpp>

namespace heliostand::hollow {

// Root-collar flare: radius(h) = taper(h) · (1 + flare · exp(−h / decay_height_m)).
// Real stems widen towards the root collar where the buttress roots leave the stem; the exponential keeps
// the surface smooth and reduces to the plain taper a few decay heights above the ground.
struct Buttress {
  double flare = 0.0;            // relative widening at h = 0 (0.4 = 40 % wider than the taper there)
  double decay_height_m = 0.3;   // height over which the flare fades by a factor e
};

class TrunkSurface {
 public:
  // radius_m(h): stem radius in metres at height h (m) above the ground, 0 ≤ h ≤ tree_height_m.
  TrunkSurface(std::function<double(double)> radius_m, double tree_height_m, Buttress buttress = {});

  // Seed 001 eq. 2: diameter (cm) = a2 · (H − h)^b2, a2 = 2.245, b2 = 0.951 inside the crown and
  // a2 = 3.336, b2 = 0.771 below the crown base (Hakodate co-dominant Todomatsu). The two fits differ by ~2 %
  // at the crown base; the below-crown one is scaled to meet the crown one there (no step in the surface).
  static TrunkSurface seed001_taper(double tree_height_m, double crown_base_m, Buttress buttress = {});

  double tree_height() const { return tree_height_; }
  const Buttress& buttress() const { return buttress_; }
  double taper_radius(double h) const;  // without the flare
  double flare_factor(double h) const;  // radius / taper radius (≥ 1)
  double radius(double h) const;        // the surface actually meshed
  double radius_slope(double h) const;  // d radius / d h (central difference)

  // Point on the surface at height h and azimuth (radians), moved `lift` metres along the outward normal.
  glm::dvec3 point(double h, double azimuth, double lift = 0.0) const;
  glm::dvec3 outward_normal(double h, double azimuth) const;

  // Signed distance-like test: > 0 outside the stem, < 0 inside (horizontal distance minus radius).
  double outside(const glm::dvec3& p) const;
  // Where the segment from `inside` to `beyond` crosses the surface (bisection; `inside` must be inside).
  // If `beyond` is itself inside, the ray is extended until it leaves the stem.
  glm::dvec3 cross_surface(const glm::dvec3& inside, const glm::dvec3& beyond) const;

 private:
  std::function<double(double)> radius_m_;
  double tree_height_;
  Buttress buttress_;
};

}  // namespace heliostand::hollow
