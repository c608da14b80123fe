#include "stand/stand_tree.hpp"

namespace heliostand {

std::vector<LightSample> StandTree::leaf_ball_light() const {
  std::vector<LightSample> samples;
  for (const auto& foliage : conifer.foliage_light()) samples.push_back({foliage.light, foliage.vector});
  return samples;
}

double StandTree::mean_light() const {
  const auto light = conifer.foliage_light();
  if (light.empty()) return 1.0;
  double sum = 0;
  for (const auto& sample : light) sum += sample.light;
  return sum / static_cast<double>(light.size());
}

}  // namespace heliostand
