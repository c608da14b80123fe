#include "stand/thinning_trigger.hpp"

#include <fmt/format.h>

namespace heliostand {
namespace {

std::optional<std::string> at_fixed_age(const ThinningTrigger& trigger, int stand_age) {
  const int since = stand_age - trigger.stand_age;
  if (since == 0) return fmt::format("stand age {}", stand_age);
  if (trigger.repeat_every_years && since > 0 && since % *trigger.repeat_every_years == 0)
    return fmt::format("stand age {} (every {} years from {})", stand_age, *trigger.repeat_every_years,
                       trigger.stand_age);
  return std::nullopt;
}

std::string condition_text(const StandCondition& condition, const StandMeasures& stand) {
  if (condition.measure == StandCondition::Measure::basal_area_m2_per_ha)
    return fmt::format("basal area {:.2f} > {:g} m²/ha", stand.basal_area_m2_per_ha, condition.threshold);
  return fmt::format("top height {:.2f} m >= {:g} m", stand.top_height_m, condition.threshold);
}

double measured(const StandCondition& condition, const StandMeasures& stand) {
  return condition.measure == StandCondition::Measure::basal_area_m2_per_ha ? stand.basal_area_m2_per_ha
                                                                           : stand.top_height_m;
}

}  // namespace

std::optional<std::string> why_thinning_fires(const ThinningTrigger& trigger, int stand_age,
                                              std::optional<int> last_fired_age, const StandMeasures& stand) {
  if (!trigger.condition) return at_fixed_age(trigger, stand_age);
  const bool armed = !last_fired_age ||
                     (trigger.repeat_every_years && stand_age - *last_fired_age >= *trigger.repeat_every_years);
  if (!armed || !trigger.condition->holds(measured(*trigger.condition, stand))) return std::nullopt;
  return condition_text(*trigger.condition, stand);
}

}  // namespace heliostand
