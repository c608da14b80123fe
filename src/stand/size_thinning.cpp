#include "stand/size_thinning.hpp"

#include <algorithm>
#include <cmath>

namespace heliostand {
namespace {

constexpr double epsilon = 1e-9;  // "exactly at target" must not remove one tree too many

double basal_area_per_ha(const std::vector<ThinningCandidate>& trees, double plot_area_ha) {
  double sum = 0;
  for (const auto& tree : trees) sum += basal_area_m2(tree.dbh_cm) / plot_area_ha;
  return sum;
}

// Unprotected trees, largest DBH first for from_above, else smallest first. Ties keep the survey order so the
// choice is deterministic.
std::vector<std::size_t> removal_order(ThinningMethod method, const std::vector<ThinningCandidate>& living) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < living.size(); ++i)
    if (!living[i].is_protected) order.push_back(i);
  const bool largest_first = method == ThinningMethod::from_above;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return largest_first ? living[a].dbh_cm > living[b].dbh_cm : living[a].dbh_cm < living[b].dbh_cm;
  });
  return order;
}

bool has_stem_target(const ThinningRule& rule) { return rule.target_stems_per_ha || rule.remove_fraction; }

std::size_t stems_to_remove(const ThinningRule& rule, std::size_t living, double plot_area_ha) {
  if (rule.target_stems_per_ha) {
    const auto keep = static_cast<std::size_t>(
        std::max(0, trees_kept_for_stem_target(*rule.target_stems_per_ha, plot_area_ha)));
    return living > keep ? living - keep : 0;
  }
  return static_cast<std::size_t>(std::lround(*rule.remove_fraction * static_cast<double>(living)));
}

double basal_area_to_keep(const ThinningRule& rule, double living_basal_area) {
  if (rule.target_basal_area_m2_per_ha) return *rule.target_basal_area_m2_per_ha;
  return (1.0 - *rule.remove_basal_area_fraction) * living_basal_area;
}

std::vector<std::size_t> at_ranks(const std::vector<std::size_t>& order, const std::vector<std::size_t>& ranks) {
  std::vector<std::size_t> chosen;
  for (std::size_t rank : ranks) chosen.push_back(order[rank]);
  return chosen;
}

// Down the removal order until the stand's basal area is at most `keep`.
std::vector<std::size_t> until_basal_area(const std::vector<std::size_t>& order,
                                          const std::vector<ThinningCandidate>& living, double plot_area_ha,
                                          double basal_area, double keep) {
  std::vector<std::size_t> chosen;
  for (std::size_t i : order) {
    if (basal_area <= keep + epsilon) break;
    chosen.push_back(i);
    basal_area -= basal_area_m2(living[i].dbh_cm) / plot_area_ha;
  }
  return chosen;
}

// The fewest evenly spread trees that bring the basal area down to `keep` (all of them if none do).
std::vector<std::size_t> neutral_to_basal_area(const std::vector<std::size_t>& order,
                                               const std::vector<ThinningCandidate>& living, double plot_area_ha,
                                               double basal_area, double keep) {
  if (basal_area <= keep + epsilon) return {};
  for (std::size_t count = 1; count <= order.size(); ++count) {
    const auto chosen = at_ranks(order, neutral_ranks(count, order.size()));
    double left = basal_area;
    for (std::size_t i : chosen) left -= basal_area_m2(living[i].dbh_cm) / plot_area_ha;
    if (left <= keep + epsilon) return chosen;
  }
  return order;
}

}  // namespace

std::vector<std::size_t> neutral_ranks(std::size_t count, std::size_t out_of) {
  count = std::min(count, out_of);
  std::vector<std::size_t> ranks;
  for (std::size_t i = 0; i < count; ++i)
    ranks.push_back(static_cast<std::size_t>(std::floor((static_cast<double>(i) + 0.5) * static_cast<double>(out_of) /
                                                        static_cast<double>(count))));
  return ranks;
}

std::vector<std::size_t> select_by_size(const ThinningRule& rule, const std::vector<ThinningCandidate>& living,
                                        double plot_area_ha) {
  const auto order = removal_order(rule.method, living);
  const bool neutral = rule.method == ThinningMethod::neutral;
  if (has_stem_target(rule)) {
    const std::size_t count = std::min(stems_to_remove(rule, living.size(), plot_area_ha), order.size());
    if (neutral) return at_ranks(order, neutral_ranks(count, order.size()));
    return {order.begin(), order.begin() + static_cast<std::ptrdiff_t>(count)};
  }
  if (!rule.target_basal_area_m2_per_ha && !rule.remove_basal_area_fraction) return {};
  const double basal_area = basal_area_per_ha(living, plot_area_ha);
  const double keep = basal_area_to_keep(rule, basal_area);
  if (neutral) return neutral_to_basal_area(order, living, plot_area_ha, basal_area, keep);
  return until_basal_area(order, living, plot_area_ha, basal_area, keep);
}

}  // namespace heliostand
