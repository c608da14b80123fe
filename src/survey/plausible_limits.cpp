#include "survey/plausible_limits.hpp"

namespace heliostand {

std::optional<PlausibleLimit> plausible_limit(SurveyColumn column) {
  using C = SurveyColumn;
  switch (column) {
    case C::x:
    case C::y: return PlausibleLimit{max_coordinate_m, "coordinates in metres stay below 10,000 km, the range of UTM northings"};
    case C::height:
    case C::crown_base: return PlausibleLimit{max_tree_height_m, "the tallest measured tree, a coast redwood, is 116 m"};
    case C::dbh: return PlausibleLimit{max_dbh_cm, "the thickest measured stems are about 11-12 m across"};
    case C::crown_radius:
      return PlausibleLimit{max_crown_radius_m, "the widest measured crowns are about 60 m across; a crown ratio is named "
                                  "crown_ratio"};
    case C::crown_diameter: return PlausibleLimit{2 * max_crown_radius_m, "the widest measured crowns are about 60 m across"};
    case C::age: return PlausibleLimit{max_tree_age_years, "the oldest known non-clonal tree is about 4,850 years old"};
    case C::crown_ratio:
      return PlausibleLimit{1.0, "a crown ratio is a fraction of the height; name a percent column crown_ratio_pct "
                                 "or set stand.survey_units"};
    default: return std::nullopt;
  }
}

}  // namespace heliostand
