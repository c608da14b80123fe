#include "run/established_canopy.hpp"

#include <spdlog/spdlog.h>

#include "scenario/scenario.hpp"
#include "stand/establishment.hpp"
#include "stand/memory_estimate.hpp"

namespace heliostand {

LightBenchmarkStand established_canopy(const Scenario& scenario, const std::string& name) {
  for (const auto& warning : scenario.survey.warnings) spdlog::warn("{}", warning);
  refuse_run_beyond_this_machine(scenario);  // a stand that `grow` would refuse is not established here either
  EstablishmentReport report;
  const std::vector<StandTree> trees = establish_stand(scenario, report);
  spdlog::info("bench light: {} established, {} trees at age {} ({} fitted, {} with crown base off, {} not fitted)",
               name, trees.size(), scenario.stand.age_at_survey_years, report.fitted,
               report.crown_base_off, report.unusable);

  LightBenchmarkStand stand;
  stand.name = name;
  for (const StandTree& tree : trees) {
    if (!tree.alive()) continue;
    const std::vector<LeafBall> balls = tree.conifer.leaf_balls();
    stand.balls.insert(stand.balls.end(), balls.begin(), balls.end());
    ++stand.tree_count;
  }
  stand.parameters = scenario.stand_light();  // as the run's stand solver sees it
  return stand;
}

}  // namespace heliostand
