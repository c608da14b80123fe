#include "scenario/scenario_limits.hpp"
#include "scenario/scenario_tables.hpp"
#include "scenario/toml_table_reader.hpp"

namespace heliostand::scenario_detail {

void parse_competition(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems) {
  const toml::table* table = as_table(node, "competition", problems);
  if (!table) return;
  TomlTableReader reader(*table, "competition", problems);
  if (auto radius = reader.number("hegyi_radius_m", positive_up_to(limit::neighbourhood_m))) draft.scenario.competition.hegyi_radius_m = *radius;
  reader.report_unknown_keys();
}

}  // namespace heliostand::scenario_detail
