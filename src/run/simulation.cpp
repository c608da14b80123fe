#include "run/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <memory>
#include <thread>

#include <spdlog/spdlog.h>

#include "compute/compute_backend.hpp"
#include "core/page_settings.hpp"
#include "core/processor.hpp"
#include "core/seconds_since.hpp"
#include "io/checkpoint_state.hpp"
#include "io/root_vtk.hpp"
#include "io/stand_output.hpp"
#include "light/far_field_buffers.hpp"
#include "light/make_light_solver.hpp"
#include "run/run_checkpoints.hpp"
#include "stand/establishment.hpp"
#include "stand/progress.hpp"
#include "stand/root_zone.hpp"
#include "stand/stage_clock.hpp"
#include "stand/stand.hpp"
#include "stand/stand_year.hpp"

namespace heliostand {
namespace {

// In the scenario's order: the events that fire in one year are applied as the file lists them.
std::vector<ThinningEvent> schedule(const Scenario& scenario) {
  std::vector<ThinningEvent> in_file_order = scenario.thinning;
  std::stable_sort(in_file_order.begin(), in_file_order.end(),
                   [](const ThinningEvent& a, const ThinningEvent& b) { return a.scenario_order < b.scenario_order; });
  return in_file_order;
}

// Competitors are counted across periodic edges when light is (the plot a tile of a larger plantation), over the
// domain the light solver wraps.
CompetitionNeighbourhood competition_for(const Scenario& scenario) {
  const LightParameters light = scenario.stand_light();
  return {scenario.competition.hegyi_radius_m,
          StandEdges{light.periodic, PlotBounds{light.plot_x_min, light.plot_y_min, light.plot_x_max, light.plot_y_max}}};
}

// The state after simulated year `year`, written atomically; the oldest beyond the kept ones are deleted.
int write_checkpoint(const std::filesystem::path& folder, int year, const checkpoint::RunIdentity& identity,
                     const checkpoint::RunParts& parts) {
  const auto path = checkpoint::write_checkpoint(folder, {year, identity, checkpoint::save_run(parts)});
  checkpoint::prune_checkpoints(folder, checkpoints_kept);
  spdlog::debug("checkpoint after year {}: {}", year, path.string());
  return 0;
}

std::vector<StandTree> established_trees(const Scenario& scenario, StageClock& clock) {
  EstablishmentReport report;
  auto trees = clock.time("establishment", [&] { return establish_stand(scenario, report); });
  spdlog::info("established {} trees at age {} ({} fitted, {} with crown base off, {} not fitted)",
               trees.size(), scenario.stand.age_at_survey_years, report.fitted, report.crown_base_off,
               report.unusable);
  return trees;
}

long living_tree_count(const Stand& stand) {
  return std::count_if(stand.trees().begin(), stand.trees().end(), [](const StandTree& tree) { return tree.alive(); });
}

// What the trees hold at the end of the run: their fates, and the size of the living crowns and root systems.
void count_trees(const Stand& stand, const RootZone* roots, SimulationSummary& summary) {
  for (const auto& tree : stand.trees()) {
    summary.trees_alive += tree.status == TreeStatus::alive;
    summary.trees_removed += tree.status == TreeStatus::removed;
    summary.trees_dead += tree.status == TreeStatus::dead;
    if (!tree.alive()) continue;
    summary.leaf_balls += tree.conifer.foliage_shoot_indices().size();
    summary.shoots += tree.conifer.shoots().size();
  }
  if (roots)
    for (const roots::RootSystem* system : roots->living_roots()) summary.root_segments += system->segments().size();
}

// A stand that outgrows LightParameters::far_field_table_mb gets coarser far-field cells (light/far_field.hpp),
// a little coarser every year as its crowns grow: said once, the first year it happens, rather than after every
// solve; the coarsest cell of the run goes to the summary (`bench stand`'s light_far_field_cell_m_max).
class FarFieldCells {
 public:
  explicit FarFieldCells(const LightParameters& light) : light_(light) {}
  void after_year(const LightSolveStatistics& last_solve, int stand_age) {
    const double cell = last_solve.far_field_cell_m;
    coarsest_ = std::max(coarsest_, cell);
    if (said_ || cell <= light_.far_field_cell_m * (1 + 1e-9)) return;
    said_ = true;
    spdlog::warn("light far field: from stand age {} a table of {} m cells would exceed far_field_table_mb = {} MB; "
                 "using {:.3g} m cells, coarser as the crowns grow (said once; docs/light.md)",
                 stand_age, light_.far_field_cell_m, light_.far_field_table_mb, cell);
  }
  double coarsest() const { return coarsest_; }

