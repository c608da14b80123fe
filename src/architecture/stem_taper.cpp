#include "architecture/stem_taper.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/angles.hpp"

namespace heliostand {

double StemTaper::diameter_cm(const SpeciesParameters& species, double h) const {
  if (h >= height_m) return 0.0;
  const double depth = height_m - std::max(h, 0.0);
  if (h >= crown_base_m) return species.stem_a_in_crown * std::pow(depth, species.stem_b_in_crown);
  return species.stem_a_below_crown * std::pow(depth, species.stem_b_below_crown);
}

double StemTaper::dbh_cm(const SpeciesParameters& species) const {
  return height_m <= breast_height_m ? 0.0 : diameter_cm(species, breast_height_m);
}

// ∫ (a d^b)^2 dd over depths d from d_low to d_high = a^2 (d_high^(2b+1) - d_low^(2b+1)) / (2b+1), in cm^2·m.
static double squared_diameter_integral(double a, double b, double d_low, double d_high) {
  const double e = 2.0 * b + 1.0;
  return a * a * (std::pow(d_high, e) - std::pow(d_low, e)) / e;
}

double StemTaper::volume_m3(const SpeciesParameters& species) const {
  if (height_m <= 0.0) return 0.0;
  const double base = std::clamp(crown_base_m, 0.0, height_m);
  const double crown_depth = height_m - base;  // depth below the top of the crown base
  const double in_crown =
      squared_diameter_integral(species.stem_a_in_crown, species.stem_b_in_crown, 0.0, crown_depth);
  const double below_crown =
      squared_diameter_integral(species.stem_a_below_crown, species.stem_b_below_crown, crown_depth, height_m);
  const double cm2_to_m2 = 1e-4;
  return pi / 4.0 * (in_crown + below_crown) * cm2_to_m2;
}

}  // namespace heliostand
