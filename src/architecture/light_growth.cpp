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

double diameter_response(const SpeciesParameters& species, double pipe_model_share) {
  return light_response(pipe_model_share, species.diameter_light_compensation, species.diameter_light_saturation);
}

}  // namespace heliostand
