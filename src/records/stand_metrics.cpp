#include "records/stand_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "geometry/angles.hpp"  // pi

namespace heliostand {
namespace {

void require_positive_area(double plot_area_ha) {
  if (!(plot_area_ha > 0)) throw std::invalid_argument("stand metrics: plot area must be > 0 ha");
}

}  // namespace

double basal_area_m2(double dbh_cm) {
  const double radius_m = dbh_cm / 200.0;
  return pi * radius_m * radius_m;
}

int top_height_tree_count(double plot_area_ha) {
  require_positive_area(plot_area_ha);
  return std::max(1, static_cast<int>(std::lround(100.0 * plot_area_ha)));
}

double top_height_m(std::span<const TreeMeasurement> trees, double plot_area_ha) {
  if (trees.empty()) return undefined_mean;
  std::vector<const TreeMeasurement*> by_dbh;
  for (const TreeMeasurement& tree : trees) by_dbh.push_back(&tree);
  std::stable_sort(by_dbh.begin(), by_dbh.end(),
                   [](const TreeMeasurement* a, const TreeMeasurement* b) { return a->dbh_cm > b->dbh_cm; });
  const std::size_t count =
      std::min(by_dbh.size(), static_cast<std::size_t>(top_height_tree_count(plot_area_ha)));
  double sum = 0;
  for (std::size_t i = 0; i < count; ++i) sum += by_dbh[i]->height_m;
  return sum / static_cast<double>(count);
}

StandMetrics measure_stand(std::span<const TreeMeasurement> trees, double plot_area_ha) {
  require_positive_area(plot_area_ha);
  StandMetrics m;
  const double n = static_cast<double>(trees.size());
  m.stems_per_ha = n / plot_area_ha;
  double basal_area = 0, dbh_squared = 0, height = 0, basal_area_times_height = 0, volume = 0;
  for (const TreeMeasurement& t : trees) {
    basal_area += basal_area_m2(t.dbh_cm);
    dbh_squared += t.dbh_cm * t.dbh_cm;
    height += t.height_m;
    basal_area_times_height += basal_area_m2(t.dbh_cm) * t.height_m;
    volume += t.volume_m3;
  }
  m.basal_area_m2_per_ha = basal_area / plot_area_ha;
  m.volume_m3_per_ha = volume / plot_area_ha;
  m.qmd_cm = trees.empty() ? undefined_mean : std::sqrt(dbh_squared / n);
  m.mean_height_m = trees.empty() ? undefined_mean : height / n;
  // Trees below breast height have no basal area and no weight: without a stem at 1.3 m, Hg is undefined.
  m.hg_m = basal_area > 0 ? basal_area_times_height / basal_area : undefined_mean;
  m.top_height_m = top_height_m(trees, plot_area_ha);
  return m;
}

}  // namespace heliostand
