#include "survey/multi_stem.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace heliostand {

namespace {
// Union-find over record indices, so chains of close stems form one group.
struct Groups {
  std::vector<std::size_t> parent;
  explicit Groups(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t{0}); }
  std::size_t root(std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(std::size_t a, std::size_t b) { parent[root(a)] = root(b); }
};
}  // namespace

std::vector<std::vector<std::size_t>> stems_sharing_a_position(const std::vector<SurveyRecord>& trees) {
  std::vector<std::size_t> by_x(trees.size());
  std::iota(by_x.begin(), by_x.end(), std::size_t{0});
  std::sort(by_x.begin(), by_x.end(), [&](std::size_t a, std::size_t b) { return trees[a].x_m < trees[b].x_m; });
  Groups groups(trees.size());
  for (std::size_t i = 0; i < by_x.size(); ++i)
    for (std::size_t j = i + 1; j < by_x.size() && trees[by_x[j]].x_m - trees[by_x[i]].x_m <= same_position_tolerance_m;
         ++j)
      if (std::hypot(trees[by_x[j]].x_m - trees[by_x[i]].x_m, trees[by_x[j]].y_m - trees[by_x[i]].y_m) <=
          same_position_tolerance_m)
        groups.join(by_x[i], by_x[j]);
  std::vector<std::vector<std::size_t>> members(trees.size());
  for (std::size_t i = 0; i < trees.size(); ++i) members[groups.root(i)].push_back(i);
  std::vector<std::vector<std::size_t>> shared;
  for (auto& group : members)
    if (group.size() > 1) {
      std::sort(group.begin(), group.end(), [&](std::size_t a, std::size_t b) { return trees[a].line < trees[b].line; });
      shared.push_back(std::move(group));
    }
  std::sort(shared.begin(), shared.end(),
            [&](const auto& a, const auto& b) { return trees[a.front()].line < trees[b.front()].line; });
  return shared;
}

MergedStems merge_stems(std::span<const SurveyRecord* const> stems) {
  SurveyRecord tree = *stems.front();
  double basal_area = 0.0, crown_area = 0.0;
  for (const SurveyRecord* stem : stems) {
    if (stem->species != tree.species)
      return {std::nullopt, fmt::format("stems of one tree must be of one species: line {} is \"{}\", line {} \"{}\"",
                                        tree.line, tree.species, stem->line, stem->species)};
    basal_area += stem->dbh_cm * stem->dbh_cm;
    crown_area += stem->crown_radius_m * stem->crown_radius_m;
    tree.height_m = std::max(tree.height_m, stem->height_m);
    tree.crown_base_m = std::min(tree.crown_base_m, stem->crown_base_m);
    tree.age_years = std::max(tree.age_years, stem->age_years);
    tree.imputed.height |= stem->imputed.height;
    tree.imputed.dbh |= stem->imputed.dbh;
    tree.imputed.crown_radius |= stem->imputed.crown_radius;
    tree.imputed.crown_base |= stem->imputed.crown_base;
    if (stem != stems.front()) tree.hollows.insert(tree.hollows.end(), stem->hollows.begin(), stem->hollows.end());
  }
  tree.dbh_cm = std::sqrt(basal_area);
  tree.crown_radius_m = std::sqrt(crown_area);
  return {std::move(tree), ""};
}

}  // namespace heliostand
