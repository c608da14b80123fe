#include "architecture/height_curve.hpp"

#include <cmath>

namespace heliostand {

double height_curve_exponent(const SpeciesParameters& species) { return 1.0 / (1.0 - species.height_exponent_m); }

// The fraction of the asymptote reached at age t: (1 - exp(-k t))^p.
static double height_fraction(const SpeciesParameters& species, double age_years) {
  if (age_years <= 0.0) return 0.0;
  return std::pow(1.0 - std::exp(-species.height_k * age_years), height_curve_exponent(species));
}

double tree_height_m(const SpeciesParameters& species, double site_asymptote_m, double age_years) {
  return site_asymptote_m * height_fraction(species, age_years);
}

double site_asymptote_for(const SpeciesParameters& species, double height_m, double age_years) {
  return height_m / height_fraction(species, age_years);
}

}  // namespace heliostand
