#pragma once
// Seed 001 eqs. 7-10: branch elongation.
//   eq. 10  crown angle = initial crown angle · (tree age)^β
//   eq. 9   first-order initial elongation = height growth · sin(crown angle) / sin(180° - crown angle - d0)
//           (law of sines in the triangle whorl – new top – branch tip: the new branch tip lies on the crown
//           cone; the printed '+' before sin(crown angle) is read as '·', the only reading that is a law of sines)
//   eq. 8   total elongation = initial elongation · (branch age)^α
//   eq. 7   this year's elongation = total elongation now - total elongation last year
// Branch age in eqs. 7-8 counts flushes: 1 in the year the branch appears, so its first shoot is the
// initial elongation.
#include "architecture/species.hpp"

namespace heliostand {

double crown_angle_deg(const SpeciesParameters& species, double tree_age_years);  // eq. 10
double first_order_initial_elongation_m(const SpeciesParameters& species, double height_growth_m,
                                        double tree_age_years);                   // eq. 9
double total_elongation_m(double initial_elongation_m, double branch_age, double alpha);   // eq. 8
double annual_elongation_m(double initial_elongation_m, int branch_age, double alpha);     // eq. 7

}  // namespace heliostand
