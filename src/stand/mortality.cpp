#include "stand/mortality.hpp"

#include <cmath>

#include "architecture/stem_taper.hpp"
#include "rng/random_stream.hpp"

namespace heliostand {

namespace {
constexpr std::uint64_t kMortality = 0x4D4F5254u;  // "MORT"
}

double suppression_probability(const SpeciesParameters& species, double radial_growth_mm) {
  const double growth = std::max(0.0, radial_growth_mm);
  return 1.0 - std::exp(-species.suppression_m1 * std::exp(-species.suppression_m2 * growth));
}

std::optional<DeathCause> draw_mortality(const ConiferTree& tree, std::uint64_t seed) {
  const SpeciesParameters& species = tree.species();
  RandomStream random(seed, {kMortality, static_cast<std::uint64_t>(tree.id()), static_cast<std::uint64_t>(tree.age())});
  // Both draws are always taken, so switching one cause off leaves the other's stream unchanged.
  const double suppression_draw = random.uniform();
  const double background_draw = random.uniform();
  if (tree.dbh_cm() > 0.0 && tree.height_m() > breast_height_m &&
      suppression_draw < suppression_probability(species, tree.recent_radial_growth_mm(species.suppression_growth_years)))
    return DeathCause::suppression;
  if (background_draw < species.background_mortality) return DeathCause::background;
  return std::nullopt;
}

}  // namespace heliostand
