#pragma once
// A thinning of the scenario ([[thinning]]): when it happens (a stand age, or a stand condition such as "basal
// area above 40 m²/ha", optionally repeating) and which trees it removes (a marking list or a regime: from
// below, from above, neutral, crop trees and their competitors, a DBH class, every k-th planted row).
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scenario/competition_settings.hpp"

namespace heliostand {

enum class ThinningMethod { ids, from_below, from_above, neutral, crop_tree, dbh_class, rows };

constexpr ThinningMethod all_thinning_methods[] = {
    ThinningMethod::ids,       ThinningMethod::from_below, ThinningMethod::from_above, ThinningMethod::neutral,
    ThinningMethod::crop_tree, ThinningMethod::dbh_class,  ThinningMethod::rows};

std::string_view thinning_method_name(ThinningMethod method);

// A state of the living stand that fires a thinning instead of a fixed age: basal area above a threshold
// (when_basal_area_exceeds_m2_per_ha) or top height at or above one (when_top_height_reaches_m).
struct StandCondition {
  enum class Measure { basal_area_m2_per_ha, top_height_m };
  Measure measure = Measure::basal_area_m2_per_ha;
  double threshold = 0;

  bool holds(double value) const {
    return measure == Measure::basal_area_m2_per_ha ? value > threshold : value >= threshold;
  }
};

// Crop-tree thinning (method "crop_tree"): the most vigorous trees (largest DBH) at least `spacing_m` apart become
// crop trees, and each one is released from its strongest competitors (largest Hegyi term d_j / (d_i · dist)).
struct CropTreeSettings {
  double crop_trees_per_ha = 0;
  double spacing_m = 0;                          // least distance between two crop trees
  double competitor_radius_m = default_competition_radius_m;  // competitors stand closer than this to their crop tree
  std::optional<int> competitors_per_crop_tree;  // the strongest n; every competitor in the radius when absent
};

// Thinning by DBH class (method "dbh_class"): trees with min_cm <= DBH < max_cm.
struct DbhClass {
  double min_cm = 0;
  double max_cm = std::numeric_limits<double>::infinity();
  bool contains(double dbh_cm) const { return dbh_cm >= min_cm && dbh_cm < max_cm; }
};

// Row thinning (method "rows"): every `interval`-th planted row from row `first_row` (1-based), the rows found
// from the planting positions (geometry/planting_rows.hpp).
struct RowSettings {
  int interval = 2;
  int first_row = 1;
  std::optional<double> azimuth_deg;  // direction the rows run; found from the positions when absent
  double tolerance_m = 1.0;           // a row is a band at most this wide across its direction
};

// Which trees a thinning removes: the method and its parameters (stand/thinning.hpp chooses them).
struct ThinningRule {
  ThinningMethod method = ThinningMethod::from_below;
  std::vector<std::string> ids;                      // method ids: survey ids of the trees to remove
  std::optional<double> target_stems_per_ha;         // from_below / from_above / neutral: exactly one target
  std::optional<double> target_basal_area_m2_per_ha;
  std::optional<double> remove_fraction;             // of the living stems (of the class, for dbh_class)
  std::optional<double> remove_basal_area_fraction;  // of the living basal area
  CropTreeSettings crop_trees;
  DbhClass dbh_class;
  RowSettings rows;
};

// When a thinning happens: a fixed stand age, or a condition of the living stand checked every year (then
// stand_age is 0), optionally repeating (stand/thinning_trigger.hpp decides, year by year).
struct ThinningTrigger {
  int stand_age = 0;  // happens at the end of the year in which the stand reaches this age
  std::optional<StandCondition> condition;
  std::optional<int> repeat_every_years;  // fires again at the earliest this many years after it fired

  bool at_fixed_age() const { return !condition; }
};

// One [[thinning]] as the stand applies it (stand/stand.hpp), in the scenario's order.
struct ThinningEvent {
  ThinningTrigger when;
  ThinningRule rule;                   // what: the method and its parameters
  std::string reason = "thinning";     // label carried into the removal outputs, e.g. "first thinning"
  bool protect_habitat_trees = true;   // trees with hollows are never removed by this event
  int line = 0;                        // scenario line of the [[thinning]] header
  int scenario_order = 0;              // 0-based position among the file's [[thinning]] tables
};

// How many trees a stems/ha target leaves on a plot: the largest count whose density does not exceed
// the target, floor(target x area). (A 1e-9 margin keeps e.g. 980 x 0.048 = 47.04 from rounding down
// wrongly when the product is an exact integer in decimal but not in binary.)
int trees_kept_for_stem_target(double target_stems_per_ha, double plot_area_ha);

}  // namespace heliostand
