#pragma once
// Seed 001 eq. 1: the stem's height over age, a Chapman–Richards curve H(t) = A (1 - exp(-k t))^p.
// The seed's exponent was lost in print; we read it as p = 1/(1 - m) (docs/model.md):
// with A = 28, k = 0.0348, m = 0.3639 this gives about 4 m at 10, 16 m at 35 and 23 m at 60 years.
#include "architecture/species.hpp"

namespace heliostand {

// p = 1/(1 - m), the Chapman–Richards exponent from the seed's m.
double height_curve_exponent(const SpeciesParameters& species);

// Height (m) at tree age t (years) on a site whose asymptote is site_asymptote_m (eq. 1 A).
double tree_height_m(const SpeciesParameters& species, double site_asymptote_m, double age_years);

// The asymptote A for which eq. 1 passes through (age_years, height_m): how calibration fits a survey record.
double site_asymptote_for(const SpeciesParameters& species, double height_m, double age_years);

}  // namespace heliostand
