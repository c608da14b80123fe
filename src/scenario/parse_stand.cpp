#include <fmt/format.h>

#include "scenario/scenario_limits.hpp"
#include "scenario/scenario_tables.hpp"
#include "scenario/toml_table_reader.hpp"
#include "survey/plausible_limits.hpp"
#include "survey/read_survey.hpp"

namespace heliostand::scenario_detail {

namespace {

// stand.survey_units = { dbh = "mm", height = "ft" }: a unit per survey column, by its canonical name.
void parse_survey_units(const toml::node* node, SurveyFormat& format, ScenarioProblems& problems) {
  if (!node) return;
  const toml::table* units = as_table(node, "stand.survey_units", problems);
  if (!units) return;
  for (auto&& [key, value] : *units) {
    const std::string path = fmt::format("stand.survey_units.{}", key.str());
    const auto column = survey_column_by_name(key.str());
    if (!column) {
      std::vector<std::string_view> names;
      for (const auto& info : survey_columns())
        if (info.quantity != Quantity::none) names.push_back(info.name);
      problems.add(key.source(), path, fmt::format("not a survey column with a unit (known: {})", fmt::join(names, ", ")));
      continue;
    }
    const std::optional<std::string_view> unit = value.value<std::string_view>();
    if (!unit) {
      problems.add(value.source(), path, fmt::format("expected a unit as a string, got {}", toml_type_phrase(value)));
      continue;
    }
    const Quantity quantity = survey_column_info(*column).quantity;
    if (!unit_factor(quantity, *unit)) {
      problems.add(value.source(), path,
                   fmt::format("'{}' is not a unit of {} (accepted: {})", *unit, key.str(), accepted_units(quantity)));
      continue;
    }
    format.units[*column] = std::string(*unit);
  }
}

void parse_survey_format(TomlTableReader& reader, SurveyFormat& format) {
  if (auto separator = reader.choice("survey_separator", field_separator_names)) format.separator = *separator;
  if (auto policy = reader.choice("multi_stem", multi_stem_policy_names)) format.multi_stem = *policy;
  parse_survey_units(reader.node("survey_units"), format, reader.problems());
}

// The plot from the survey's stem positions, widened by the margin on every side.
void plot_from_survey(TomlTableReader& reader, ScenarioDraft& draft, double margin_m) {
  StandSettings& stand = draft.scenario.stand;
  if (stand.survey_file.empty()) return;
  const auto extent = survey_extent(stand.survey_file, stand.survey_format);
  if (!extent) return;  // the survey's own problems are reported when it is read
  const PlotBounds plot{extent->x_min - margin_m, extent->y_min - margin_m, extent->x_max + margin_m,
                        extent->y_max + margin_m};
  if (plot.width_m() <= 0.0 || plot.depth_m() <= 0.0) {
    reader.problem("plot_margin_m", fmt::format("the trees stand on a line or a point ({:g} x {:g} m): give a margin "
                                                "> 0 or the plot bounds",
                                                extent->x_max - extent->x_min, extent->y_max - extent->y_min));
    return;
  }
  stand.plot = plot;
  stand.plot_margin_m = margin_m;
  draft.plot_valid = true;
}
}  // namespace

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
  if (auto age = reader.integer("age_at_survey", from_up_to(1, limit::grown_tree_age), true)) {
    stand.age_at_survey_years = static_cast<int>(*age);
    draft.age_valid = true;
  }

  parse_survey_format(reader, stand.survey_format);
  const auto margin = reader.number("plot_margin_m", non_negative_up_to(limit::plot_margin_m));
  const bool from_survey = margin.has_value();
  const NumberRange coordinate = magnitude_up_to(limit::coordinate_m);
  const auto x_min = reader.number("x_min", coordinate, !from_survey);
  const auto y_min = reader.number("y_min", coordinate, !from_survey);
  const auto x_max = reader.number("x_max", coordinate, !from_survey);
  const auto y_max = reader.number("y_max", coordinate, !from_survey);
  if (from_survey) {
    if (x_min || y_min || x_max || y_max)
      reader.problem("plot_margin_m", "give either the plot bounds (x_min, y_min, x_max, y_max) or plot_margin_m, "
                                      "not both");
    else
      plot_from_survey(reader, draft, *margin);
  }
  bool plot_ok = !from_survey && x_min && y_min && x_max && y_max;
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
