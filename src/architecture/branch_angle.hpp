#pragma once
// Seed 001 eqs. 4-6: the angle of a first-order branch from the stem axis (degrees),
//   angle = (tree age - year of emergence)·rate + d0 + droop,  rate = (d1 - d0)/lifespan,
//   droop = branch age · annual droop.
// Both "tree age - year of emergence" and "branch age" here count the years since emergence (0 in the year
// the branch flushes), so a new branch leaves the stem at exactly d0, the seed's "initial branching angle".
#include "architecture/species.hpp"

namespace heliostand {

double branch_angle_rate_deg_per_year(const SpeciesParameters& species);             // eq. 5
double branch_droop_deg(const SpeciesParameters& species, double years_since_emergence);  // eq. 6
double first_order_branch_angle_deg(const SpeciesParameters& species, double years_since_emergence);  // eq. 4

}  // namespace heliostand
