// heliostand grow SCENARIO --out DIR: establish the surveyed stand and grow it year by year; with
// --checkpoint-every N it saves its state every N years, and --resume continues a killed run from it.
#include <unistd.h>

#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include "cli/commands.hpp"
#include "cli/number_checks.hpp"
#include "cli/path_checks.hpp"
#include "cli/seed_option.hpp"
#include "compute/device_choice.hpp"
#include "run/simulation.hpp"
#include "scenario/scenario.hpp"
#include "stand/memory_estimate.hpp"

namespace heliostand::cli {
namespace {

struct GrowArguments {
  std::string scenario;
  std::string out;
  bool force = false;
  std::optional<std::uint64_t> seed;
  std::optional<int> years;
  std::string device;
  bool no_vtk = false;
  int checkpoint_every = 0;
  bool resume = false;
  std::string command_line;
};

int grow(const GrowArguments& arguments) {
  // Every input is read and checked before the output folder is touched.
  Scenario scenario = load_scenario(arguments.scenario);
  if (arguments.seed) scenario.set_seed(*arguments.seed);
  if (arguments.years) scenario.set_years(*arguments.years);
  for (const auto& warning : scenario.survey.warnings) spdlog::warn("{}", warning);
  // A stand far beyond the machine's memory is refused now, not after hours of growth.
  refuse_run_beyond_this_machine(scenario);

  SimulationOptions options;
  options.output_folder = arguments.out;
  options.force = arguments.force;
  options.device = arguments.device;
  options.write_vtk = !arguments.no_vtk;
  options.show_progress = ::isatty(STDERR_FILENO) == 1;
  options.command_line = arguments.command_line;
  options.checkpoint_every_years = arguments.checkpoint_every;
  options.resume = arguments.resume;
  const SimulationSummary summary = run_simulation(scenario, options);
  spdlog::info("grew age {} -> {}: {} alive, {} removed, {} dead; {:.1f} s ({:.1f} s light) -> {}",
               summary.first_stand_age, summary.last_stand_age, summary.trees_alive, summary.trees_removed,
               summary.trees_dead, summary.wall_seconds, summary.light_seconds, arguments.out);
  return 0;
}

}  // namespace

void add_grow_command(CLI::App& app, int& status) {
  auto* command = app.add_subcommand("grow", "Grow a surveyed stand and write VTK and CSV outputs");
  auto arguments = std::make_shared<GrowArguments>();
  command->add_option("scenario", arguments->scenario, "Scenario TOML file")->required();
  command->add_option("-o,--out", arguments->out, "Output folder")->required()->check(path_check("folder"));
  command->add_flag("-f,--force", arguments->force, "Replace the contents of a non-empty output folder");
  command->add_option("--seed", arguments->seed, "Random seed (overrides run.seed)")->check(seed_check());
  command->add_option("--years", arguments->years, "Years to simulate (overrides run.years)")
      ->check(whole_number_check());
  command->add_option("--device", arguments->device, "auto | reference | opencl | opencl:N (overrides run.device)")
      ->check([](const std::string& text) {
        try {
          compute::DeviceChoice::parse(text);
          return std::string();
        } catch (const std::invalid_argument& e) {
          return std::string(e.what());
        }
      });
  command->add_flag("--no-vtk", arguments->no_vtk, "Write the tables only (batch forecasts)");
  command->add_option("--checkpoint-every", arguments->checkpoint_every,
                      "Write a checkpoint after every N simulated years (the newest two are kept)")
      ->check(whole_number_check());
  auto* resume = command->add_flag("--resume", arguments->resume,
                                   "Continue the interrupted run in --out from its newest usable checkpoint "
                                   "(same scenario and options)");
  resume->excludes("--force");
  command->callback([arguments, &status] {
    arguments->command_line = invoked_command_line();
    status = report_errors([&] { return grow(*arguments); });
  });
}

}  // namespace heliostand::cli
