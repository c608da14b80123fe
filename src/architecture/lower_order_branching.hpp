#pragma once
// Seed 001 §3.2: second and lower orders branch in opposite pairs. Their initial elongation is linear in
// the parent's elongation (Fig. 5; we take the line through the origin, slope second_order_elongation_ratio),
// third-order buds flush with a probability that steps with the parent (2nd-order) shoot's elongation, and no
// lateral grows on a parent shoot shorter than the minimum parent length.
#include "architecture/species.hpp"

namespace heliostand {

// Initial elongation (m) of a lateral of order ≥ 2 borne on a parent shoot of the given elongation (m).
double lower_order_initial_elongation_m(const SpeciesParameters& species, double parent_elongation_m);

// Probability that one bud of a lateral pair of `order` flushes on a parent shoot of the given elongation.
// Order 2: 1 (the regular opposite pair); order 3: the seed's occurrence table; beyond max_order: 0.
// Always 0 when the parent shoot is shorter than the minimum parent length.
double lateral_occurrence_probability(const SpeciesParameters& species, int order, double parent_elongation_m);

}  // namespace heliostand
