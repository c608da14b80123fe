#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <set>

#include "scenario/scenario_tables.hpp"
#include "scenario/toml_table_reader.hpp"

namespace heliostand::scenario_detail {

namespace {

std::optional<ThinningMethod> method_named(std::string_view name) {
  for (auto method : {ThinningMethod::ids, ThinningMethod::from_below, ThinningMethod::from_above}) {
    if (thinning_method_name(method) == name) return method;
  }
  return std::nullopt;
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

void check_age(TomlTableReader& reader, const ScenarioDraft& draft, int age) {
  if (!draft.age_valid) return;
  const int survey_age = draft.scenario.stand.age_at_survey_years;
  if (age < survey_age) {
    reader.problem("age", fmt::format("thinning at age {} is before the survey (stand age {})", age, survey_age));
  } else if (draft.years_valid && age > survey_age + draft.scenario.run.years) {
    reader.problem("age", fmt::format("thinning at age {} is after the end of the run (stand age {})", age,
                                      survey_age + draft.scenario.run.years));
  }
}

void parse_event(const toml::table& table, const std::string& path, ScenarioDraft& draft, ScenarioProblems& problems) {
  TomlTableReader reader(table, path, problems);
  ThinningEvent event;
  event.line = reader.line();
  ScenarioDraft::ThinningKeys keys{path, 0, 0};

  const auto age = reader.integer("age", at_least(1), true);
  if (age) {
    event.age_years = static_cast<int>(*age);
    check_age(reader, draft, event.age_years);
  }
  std::optional<ThinningMethod> method;
  if (auto name = reader.string("method", true)) {
    method = method_named(*name);
    if (!method) reader.problem("method", fmt::format("expected \"ids\", \"from_below\" or \"from_above\", got \"{}\"", *name));
  }
  event.ids = read_ids(reader);
  keys.ids_line = reader.line_of("ids");
  event.target_stems_per_ha = reader.number("target_stems_per_ha", positive());
  event.target_basal_area_m2_per_ha = reader.number("target_basal_area_m2_per_ha", positive());
  const bool has_ids = reader.table().contains("ids");
  const bool has_stems = reader.table().contains("target_stems_per_ha");
  const bool has_basal_area = reader.table().contains("target_basal_area_m2_per_ha");
  keys.target_line = reader.line_of(has_stems ? "target_stems_per_ha" : "target_basal_area_m2_per_ha");
  if (auto reason = reader.string("reason")) event.reason = *reason;
  if (auto protect = reader.boolean("protect_habitat_trees")) event.protect_habitat_trees = *protect;
  reader.report_unknown_keys();

  if (method == ThinningMethod::ids) {
    if (!has_ids) problems.add(reader.line(), reader.key_path("ids"), "required key missing (method \"ids\" names the trees to remove)");
    if (has_stems) reader.problem("target_stems_per_ha", "not used by method \"ids\" (remove the key or change the method)");
    if (has_basal_area) reader.problem("target_basal_area_m2_per_ha", "not used by method \"ids\" (remove the key or change the method)");
  } else if (method) {
    if (has_ids) reader.problem("ids", fmt::format("not used by method \"{}\" (it chooses trees by size)", thinning_method_name(*method)));
    if (has_stems == has_basal_area) {
      problems.add(reader.line(), path,
                   fmt::format("method \"{}\" needs exactly one of target_stems_per_ha and "
                               "target_basal_area_m2_per_ha, got {}",
                               thinning_method_name(*method), has_stems ? "both" : "neither"));
    }
  }
  if (method) event.method = *method;
  draft.scenario.thinning.push_back(std::move(event));
  draft.thinning_keys.push_back(std::move(keys));
}

}  // namespace

void parse_thinning(const toml::node* node, ScenarioDraft& draft, ScenarioProblems& problems) {
  for_each_table_of_array(node, "thinning", problems,
                          [&](const toml::table& table, const std::string& path) { parse_event(table, path, draft, problems); });
}

void check_thinning_against_survey(ScenarioDraft& draft, ScenarioProblems& problems) {
  auto& events = draft.scenario.thinning;
  std::vector<std::size_t> order(events.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return events[a].age_years < events[b].age_years; });

  const Survey& survey = draft.scenario.survey;
  std::set<std::string> surveyed, habitat;
  for (const auto& tree : survey.trees) {
    surveyed.insert(tree.id);
    if (!tree.hollows.empty()) habitat.insert(tree.id);
  }
  std::map<std::string, std::string> removed_by;  // id -> key path of the event removing it
  const double area_ha = draft.scenario.plot_area_ha();
  // The most stems/ha the stand can have at each event: no event adds trees, so the survey density,
  // lowered by each earlier stems target and each earlier removal by id.
  double max_stems_per_ha = static_cast<double>(survey.trees.size()) / area_ha;

  for (std::size_t index : order) {
    const ThinningEvent& event = events[index];
    const auto& keys = draft.thinning_keys[index];
    if (event.method == ThinningMethod::ids) {
      for (const auto& id : event.ids) {
        if (!surveyed.count(id)) {
          problems.add(keys.ids_line, keys.path + ".ids", fmt::format("tree id \"{}\" is not in the survey", id));
        } else if (event.protect_habitat_trees && habitat.count(id)) {
          // Naming a protected tree would silently do nothing: say so, and how to remove it on purpose.
          problems.add(keys.ids_line, keys.path + ".ids",
                       fmt::format("tree id \"{}\" carries a hollow (a habitat tree, protected from thinning); set "
                                   "protect_habitat_trees = false in this thinning to remove it",
                                   id));
        } else if (auto [it, fresh] = removed_by.emplace(id, keys.path); !fresh) {
          problems.add(keys.ids_line, keys.path + ".ids",
                       fmt::format("tree id \"{}\" is already removed by {}", id, it->second));
        } else {
          max_stems_per_ha -= 1.0 / area_ha;
        }
      }
    } else if (event.target_stems_per_ha) {
      const double target = *event.target_stems_per_ha;
      if (target >= max_stems_per_ha - 1e-9) {
        problems.add(keys.target_line, keys.path + ".target_stems_per_ha",
                     fmt::format("target {:g} stems/ha is not below the stand's density at that age (at most {:.1f} "
                                 "stems/ha: {} surveyed trees on {:g} ha, less earlier thinnings)",
                                 target, max_stems_per_ha, survey.trees.size(), area_ha));
      } else {
        max_stems_per_ha = target;
      }
    }
  }
  std::vector<ThinningEvent> sorted;
  for (std::size_t index : order) sorted.push_back(std::move(events[index]));
  events = std::move(sorted);
}

}  // namespace heliostand::scenario_detail
