#include "light/synthetic_canopy.hpp"

#include <algorithm>
#include <cmath>

#include "rng/random_stream.hpp"

namespace heliostand {

SyntheticCanopy make_synthetic_canopy(std::size_t ball_count, std::uint64_t seed, const SyntheticCanopyShape& shape) {
  SyntheticCanopy canopy;
  // The balls' room first: a count beyond any memory throws here, before the crowns (2^59 balls' crowns alone would
  // be drawn for days).
  canopy.balls.reserve(ball_count);
  canopy.tree_of_ball.reserve(ball_count);
  // Rounded up after the division, so that no count near 2^64 wraps to a single tree.
  const std::size_t per_tree = shape.balls_per_tree;
  const std::size_t wanted_trees = std::max<std::size_t>(1, ball_count / per_tree + (ball_count % per_tree != 0));
  const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(double(wanted_trees))));
  canopy.tree_count = side * side;
  canopy.plot_size_m = side * shape.spacing_m;

  struct Crown {
    glm::dvec3 apex;
    double length, radius;
  };
  std::vector<Crown> crowns;
  for (std::size_t tree = 0; tree < canopy.tree_count; ++tree) {
    RandomStream random(seed, {tree, 1});
    const double x = (tree % side + 0.5) * shape.spacing_m + 0.1 * shape.spacing_m * random.symmetric();
    const double y = (tree / side + 0.5) * shape.spacing_m + 0.1 * shape.spacing_m * random.symmetric();
    const double scale = 1.0 + 0.15 * random.symmetric();
    crowns.push_back({{x, y, shape.height_m * scale}, shape.crown_length_m * scale, shape.crown_radius_m * scale});
  }
  for (std::size_t k = 0; k < ball_count; ++k) {
    const std::size_t tree = k % canopy.tree_count;
    const Crown& crown = crowns[tree];
    RandomStream random(seed, {tree, 2, k});
    // uniform in the cone: draw in the enclosing cylinder, keep points inside the cone
    glm::dvec3 offset;
    do {
      offset = {crown.radius * random.symmetric(), crown.radius * random.symmetric(), -crown.length * random.uniform()};
    } while (std::hypot(offset.x, offset.y) > crown.radius * (-offset.z / crown.length));
    canopy.balls.push_back({crown.apex + offset, shape.ball_radius_m});
    canopy.tree_of_ball.push_back(static_cast<int>(tree));
  }
  return canopy;
}

}  // namespace heliostand
