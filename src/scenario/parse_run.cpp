#include <stdexcept>

#include <fmt/format.h>

#include "scenario/output_detail.hpp"
#include "scenario/scenario_limits.hpp"
#include "scenario/scenario_tables.hpp"
#include "scenario/toml_table_reader.hpp"
#include "scenario/vtk_compression.hpp"

namespace heliostand::scenario_detail {

void parse_run(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems) {
  if (!node) {
    problems.add(0, "run", "required table missing (it gives at least the years to simulate)");
    return;
  }
  const toml::table* table = as_table(node, "run", problems);
  if (!table) return;
  TomlTableReader reader(*table, "run", problems);
  RunSettings& run = draft.scenario.run;

  if (auto years = reader.integer("years", from_up_to(1, limit::tree_lifetime), true)) {
    run.years = static_cast<int>(*years);
    draft.years_valid = true;
  }
  if (auto seed = reader.integer("seed", any_seed())) run.seed = static_cast<std::uint64_t>(*seed);
  if (auto interval = reader.integer("output_interval", from_up_to(1, limit::tree_lifetime))) run.output_interval_years = static_cast<int>(*interval);
  if (auto detail = reader.choice("detail", output_detail_names)) run.output_detail = *detail;
  if (auto compression = reader.choice("vtk_compression", vtk_compression_names)) run.vtk_compression = *compression;
  if (auto interval = reader.integer("roots_output_interval", non_negative_up_to(limit::tree_lifetime)))
    run.roots_output_interval_years = static_cast<int>(*interval);
  if (auto device = reader.string("device")) {
    try {
      run.device = compute::DeviceChoice::parse(*device);
    } catch (const std::invalid_argument&) {
      reader.problem("device", fmt::format("expected \"auto\", \"reference\", \"opencl\" or \"opencl:N\", got \"{}\"",
                                           *device));
    }
  }
  reader.report_unknown_keys();
}

}  // namespace heliostand::scenario_detail
