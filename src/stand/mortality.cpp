#include "stand/mortality.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

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

namespace {
double density_share(const CrowdingCandidate& tree, double plot_area_ha) {
  if (tree.dbh_cm <= 0.0 || tree.density_limit <= 0.0) return 0.0;
  return std::pow(tree.dbh_cm / reineke_reference_dbh_cm, reineke_slope) / tree.density_limit / plot_area_ha;
}
}  // namespace

double relative_density(std::span<const CrowdingCandidate> trees, double plot_area_ha) {
  double sum = 0.0;
  for (const auto& tree : trees) sum += density_share(tree, plot_area_ha);
  return sum;
}

std::vector<std::size_t> select_crowding_deaths(std::span<const CrowdingCandidate> trees, double plot_area_ha) {
  double density = relative_density(trees, plot_area_ha);
  std::vector<std::size_t> order(trees.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (trees[a].recent_growth_mm != trees[b].recent_growth_mm)
      return trees[a].recent_growth_mm < trees[b].recent_growth_mm;
    return trees[a].dbh_cm < trees[b].dbh_cm;
  });
  std::vector<std::size_t> deaths;
  for (std::size_t i : order) {
    if (density <= 1.0) break;
    const double share = density_share(trees[i], plot_area_ha);
    if (share <= 0.0) continue;  // below breast height: no part of the density index
    deaths.push_back(i);
    density -= share;
  }
  return deaths;
}

}  // namespace heliostand
