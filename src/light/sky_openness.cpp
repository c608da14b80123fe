#include "light/sky_openness.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace heliostand {

std::vector<double> sky_openness(std::span<const LightSample> samples, std::span<const int> tree_of_ball,
                                 std::size_t tree_count) {
  if (samples.size() != tree_of_ball.size())
    throw std::invalid_argument("sky_openness: " + std::to_string(samples.size()) + " light samples but " +
                                std::to_string(tree_of_ball.size()) + " tree indices");
  std::vector<double> total(tree_count, 0.0);
  std::vector<std::size_t> count(tree_count, 0);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const int tree = tree_of_ball[k];
    if (tree < 0 || static_cast<std::size_t>(tree) >= tree_count)
      throw std::invalid_argument("sky_openness: ball " + std::to_string(k) + " belongs to tree " +
                                  std::to_string(tree) + ", outside 0.." + std::to_string(tree_count - 1));
    total[tree] += samples[k].light;
    ++count[tree];
  }
  std::vector<double> openness(tree_count, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t tree = 0; tree < tree_count; ++tree)
    if (count[tree] > 0) openness[tree] = total[tree] / count[tree];
  return openness;
}

}  // namespace heliostand
