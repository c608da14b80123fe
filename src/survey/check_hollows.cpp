#include "survey/check_hollows.hpp"

#include <fmt/format.h>

#include <charconv>

#include "hollow/conifer_trunk.hpp"
#include "hollow/hollow_mesh.hpp"

namespace heliostand {
namespace {

// validate_hollows() names fields "hollows[i].width_m": split that into the index and the field.
std::pair<std::size_t, std::string> hollow_and_field(const std::string& field) {
  const auto open = field.find('[');
  const auto close = field.find("].");
  std::size_t index = 0;
  if (open == std::string::npos || close == std::string::npos) return {0, field};
  std::from_chars(field.data() + open + 1, field.data() + close, index);
  return {index, field.substr(close + 2)};
}

// The number of hollow `index` among the tree's hollows written in the survey cell (1-based).
std::size_t number_in_cell(const SurveyRecord& tree, std::size_t index) {
  std::size_t number = 0;
  for (std::size_t i = 0; i <= index; ++i) number += tree.hollows[i].field_kind == "column";
  return number;
}

// A problem of hollow `index`, placed where that hollow was written: a survey cell names the tree by its line
// and the hollow by its number in the cell; a scenario key path already names the hollow.
InputProblem placed(const SurveyRecord& tree, std::size_t index, const std::string& field, const std::string& reason) {
  const TreeHollow& hollow = tree.hollows[index];
  if (hollow.field_kind == "key")
    return {hollow.file, hollow.line, hollow.field + "." + field, fmt::format("tree \"{}\": {}", tree.id, reason), "key"};
  return {hollow.file, hollow.line, hollow.field,
          fmt::format("tree \"{}\", hollow {}: {}: {}", tree.id, number_in_cell(tree, index), field, reason), "column"};
}

// Another hollow named in a reason ("hollows[2]") is named as the user wrote it.
std::string with_user_names(const SurveyRecord& tree, std::string reason) {
  for (std::size_t i = 0; i < tree.hollows.size(); ++i) {
    const std::string internal = fmt::format("hollows[{}]", i);
    const TreeHollow& other = tree.hollows[i];
    const std::string name = other.field_kind == "key"
                                 ? other.field
                                 : fmt::format("hollow {} of column '{}'", number_in_cell(tree, i), other.field);
    for (auto at = reason.find(internal); at != std::string::npos; at = reason.find(internal, at + name.size()))
      reason.replace(at, internal.size(), name);
  }
  return reason;
}

}  // namespace

std::vector<InputProblem> check_tree_hollows(const SurveyRecord& tree, const SpeciesParameters& species) {
  std::vector<InputProblem> problems;
  if (tree.hollows.empty()) return problems;
  const hollow::TrunkSurface trunk = hollow::conifer_trunk(species, tree.height_m, tree.crown_base_m);
  std::vector<hollow::HollowSpec> specs;
  for (const auto& hollow : tree.hollows) specs.push_back(hollow.spec);
  for (const InputProblem& problem : hollow::validate_hollows(specs, trunk)) {
    const auto [index, field] = hollow_and_field(problem.field);
    if (index < tree.hollows.size()) problems.push_back(placed(tree, index, field, with_user_names(tree, problem.reason)));
  }
  return problems;
}

}  // namespace heliostand
