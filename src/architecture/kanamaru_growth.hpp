#pragma once
// Seed 000's growth loop (Kanamaru et al. 1991, Fig. 9) for a DichotomyTree: each generation adds children,
// lights every new branch's leaf ball through the leaf balls of all current tips, removes the branches below
// their death threshold (recursively toward the root) and turns the survivors toward their light vector.
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "architecture/death_threshold.hpp"
#include "architecture/dichotomy_tree.hpp"
#include "light/kanamaru_light_solver.hpp"
#include "light/light_parameters.hpp"
#include "light/light_solver.hpp"

namespace heliostand {

// How a generation's new branches are thinned out. Fig. 10(a) prunes at random, Fig. 10(b)-(f) by light.
enum class Pruning { light, random, none };

struct KanamaruParameters {
  int generations = 40;              // G (Table 1)
  double heliotropism = 0.4;         // I (Table 1)
  double leaf_ball_radius = 2.0;     // R in branch lengths (Table 1)
  DeathThreshold death{0.6, 0.3};    // D0 (Table 1) and the seed's dither 0.3
  double branching_angle_deg = 10.0; // Fig. 7
  Pruning pruning = Pruning::light;
  // Fig. 10(a): with random pruning each new branch survives with this probability, unless a per-generation
  // survivor count is prescribed (KanamaruRun::random_survivors) to match a light-pruned run.
  double random_survival = 0.5;
  // The sky: intensity ratio L (Table 1: 3/2) and transmittance t live here; exact (no culling) by default
  // because branch lengths are not metres.
  LightParameters light = default_kanamaru_light();
  // Whether a leaf ball that contains the receiving ball's centre shades it. The seed projects every other
  // ball's shadow onto the receiver's celestial sphere (Fig. 3); a ball around the viewpoint has no
  // projection, so by default it casts none (docs/model.md explains why this matters: with R = 2 every tip
  // lies inside its sibling's ball). true: the stand's light solver rule (shaded in every direction), through
  // the shared ReferenceLightSolver (light/kanamaru_light_solver.hpp).
  bool enclosing_balls_shade = false;

  static LightParameters default_kanamaru_light();
};

// What one generation did, for the validation tables.
struct GenerationRecord {
  int generation = 0;
  int added = 0;
  int survived = 0;     // new branches kept
  double mean_light = 0;  // over the new branches
};

class KanamaruGrowth {
 public:
  KanamaruGrowth(const KanamaruParameters& parameters, std::uint64_t seed);

  GenerationRecord grow_generation(DichotomyTree& tree);
  // Grows to `generation` (or parameters.generations), calling `after` after each generation.
  void grow(DichotomyTree& tree, int generation, const std::function<void(const DichotomyTree&)>& after = {});

  // Random pruning with prescribed survivors per generation (index = generation); beyond the list the
  // survival probability applies.
  std::vector<int> random_survivors;
  const std::vector<GenerationRecord>& history() const { return history_; }

 private:
  std::vector<LightSample> light_of(const DichotomyTree& tree, const std::vector<int>& receivers);

  KanamaruParameters parameters_;
  std::uint64_t seed_;
  std::unique_ptr<LightSolver> solver_;  // seed 000's rule (light/kanamaru_light_solver.hpp)
  std::vector<GenerationRecord> history_;
};

}  // namespace heliostand
