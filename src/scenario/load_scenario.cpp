#include <fmt/format.h>

#include <algorithm>
#include <array>

#include "scenario/scenario.hpp"
#include "scenario/scenario_tables.hpp"
#include "scenario/toml_file.hpp"
#include "survey/read_survey.hpp"

namespace heliostand {

namespace scenario_detail {

std::span<const TableParserEntry> scenario_table_parsers() {
  static constexpr std::array<TableParserEntry, 11> parsers{{
      {"stand", parse_stand},
      {"run", parse_run},
      {"species", parse_species},
      {"light", parse_light},
      {"competition", parse_competition},  // before thinning: its radius is crop-tree release's default
      {"thinning", parse_thinning},
      {"roots", parse_roots},  // after species: [roots.SPECIES] names a species
      {"soil", parse_soil},
      {"coupling", parse_coupling},
      {"root_pruning", parse_root_pruning},
      {"hollow", parse_hollow},
  }};
  return parsers;
}

}  // namespace scenario_detail

namespace {

using namespace scenario_detail;

void report_unknown_tables(const toml::table& root, ScenarioProblems& problems) {
  std::vector<std::string_view> known;
  for (const auto& entry : scenario_table_parsers()) known.push_back(entry.key);
  for (auto&& [key, value] : root) {
    if (std::find(known.begin(), known.end(), key.str()) != known.end()) continue;
    problems.add(key.source(), std::string(key.str()),
                 fmt::format("unknown table or key (known: {})", fmt::join(known, ", ")));
  }
}

void read_stand_survey(ScenarioDraft& draft, ScenarioProblems& problems) {
  if (!draft.survey_label) return;
  Scenario& scenario = draft.scenario;
  SurveyReadOptions options;
  if (draft.plot_valid) options.plot = scenario.stand.plot;
  options.format = scenario.stand.survey_format;
  // A bad stand age is reported already; a stand-in keeps every record from repeating it.
  options.stand_age_years = draft.age_valid ? scenario.stand.age_at_survey_years : 1;
  options.species = scenario.species;
  options.default_species = scenario.stand.default_species.empty() ? draft.default_species_key.value_or("todomatsu")
                                                                    : scenario.stand.default_species;
  try {
    scenario.survey = read_survey(*draft.survey_label, options);
    scenario.survey.file = scenario.stand.survey_file;
  } catch (const InputError& error) {
    problems.merge(error);
    draft.survey_label.reset();  // unusable for cross-checks
  }
}

}  // namespace

Scenario load_scenario(const std::filesystem::path& file) {
  const std::string label = file.string();
  const toml::table root = read_toml_file(file, label, "scenario");

  ScenarioProblems problems(label);
  ScenarioDraft draft;
  draft.base_dir = file.parent_path();
  draft.scenario.file = std::filesystem::absolute(file).lexically_normal();

  report_unknown_tables(root, problems);
  for (const auto& entry : scenario_table_parsers()) entry.parse(root.get(entry.key), draft, problems);

  read_stand_survey(draft, problems);
  if (draft.survey_label) {
    attach_hollows_to_survey(draft, problems);
    check_tree_ages(draft, problems);
    if (draft.years_valid) check_crown_closure(draft, problems);
  }
  if (draft.survey_label && draft.plot_valid) {
    check_thinning_against_survey(draft, problems);
  }
  problems.throw_if_any();
  return std::move(draft.scenario);
}

void Scenario::set_years(int years) {
  std::vector<InputProblem> problems;
  const std::string label = file.string();
  if (years < 1) problems.push_back({label, 0, "run.years", fmt::format("--years must be at least 1, got {}", years)});
  const int final_age = stand.age_at_survey_years + years;
  for (const auto& event : thinning) {
    if (event.when.at_fixed_age() && event.when.stand_age > final_age) {
      problems.push_back({label, event.line, "run.years",
                          fmt::format("--years {} ends the run at stand age {}, before the thinning at age {}", years,
                                      final_age, event.when.stand_age)});
    }
  }
  const int before = run.years;
  run.years = years;
  for (const auto& closure : scenario_detail::crown_closures(*this))
    problems.push_back({label, 0, "run.years", fmt::format("--years {}: species {}: {}", years, closure.species,
                                                          closure.reason(*this))});
  if (!problems.empty()) {
    run.years = before;
    throw InputError(std::move(problems), "key");
  }
}

}  // namespace heliostand
