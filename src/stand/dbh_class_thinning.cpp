#include "stand/dbh_class_thinning.hpp"

#include <algorithm>
#include <cmath>

#include "stand/size_thinning.hpp"

namespace heliostand {

std::vector<std::size_t> select_by_dbh_class(const ThinningRule& rule, const std::vector<ThinningCandidate>& living) {
  std::vector<std::size_t> in_class;  // the unprotected ones
  std::size_t class_stems = 0;        // protected ones too: they count toward the fraction as toward a density
  for (std::size_t i = 0; i < living.size(); ++i) {
    if (!rule.dbh_class.contains(living[i].dbh_cm)) continue;
    ++class_stems;
    if (!living[i].is_protected) in_class.push_back(i);
  }
  std::stable_sort(in_class.begin(), in_class.end(),
                   [&](std::size_t a, std::size_t b) { return living[a].dbh_cm < living[b].dbh_cm; });
  if (!rule.remove_fraction) return in_class;
  const auto count = static_cast<std::size_t>(std::lround(*rule.remove_fraction * static_cast<double>(class_stems)));
  std::vector<std::size_t> chosen;
  for (std::size_t rank : neutral_ranks(count, in_class.size())) chosen.push_back(in_class[rank]);
  return chosen;
}

}  // namespace heliostand
