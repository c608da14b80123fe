#pragma once
// Seed 001 eq. 3: first-order branches per whorl = a3 x + b3 (≈ 4.6 for the heavy-snow provenance), and
// their azimuths: spread evenly around the stem from a random start, each jittered.
#include <vector>

#include "architecture/species.hpp"
#include "rng/random_stream.hpp"

namespace heliostand {

double mean_branches_per_whorl(const SpeciesParameters& species);

// floor(mean) plus one more with probability frac(mean), so the long-run mean is eq. 3 exactly.
int draw_whorl_size(const SpeciesParameters& species, RandomStream& random);

// n azimuths (radians, [0, 2π)): a random start, even spacing 2π/n, each moved by up to
// ± jitter·spacing/2 so neighbours never swap.
std::vector<double> whorl_azimuths(int n, double jitter, RandomStream& random);

}  // namespace heliostand
