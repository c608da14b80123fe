#include "architecture/branch_diameter.hpp"

#include <cmath>

namespace heliostand {

double branch_diameter_cm(const SpeciesParameters& species, double length_from_tip_m) {
  if (length_from_tip_m <= 0.0) return 0.0;
  const double length_cm = 100.0 * length_from_tip_m;  // the seed fits eq. 11 in centimetres
  return species.branch_a11 * std::pow(length_cm, species.branch_b11);
}

}  // namespace heliostand
