#include <fmt/format.h>

#include "scenario/scenario_tables.hpp"
#include "scenario/toml_table_reader.hpp"

namespace heliostand::scenario_detail {

const toml::table* as_table(const toml::node* node, std::string_view key, ScenarioProblems& problems) {
  if (!node) return nullptr;
  if (const toml::table* table = node->as_table()) return table;
  problems.add(node->source(), std::string(key), fmt::format("expected a table, got {}", toml_type_phrase(*node)));
  return nullptr;
}

void for_each_table_of_array(const toml::node* node, std::string_view key, ScenarioProblems& problems,
                             const std::function<void(const toml::table&, const std::string& path)>& parse) {
  if (!node) return;
  const toml::array* tables = node->as_array();
  if (!tables) {
    problems.add(node->source(), std::string(key),
                 fmt::format("expected an array of tables ([[{}]]), got {}", key, toml_type_phrase(*node)));
    return;
  }
  for (std::size_t i = 0; i < tables->size(); ++i) {
    const std::string path = fmt::format("{}[{}]", key, i + 1);  // 1-based: the first [[key]] is [1]
    const toml::node& element = *tables->get(i);
    if (const toml::table* table = element.as_table()) parse(*table, path);
    else problems.add(element.source(), path, fmt::format("expected a table, got {}", toml_type_phrase(element)));
  }
}

void parse_stand(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems) {
  if (!node) {
    problems.add(0, "stand", "required table missing (it names the survey, the stand age and the plot)");
    return;
  }
  const toml::table* table = as_table(node, "stand", problems);
  if (!table) return;
  TomlTableReader reader(*table, "stand", problems);
  StandSettings& stand = draft.scenario.stand;

  if (auto survey = reader.string("survey", true)) {
    if (survey->empty()) {
      reader.problem("survey", "expected the path of the survey CSV, got an empty string");
    } else {
      const std::filesystem::path shown = (draft.base_dir / *survey).lexically_normal();
      std::error_code ec;
      if (!std::filesystem::is_regular_file(shown, ec)) {
        reader.problem("survey", fmt::format("survey file \"{}\" not found (paths are relative to the scenario file)",
                                             shown.string()));
      } else {
        draft.survey_label = shown.string();
        draft.survey_key_line = reader.line_of("survey");
        stand.survey_file = std::filesystem::absolute(shown).lexically_normal();
      }
    }
  }
  if (auto age = reader.integer("age_at_survey", at_least(1), true)) {
    stand.age_at_survey_years = static_cast<int>(*age);
    draft.age_valid = true;
  }

  const auto x_min = reader.number("x_min", any_number(), true);
  const auto y_min = reader.number("y_min", any_number(), true);
  const auto x_max = reader.number("x_max", any_number(), true);
  const auto y_max = reader.number("y_max", any_number(), true);
  bool plot_ok = x_min && y_min && x_max && y_max;
  if (x_min && x_max && *x_max <= *x_min) {
    reader.problem("x_max", fmt::format("must be greater than x_min ({:g}), got {:g}", *x_min, *x_max));
    plot_ok = false;
  }
  if (y_min && y_max && *y_max <= *y_min) {
    reader.problem("y_max", fmt::format("must be greater than y_min ({:g}), got {:g}", *y_min, *y_max));
    plot_ok = false;
  }
  if (plot_ok) {
    stand.plot = PlotBounds{*x_min, *y_min, *x_max, *y_max};
    draft.plot_valid = true;
  }

  if (auto name = reader.string("default_species")) {
    draft.default_species_key = *name;
    draft.default_species_line = reader.line_of("default_species");
  }
  reader.report_unknown_keys();
}

}  // namespace heliostand::scenario_detail
