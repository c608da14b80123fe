// When a [[thinning]] happens: `age`, or a condition of the living stand (`when_basal_area_exceeds_m2_per_ha`,
// `when_top_height_reaches_m`), exactly one of them; `repeat` / `repeat_every_years` make it fire again
// (stand/thinning_trigger.hpp).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <string_view>
#include <vector>

#include "scenario/scenario_limits.hpp"
#include "scenario/scenario_tables.hpp"

namespace heliostand::scenario_detail {

namespace {

// `repeat = true` without an interval: five years, a common thinning cycle in young conifer plantations, and long
// enough for the stand to answer one thinning before the next.
constexpr int default_repeat_interval_years = 5;

constexpr std::array<std::string_view, 3> when_keys{"age", "when_basal_area_exceeds_m2_per_ha",
                                                    "when_top_height_reaches_m"};

void check_age(TomlTableReader& reader, const ScenarioDraft& draft, int age) {
  if (!draft.age_valid) return;
  const int survey_age = draft.scenario.stand.age_at_survey_years;
  if (age < survey_age) {
    reader.problem("age", fmt::format("thinning at age {} is before the survey (stand age {})", age, survey_age));
  } else if (draft.years_valid && age > survey_age + draft.scenario.run.years) {
    reader.problem("age", fmt::format("thinning at age {} is after the end of the run (stand age {})", age,
                                      survey_age + draft.scenario.run.years));
  }
}

void read_repetition(TomlTableReader& reader, ThinningTrigger& when) {
  const auto repeat = reader.boolean("repeat");
  const auto every = reader.integer("repeat_every_years", from_up_to(1, limit::tree_lifetime));
  if (repeat == false && reader.table().contains("repeat_every_years")) {
    reader.problem("repeat_every_years", "not used with repeat = false (remove one of the two)");
  } else if (every) {
    when.repeat_every_years = static_cast<int>(*every);
  } else if (repeat == true) {
    when.repeat_every_years = default_repeat_interval_years;
  }
}

}  // namespace

void read_thinning_when(TomlTableReader& reader, const ScenarioDraft& draft, ThinningTrigger& when) {
  std::vector<std::string_view> given;
  for (auto key : when_keys)
    if (reader.table().contains(key)) given.push_back(key);
  if (given.empty())
    reader.problems().add(reader.line(), reader.key_path("age"),
                          "required key missing (or, instead of a fixed age, a condition: "
                          "when_basal_area_exceeds_m2_per_ha or when_top_height_reaches_m)");

  if (auto age = reader.integer("age", from_up_to(1, limit::tree_lifetime))) {
    when.stand_age = static_cast<int>(*age);
    check_age(reader, draft, when.stand_age);
  }
  if (auto threshold = reader.number("when_basal_area_exceeds_m2_per_ha", positive_up_to(limit::basal_area_m2_per_ha)))
    when.condition = StandCondition{StandCondition::Measure::basal_area_m2_per_ha, *threshold};
  if (auto threshold = reader.number("when_top_height_reaches_m", positive_up_to(limit::tree_height)))
    when.condition = StandCondition{StandCondition::Measure::top_height_m, *threshold};
  if (given.size() > 1)
    reader.problem(given[1], fmt::format("a thinning happens at an age or on one condition: give one of age, "
                                         "when_basal_area_exceeds_m2_per_ha and when_top_height_reaches_m, got {}",
                                         fmt::join(given, " and ")));
  read_repetition(reader, when);
}

}  // namespace heliostand::scenario_detail
