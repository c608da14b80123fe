#pragma once
// Choosing the trees a thinning removes. Forestry thinning is stated either as an explicit list of trees (a
// marking list) or as a regime (docs/formats.md [[thinning]]):
//   from_below   the smallest stems first (suppressed trees, the usual low thinning)
//   from_above   the largest first (crown thinning favouring the rest)
//   neutral      evenly across the DBH distribution, which keeps its shape
//     ... each to a target density (stems/ha), basal area (m²/ha), or a fraction of either;
//   crop_tree    the strongest competitors of chosen crop trees (stand/crop_tree_thinning.hpp)
//   dbh_class    all or a fraction of the trees of a DBH class
//   rows         every k-th planted row (geometry/planting_rows.hpp)
// Each regime is a pure function of the living trees (one file each); this is the dispatch.
#include <optional>
#include <string>
#include <vector>

#include "geometry/neighbourhood.hpp"     // StandEdges
#include "records/stand_metrics.hpp"       // basal_area_m2, which the targets are stated in
#include "scenario/thinning_event.hpp"  // ThinningRule: the method and the regimes' settings

namespace heliostand {

// A living tree as thinning sees it.
struct ThinningCandidate {
  std::string label;
  double dbh_cm = 0;
  bool is_protected = false;  // habitat trees (hollows) are kept when protection is on
  double height_m = 0;
  double x_m = 0, y_m = 0;    // stem base
  double hegyi_index = 0;     // competition it suffers (stand/hegyi_index.hpp), 1/m
  int planting_row = -1;      // 0-based planting row (geometry/planting_rows.hpp); -1 when not known
};

// The plot the candidates stand on.
struct ThinningPlot {
  double area_ha = 0;
  StandEdges edges;  // for distances between trees (crop-tree thinning)
};

// Indices (into `living`) of the trees to remove, in removal order. Protected trees are never chosen
// (a rule whose target cannot be met without them removes what it can). Listed ids that are not
// among `living` are ignored here: the scenario check reports them before the run starts.
std::vector<std::size_t> select_for_thinning(const ThinningRule& rule, const std::vector<ThinningCandidate>& living,
                                             const ThinningPlot& plot);
// The same on a plot whose edges do not matter to the rule (every rule but crop_tree).
std::vector<std::size_t> select_for_thinning(const ThinningRule& rule, const std::vector<ThinningCandidate>& living,
                                             double plot_area_ha);

}  // namespace heliostand
