#pragma once
// Hegyi's (1974) distance-dependent competition index: the competition a subject tree i suffers from the
// neighbours j standing closer than a fixed radius R,
//     CI_i = Σ_{j ≠ i, dist_ij < R} (d_j / d_i) / dist_ij      (d = DBH, dist in m; unit 1/m),
// so a big neighbour close by weighs most. Hegyi, F. (1974): A simulation model for managing jack-pine
// stands. In: Fries, J. (ed.), Growth models for tree and stand simulation. Royal College of Forestry,
// Stockholm, Research Notes 30, pp. 74–90. Distances follow the stand's edges (geometry/neighbourhood.hpp).
#include <span>
#include <vector>

#include "geometry/neighbourhood.hpp"

namespace heliostand {

// Two stems closer than this count as this far apart: a survey may put two stems on one spot, and the index
// must stay finite.
constexpr double closest_competitor_m = 0.1;

// One competitor's term (d_j / d_i) / dist. Zero for a competitor without a DBH (shorter than breast height).
double hegyi_term(double subject_dbh_cm, double competitor_dbh_cm, double distance_m);

// CI of every stem of `stems` (dbh_cm in the same order). NaN for a stem without a DBH: it has no index.
std::vector<double> hegyi_indices(const Neighbourhood& stems, std::span<const double> dbh_cm, double radius_m);

}  // namespace heliostand
