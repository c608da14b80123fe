#pragma once
// Why trees die (docs/model.md "Mortality"), each death with a cause code in events.csv and stand_table.csv:
//   light        — starvation: the tree carries no living foliage any more (or its leader stays shaded out for
//                  suppressed_years_to_death years, an experiment's rule; off by default);
//   suppression  — the probability of death rises as recent radial growth falls: p = 1 - exp(-m1 exp(-m2 G)),
//                  G the mean radial increment at breast height over the last years, mm/year (Kobe & Coates
//                  1997's form, used by SORTIE-ND's growth-based mortality). Trees below breast height have no
//                  diameter growth to judge and are exempt;
//                  Crowding is suppression too: when a stand's density passes its species' self-thinning limit
//                  (Reineke's stand density index, a fraction of the maximum), the trees that grew least die
//                  until it is back under the limit — as FVS's density-related mortality holds stands below SDImax;
//   background   — an optional constant annual probability (windthrow, disease...; off by default).
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "architecture/conifer_tree.hpp"
#include "records/death_cause.hpp"

namespace heliostand {

// Annual probability of death by suppression for a recent radial growth of `radial_growth_mm` per year.
double suppression_probability(const SpeciesParameters& species, double radial_growth_mm);

// Whether the tree dies this year of suppression or background mortality, from the stream (seed, tree id, tree
// age): the draw of one tree never depends on another's. Starvation is decided by the light response.
std::optional<DeathCause> draw_mortality(const ConiferTree& tree, std::uint64_t seed);

// Crowding (self-thinning at maximum density). Each living tree's share of the stand density index, after
// Reineke (1933) summed tree by tree (Shaw 2000): (DBH / 25.4 cm)^1.605 per plot hectare, over its species' limit
// (max_stand_density_index x self_thinning_limit).
struct CrowdingCandidate {
  double dbh_cm = 0;
  double density_limit = 0;     // stems/ha at Dq 25.4 cm the species tolerates
  double recent_growth_mm = 0;  // recent radial growth (the least-growing die first)
};
inline constexpr double reineke_slope = 1.605;
inline constexpr double reineke_reference_dbh_cm = 25.4;

// Σ (D/25.4)^1.605 / limit / area: 1 is the self-thinning limit.
double relative_density(std::span<const CrowdingCandidate> trees, double plot_area_ha);
// The trees that die of crowding this year, least recent growth first (ties: the thinner), until the relative
// density is at most 1. Empty when the stand is under its limit.
std::vector<std::size_t> select_crowding_deaths(std::span<const CrowdingCandidate> trees, double plot_area_ha);

}  // namespace heliostand
