#include "architecture/lower_order_branching.hpp"

namespace heliostand {

double lower_order_initial_elongation_m(const SpeciesParameters& species, double parent_elongation_m) {
  return species.second_order_elongation_ratio * parent_elongation_m;
}

static double third_order_table(const SpeciesParameters& species, double parent_elongation_cm) {
  for (const auto& step : species.third_order_occurrence)
    if (parent_elongation_cm >= step.min_parent_elongation_cm) return step.probability;
  return 0.0;  // below the last threshold (2 cm): none
}

double lateral_occurrence_probability(const SpeciesParameters& species, int order, double parent_elongation_m) {
  if (order < 2 || order > species.max_order) return 0.0;
  if (parent_elongation_m < species.min_parent_length_m) return 0.0;
  if (order == 2) return 1.0;
  // The seed measured the table on 2nd-order parents; we use it for every order ≥ 3.
  return third_order_table(species, 100.0 * parent_elongation_m);
}

}  // namespace heliostand
