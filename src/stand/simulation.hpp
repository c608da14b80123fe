#pragma once
// A whole run: establish the stand from its survey, then grow it year by year, lighting it, thinning it
// and writing the output years. The CLI's `grow` is a thin shell around this.
#include <filesystem>
#include <functional>
#include <string>

#include "scenario/scenario.hpp"

namespace heliostand {

class Stand;

struct SimulationOptions {
  std::filesystem::path output_folder;
  bool force = false;          // replace an earlier run in a non-empty output folder
  std::string device;          // overrides the scenario's run.device when not empty
  bool write_vtk = true;
  bool show_progress = false;  // a progress line on stderr (the CLI turns it on for terminals)
  std::string command_line;    // recorded in run.json
  // Called with the stand at the end of every year of the loop (after thinning; year 0 = the established
  // stand): lets validation programs measure crowns without re-reading the outputs.
  std::function<void(const Stand&, int year)> observe_year;
};

struct SimulationSummary {
  int first_stand_age = 0, last_stand_age = 0;
  int trees_alive = 0, trees_removed = 0, trees_dead = 0;
  double wall_seconds = 0, light_seconds = 0;
};

SimulationSummary run_simulation(const Scenario& scenario, const SimulationOptions& options);

}  // namespace heliostand
