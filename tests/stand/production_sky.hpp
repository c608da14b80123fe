#pragma once
// The sky a stand sees in production (standard overcast, ground albedo; parse_light's stand default), divided
// as coarsely as a test can afford.
#include "light/light_parameters.hpp"

namespace heliostand::testing {

inline LightParameters production_sky(int bands, int sectors) {
  LightParameters light;
  light.sky = LightParameters::Sky::standard_overcast;
  light.sky_bands = bands;
  light.sky_sectors = sectors;
  return light;
}

}  // namespace heliostand::testing
