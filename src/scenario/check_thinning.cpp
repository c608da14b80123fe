// The [[thinning]] events against the survey: named trees exist and leave once, stem targets fall over time, row
// thinnings find planting rows in the surveyed positions, crop-tree thinnings have at least one crop tree. Then the
// events are sorted by age.
#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <map>
#include <numeric>
#include <set>

#include "geometry/planting_rows.hpp"
#include "scenario/scenario_tables.hpp"

namespace heliostand::scenario_detail {

namespace {

using Keys = ScenarioDraft::ThinningKeys;

// Fixed-age events by age (file order among equal ages), then the triggered ones in file order: when those fire is
// only known while the stand grows.
std::vector<std::size_t> chronological_order(const std::vector<ThinningEvent>& events) {
  std::vector<std::size_t> order(events.size());
  std::iota(order.begin(), order.end(), 0);
  auto age = [&](std::size_t k) {
    return events[k].when.at_fixed_age() ? events[k].when.stand_age : std::numeric_limits<int>::max();
  };
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return age(a) < age(b); });
  return order;
}

void check_rows(const RowSettings& rows, const Keys& keys, const Survey& survey, ScenarioProblems& problems) {
  std::vector<glm::dvec2> positions;
  for (const auto& tree : survey.trees) positions.push_back({tree.x_m, tree.y_m});
  const PlantingRowsFound found = find_planting_rows(positions, rows.azimuth_deg, rows.tolerance_m);
  if (!found.rows) {
    problems.add(keys.method_line, keys.path + ".method",
                 fmt::format("method \"rows\" finds no planting rows in the survey's positions: {}", found.problem));
  } else if (rows.first_row > found.rows->count) {
    problems.add(keys.first_row_line, keys.path + ".first_row",
                 fmt::format("row {} is beyond the last of the survey's {} planting rows (along {:.1f}°)",
                             rows.first_row, found.rows->count, found.rows->azimuth_deg));
  }
}

void check_crop_tree_count(const CropTreeSettings& crop_trees, const Keys& keys, double area_ha,
                           ScenarioProblems& problems) {
  const double wanted = crop_trees.crop_trees_per_ha;
  if (!(wanted > 0) || trees_kept_for_stem_target(wanted, area_ha) >= 1) return;  // a missing key is reported already
  problems.add(keys.crop_trees_line, keys.path + ".crop_trees_per_ha",
               fmt::format("{:g} crop trees/ha on {:g} ha is less than one crop tree (floor of {:.2f})",
                           wanted, area_ha, wanted * area_ha));
}

}  // namespace

void check_thinning_against_survey(ScenarioDraft& draft, ScenarioProblems& problems) {
  auto& events = draft.scenario.thinning;
  const std::vector<std::size_t> order = chronological_order(events);

  const Survey& survey = draft.scenario.survey;
  std::set<std::string> surveyed, habitat;
  for (const auto& tree : survey.trees) {
    surveyed.insert(tree.id);
    if (!tree.hollows.empty()) habitat.insert(tree.id);
  }
  std::map<std::string, std::string> removed_by;  // id -> key path of the event removing it
  const double area_ha = draft.scenario.plot_area_ha();
  // The most stems/ha the stand can have at each fixed-age event: no event adds trees, so the survey density,
  // lowered by each earlier stems target and each earlier removal by id. Triggered events lower nothing here: when
  // they fire is not known yet, and their own stem targets are not checked (one that is met already removes nothing).
  double max_stems_per_ha = static_cast<double>(survey.trees.size()) / area_ha;

  for (std::size_t index : order) {
    const ThinningEvent& event = events[index];
    const ThinningRule& rule = event.rule;
    const auto& keys = draft.thinning_keys[index];
    // Age 0: its "when" was not valid (reported already); nothing is known about when it happens.
    const bool fixed_age = event.when.at_fixed_age() && event.when.stand_age > 0;
    const bool by_size = rule.method == ThinningMethod::from_below || rule.method == ThinningMethod::from_above ||
                         rule.method == ThinningMethod::neutral;
    if (rule.method == ThinningMethod::ids) {
      for (const auto& id : rule.ids) {
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
        } else if (fixed_age) {
          max_stems_per_ha -= 1.0 / area_ha;
        }
      }
    } else if (rule.target_stems_per_ha && fixed_age && by_size) {
      const double target = *rule.target_stems_per_ha;
      if (target >= max_stems_per_ha - 1e-9) {
        problems.add(keys.target_line, keys.path + ".target_stems_per_ha",
                     fmt::format("target {:g} stems/ha is not below the stand's density at that age (at most {:.1f} "
                                 "stems/ha: {} surveyed trees on {:g} ha, less earlier thinnings)",
                                 target, max_stems_per_ha, survey.trees.size(), area_ha));
      } else {
        max_stems_per_ha = target;
      }
    }
    if (rule.method == ThinningMethod::rows) check_rows(rule.rows, keys, survey, problems);
    if (rule.method == ThinningMethod::crop_tree) check_crop_tree_count(rule.crop_trees, keys, area_ha, problems);
  }
  std::vector<ThinningEvent> sorted;
  for (std::size_t index : order) sorted.push_back(std::move(events[index]));
  events = std::move(sorted);
}

}  // namespace heliostand::scenario_detail
