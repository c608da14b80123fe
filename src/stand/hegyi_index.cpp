#include "stand/hegyi_index.hpp"

#include <algorithm>
#include <limits>

namespace heliostand {

double hegyi_term(double subject_dbh_cm, double competitor_dbh_cm, double distance_m) {
  return competitor_dbh_cm / subject_dbh_cm / std::max(distance_m, closest_competitor_m);
}

std::vector<double> hegyi_indices(const Neighbourhood& stems, std::span<const double> dbh_cm, double radius_m) {
  std::vector<double> indices(stems.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < stems.size(); ++i) {
    if (!(dbh_cm[i] > 0)) continue;
    double index = 0;
    for (const Neighbour& j : stems.within(i, radius_m)) index += hegyi_term(dbh_cm[i], dbh_cm[j.stem], j.distance_m);
    indices[i] = index;
  }
  return indices;
}

}  // namespace heliostand
