#pragma once
// Establishing the stand from its survey: every surveyed tree is fitted to its record (height, crown
// radius, crown base) and grown from planting to its surveyed age, one by one (seed 001 §3.4).
#include <cstdint>
#include <vector>

#include "scenario/scenario.hpp"
#include "stand/stand_tree.hpp"

namespace heliostand {

struct EstablishmentReport {
  int fitted = 0;          // every target within tolerance
  int crown_base_off = 0;  // usable, crown base beyond its (best-effort) tolerance
  int unusable = 0;        // height or crown radius could not be fitted: grown with the closest fit, warned
};

// One StandTree per survey record, in survey order, calibrated and grown to the survey age. Trees are
// independent here, so they are fitted on all cores; each draws from its own random stream, so the
// result does not depend on the number of threads.
std::vector<StandTree> establish_stand(const Scenario& scenario, EstablishmentReport& report);

}  // namespace heliostand
