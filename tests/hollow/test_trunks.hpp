#pragma once
// The trunks the hollow tests carve: seed 001's taper on a tree of a given height and crown base.
#include "hollow/trunk_surface.hpp"

namespace heliostand::testing {

// A 30 m tree with its crown base at 15 m; `flare` widens its root collar (0.4 = 40 %), fading over 0.3 m.
inline hollow::TrunkSurface tall_trunk(double flare = 0.0) {
  return hollow::TrunkSurface::seed001_taper(30.0, 15.0, {flare, 0.3});
}

// A 20 m tree with its crown base at 10 m.
inline hollow::TrunkSurface short_trunk() { return hollow::TrunkSurface::seed001_taper(20.0, 10.0); }

}  // namespace heliostand::testing
