// [[root_pruning]]: cut roots by path and depth, once at a stand age or every year (seed 003 Fig. 14).
#include <fmt/format.h>

#include "scenario/scenario_limits.hpp"
#include "scenario/scenario_tables.hpp"
#include "scenario/toml_table_reader.hpp"

namespace heliostand::scenario_detail {

namespace {

void parse_root_pruning_event(const toml::table& table, const std::string& path, ScenarioDraft& draft,
                              ScenarioProblems& problems) {
  TomlTableReader reader(table, path, problems);
  RootPruningEvent event;
  event.line = reader.line();
  if (auto age = reader.integer("age", from_up_to(1, limit::tree_lifetime))) {
    event.stand_age = static_cast<int>(*age);
    const int survey_age = draft.scenario.stand.age_at_survey_years;
    if (draft.age_valid && (*age <= survey_age || (draft.years_valid && *age > survey_age + draft.scenario.run.years)))
      reader.problem("age", fmt::format("root pruning at age {} is outside the simulated years (stand age {} to {})", *age,
                                        survey_age + 1, survey_age + draft.scenario.run.years));
  }
  if (auto every = reader.boolean("every_year")) event.every_year = *every;
  if (event.stand_age.has_value() == event.every_year)
    problems.add(event.line, path, "needs exactly one of age and every_year = true");
  if (const toml::node* node = reader.node("sectors")) {
    const toml::array* array = node->as_array();
    if (!array || array->empty()) {
      reader.problem("sectors", fmt::format("expected a non-empty array of paths 0..7, got {}", toml_type_phrase(*node)));
    } else {
      for (std::size_t i = 0; i < array->size(); ++i) {
        const auto sector = array->get(i)->value_exact<std::int64_t>();
        if (!sector || *sector < 0 || *sector > 7) {
          reader.problem("sectors", fmt::format("element {}: expected a path 0..7 (45° sectors counter-clockwise from east)", i + 1));
        } else {
          event.sectors.push_back(static_cast<int>(*sector));
        }
      }
    }
  }
  if (auto v = reader.number("min_depth_m", non_negative_up_to(limit::soil_depth_m))) event.min_depth_m = *v;
  if (auto v = reader.number("min_distance_m", non_negative_up_to(limit::root_reach_m))) event.min_distance_m = *v;
  if (const toml::node* node = reader.node("trees")) {
    const toml::array* array = node->as_array();
    if (!array) {
      reader.problem("trees", fmt::format("expected an array of survey ids, got {}", toml_type_phrase(*node)));
    } else {
      for (std::size_t i = 0; i < array->size(); ++i) {
        const toml::node& element = *array->get(i);
        if (auto text = element.value_exact<std::string>()) event.tree_labels.push_back(*text);
        else if (auto number = element.value_exact<std::int64_t>()) event.tree_labels.push_back(std::to_string(*number));
        else reader.problem("trees", fmt::format("element {}: expected a tree id, got {}", i + 1, toml_type_phrase(element)));
      }
    }
  }
  reader.report_unknown_keys();
  draft.scenario.roots.pruning.push_back(std::move(event));
}

}  // namespace

void parse_root_pruning(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems) {
  for_each_table_of_array(node, "root_pruning", problems,
                          [&](const toml::table& table, const std::string& path) {
                            parse_root_pruning_event(table, path, draft, problems);
                          });
}

}  // namespace heliostand::scenario_detail
