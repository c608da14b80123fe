// [coupling]: seed 003's crown–root balance coefficients (coupling/coupling_parameters.hpp).
#include "scenario/scenario_limits.hpp"
#include "scenario/scenario_tables.hpp"
#include "scenario/toml_table_reader.hpp"

namespace heliostand::scenario_detail {

void parse_coupling(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems) {
  if (!node) return;
  const toml::table* table = as_table(node, "coupling", problems);
  if (!table) return;
  TomlTableReader reader(*table, "coupling", problems);
  CouplingParameters& p = draft.scenario.roots.coupling;
  if (auto v = reader.boolean("enabled")) p.enabled = *v;
  if (auto v = reader.number("rho", positive_up_to(limit::coupling_coefficient))) p.rho = *v;
  if (auto v = reader.number("tau", positive_up_to(limit::coupling_coefficient))) p.tau = *v;
  if (auto v = reader.number("alpha_b", between(0.0, 1.0))) p.alpha_b = *v;  // added to a probability
  if (auto v = reader.number("alpha_r", between(0.0, 10.0))) p.alpha_r = *v;
  reader.report_unknown_keys();
}

}  // namespace heliostand::scenario_detail
