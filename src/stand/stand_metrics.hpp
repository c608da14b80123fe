#pragma once
// Stand-level forestry metrics of one output year: the rows of stand_table.csv (docs/formats.md).
#include <array>
#include <iterator>
#include <span>
#include <vector>

#include "io/stand_snapshot.hpp"
#include "io/tree_event.hpp"
#include "stand/mortality.hpp"

namespace heliostand {

// What a stand metric needs from one tree.
struct TreeMeasurement {
  double dbh_cm = 0;
  double height_m = 0;
  double volume_m3 = 0;
};

// Metrics of a set of trees on a plot, per hectare. Means are NaN when there is no tree.
struct StandMetrics {
  double stems_per_ha = 0;
  double basal_area_m2_per_ha = 0;  // Σ π (dbh/200)² / area_ha
  double qmd_cm = 0;                // Dg, quadratic mean diameter sqrt(mean dbh²): the tree of mean basal area
  double mean_height_m = 0;         // arithmetic mean height
  double hg_m = 0;                  // Hg, Lorey's height: mean height weighted by basal area, Σ g h / Σ g
  double top_height_m = 0;          // mean height of the 100 largest-DBH trees per ha
  double volume_m3_per_ha = 0;
};

// Number of trees whose mean height is the top height on a plot of `plot_area_ha`:
// 100 per ha, rounded to the nearest whole tree, at least one.
int top_height_tree_count(double plot_area_ha);

// Mean height of the top_height_tree_count(plot_area_ha) trees of largest DBH (all trees if fewer).
// Ties in DBH keep the input order. NaN when there is no tree.
double top_height_m(std::span<const TreeMeasurement> trees, double plot_area_ha);

StandMetrics measure_stand(std::span<const TreeMeasurement> trees, double plot_area_ha);

// One row of stand_table.csv.
struct StandTableRow {
  int stand_age = 0;
  int year_index = 0;
  StandMetrics living;                       // trees with status alive
  double removed_stems_per_ha = 0;           // removed (thinned) since the previous output row
  double removed_basal_area_m2_per_ha = 0;
  double removed_volume_m3_per_ha = 0;
  double dead_stems_per_ha = 0;              // died since the previous output row, all causes
  double dead_basal_area_m2_per_ha = 0;
  double dead_volume_m3_per_ha = 0;
  // The same per cause of death, in all_death_causes order (stand/mortality.hpp: light, suppression, background).
  struct Losses {
    double stems_per_ha = 0, basal_area_m2_per_ha = 0, volume_m3_per_ha = 0;
  };
  std::array<Losses, std::size(all_death_causes)> dead_by_cause{};
};

// Living metrics from the snapshot's alive trees; removed_* and dead_* from `events_since_last_row`
// (the events of the years since the previous output row, this year included).
StandTableRow stand_table_row(const StandSnapshot& snapshot, double plot_area_m2,
                              std::span<const TreeEvent> events_since_last_row);

}  // namespace heliostand
