// heliostand check SCENARIO: read and validate the scenario and its survey, write nothing.
#include <exception>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include "cli/commands.hpp"
#include "compute/compute_backend.hpp"
#include "compute/device_memory.hpp"
#include "core/usable_memory.hpp"
#include "light/far_field_buffers.hpp"
#include "scenario/scenario.hpp"
#include "stand/memory_estimate.hpp"
#include "stand/thinning.hpp"

namespace heliostand::cli {
namespace {

// "age 40", "age 40, then every 5 years", "when basal area > 40 m2/ha, again after 5 years or more".
std::string when_text(const ThinningTrigger& trigger) {
  std::string when;
  if (trigger.at_fixed_age()) {
    when = fmt::format("age {}", trigger.stand_age);
  } else if (trigger.condition->measure == StandCondition::Measure::basal_area_m2_per_ha) {
    when = fmt::format("when basal area > {:g} m2/ha", trigger.condition->threshold);
  } else {
    when = fmt::format("when top height >= {:g} m", trigger.condition->threshold);
  }
  if (trigger.repeat_every_years)
    when += trigger.at_fixed_age() ? fmt::format(", then every {} years", *trigger.repeat_every_years)
                                   : fmt::format(", again after {} years or more", *trigger.repeat_every_years);
  return when;
}

// The run's memory as `grow` estimates it, beside what this machine lets a run use. A scenario written for a larger
// machine is not bad input, so check says that grow would refuse it here and still succeeds.
void print_memory(const Scenario& scenario) {
  const MemoryEstimate estimate = estimate_run_memory(scenario);
  std::string line = fmt::format("memory     about {} estimated", gibibytes(estimate.bytes));
  if (const auto usable = usable_memory_bytes())
    line += fmt::format(", of the {} this machine lets a run use{}", gibibytes(*usable),
                        estimate.bytes > *usable ? ": grow refuses it here" : "");
  fmt::print("{} (docs/performance.md \"Memory\")\n", line);
}

// The device `grow` would open (run.device; `--device` may choose another) and whether it holds the far-field
// table's cap (light/far_field_buffers.hpp). Like the memory, the device is the machine's, not the input's: check
// says that grow would refuse the cap here and still succeeds.
void print_device(const Scenario& scenario) {
  std::string line;
  try {
    const auto backend = compute::ComputeBackend::open(scenario.run.device);
    line = backend.name();
    if (const auto memory = backend.memory()) {
      line += fmt::format(", {:.0f} MB a buffer", compute::whole_megabytes(memory->buffer_bytes));
      if (far_field_beyond_device(scenario.stand_light(), *memory, backend.name()))
        line += fmt::format(": grow refuses light.far_field_table_mb = {} MB here", scenario.light.far_field_table_mb);
    }
  } catch (const std::exception& e) {  // a device this machine does not have (opencl:N)
    line = e.what();
  }
  fmt::print("device     {}\n", line);
}

void print_summary(const Scenario& scenario) {
  double basal_area = 0;
  for (const auto& tree : scenario.survey.trees) basal_area += basal_area_m2(tree.dbh_cm);
  const double area = scenario.plot_area_ha();
  fmt::print("scenario   {}\n", scenario.file.string());
  fmt::print("survey     {} ({} trees)\n", scenario.survey.file.string(), scenario.survey.trees.size());
  fmt::print("plot       {:.4f} ha, {:.0f} stems/ha, basal area {:.2f} m2/ha\n", area,
             static_cast<double>(scenario.survey.trees.size()) / area, basal_area / area);
  fmt::print("run        age {} -> {} ({} years), seed {}, output every {} years\n",
             scenario.stand.age_at_survey_years, scenario.final_age_years(), scenario.run.years,
             scenario.run.seed, scenario.run.output_interval_years);
  for (const auto& event : scenario.thinning)
    fmt::print("thinning   {}: {} ({}{})\n", when_text(event.when), event.reason,
               thinning_method_name(event.rule.method),
               event.protect_habitat_trees ? "" : ", habitat trees not protected");
  std::vector<std::string> habitat;
  std::size_t hollows = 0;
  for (const auto& tree : scenario.survey.trees) {
    if (tree.hollows.empty()) continue;
    habitat.push_back(tree.id);
    hollows += tree.hollows.size();
  }
  if (!habitat.empty())
    fmt::print("habitat    {} trees with {} hollows: {}\n", habitat.size(), hollows, fmt::join(habitat, ", "));
  print_memory(scenario);
  print_device(scenario);
}

}  // namespace

void add_check_command(CLI::App& app, int& status) {
  auto* command = app.add_subcommand("check", "Validate a scenario and its survey; write nothing");
  auto path = std::make_shared<std::string>();
  command->add_option("scenario", *path, "Scenario TOML file")->required();
  command->callback([path, &status] {
    status = report_errors([&] {
      const Scenario scenario = load_scenario(*path);
      for (const auto& warning : scenario.survey.warnings) spdlog::warn("{}", warning);
      print_summary(scenario);
      return 0;
    });
  });
}

}  // namespace heliostand::cli
