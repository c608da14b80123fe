#pragma once
// Seed 003 §6 (Figs. 12–14) as runnable experiments: one Todomatsu planted in the open, crown and roots
// grown together for a number of years through the stand machinery (Stand + light solver + RootZone),
// with the sky light, the soil's nutrient level or root pruning varied.
#include <cstdint>

#include "scenario/roots_settings.hpp"

namespace heliostand::coupling_validation {

struct CoupledExperiment {
  double sky_scale = 1.0;       // Fig. 12: ×0.5, ×0.7 of the full sky
  double nutrient = 1.0;        // Fig. 13: 0.5 poor, 1.0 rich
  bool prune_right_paths = false;  // Fig. 14: roots of the right-hand (east) paths cut every year
  bool prune_left_paths = false;   // the mirror experiment (west paths cut): cancels the whorls' chance asymmetry
  bool coupled = true;          // false: Branch_n = Root_n = 0 (the break that must fail every assertion)
  int years = 12;
  std::uint64_t seed = 1;
};

struct CoupledResult {
  double root_branches = 0;     // new roots started (not continuations), summed over the years
  double root_length_m = 0;     // living root length at the end
  double shoots = 0;            // living shoots at the end
  double leaf_balls = 0;
  double foliage_right = 0;     // leaf balls on branches of paths 6, 7, 0, 1 (east half: x > trunk)
  double foliage_left = 0;      // paths 2..5 (west half)
  double mean_lp_over_wp = 0;   // diagnostic: mean over the years of Σ_n LP_n / Σ_n WP_n
};

CoupledResult run_coupled(const CoupledExperiment& experiment);

// Mean of each quantity over seeds 1..count.
CoupledResult mean_over_seeds(CoupledExperiment experiment, int count);

// The right-hand paths of Fig. 14 (east half around the trunk): 6, 7, 0, 1.
bool is_right_path(int path);

}  // namespace heliostand::coupling_validation
