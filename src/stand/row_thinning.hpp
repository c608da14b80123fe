#pragma once
// Row thinning (method rows): every row_interval-th planted row leaves, starting at first_row (rows numbered from 1
// as geometry/planting_rows.hpp orders them): with interval 3 and first row 2, rows 2, 5, 8, … go. Every unprotected
// living tree of those rows is removed; a tree whose row is not known stays.
#include <cstddef>
#include <vector>

#include "stand/thinning.hpp"

namespace heliostand {

bool is_thinned_row(const RowSettings& rows, int planting_row);  // planting_row 0-based

std::vector<std::size_t> select_by_rows(const ThinningRule& rule, const std::vector<ThinningCandidate>& living);

}  // namespace heliostand
