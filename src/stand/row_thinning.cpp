#include "stand/row_thinning.hpp"

#include <algorithm>

namespace heliostand {

bool is_thinned_row(const RowSettings& rows, int planting_row) {
  const int from_first = planting_row - (rows.first_row - 1);
  return planting_row >= 0 && from_first >= 0 && from_first % rows.interval == 0;
}

std::vector<std::size_t> select_by_rows(const ThinningRule& rule, const std::vector<ThinningCandidate>& living) {
  std::vector<std::size_t> chosen;
  for (std::size_t i = 0; i < living.size(); ++i)
    if (!living[i].is_protected && is_thinned_row(rule.rows, living[i].planting_row)) chosen.push_back(i);
  // Row by row, as a harvester works them.
  std::stable_sort(chosen.begin(), chosen.end(),
                   [&](std::size_t a, std::size_t b) { return living[a].planting_row < living[b].planting_row; });
  return chosen;
}

}  // namespace heliostand
