#include "light/light_sum.hpp"

#include <glm/geometric.hpp>

namespace heliostand {

LightSample light_sample(const CelestialSphere& sky, std::span<const double> intensity) {
  double received = 0;
  glm::dvec3 flux(0.0);
  for (std::size_t q = 0; q < sky.patches().size(); ++q) {
    const auto& patch = sky.patches()[q];
    received += intensity[q] * patch.solid_angle;
    flux += patch.direction * (intensity[q] * patch.solid_angle);
  }
  const double unshaded = sky.unshaded_total();
  const double length = glm::length(flux);
  LightSample sample;
  sample.light = received / unshaded;
  sample.vector = length > balanced_light_fraction * unshaded ? flux / length : glm::dvec3(0.0);
  return sample;
}

}  // namespace heliostand
