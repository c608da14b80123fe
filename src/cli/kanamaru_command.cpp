// heliostand kanamaru SCENARIO --out DIR: one seed-000 experiment (stands/kanamaru-*), the simple dichotomy model
// or a bud start grown with heliotropism and death by light (registered in cli/app.cpp).
#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include "cli/commands.hpp"
#include "cli/path_checks.hpp"
#include "experiments/kanamaru/kanamaru_scenario.hpp"

namespace heliostand::cli {

void add_kanamaru_command(CLI::App& app, int& status) {
  auto* command = app.add_subcommand("kanamaru", "Grow a seed-000 (Kanamaru et al. 1991) dichotomy or bud-start experiment");
  auto scenario = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  command->add_option("scenario", *scenario, "Scenario TOML file with a [model] table")->required();
  auto force = std::make_shared<bool>(false);
  command->add_option("-o,--out", *out, "Output folder (new or empty)")->required()->check(path_check("folder"));
  command->add_flag("--force", *force, "Replace an earlier heliostand output in the folder");
  command->callback([scenario, out, force, &status] {
    status = report_errors([&] {
      const KanamaruRunSummary summary = run_kanamaru(load_kanamaru_scenario(*scenario), *out, *force);
      spdlog::info("{} generations: {} living tips, {} living branches; {:.1f} s -> {}", summary.generations,
                   summary.tips, summary.living_branches, summary.seconds, *out);
      return 0;
    });
  });
}

}  // namespace heliostand::cli
