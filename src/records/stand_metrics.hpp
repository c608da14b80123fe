#pragma once
// Stand-level forestry metrics of a set of living trees on a plot, per hectare: the living part of a
// stand_table.csv row (docs/formats.md; the rows themselves: records/stand_table_ledger.hpp).
#include <limits>
#include <span>
#include <string>

namespace heliostand {

// Basal area of one stem, m²: its cross-section at breast height, π (d/200)², DBH in cm.
double basal_area_m2(double dbh_cm);

// A mean over no tree, or a rate over no year: NaN, which the tables write as an empty field.
inline constexpr double undefined_mean = std::numeric_limits<double>::quiet_NaN();

// What a stand metric needs from one tree.
struct TreeMeasurement {
  double dbh_cm = 0;
  double height_m = 0;
  double volume_m3 = 0;   // stem volume
  std::string species;    // last, so that {dbh, height, volume} still measures a tree of no particular species
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

}  // namespace heliostand
