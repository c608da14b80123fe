#include "stand/thinning.hpp"

#include "stand/crop_tree_thinning.hpp"
#include "stand/dbh_class_thinning.hpp"
#include "stand/row_thinning.hpp"
#include "stand/size_thinning.hpp"

namespace heliostand {

namespace {

std::vector<std::size_t> by_marking_list(const ThinningRule& rule, const std::vector<ThinningCandidate>& living) {
  std::vector<std::size_t> chosen;
  for (const auto& id : rule.ids)
    for (std::size_t i = 0; i < living.size(); ++i)
      if (living[i].label == id && !living[i].is_protected) chosen.push_back(i);
  return chosen;
}

}  // namespace

std::vector<std::size_t> select_for_thinning(const ThinningRule& rule, const std::vector<ThinningCandidate>& living,
                                             const ThinningPlot& plot) {
  switch (rule.method) {
    case ThinningMethod::ids: return by_marking_list(rule, living);
    case ThinningMethod::from_below:
    case ThinningMethod::from_above:
    case ThinningMethod::neutral: return select_by_size(rule, living, plot.area_ha);
    case ThinningMethod::crop_tree: return select_crop_tree_competitors(rule, living, plot);
    case ThinningMethod::dbh_class: return select_by_dbh_class(rule, living);
    case ThinningMethod::rows: return select_by_rows(rule, living);
  }
  return {};
}

std::vector<std::size_t> select_for_thinning(const ThinningRule& rule, const std::vector<ThinningCandidate>& living,
                                             double plot_area_ha) {
  return select_for_thinning(rule, living, ThinningPlot{plot_area_ha, StandEdges{}});
}

}  // namespace heliostand
