// What the model can grow, checked once the survey is read (scenario/scenario_limits.hpp): every tree young enough for
// establishment to regrow it, and eq. 9's branch triangle open at the oldest age each species reaches in the run.
#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "architecture/elongation.hpp"
#include "scenario/scenario_limits.hpp"
#include "scenario/scenario_tables.hpp"

namespace heliostand::scenario_detail {

std::vector<CrownClosure> crown_closures(const Scenario& scenario) {
  // The crown angle grows with age (beta >= 0), so the triangle is narrowest at the oldest age a tree reaches.
  std::map<std::string, double> oldest;
  for (const auto& tree : scenario.survey.trees)
    oldest[tree.species] = std::max(oldest[tree.species], tree.age_years + scenario.run.years);
  std::vector<CrownClosure> found;
  for (const auto& [name, age] : oldest) {
    const auto species = scenario.species.find(name);
    if (species == scenario.species.end()) continue;  // reported by the survey reader
    const double theta = crown_angle_deg(species->second, age);
    const double opening = 180.0 - theta - species->second.initial_branch_angle_deg;
    if (opening < limit::min_branch_triangle_opening_deg) found.push_back({name, age, theta, opening});
  }
  return found;
}

std::string CrownClosure::reason(const Scenario& scenario) const {
  const SpeciesParameters& s = scenario.species.at(species);
  return fmt::format("at tree age {:g} the crown angle {:g} x {:g}^{:g} = {:.4g}° and initial_branch_angle_deg {:g}° "
                     "leave eq. 9's branch triangle {:.4g}° open, less than {:g}°: a first-order branch's first shoot, "
                     "dH sin(theta) / sin(180° - theta - d0), grows without bound as it closes (lower "
                     "crown_angle_beta, initial_crown_angle_deg or initial_branch_angle_deg)",
                     age_years, s.initial_crown_angle_deg, age_years, s.crown_angle_beta, crown_angle_deg,
                     s.initial_branch_angle_deg, opening_deg, limit::min_branch_triangle_opening_deg);
}

void check_crown_closure(const ScenarioDraft& draft, ScenarioProblems& problems) {
  for (const CrownClosure& closure : crown_closures(draft.scenario)) {
    const auto table = std::find_if(draft.species_order.begin(), draft.species_order.end(),
                                    [&](const auto& entry) { return entry.first == closure.species; });
    problems.add(table == draft.species_order.end() ? 0 : table->second,
                 fmt::format("species.{}.crown_angle_beta", closure.species), closure.reason(draft.scenario));
  }
}

void check_tree_ages(const ScenarioDraft& draft, ScenarioProblems& problems) {
  const Survey& survey = draft.scenario.survey;
  std::vector<InputProblem> found;
  for (const auto& tree : survey.trees) {
    // An imputed age is the stand's, checked as stand.age_at_survey.
    if (tree.imputed.age || tree.age_years <= limit::grown_tree_age.max) continue;
    found.push_back({draft.survey_label.value_or(survey.file.string()), tree.line, "age",
                     fmt::format("{:g} years is beyond the {:g} years the model can grow a tree to ({})",
                                 tree.age_years, limit::grown_tree_age.max, limit::grown_tree_age.why),
                     "column"});
  }
  if (!found.empty()) problems.merge(InputError(found, "column"));
}

}  // namespace heliostand::scenario_detail
