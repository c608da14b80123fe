#pragma once
// Seed 000's two sums over the celestial sphere, from the intensity B(h, v) reaching a ball per patch:
//   light = Σ B S / Σ B0 S,   vector = normalize(Σ N B S)  ((0,0,0) when that sum is negligible).
#include <span>

#include "light/celestial_sphere.hpp"
#include "light/light_solver.hpp"

namespace heliostand {

// Below this fraction of Σ B0 S the light has no preferred direction (float round-off on the device is
// ~1e-7 of it, so both backends agree on which side a balanced sky falls). cl/light.cl gets this value as the
// build option BALANCED_LIGHT_FRACTION.
constexpr double balanced_light_fraction = 1e-5;

LightSample light_sample(const CelestialSphere& sky, std::span<const double> intensity);

}  // namespace heliostand
