#pragma once
// Seed 000's light response applied to a seed-001 conifer in the stand (docs/model.md, "Growth from light"):
// after the stand's yearly light solve, every shoot that flushed this year
//  - turns toward its leaf ball's light vector in the whole stand by the fraction I (heliotropism_strength);
//  - dies, with its axis and all that axis carries, when its relative light is below its own threshold
//    D = D0 + dither * U(-1, 1) (death_threshold, death_threshold_dither).
// Relative light = the shoot's light in the stand / its light with its own tree standing alone (open grown):
// the share of its own-crown light that the neighbours leave it. Self-shading is already seed 001's business
// (growth stop by order, eq. 12, calibrated to the surveyed crown base), and the stand solver's absolute light
// in a conifer crown is dominated by the foliage around each ball (docs/model.md: 0.01-0.03 even for an open
// tree), so the threshold acts on competition only: an open-grown tree keeps its crown.
// The stem leader is not bent (the stem stays vertical, seed 001) but faces the threshold. A tree dies of light
// (cause "light") when its leader is shaded out and its branches carry no living foliage any more, or when its
// leader has been shaded out `suppressed_years_to_death` years in a row (overtopped).
#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "architecture/conifer_tree.hpp"
#include "light/light_solver.hpp"

namespace heliostand {

struct LightResponseOutcome {
  int new_shoots = 0;    // this year's shoots that carry foliage (stem included)
  int bent = 0;          // branch shoots turned by heliotropism
  int shaded_out = 0;    // branch shoots below their threshold
  int axes_killed = 0;   // axes that died with them (laterals included)
  bool leader_shaded = false;
  bool tree_died = false;
};

// A leaf ball's relative light: its light in the stand under a sky of `sky_scale` over its light with its tree
// alone under the reference sky, at most 1. Neighbours can only take light away; a ball in total darkness even
// alone has nothing to lose (1).
inline double relative_light(double stand_light, double open_light, double sky_scale = 1.0) {
  return open_light > 0.0 ? std::min(1.0, sky_scale * stand_light / open_light) : 1.0;
}

// The light of every leaf ball with the tree standing alone (the open-grown reference), one sample per leaf ball
// in ConiferTree::leaf_balls() order.
std::vector<LightSample> open_grown_light(const ConiferTree& tree, LightSolver& solver);

// Reads this year's light from the tree's shoots (Shoot::relative_light, light_vector; set by the stand's
// illuminate step). Thresholds draw from the stream (seed, tree id, tree age, shoot index): independent of other
// trees.
LightResponseOutcome respond_to_light(ConiferTree& tree, std::uint64_t seed);

}  // namespace heliostand
