#pragma once
// A branch axis: the chain of annual shoots one bud lineage has produced (the stem is axis 0). Growth rules
// (elongation, growth stop, droop, fall) act on axes; geometry lives in the shoots.
#include <vector>

namespace heliostand {

struct BranchAxis {
  int id = 0;                  // creation number, stable for the tree's life: tags the axis's random streams
  int order = 0;               // 0 stem, 1 first order, ...
  int parent_axis = -1;        // index in the tree's axis list; -1 for the stem
  int first_order_root = -1;   // the first-order axis it hangs on (itself for first order, -1 on the stem)
  int year_formed = 0;         // tree age in the year of emergence
  double initial_elongation_m = 0;  // eq. 9 (first order) or linear in the parent (lower orders)
  double azimuth_rad = 0;      // first order: direction around the stem (x east = 0, counter-clockwise)
  std::vector<int> shoots;     // indices in the tree's shoot list, base to tip
  bool alive = true;
  int year_stopped = 0;        // tree age in the year growth stopped and the axis died
  double length_at_death_m = 0;  // eq. 13 measures the fallen fraction against this
  int starved_years = 0;       // years in a row its tip's light allowed no elongation (first order, in a stand)
};

}  // namespace heliostand
