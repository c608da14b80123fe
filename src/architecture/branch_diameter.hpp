#pragma once
// Seed 001 eq. 11: branch diameter (cm) = a11 · (length from the branch tip, cm)^b11.
#include "architecture/species.hpp"

namespace heliostand {

double branch_diameter_cm(const SpeciesParameters& species, double length_from_tip_m);

}  // namespace heliostand