 private:
  const LightParameters& light_;
  bool said_ = false;
  double coarsest_ = 0;
};

// The stand solves' parts, summed year by year: which part of the light a change must shorten (`bench stand`).
void add_light_parts(const LightSolveStatistics& last_solve, SimulationSummary& summary) {
  summary.light_search_seconds += last_solve.search_seconds;
  summary.light_far_field_seconds += last_solve.far_field_seconds;
  summary.light_shading_seconds += last_solve.evaluate_seconds;
}

// The year's part of each stage: the clock's totals after it less those before it (`before`, the clock as it stood).
YearCost year_cost(int year, const Stand& stand, const StageClock& before, const StageClock& clock,
                   const LightSolveStatistics& solve) {
  YearCost cost;
  cost.year = year;
  cost.stand_age = stand.stand_age();
  cost.trees_alive = living_tree_count(stand);
  for (const auto& [stage, total] : clock.stages())
    cost.stage_seconds.emplace_back(stage, total - before.seconds(stage));
  for (const auto& [stage, total] : clock.cpu_stages())
    cost.stage_cpu_seconds.emplace_back(stage, total - before.cpu_seconds(stage));
  cost.light_search_seconds = solve.search_seconds;
  cost.light_far_field_seconds = solve.far_field_seconds;
  cost.light_shading_seconds = solve.evaluate_seconds;
  cost.light_tile_candidates_per_ball = solve.mean_tile_candidates;
  return cost;
}

// The compute backend and the run's two light solvers. One backend for the whole run: the light of the stand, the
// open-grown light and the roots share its device.
struct RunSolvers {
  compute::ComputeBackend backend;  // first: the solvers refer to its device, so they go before it does
  std::unique_ptr<LightSolver> stand;
  // The open-grown reference (each tree alone, once a year): a few hundred balls, so the exact solver is cheapest
  // (culling and far field only pay off for a whole stand); a tree alone is not repeated across periodic plot
  // edges; and it sees the reference sky (sky_scale 1), so a dimmer stand sky lowers every relative light.
  std::unique_ptr<LightSolver> open_grown;
};

RunSolvers open_solvers(const Scenario& scenario, const SimulationOptions& options,
                        const LightParameters& stand_light) {
  auto backend = compute::ComputeBackend::open(
      options.device.empty() ? scenario.run.device : compute::DeviceChoice::parse(options.device));
  spdlog::info("compute backend (light and roots): {}", backend.name());
  refuse_far_field_beyond_device(stand_light, backend, scenario.file.string());
  LightParameters open_grown = stand_light;
  open_grown.exact = true;
  open_grown.periodic = false;
  open_grown.sky_scale = 1.0;
  auto stand_solver = make_light_solver(backend, stand_light);
  auto open_grown_solver = make_light_solver(backend, open_grown);
  return {std::move(backend), std::move(stand_solver), std::move(open_grown_solver)};
}

// The run's totals once its last year is grown (the by-year costs and light parts are summed as it goes).
void close_summary(const Stand& stand, const RootZone* roots, const LightSolver& solver, const StageClock& clock,
                   const FarFieldCells& far_field_cells, const checkpoint::RunProgress& run_progress,
                   int first_stand_age, SimulationSummary& summary) {
  summary.first_stand_age = first_stand_age;
  summary.last_stand_age = stand.stand_age();
  count_trees(stand, roots, summary);
  summary.tree_years = run_progress.tree_years;
  summary.device = solver.name();
  summary.light_tile_candidates_per_ball = solver.last_statistics().mean_tile_candidates;
  summary.light_far_field_cell_m_max = far_field_cells.coarsest();
  summary.stage_seconds = clock.stages();
  summary.stage_cpu_seconds = clock.cpu_stages();
  summary.light_seconds = clock.seconds("light") + clock.seconds("light (open grown)");
}

// run.json's record of the run. A resumed run records the run it continues: its first command and start
// (docs/user-guide.md).
RunManifest run_manifest(const Scenario& scenario, const std::string& device, const SimulationSummary& summary,
                         const checkpoint::RunProgress& run_progress) {
  RunManifest manifest;
  manifest.started_utc = run_progress.started_utc;
  manifest.command_line = run_progress.command_line;
  manifest.scenario_path = scenario.file.string();
  manifest.seed = scenario.run.seed;
  manifest.device = device;
  manifest.first_stand_age = summary.first_stand_age;
  manifest.last_stand_age = summary.last_stand_age;
  manifest.stage_seconds = summary.stage_seconds;
  manifest.wall_seconds = summary.wall_seconds;
  manifest.finished_utc = utc_now_iso8601();
  manifest.finished_on_hardware_threads = std::thread::hardware_concurrency();
  manifest.finished_on_processor = this_processor();
  manifest.finished_on_pages = this_process_page_settings();
  return manifest;
}

}  // namespace

SimulationSummary run_simulation(const Scenario& scenario, const SimulationOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  checkpoint::RunProgress run_progress{0, 0.0, utc_now_iso8601(), options.command_line};
  // The backend and solvers first: a device that does not exist must fail before the output folder is taken.
  const LightParameters stand_light = scenario.stand_light();
  const RunSolvers solvers = open_solvers(scenario, options, stand_light);
  // Read before the folder is taken: an identity that cannot be formed must not leave a folder behind.
  const checkpoint::RunIdentity identity = options.checkpoint_every_years > 0 || options.resume
                                               ? run_identity(scenario, solvers.backend.name(), options.write_vtk)
                                               : checkpoint::RunIdentity{};
  StandOutput output({.folder = options.output_folder,
                      .force = options.force,
                      .plot_area_m2 = scenario.plot_area_ha() * 1e4,
                      .write_vtk = options.write_vtk,
                      .detail = scenario.run.output_detail,
                      .compression = scenario.run.vtk_compression,
                      .resume = options.resume});

  StageClock clock;
  // A resumed run's stand and roots come from its checkpoint: they start empty and are not spun up.
  Stand stand(scenario.plot_area_ha(), scenario.stand.age_at_survey_years,
              options.resume ? std::vector<StandTree>{} : established_trees(scenario, clock),
              schedule(scenario), competition_for(scenario));
  // Roots and the crown–root coupling (stand/root_zone.hpp): spun up under the established stand.
  auto roots = options.resume ? make_root_zone(scenario, solvers.backend)
                              : clock.time("roots", [&] { return establish_root_zone(scenario, stand, solvers.backend); });
  if (roots && output.vtk() && scenario.run.roots_output_interval_years > 0)
    add_root_blocks(*output.vtk(), *roots, scenario.run.roots_output_interval_years);

  StandYear simulated_year(stand, *solvers.stand, *solvers.open_grown, roots ? &*roots : nullptr, &output,
                           {scenario.run.seed, scenario.light.sky_scale, scenario.run.years,
                            scenario.run.output_interval_years},
                           clock);
  const checkpoint::RunParts parts{stand, roots ? &*roots : nullptr, output, simulated_year, clock, run_progress};
  int first_year = 0;
  if (options.resume)
    first_year = 1 + resume_from_newest(options.output_folder, identity, [&](const checkpoint::CheckpointFile& file) {
      checkpoint::load_run(file.payload, scenario, parts);
    });
  const double earlier_wall_seconds = run_progress.wall_seconds;  // of the sessions before a resume
  auto wall_seconds = [&] {
    return earlier_wall_seconds + seconds_since(started);
  };

  ProgressLine progress(scenario.run.years, options.show_progress);
  FarFieldCells far_field_cells(stand_light);
  SimulationSummary summary;
  const LightSolver& solver = *solvers.stand;
  for (int year = first_year; year <= scenario.run.years; ++year) {
    const StageClock before = clock;
    if (year > 0) run_progress.tree_years += living_tree_count(stand);  // the trees that grow this year
    simulated_year.run(year);
    far_field_cells.after_year(solver.last_statistics(), stand.stand_age());
    add_light_parts(solver.last_statistics(), summary);
    if (options.observe_year) options.observe_year(stand, year);
    if (is_checkpoint_year(year, options.checkpoint_every_years, scenario.run.years)) {
      run_progress.wall_seconds = wall_seconds();
      clock.time("checkpoint", [&] { return write_checkpoint(options.output_folder, year, identity, parts); });
    }
    summary.by_year.push_back(year_cost(year, stand, before, clock, solver.last_statistics()));
    progress.update(year);
  }
  progress.finish();

  close_summary(stand, roots ? &*roots : nullptr, solver, clock, far_field_cells, run_progress,
                scenario.stand.age_at_survey_years, summary);
  summary.wall_seconds = wall_seconds();
  output.finish(run_manifest(scenario, solvers.backend.name(), summary, run_progress));
  // The run is finished (run.json written): nothing will resume it.
  checkpoint::prune_checkpoints(options.output_folder, 0);
  return summary;
}

}  // namespace heliostand
