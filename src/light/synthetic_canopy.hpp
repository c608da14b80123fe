#pragma once
// Reproducible synthetic stands for benchmarks and tests: conical conifer crowns on a square planting grid,
// each filled with leaf balls at random (uniform in the crown volume). Defaults give a dense young
// plantation: 1600 stems/ha (2.5 m spacing), 12 m tall trees with a 6 m crown, 100 leaf balls of 0.3 m
// per tree -- a stand-average optical density of ~0.75 ball hits per metre of canopy.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "light/leaf_ball.hpp"

namespace heliostand {

struct SyntheticCanopyShape {
  double spacing_m = 2.5;        // planting grid
  std::size_t balls_per_tree = 100;
  double height_m = 12.0;        // mean tree height (each tree +-15 %)
  double crown_length_m = 6.0;   // apex down to crown base
  double crown_radius_m = 1.4;   // at the crown base
  double ball_radius_m = 0.3;
};

struct SyntheticCanopy {
  std::vector<LeafBall> balls;
  std::vector<int> tree_of_ball;
  std::size_t tree_count = 0;
  double plot_size_m = 0;  // the square plot [0, size] x [0, size] holding the planting grid
};

// `ball_count` balls spread over a square grid of ceil(sqrt(ball_count / balls_per_tree))^2 trees.
SyntheticCanopy make_synthetic_canopy(std::size_t ball_count, std::uint64_t seed,
                                      const SyntheticCanopyShape& shape = {});

}  // namespace heliostand
