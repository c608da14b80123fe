#include "stand/simulation.hpp"

#include <chrono>
#include <map>

#include <spdlog/spdlog.h>

#include "io/stand_output.hpp"
#include "light/make_light_solver.hpp"
#include "stand/establishment.hpp"
#include "stand/progress.hpp"
#include "stand/root_zone.hpp"
#include "stand/snapshot.hpp"
#include "stand/stand.hpp"

namespace heliostand {
namespace {

// Wall time per stage of the yearly loop, for run.json.
class StageClock {
 public:
  template <typename Work>
  auto time(const std::string& stage, Work work) {
    const auto start = std::chrono::steady_clock::now();
    struct Stop {
      StageClock& clock;
      const std::string& stage;
      std::chrono::steady_clock::time_point start;
      ~Stop() { clock.add(stage, std::chrono::steady_clock::now() - start); }
    } stop{*this, stage, start};
    return work();
  }
  double seconds(const std::string& stage) const {
    for (const auto& [name, value] : stages_) if (name == stage) return value;
    return 0;
  }
  const std::vector<std::pair<std::string, double>>& stages() const { return stages_; }

 private:
  void add(const std::string& stage, std::chrono::steady_clock::duration elapsed) {
    const double seconds = std::chrono::duration<double>(elapsed).count();
    for (auto& [name, value] : stages_)
      if (name == stage) { value += seconds; return; }
    stages_.emplace_back(stage, seconds);
  }
  std::vector<std::pair<std::string, double>> stages_;
};

std::vector<ScheduledThinning> schedule(const Scenario& scenario) {
  std::vector<ScheduledThinning> events;
  for (const auto& event : scenario.thinning)
    events.push_back({event.age_years,
                      ThinningRule{event.method, event.ids, event.target_stems_per_ha,
                                   event.target_basal_area_m2_per_ha},
                      event.reason, event.protect_habitat_trees});
  return events;
}

LightParameters light_for(const Scenario& scenario) {
  LightParameters light = scenario.light;
  light.plot_x_min = scenario.stand.plot.x_min;
  light.plot_y_min = scenario.stand.plot.y_min;
  light.plot_x_max = scenario.stand.plot.x_max;
  light.plot_y_max = scenario.stand.plot.y_max;
  return light;
}

bool is_output_year(const Scenario& scenario, int years_done) {
  return years_done == scenario.run.years || years_done % scenario.run.output_interval_years == 0;
}

}  // namespace

SimulationSummary run_simulation(const Scenario& scenario, const SimulationOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  RunManifest manifest;
  manifest.started_utc = utc_now_iso8601();
  // The solver first: a device that does not exist must fail before the output folder is taken.
  const std::string device = options.device.empty() ? scenario.run.device.text() : options.device;
  auto solver = make_light_solver(device, light_for(scenario));
  spdlog::info("light solver: {}", solver->name());
  // The open-grown reference of the light response (each tree alone, once a year): a few hundred balls, so
  // the exact solver is cheapest (culling and far field only pay off for a whole stand), and a tree alone is
  // not repeated across periodic plot edges.
  LightParameters open_grown = light_for(scenario);
  open_grown.exact = true;
  open_grown.periodic = false;
  auto open_grown_solver = make_light_solver(device, open_grown);
  StandOutput output({options.output_folder, options.force, scenario.plot_area_ha() * 1e4, options.write_vtk});

  StageClock clock;
  EstablishmentReport report;
  auto trees = clock.time("establishment", [&] { return establish_stand(scenario, report); });
  spdlog::info("established {} trees at age {} ({} fitted, {} with crown base off, {} not fitted)",
               trees.size(), scenario.stand.age_at_survey_years, report.fitted, report.crown_base_off,
               report.unusable);
  Stand stand(scenario.plot_area_ha(), scenario.stand.age_at_survey_years, std::move(trees),
              schedule(scenario));
  // Roots and the crown–root coupling (stand/root_zone.hpp): spun up under the established stand.
  auto roots = clock.time("roots", [&] { return establish_root_zone(scenario, stand); });
  if (roots && output.vtk()) add_root_blocks(*output.vtk(), *roots);

  ProgressLine progress(scenario.run.years, options.show_progress);
  SnapshotTracker snapshots(output.vtk() != nullptr);
  for (int year = 0; year <= scenario.run.years; ++year) {
    if (year > 0) clock.time("growth", [&] { stand.grow_year(); return 0; });
    const std::size_t balls = clock.time("light", [&] { return stand.illuminate(*solver); });
    spdlog::debug("age {}: {} leaf balls lit", stand.stand_age(), balls);
    // Order matters: the crown-root coupling reads this year's light of every leaf ball, before the light
    // response bends and kills shoots (which changes the leaf-ball list).
    if (roots) clock.time("roots", [&] { year > 0 ? roots->grow_year(stand) : roots->couple(stand); return 0; });
    // The established trees grew without neighbours; competition acts from the first simulated year on.
    if (year > 0)
      output.record_events(clock.time("light response", [&] { return stand.respond_to_light(*open_grown_solver, scenario.run.seed); }));
    const auto removals = stand.thin();
    output.record_events(removals);
    if (is_output_year(scenario, year))
      clock.time("output", [&] {
        StandSnapshot snapshot = snapshots.take(stand, year);
        if (roots) roots->annotate(snapshot);
        output.write_year(snapshot);
        return 0;
      });
    if (options.observe_year) options.observe_year(stand, year);
    progress.update(year);
  }
  progress.finish();

  SimulationSummary summary;
  summary.first_stand_age = scenario.stand.age_at_survey_years;
  summary.last_stand_age = stand.stand_age();
  for (const auto& tree : stand.trees()) {
    summary.trees_alive += tree.status == TreeStatus::alive;
    summary.trees_removed += tree.status == TreeStatus::removed;
    summary.trees_dead += tree.status == TreeStatus::dead;
  }
  summary.light_seconds = clock.seconds("light");
  summary.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  manifest.command_line = options.command_line;
  manifest.scenario_path = scenario.file.string();
  manifest.seed = scenario.run.seed;
  manifest.device = solver->name();
  manifest.first_stand_age = summary.first_stand_age;
  manifest.last_stand_age = summary.last_stand_age;
  manifest.stage_seconds = clock.stages();
  manifest.wall_seconds = summary.wall_seconds;
  manifest.finished_utc = utc_now_iso8601();
  output.finish(std::move(manifest));
  return summary;
}

}  // namespace heliostand
