#include "survey/check_hollows.hpp"

#include <fmt/format.h>

#include "architecture/stem_taper.hpp"
#include "hollow/conifer_trunk.hpp"
#include "hollow/hollow_mesh.hpp"

namespace heliostand {
namespace {

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

// How the user wrote hollow `index`: its scenario key path, or its place in the survey cell.
std::string user_name(const SurveyRecord& tree, std::size_t index) {
  const TreeHollow& hollow = tree.hollows[index];
  if (hollow.field_kind == "key") return hollow.field;
  return fmt::format("hollow {} of column '{}'", number_in_cell(tree, index), hollow.field);
}

}  // namespace

std::vector<InputProblem> check_tree_hollows(const SurveyRecord& tree, const SpeciesParameters& species) {
  std::vector<InputProblem> problems;
  if (tree.hollows.empty()) return problems;
  // The stem as the stand will start it: the species' taper scaled to the record's DBH (ConiferTree::stem_scale).
  const double taper_dbh = StemTaper{tree.height_m, tree.crown_base_m}.dbh_cm(species);
  const double scale = tree.dbh_cm > 0.0 && taper_dbh > 0.0 ? tree.dbh_cm / taper_dbh : 1.0;
  const hollow::TrunkSurface trunk = hollow::conifer_trunk(species, tree.height_m, tree.crown_base_m, scale);
  std::vector<hollow::HollowSpec> specs;
  for (const auto& hollow : tree.hollows) specs.push_back(hollow.spec);
  const auto name_of = [&](std::size_t index) { return user_name(tree, index); };
  for (const auto& [index, problem] : hollow::hollow_problems(specs, trunk, name_of))
    problems.push_back(placed(tree, index, problem.field, problem.reason));
  return problems;
}

}  // namespace heliostand
