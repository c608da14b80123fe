// [[thinning]] tables: when (parse_thinning_when.cpp), which method, and the method's parameters. Every key a method
// does not use is an error, as is a missing key it needs; the checks against the survey are in check_thinning.cpp.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <string_view>

#include "scenario/scenario_limits.hpp"
#include "scenario/scenario_tables.hpp"
#include "scenario/toml_table_reader.hpp"

namespace heliostand::scenario_detail {

namespace {

using namespace std::string_view_literals;

constexpr std::array size_targets{"target_stems_per_ha"sv, "target_basal_area_m2_per_ha"sv, "remove_fraction"sv,
                                  "remove_basal_area_fraction"sv};

// Every key that parameterises some method, in the order problems about them are listed.
constexpr std::array method_parameters{
    "ids"sv,           "target_stems_per_ha"sv, "target_basal_area_m2_per_ha"sv, "remove_fraction"sv,
    "remove_basal_area_fraction"sv, "crop_trees_per_ha"sv, "crop_tree_spacing_m"sv,   "competitor_radius_m"sv,
    "competitors_per_crop_tree"sv,  "dbh_min_cm"sv,        "dbh_max_cm"sv,            "row_interval"sv,
    "first_row"sv,                  "row_azimuth_deg"sv,   "row_tolerance_m"sv};

bool is_size_method(ThinningMethod method) {
  return method == ThinningMethod::from_below || method == ThinningMethod::from_above ||
         method == ThinningMethod::neutral;
}

bool method_uses(ThinningMethod method, std::string_view key) {
  auto one_of = [&](std::initializer_list<std::string_view> keys) {
    return std::find(keys.begin(), keys.end(), key) != keys.end();
  };
  switch (method) {
    case ThinningMethod::ids: return key == "ids";
    case ThinningMethod::from_below:
    case ThinningMethod::from_above:
    case ThinningMethod::neutral: return std::find(size_targets.begin(), size_targets.end(), key) != size_targets.end();
    case ThinningMethod::crop_tree:
      return one_of({"crop_trees_per_ha", "crop_tree_spacing_m", "competitor_radius_m", "competitors_per_crop_tree"});
    case ThinningMethod::dbh_class: return one_of({"dbh_min_cm", "dbh_max_cm", "remove_fraction"});
    case ThinningMethod::rows: return one_of({"row_interval", "first_row", "row_azimuth_deg", "row_tolerance_m"});
  }
  return false;
}

// What a "not used" message tells the user about the method instead.
std::string_view how_it_chooses(ThinningMethod method) {
  switch (method) {
    case ThinningMethod::ids: return "remove the key or change the method";
    case ThinningMethod::from_below:
    case ThinningMethod::from_above:
    case ThinningMethod::neutral: return "it chooses trees by size";
    case ThinningMethod::crop_tree: return "it chooses crop trees and removes their competitors";
    case ThinningMethod::dbh_class: return "it chooses trees by DBH class";
    case ThinningMethod::rows: return "it chooses planted rows";
  }
  return "";
}

struct RequiredKey {
  ThinningMethod method;
  std::string_view key;
  std::string_view why;
};
constexpr std::array required_keys{
    RequiredKey{ThinningMethod::ids, "ids", "method \"ids\" names the trees to remove"},
    RequiredKey{ThinningMethod::crop_tree, "crop_trees_per_ha", "method \"crop_tree\" needs how many crop trees per ha"},
    RequiredKey{ThinningMethod::crop_tree, "crop_tree_spacing_m",
                "method \"crop_tree\" needs the least distance between two crop trees"},
    RequiredKey{ThinningMethod::rows, "row_interval", "method \"rows\" removes every row_interval-th planted row"},
};

std::optional<ThinningMethod> method_named(std::string_view name) {
  for (auto method : all_thinning_methods)
    if (thinning_method_name(method) == name) return method;
  return std::nullopt;
}

std::string method_choices() {
  std::vector<std::string> quoted;
  for (auto method : all_thinning_methods) quoted.push_back(fmt::format("\"{}\"", thinning_method_name(method)));
  const std::string last = quoted.back();
  quoted.pop_back();
  return fmt::format("{} or {}", fmt::join(quoted, ", "), last);
}

// ids = ["T3", 17, ...]: survey ids are text; integers are accepted for numeric ids.
std::vector<std::string> read_ids(TomlTableReader& reader) {
  const toml::node* node = reader.node("ids");
  std::vector<std::string> ids;
  if (!node) return ids;
  const toml::array* array = node->as_array();
  if (!array) {
    reader.problem("ids", fmt::format("expected an array of tree ids, got {}", toml_type_phrase(*node)));
    return ids;
  }
  if (array->empty()) reader.problem("ids", "expected at least one tree id, got an empty array");
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& element = *array->get(i);
    if (auto text = element.value_exact<std::string>()) {
      ids.push_back(*text);
    } else if (auto number = element.value_exact<std::int64_t>()) {
      ids.push_back(std::to_string(*number));
    } else {
      reader.problems().add(element.source(), fmt::format("{}[{}]", reader.key_path("ids"), i + 1),
                            fmt::format("expected a tree id (string or integer), got {}", toml_type_phrase(element)));
    }
  }
  return ids;
}

constexpr NumberRange fraction{0.0, 1.0, true, false};  // (0, 1]

void read_size_targets(TomlTableReader& reader, ThinningRule& rule) {
  rule.target_stems_per_ha = reader.number("target_stems_per_ha", positive_up_to(limit::stems_per_ha));
  rule.target_basal_area_m2_per_ha =
      reader.number("target_basal_area_m2_per_ha", positive_up_to(limit::basal_area_m2_per_ha));
  rule.remove_fraction = reader.number("remove_fraction", fraction);
  rule.remove_basal_area_fraction = reader.number("remove_basal_area_fraction", fraction);
}

void read_crop_tree_keys(TomlTableReader& reader, const ScenarioDraft& draft, CropTreeSettings& crop_trees) {
  if (auto n = reader.number("crop_trees_per_ha", positive_up_to(limit::stems_per_ha))) crop_trees.crop_trees_per_ha = *n;
  if (auto spacing = reader.number("crop_tree_spacing_m", non_negative_up_to(limit::neighbourhood_m))) crop_trees.spacing_m = *spacing;
  crop_trees.competitor_radius_m = reader.number("competitor_radius_m", positive_up_to(limit::neighbourhood_m))
                                       .value_or(draft.scenario.competition.hegyi_radius_m);
  if (auto n = reader.integer("competitors_per_crop_tree", from_up_to(1, limit::competitors)))
    crop_trees.competitors_per_crop_tree = static_cast<int>(*n);
}

void read_dbh_class_keys(TomlTableReader& reader, DbhClass& dbh_class) {
  const auto min = reader.number("dbh_min_cm", non_negative_up_to(limit::dbh_cm));
  const auto max = reader.number("dbh_max_cm", positive_up_to(limit::dbh_cm));
  if (min) dbh_class.min_cm = *min;
  if (max) dbh_class.max_cm = *max;
  if (min && max && *max <= *min)
    reader.problem("dbh_max_cm", fmt::format("must be greater than dbh_min_cm ({:g}), got {:g}", *min, *max));
}

void read_row_keys(TomlTableReader& reader, RowSettings& rows) {
  if (auto k = reader.integer("row_interval", from_up_to(2, limit::planting_rows))) rows.interval = static_cast<int>(*k);
  if (auto first = reader.integer("first_row", from_up_to(1, limit::planting_rows))) rows.first_row = static_cast<int>(*first);
  rows.azimuth_deg = reader.number("row_azimuth_deg", NumberRange{0.0, 360.0, false, true});
  if (auto tolerance = reader.number("row_tolerance_m", positive_up_to(limit::neighbourhood_m))) rows.tolerance_m = *tolerance;
}

void check_method_keys(TomlTableReader& reader, ThinningMethod method) {
  for (const auto& required : required_keys)
    if (required.method == method && !reader.table().contains(required.key))
      reader.problems().add(reader.line(), reader.key_path(required.key),
                            fmt::format("required key missing ({})", required.why));
  for (auto key : method_parameters)
    if (reader.table().contains(key) && !method_uses(method, key))
      reader.problem(key, fmt::format("not used by method \"{}\" ({})", thinning_method_name(method),
                                      how_it_chooses(method)));
}

void check_one_size_target(TomlTableReader& reader, ThinningMethod method, const std::string& path) {
  std::vector<std::string_view> given;
  for (auto key : size_targets)
    if (reader.table().contains(key)) given.push_back(key);
  if (given.size() == 1) return;
  reader.problems().add(reader.line(), path,
                        fmt::format("method \"{}\" needs exactly one of target_stems_per_ha, "
                                    "target_basal_area_m2_per_ha, remove_fraction and remove_basal_area_fraction, "
                                    "got {}",
                                    thinning_method_name(method),
                                    given.empty() ? std::string("none") : fmt::format("{}", fmt::join(given, " and "))));
}

void check_dbh_class_bounds(TomlTableReader& reader) {
  if (reader.table().contains("dbh_min_cm") || reader.table().contains("dbh_max_cm")) return;
  reader.problems().add(reader.line(), reader.key_path("dbh_min_cm"),
                        "required key missing (method \"dbh_class\" needs the class: dbh_min_cm, dbh_max_cm or both)");
}

ScenarioDraft::ThinningKeys key_lines(const TomlTableReader& reader, const std::string& path) {
  ScenarioDraft::ThinningKeys keys{path};
  keys.ids_line = reader.line_of("ids");
  auto target = std::find_if(size_targets.begin(), size_targets.end(),
                             [&](std::string_view key) { return reader.table().contains(key); });
  keys.target_line = reader.line_of(target != size_targets.end() ? *target : "target_basal_area_m2_per_ha");
  keys.method_line = reader.line_of("method");
  keys.first_row_line = reader.line_of("first_row");
  keys.crop_trees_line = reader.line_of("crop_trees_per_ha");
  return keys;
}

void parse_thinning_event(const toml::table& table, const std::string& path, ScenarioDraft& draft,
                          ScenarioProblems& problems) {
  TomlTableReader reader(table, path, problems);
  ThinningEvent event;
  event.line = reader.line();
  event.scenario_order = static_cast<int>(draft.scenario.thinning.size());

  read_thinning_when(reader, draft, event.when);
  std::optional<ThinningMethod> method;
  if (auto name = reader.string("method", true)) {
    method = method_named(*name);
    if (!method) reader.problem("method", fmt::format("expected {}, got \"{}\"", method_choices(), *name));
  }
  event.rule.ids = read_ids(reader);
  read_size_targets(reader, event.rule);
  read_crop_tree_keys(reader, draft, event.rule.crop_trees);
  read_dbh_class_keys(reader, event.rule.dbh_class);
  read_row_keys(reader, event.rule.rows);
  if (auto reason = reader.string("reason")) event.reason = *reason;
  if (auto protect = reader.boolean("protect_habitat_trees")) event.protect_habitat_trees = *protect;
  reader.report_unknown_keys();

  if (method) {
    check_method_keys(reader, *method);
    if (is_size_method(*method)) check_one_size_target(reader, *method, path);
    if (*method == ThinningMethod::dbh_class) check_dbh_class_bounds(reader);
    event.rule.method = *method;
  }
  draft.thinning_keys.push_back(key_lines(reader, path));
  draft.scenario.thinning.push_back(std::move(event));
}

}  // namespace

void parse_thinning(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems) {
  for_each_table_of_array(node, "thinning", problems,
                          [&](const toml::table& table, const std::string& path) {
                            parse_thinning_event(table, path, draft, problems);
                          });
}

}  // namespace heliostand::scenario_detail
