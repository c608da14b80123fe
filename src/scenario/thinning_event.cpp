#include "scenario/thinning_event.hpp"

#include <cmath>

namespace heliostand {

std::string_view thinning_method_name(ThinningMethod method) {
  switch (method) {
    case ThinningMethod::ids: return "ids";
    case ThinningMethod::from_below: return "from_below";
    case ThinningMethod::from_above: return "from_above";
  }
  return "ids";
}

int trees_kept_for_stem_target(double target_stems_per_ha, double plot_area_ha) {
  return static_cast<int>(std::floor(target_stems_per_ha * plot_area_ha + 1e-9));
}

}  // namespace heliostand
