#include "stand/stand_tree.hpp"

namespace heliostand {

double StandTree::mean_light() const {
  if (leaf_ball_light.empty()) return 1.0;
  double sum = 0;
  for (const auto& sample : leaf_ball_light) sum += sample.light;
  return sum / static_cast<double>(leaf_ball_light.size());
}

}  // namespace heliostand
