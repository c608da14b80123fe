#pragma once
// Thinning by DBH class (method dbh_class): the unprotected trees with dbh_min_cm <= DBH < dbh_max_cm leave —
// all of them, or a fraction f of them (round(f × the class's living stems, protected ones included), as
// many as are unprotected), spread evenly across the class by DBH like a
// neutral thinning (stand/size_thinning.hpp), so that no end of the class is favoured.
#include <cstddef>
#include <vector>

#include "stand/thinning.hpp"

namespace heliostand {

std::vector<std::size_t> select_by_dbh_class(const ThinningRule& rule, const std::vector<ThinningCandidate>& living);

}  // namespace heliostand
