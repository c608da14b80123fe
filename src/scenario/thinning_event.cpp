#include "scenario/thinning_event.hpp"

#include <cmath>

namespace heliostand {

std::string_view thinning_method_name(ThinningMethod method) {
  switch (method) {
    case ThinningMethod::ids: return "ids";
    case ThinningMethod::from_below: return "from_below";
    case ThinningMethod::from_above: return "from_above";
    case ThinningMethod::neutral: return "neutral";
    case ThinningMethod::crop_tree: return "crop_tree";
    case ThinningMethod::dbh_class: return "dbh_class";
    case ThinningMethod::rows: return "rows";
  }
  return "ids";
}

int trees_kept_for_stem_target(double target_stems_per_ha, double plot_area_ha) {
  return static_cast<int>(std::floor(target_stems_per_ha * plot_area_ha + 1e-9));
}

}  // namespace heliostand
