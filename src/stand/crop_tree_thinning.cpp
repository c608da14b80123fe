#include "stand/crop_tree_thinning.hpp"

#include <algorithm>

#include "stand/hegyi_index.hpp"

namespace heliostand {
namespace {

std::vector<glm::dvec2> positions_of(const std::vector<ThinningCandidate>& living) {
  std::vector<glm::dvec2> positions;
  for (const auto& tree : living) positions.push_back({tree.x_m, tree.y_m});
  return positions;
}

std::vector<std::size_t> by_vigour(const std::vector<ThinningCandidate>& living) {
  std::vector<std::size_t> order(living.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (living[a].dbh_cm != living[b].dbh_cm) return living[a].dbh_cm > living[b].dbh_cm;
    return living[a].hegyi_index < living[b].hegyi_index;
  });
  return order;
}

std::vector<std::size_t> spaced_crop_trees(const CropTreeSettings& settings, const std::vector<ThinningCandidate>& living,
                                           const ThinningPlot& plot, const Neighbourhood& stems) {
  const auto wanted = static_cast<std::size_t>(
      std::max(0, trees_kept_for_stem_target(settings.crop_trees_per_ha, plot.area_ha)));
  std::vector<std::size_t> crop_trees;
  for (std::size_t candidate : by_vigour(living)) {
    if (crop_trees.size() >= wanted) break;
    const bool spaced = std::all_of(crop_trees.begin(), crop_trees.end(), [&](std::size_t crop_tree) {
      return stems.distance(candidate, crop_tree) >= settings.spacing_m;
    });
    if (spaced) crop_trees.push_back(candidate);
  }
  return crop_trees;
}

// The removable competitors of one crop tree, strongest first (ties: nearer, then survey order).
std::vector<Neighbour> competitors_of(std::size_t crop_tree, const ThinningRule& rule,
                                      const std::vector<ThinningCandidate>& living, const Neighbourhood& stems,
                                      const std::vector<bool>& is_crop_tree) {
  std::vector<Neighbour> competitors;
  for (const Neighbour& j : stems.within(crop_tree, rule.crop_trees.competitor_radius_m))
    if (!is_crop_tree[j.stem] && !living[j.stem].is_protected) competitors.push_back(j);
  const double crop_dbh = living[crop_tree].dbh_cm;
  auto strength = [&](const Neighbour& j) { return hegyi_term(crop_dbh, living[j.stem].dbh_cm, j.distance_m); };
  std::stable_sort(competitors.begin(), competitors.end(), [&](const Neighbour& a, const Neighbour& b) {
    if (strength(a) != strength(b)) return strength(a) > strength(b);
    return a.distance_m < b.distance_m;
  });
  if (rule.crop_trees.competitors_per_crop_tree)
    competitors.resize(std::min(competitors.size(), static_cast<std::size_t>(*rule.crop_trees.competitors_per_crop_tree)));
  return competitors;
}

}  // namespace

std::vector<std::size_t> select_crop_trees(const CropTreeSettings& settings,
                                           const std::vector<ThinningCandidate>& living, const ThinningPlot& plot) {
  const auto positions = positions_of(living);
  const Neighbourhood stems(positions, plot.edges);
  return spaced_crop_trees(settings, living, plot, stems);
}

std::vector<std::size_t> select_crop_tree_competitors(const ThinningRule& rule,
                                                      const std::vector<ThinningCandidate>& living,
                                                      const ThinningPlot& plot) {
  const auto positions = positions_of(living);
  const Neighbourhood stems(positions, plot.edges);
  std::vector<bool> is_crop_tree(living.size(), false), removed(living.size(), false);
  const auto crop_trees = spaced_crop_trees(rule.crop_trees, living, plot, stems);
  for (std::size_t crop_tree : crop_trees) is_crop_tree[crop_tree] = true;
  std::vector<std::size_t> chosen;
  for (std::size_t crop_tree : crop_trees)
    for (const Neighbour& competitor : competitors_of(crop_tree, rule, living, stems, is_crop_tree))
      if (!removed[competitor.stem]) {
        removed[competitor.stem] = true;
        chosen.push_back(competitor.stem);
      }
  return chosen;
}

}  // namespace heliostand
