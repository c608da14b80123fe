#pragma once
// When a scheduled thinning happens. Checked every simulated year at the thinning step, after mortality, against
// the living stand as the earlier thinnings of that year left it:
//   fixed age     fires in the year the stand reaches `stand_age`; repeating every k years, also at age + k, + 2k, …
//   condition     fires in the first year the condition holds (basal area above X m²/ha, or top height at or above
//                 Y m); it then stays spent, or, repeating every k years, re-arms: it fires again in any later year
//                 the condition holds and at least k years have passed since it last fired. The minimum interval
//                 keeps a thinning that cannot bring the stand below its threshold (protected trees, a target above
//                 the threshold) from firing every year.
#include <optional>
#include <string>

#include "scenario/thinning_event.hpp"  // ThinningTrigger

namespace heliostand {

// The living stand as the conditions see it (records/stand_metrics.hpp).
struct StandMeasures {
  double basal_area_m2_per_ha = 0;
  double top_height_m = 0;
};

// Why the thinning happens at `stand_age` — "stand age 40", "basal area 41.2 > 40 m²/ha" — or nothing when it does
// not. `last_fired_age`: when it last happened, if ever.
std::optional<std::string> why_thinning_fires(const ThinningTrigger& trigger, int stand_age,
                                              std::optional<int> last_fired_age, const StandMeasures& stand);

}  // namespace heliostand
