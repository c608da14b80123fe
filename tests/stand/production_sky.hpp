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

// Four bands of eight sectors: enough for a few small trees to shade each other.
inline LightParameters coarse_sky() { return production_sky(4, 8); }

}  // namespace heliostand::testing
