#pragma once
// Choosing the trees a thinning removes. Forestry thinning is stated either as an explicit list of
// trees (a marking list) or as a rule: "from below" takes the smallest stems first (suppressed trees,
// the usual low thinning), "from above" the largest first (crown thinning favouring the rest), until
// the stand is down to a target density (stems/ha) or basal area (m²/ha).
#include <optional>
#include <string>
#include <vector>

#include "scenario/thinning_event.hpp"  // ThinningMethod

namespace heliostand {

struct ThinningRule {
  ThinningMethod method = ThinningMethod::from_below;
  std::vector<std::string> ids;                     // with ThinningMethod::ids: survey labels to remove
  std::optional<double> target_stems_per_ha;        // with from_below / from_above: exactly one target
  std::optional<double> target_basal_area_m2_per_ha;
};

// A living tree as thinning sees it.
struct ThinningCandidate {
  std::string label;
  double dbh_cm = 0;
  bool is_protected = false;  // habitat trees (hollows) are kept when protection is on
};

// Indices (into `living`) of the trees to remove, in removal order. Protected trees are never chosen
// (a rule whose target cannot be met without them removes what it can). Listed ids that are not
// among `living` are ignored here: the scenario check reports them before the run starts.
std::vector<std::size_t> select_for_thinning(const ThinningRule& rule,
                                             const std::vector<ThinningCandidate>& living,
                                             double plot_area_ha);

double basal_area_m2(double dbh_cm);  // cross-section at breast height, π (d/200)²

}  // namespace heliostand
