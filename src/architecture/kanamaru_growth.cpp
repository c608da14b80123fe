#include "architecture/kanamaru_growth.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <glm/geometric.hpp>

#include "architecture/heliotropism.hpp"
#include "geometry/angles.hpp"
#include "rng/random_stream.hpp"

namespace heliostand {

LightParameters KanamaruParameters::default_kanamaru_light() {
  LightParameters light;
  light.sky_bands = 16;
  light.sky_sectors = 32;
  light.intensity_ratio = 1.5;  // L = 3/2
  light.transmittance = 0.5;    // calibrated against Fig. 10(e) (docs/model.md, seed 000)
  light.exact = true;
  return light;
}

KanamaruGrowth::KanamaruGrowth(const KanamaruParameters& parameters, std::uint64_t seed)
    : parameters_(parameters),
      seed_(seed),
      solver_(std::make_unique<KanamaruLightSolver>(parameters_.light, parameters_.enclosing_balls_shade)) {}

// Every current tip carries a leaf ball; the new branches are the receivers.
std::vector<LightSample> KanamaruGrowth::light_of(const DichotomyTree& tree, const std::vector<int>& receivers) {
  const std::vector<int> tips = tree.tips();
  const std::vector<LeafBall> balls = tree.leaf_balls(tips, parameters_.leaf_ball_radius);
  std::vector<std::uint32_t> slots;
  for (int r : receivers) {
    const auto found = std::lower_bound(tips.begin(), tips.end(), r);
    slots.push_back(static_cast<std::uint32_t>(found - tips.begin()));
  }
  return solver_->solve_for(balls, slots);
}

GenerationRecord KanamaruGrowth::grow_generation(DichotomyTree& tree) {
  const std::vector<int> added = tree.add_generation(parameters_.death);
  GenerationRecord record;
  record.generation = tree.generation();
  record.added = static_cast<int>(added.size());
  // Light for every new branch first, then the decisions (Fig. 9): a removal this generation does not
  // brighten its siblings until the next one.
  const std::vector<LightSample> light = light_of(tree, added);
  std::vector<char> dies(added.size(), 0);
  if (parameters_.pruning == Pruning::light) {
    for (std::size_t k = 0; k < added.size(); ++k)
      dies[k] = dies_of_shade(light[k].light, tree.branches()[added[k]].threshold);
  } else if (parameters_.pruning == Pruning::random) {
    RandomStream random(seed_, {0x4A4Du, static_cast<std::uint64_t>(tree.generation())});
    const auto g = static_cast<std::size_t>(tree.generation());
    if (g < random_survivors.size()) {
      // Keep exactly the prescribed number, chosen uniformly (partial Fisher-Yates).
      std::vector<std::size_t> order(added.size());
      std::iota(order.begin(), order.end(), 0);
      for (std::size_t k = 0; k + 1 < order.size(); ++k)
        std::swap(order[k], order[k + static_cast<std::size_t>(random.below(static_cast<int>(order.size() - k)))]);
      std::fill(dies.begin(), dies.end(), 1);
      const std::size_t keep = std::min<std::size_t>(order.size(), static_cast<std::size_t>(std::max(0, random_survivors[g])));
      for (std::size_t k = 0; k < keep; ++k) dies[order[k]] = 0;
    } else {
      for (auto& d : dies) d = !random.chance(parameters_.random_survival);
    }
  }
  for (std::size_t k = 0; k < added.size(); ++k) {
    record.mean_light += light[k].light / std::max<std::size_t>(added.size(), 1);
    if (dies[k]) {
      tree.remove_branch(added[k]);
    } else {
      ++record.survived;
      tree.turn_branch(added[k], heliotropic_direction(tree.direction(added[k]), light[k].vector,
                                                        parameters_.heliotropism));
    }
  }
  history_.push_back(record);
  return record;
}

void KanamaruGrowth::grow(DichotomyTree& tree, int generation,
                          const std::function<void(const DichotomyTree&)>& after) {
  while (tree.generation() < generation) {
    grow_generation(tree);
    if (after) after(tree);
  }
}

}  // namespace heliostand
