#pragma once
// Why a tree died, as events.csv and the dead_<cause>_* columns of stand_table.csv name it. The rules that decide
// a death are the stand's (stand/mortality.hpp); the causes are part of a run's record, which both the stand and
// the writers read.
#include <string_view>

namespace heliostand {

enum class DeathCause { light, suppression, background };

constexpr std::string_view cause_code(DeathCause cause) {
  switch (cause) {
    case DeathCause::light: return "light";
    case DeathCause::suppression: return "suppression";
    case DeathCause::background: return "background";
  }
  return "unknown";
}
inline constexpr DeathCause all_death_causes[] = {DeathCause::light, DeathCause::suppression,
                                                   DeathCause::background};

}  // namespace heliostand
