#pragma once
// Seed 000's light response applied to a seed-001 conifer in the stand (MODEL.md §5): after the stand's yearly
// light solve, every shoot that flushed this year
//  - dies, with its axis and all that axis carries, when its leaf ball's light is below its own threshold
//    D = D0 + dither * U(-1, 1) (species death_threshold, death_threshold_dither);
//  - otherwise turns toward its leaf ball's light vector by the fraction I (species heliotropism_strength).
// The stem leader is not bent (the stem stays vertical, seed 001) but faces the threshold: a tree whose leader
// is shaded out and whose branches carry no living foliage any more is dead (cause "light").
#include <cstdint>
#include <span>

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

// `light`: one sample per leaf ball, in ConiferTree::leaf_balls() order (StandTree::leaf_ball_light).
// Thresholds draw from the stream (seed, tree id, tree age, shoot index): independent of other trees.
LightResponseOutcome respond_to_light(ConiferTree& tree, std::span<const LightSample> light, std::uint64_t seed);

}  // namespace heliostand
