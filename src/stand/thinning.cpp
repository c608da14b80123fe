#include "stand/thinning.hpp"

#include <algorithm>
#include <numeric>

#include "geometry/angles.hpp"

namespace heliostand {

double basal_area_m2(double dbh_cm) {
  const double radius_m = dbh_cm / 200.0;
  return pi * radius_m * radius_m;
}

namespace {

std::vector<std::size_t> by_marking_list(const ThinningRule& rule,
                                         const std::vector<ThinningCandidate>& living) {
  std::vector<std::size_t> chosen;
  for (const auto& id : rule.ids)
    for (std::size_t i = 0; i < living.size(); ++i)
      if (living[i].label == id && !living[i].is_protected) chosen.push_back(i);
  return chosen;
}

// Unprotected trees, smallest DBH first (from below) or largest first (from above). Ties keep the
// survey order so the choice is deterministic.
std::vector<std::size_t> removal_order(const ThinningRule& rule,
                                       const std::vector<ThinningCandidate>& living) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < living.size(); ++i)
    if (!living[i].is_protected) order.push_back(i);
  const bool smallest_first = rule.method == ThinningMethod::from_below;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return smallest_first ? living[a].dbh_cm < living[b].dbh_cm : living[a].dbh_cm > living[b].dbh_cm;
  });
  return order;
}

}  // namespace

std::vector<std::size_t> select_for_thinning(const ThinningRule& rule,
                                             const std::vector<ThinningCandidate>& living,
                                             double plot_area_ha) {
  if (rule.method == ThinningMethod::ids) return by_marking_list(rule, living);

  // A stems/ha target keeps floor(target × area) trees (the scenario check uses the same rule); a basal-area
  // target removes until the remaining cross-sections sum to at most the target.
  const auto order = removal_order(rule, living);
  std::vector<std::size_t> chosen;
  if (rule.target_stems_per_ha) {
    const auto keep = static_cast<std::size_t>(
        std::max(0, trees_kept_for_stem_target(*rule.target_stems_per_ha, plot_area_ha)));
    for (std::size_t k = 0; k < order.size() && living.size() - chosen.size() > keep; ++k)
      chosen.push_back(order[k]);
  } else if (rule.target_basal_area_m2_per_ha) {
    double basal_area_per_ha = 0;
    for (const auto& tree : living) basal_area_per_ha += basal_area_m2(tree.dbh_cm) / plot_area_ha;
    constexpr double epsilon = 1e-9;  // "exactly at target" must not remove one tree too many
    for (std::size_t i : order) {
      if (basal_area_per_ha <= *rule.target_basal_area_m2_per_ha + epsilon) break;
      chosen.push_back(i);
      basal_area_per_ha -= basal_area_m2(living[i].dbh_cm) / plot_area_ha;
    }
  }
  return chosen;
}

}  // namespace heliostand
