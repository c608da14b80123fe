#include "stand/light_response.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include <glm/geometric.hpp>

#include "architecture/death_threshold.hpp"
#include "architecture/heliotropism.hpp"
#include "rng/random_stream.hpp"

namespace heliostand {

namespace {
constexpr std::uint64_t kShootThreshold = 0x5EED000u;

// New shoots of orders above foliage_max_order have no leaf ball of their own: their foliage is lumped into
// the balls of the branch that bears them (species.hpp). They turn toward the light vector of the nearest ball
// on the same first-order branch — every new shoot is heliotropic — and die with that branch's shoots
// (kill_shaded_shoots takes the laterals of a dead shoot along).
void bend_lumped_laterals(ConiferTree& tree, const std::vector<int>& foliage, const std::vector<int>& shaded_out,
                          LightResponseOutcome& outcome) {
  const double strength = tree.species().heliotropism_strength;
  if (strength <= 0.0) return;
  const auto& shoots = tree.shoots();
  // A shaded-out shoot dies with its whole axis (ConiferTree::kill_shaded_shoots).
  std::unordered_set<int> dying_axes;
  for (int s : shaded_out) dying_axes.insert(shoots[s].axis);
  const std::unordered_set<int> with_ball(foliage.begin(), foliage.end());
  // The balls of each surviving first-order branch (axis id of its order-1 shoots).
  std::unordered_map<int, std::vector<std::size_t>> balls_of_branch;
  for (std::size_t k = 0; k < foliage.size(); ++k)
    if (shoots[foliage[k]].order == 1 && dying_axes.count(shoots[foliage[k]].axis) == 0)
      balls_of_branch[shoots[foliage[k]].axis].push_back(k);
  for (int s : tree.new_shoot_indices()) {
    const Shoot& shoot = shoots[s];
    if (shoot.order < 2 || with_ball.count(s) != 0) continue;
    int ancestor = shoot.parent;
    while (ancestor >= 0 && shoots[ancestor].order > 1) ancestor = shoots[ancestor].parent;
    if (ancestor < 0 || shoots[ancestor].order != 1) continue;
    const auto branch = balls_of_branch.find(shoots[ancestor].axis);
    if (branch == balls_of_branch.end()) continue;  // the branch has no living foliage left
    std::size_t nearest = branch->second.front();
    for (std::size_t k : branch->second)
      if (glm::distance(shoots[foliage[k]].tip, shoot.base) < glm::distance(shoots[foliage[nearest]].tip, shoot.base))
        nearest = k;
    const glm::dvec3 towards = shoots[foliage[nearest]].light_vector;
    tree.bend_shoot(s, heliotropic_direction(shoot.tip - shoot.base, towards, strength));
    ++outcome.bent;
  }
}

}  // namespace

std::vector<LightSample> open_grown_light(const ConiferTree& tree, LightSolver& solver) {
  return solver.solve(tree.leaf_balls());
}

LightResponseOutcome respond_to_light(ConiferTree& tree, std::uint64_t seed) {
  const std::vector<int> foliage = tree.foliage_shoot_indices();
  const SpeciesParameters& species = tree.species();
  const DeathThreshold threshold{species.death_threshold, species.death_threshold_dither};
  LightResponseOutcome outcome;
  std::vector<int> shaded_out;
  for (std::size_t k = 0; k < foliage.size(); ++k) {
    const int s = foliage[k];
    const Shoot& shoot = tree.shoots()[s];
    if (shoot.year_formed != tree.age()) continue;
    ++outcome.new_shoots;
    RandomStream random(seed, {kShootThreshold, static_cast<std::uint64_t>(tree.id()),
                               static_cast<std::uint64_t>(tree.age()), static_cast<std::uint64_t>(s)});
    const bool dies = dies_of_shade(shoot.relative_light, threshold.draw(random));
    if (shoot.order == 0) {
      outcome.leader_shaded = outcome.leader_shaded || dies;
    } else if (dies) {
      shaded_out.push_back(s);
    } else if (species.heliotropism_strength > 0.0) {
      // A new shoot carries nothing yet: bending it moves only itself.
      tree.bend_shoot(s, heliotropic_direction(shoot.tip - shoot.base, shoot.light_vector, species.heliotropism_strength));
      ++outcome.bent;
    }
  }
  bend_lumped_laterals(tree, foliage, shaded_out, outcome);
  outcome.shaded_out = static_cast<int>(shaded_out.size());
  outcome.axes_killed = tree.kill_shaded_shoots(shaded_out);
  tree.record_leader_light(outcome.leader_shaded);
  outcome.tree_died = (outcome.leader_shaded && !tree.has_living_branch_foliage()) ||
                      tree.leader_shaded_years() >= species.suppressed_years_to_death;
  return outcome;
}

}  // namespace heliostand
