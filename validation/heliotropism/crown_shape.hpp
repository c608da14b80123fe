#pragma once
// Measures of a seed-000 crown that the paper's findings name and architecture/crown_metrics does not: whether the
// leaf balls form one crown, whether drooping boughs turn their tips up, and how evenly the tips cover the ground
// in top view once their number is accounted for (validation/heliotropism, docs/model.md "Table of findings").
#include <vector>

#include "architecture/crown_metrics.hpp"

namespace heliostand {

struct CrownShape {
  // Fraction of the tips in the largest group whose tips are chained by gaps narrower than 4R (single linkage): 1
  // for one crown. Not 2R (touching leaf balls): light pruning keeps the tips in sibling clusters and leaves
  // holes between them up to the 4R scale at which crowding and holes are measured (crown_metrics.hpp), so even
  // the Table 1 tree splits at 2R; a gap wider than 4R is a gap between crowns.
  double connected = 0;
  // Drooping tips (below their bough's base) whose own branch points above the horizontal, as a fraction of the
  // drooping tips (0 when none droops): the weeping boughs of Fig. 10 that turn their tips up.
  double tip_up = 0;
  double drooping = 0;  // fraction of all tips below their bough's base (as CrownMetrics::drooping)
  // Top view: Clark & Evans (1954) aggregation index, mean nearest-neighbour distance over the 0.5 / sqrt(density)
  // expected of a random pattern of the same density inside the tips' convex hull: 1 random, < 1 clumped,
  // > 1 even. Independent of the number of tips, unlike crowding.
  double evenness = 0;
  // The crown outline without the bare stem: width (mean of the x and y extents) over crown depth (highest −
  // lowest tip).
  double width_over_depth = 0;
};

CrownShape measure_crown_shape(const std::vector<CrownTip>& tips, double leaf_ball_radius);
CrownShape mean_of(const std::vector<CrownShape>& all);

// Area of the convex hull of the tips in top view (x, y).
double top_view_hull_area(const std::vector<CrownTip>& tips);

}  // namespace heliostand
