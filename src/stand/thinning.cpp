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

  // Remove until the stand is at or below the target: stems/ha counts trees, basal area sums their
  // cross-sections. A small epsilon keeps "exactly at target" from removing one tree too many.
  double stems_per_ha = static_cast<double>(living.size()) / plot_area_ha;
  double basal_area_per_ha = 0;
  for (const auto& tree : living) basal_area_per_ha += basal_area_m2(tree.dbh_cm) / plot_area_ha;
  auto above_target = [&] {
    constexpr double epsilon = 1e-9;
    if (rule.target_stems_per_ha) return stems_per_ha > *rule.target_stems_per_ha + epsilon;
    if (rule.target_basal_area_m2_per_ha)
      return basal_area_per_ha > *rule.target_basal_area_m2_per_ha + epsilon;
    return false;
  };

  std::vector<std::size_t> chosen;
  for (std::size_t i : removal_order(rule, living)) {
    if (!above_target()) break;
    chosen.push_back(i);
    stems_per_ha -= 1.0 / plot_area_ha;
    basal_area_per_ha -= basal_area_m2(living[i].dbh_cm) / plot_area_ha;
  }
  return chosen;
}

}  // namespace heliostand
