#pragma once
// Seed 001 eqs. 12-13: when branches stop growing and how fast their dead remains fall.
//   eq. 12  growth-stop years of order n = growth-stop years of order n-1 + activity   (n ≥ 2)
//   eq. 13  dead-branch loss rate = years since growth stopped / years a dead branch stays attached
// A branch grows while (years since emergence) < its growth-stop years, then dies in that year.
#include "architecture/species.hpp"

namespace heliostand {

// Growth-stop years of a branch order (1 = first order) given the first-order value.
double growth_stop_years(const SpeciesParameters& species, double first_order_years, int order);

// True in every year a branch of that age (years since emergence, 0 in its first year) may still flush.
bool still_growing(double years_since_emergence, double growth_stop_years);

// The fraction of a dead branch's length that has fallen (tip first), clamped to [0, 1].
double dead_branch_loss_fraction(const SpeciesParameters& species, double years_since_stop);

}  // namespace heliostand
