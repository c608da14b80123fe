#pragma once
// Seed 000's death threshold: every branch draws its own threshold D = D0 + dither * random, random uniform
// in [-1, 1) (the seed: dither 0.3, "like random dithering in pseudo-colouring": a fixed D would kill many
// branches at once). A branch whose light is below its D dies.
#include "rng/random_stream.hpp"

namespace heliostand {

struct DeathThreshold {
  double standard = 0.6;  // D0 (Table 1)
  double dither = 0.3;    // the seed's empirical 0.3

  double draw(RandomStream& random) const { return standard + dither * random.symmetric(); }
};

inline bool dies_of_shade(double light, double threshold) { return light < threshold; }

}  // namespace heliostand
