#pragma once
// A scheduled thinning (scenario [[thinning]]): at a stand age, remove named trees, or the smallest
// ("from below") or largest ("from above") trees by DBH until a stand density target is reached.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace heliostand {

enum class ThinningMethod { ids, from_below, from_above };

std::string_view thinning_method_name(ThinningMethod method);

struct ThinningEvent {
  int age_years = 0;  // stand age at which the trees are removed
  ThinningMethod method = ThinningMethod::ids;
  std::vector<std::string> ids;                      // method ids: survey ids of the trees to remove
  std::optional<double> target_stems_per_ha;         // from_below / from_above: exactly one target
  std::optional<double> target_basal_area_m2_per_ha;
  std::string reason = "thinning";                   // label carried into the removal outputs
  bool protect_habitat_trees = true;                 // trees with hollows are never removed by this event
  int line = 0;                                      // scenario line of the [[thinning]] header
};

// How many trees a stems/ha target leaves on a plot: the largest count whose density does not exceed
// the target, floor(target x area). (A 1e-9 margin keeps e.g. 980 x 0.048 = 47.04 from rounding down
// wrongly when the product is an exact integer in decimal but not in binary.)
int trees_kept_for_stem_target(double target_stems_per_ha, double plot_area_ha);

}  // namespace heliostand
