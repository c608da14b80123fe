#pragma once
// A whole run: establish the stand from its survey, then grow it year by year, lighting it, thinning it
// and writing the output years. The CLI's `grow` is a thin shell around this.
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

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
  // Write a checkpoint after every this many simulated years (0: none; run/run_checkpoints.hpp).
  int checkpoint_every_years = 0;
  // Continue the interrupted run in output_folder from its newest usable checkpoint instead of starting afresh.
  bool resume = false;
  // Called with the stand at the end of every year of the loop (after thinning; year 0 = the established
  // stand): lets validation programs measure crowns without re-reading the outputs.
  std::function<void(const Stand&, int year)> observe_year;
};

// What one simulated year cost (`heliostand bench stand`'s `by_year`): where a run's time goes as the stand grows.
struct YearCost {
  int year = 0, stand_age = 0;
  long trees_alive = 0;                                        // at the end of the year
  std::vector<std::pair<std::string, double>> stage_seconds;  // this year's part of each stage of the run's clock
  std::vector<std::pair<std::string, double>> stage_cpu_seconds;  // the process's CPU seconds in each of them
  // This year's stand solve: its parts (as SimulationSummary's sums) and the near-field candidates a ball scanned.
  double light_search_seconds = 0, light_far_field_seconds = 0, light_shading_seconds = 0;
  double light_tile_candidates_per_ball = 0;
};

struct SimulationSummary {
  int first_stand_age = 0, last_stand_age = 0;
  int trees_alive = 0, trees_removed = 0, trees_dead = 0;
  double wall_seconds = 0, light_seconds = 0;
  std::string device;                                        // the light solver's name, as run.json
  std::vector<std::pair<std::string, double>> stage_seconds;  // as run.json
  // The process's CPU seconds (every thread) in each stage: over stage_seconds, the cores it kept busy.
  std::vector<std::pair<std::string, double>> stage_cpu_seconds;
  // The size of the run, for `heliostand bench stand`: tree-years = Σ over the simulated years of the trees that
  // grew in it; the rest counts what the living trees hold at the end.
  long tree_years = 0;
  std::size_t leaf_balls = 0;     // one per foliage-carrying shoot tip (what the light solver sees)
  std::size_t shoots = 0;         // living and dead shoots still attached (the crowns as held in memory)
  std::size_t root_segments = 0;  // of their root systems
  double light_tile_candidates_per_ball = 0;  // near-field candidates each ball scanned in the last light solve
  double light_far_field_cell_m_max = 0;  // coarsest far-field cell of the run's stand solves (m; 0: no far field)
  // Where the stand solves' time went, summed over the run's years (LightSolveStatistics; a resumed run counts its
  // own years only): the near-field search (k-d tree, tile lists), the far field (density and optical-depth table)
  // and the shading (the kernel, with the trees alone where the solver lights them in the same pass).
  double light_search_seconds = 0, light_far_field_seconds = 0, light_shading_seconds = 0;
  // Each year of the loop (year 0: the surveyed stand lit and coupled; a resumed run: its own years), in order.
  // The stages before the loop (establishment, the roots' spin-up) belong to no year.
  std::vector<YearCost> by_year;
};

SimulationSummary run_simulation(const Scenario& scenario, const SimulationOptions& options);

}  // namespace heliostand
