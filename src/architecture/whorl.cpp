#include "architecture/whorl.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/angles.hpp"

namespace heliostand {

double mean_branches_per_whorl(const SpeciesParameters& species) {
  return species.whorl_a3 * species.crown_shape_ratio + species.whorl_b3;
}

int draw_whorl_size(const SpeciesParameters& species, RandomStream& random) {
  const double mean = std::max(0.0, mean_branches_per_whorl(species));
  const double whole = std::floor(mean);
  return static_cast<int>(whole) + (random.chance(mean - whole) ? 1 : 0);
}

std::vector<double> whorl_azimuths(int n, double jitter, RandomStream& random) {
  std::vector<double> azimuths;
  if (n <= 0) return azimuths;
  const double spacing = 2.0 * pi / n;
  const double start = random.uniform(0.0, 2.0 * pi);
  const double half_jitter = 0.5 * std::clamp(jitter, 0.0, 1.0) * spacing;
  for (int i = 0; i < n; ++i) {
    const double azimuth = start + i * spacing + half_jitter * random.symmetric();
    azimuths.push_back(std::fmod(azimuth + 4.0 * pi, 2.0 * pi));
  }
  return azimuths;
}

}  // namespace heliostand
