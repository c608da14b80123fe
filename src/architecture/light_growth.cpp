#include "architecture/light_growth.hpp"

#include <algorithm>
#include <cmath>

namespace heliostand {

double light_response(double relative_light, double zero, double saturation) {
  if (!(saturation > zero)) return relative_light >= zero ? 1.0 : 0.0;
  return std::clamp((relative_light - zero) / (saturation - zero), 0.0, 1.0);
}

double elongation_response(const SpeciesParameters& species, double relative_light) {
  return light_response(relative_light, species.elongation_light_zero, species.elongation_light_saturation);
}

double height_response(const SpeciesParameters& species, double relative_light) {
  return light_response(relative_light, species.height_light_zero, species.height_light_saturation);
}

double diameter_response(const SpeciesParameters& species, double absorbed_share) {
  const double c = std::clamp(species.diameter_light_compensation, 0.0, 0.99);
  return std::pow(std::max((absorbed_share - c) / (1.0 - c), 0.0), species.diameter_light_exponent);
}

}  // namespace heliostand
