#pragma once
// Why trees die (docs/model.md "Mortality"), each death with a cause code in events.csv and stand_table.csv:
//   light        — starvation: the tree carries no living foliage any more (or its leader stays shaded out for
//                  suppressed_years_to_death years, an experiment's rule; off by default);
//   suppression  — the probability of death rises as recent radial growth falls: p = 1 - exp(-m1 exp(-m2 G)),
//                  G the mean radial increment at breast height over the last years, mm/year (Kobe & Coates
//                  1997's form, used by SORTIE-ND's growth-based mortality). Trees below breast height have no
//                  diameter growth to judge and are exempt;
//   background   — an optional constant annual probability (windthrow, disease...; off by default).
#include <cstdint>
#include <optional>
#include <string_view>

#include "architecture/conifer_tree.hpp"

namespace heliostand {

enum class DeathCause { light, suppression, background };

constexpr std::string_view cause_code(DeathCause cause) {
  switch (cause) {
    case DeathCause::light: return "light";
    case DeathCause::suppression: return "suppression";
    case DeathCause::background: return "background";
  }
  return "unknown";
}
inline constexpr DeathCause all_death_causes[] = {DeathCause::light, DeathCause::suppression,
                                                   DeathCause::background};

// Annual probability of death by suppression for a recent radial growth of `radial_growth_mm` per year.
double suppression_probability(const SpeciesParameters& species, double radial_growth_mm);

// Whether the tree dies this year of suppression or background mortality, from the stream (seed, tree id, tree
// age): the draw of one tree never depends on another's. Starvation is decided by the light response.
std::optional<DeathCause> draw_mortality(const ConiferTree& tree, std::uint64_t seed);

}  // namespace heliostand
