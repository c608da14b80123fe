#include "survey/check_hollows.hpp"

#include <fmt/format.h>

#include "hollow/conifer_trunk.hpp"
#include "hollow/hollow_mesh.hpp"

namespace heliostand {
namespace {

// A HollowSpec problem, placed where the hollow was written: a survey cell names the tree by its line
// and the hollow by its number in the cell; a scenario key path already names the hollow.
InputProblem placed(const SurveyRecord& tree, std::size_t index_in_column, const TreeHollow& hollow,
                    const InputProblem& problem) {
  if (hollow.field_kind == "key") {
    return {hollow.file, hollow.line, hollow.field + "." + problem.field,
            fmt::format("tree \"{}\": {}", tree.id, problem.reason), "key"};
  }
  return {hollow.file, hollow.line, hollow.field,
          fmt::format("tree \"{}\", hollow {}: {}: {}", tree.id, index_in_column + 1, problem.field, problem.reason),
          "column"};
}

}  // namespace

std::vector<InputProblem> check_tree_hollows(const SurveyRecord& tree, const SpeciesParameters& species) {
  std::vector<InputProblem> problems;
  if (tree.hollows.empty()) return problems;
  const hollow::TrunkSurface trunk = hollow::conifer_trunk(species, tree.height_m, tree.crown_base_m);
  std::size_t in_column = 0;
  for (std::size_t i = 0; i < tree.hollows.size(); ++i) {
    const TreeHollow& hollow = tree.hollows[i];
    for (const InputProblem& problem : hollow::validate(hollow.spec, trunk))
      problems.push_back(placed(tree, in_column, hollow, problem));
    if (hollow.field_kind == "column") ++in_column;
  }
  return problems;
}

}  // namespace heliostand
