#pragma once
// Measures of a seed-000 crown from its living tips (the leaf-ball centres), used to compare the figures'
// parameter sweeps (validation/heliotropism) and the stand-scale gap response.
#include <vector>

#include <glm/vec3.hpp>

#include "architecture/dichotomy_tree.hpp"

namespace heliostand {

struct CrownTip {
  glm::dvec3 position{0.0};
  glm::dvec3 direction{0.0, 0.0, 1.0};  // of the tip branch
  double branch_base_z = 0;             // height of its bough's base (crown_tips: the ancestor a few generations back)
};

struct CrownMetrics {
  int tips = 0;
  double width = 0;             // mean of the x and y extents of the tips
  double height = 0;            // top tip − lowest tip
  double top = 0, bottom = 0;   // highest and lowest tip
  double drooping = 0;          // fraction of tips below their bough's base (weeping branches)
  double downward = 0;          // fraction of tips whose branch points below the horizontal
  double nearest_neighbour = 0; // mean distance to the nearest other tip in top view (x, y)
  double roundness_cv = 0;      // coefficient of variation of the tip distances from their centroid
  double quadrat_cv = 0;        // top view: coefficient of variation of tip counts in square cells (crowding and
                                // holes); the cells cover the tips' bounding box
  double crowding = 0;          // top view: mean number of other tips within the crowding radius
  double min_x = 0, max_x = 0;  // extent along x (gap side)
};

// Defaults suit R = 2: light pruning controls density beyond the leaf-ball radius (balls closer than R do not
// shade, kanamaru_growth.hpp), so crowding is counted within 2R and quadrats are 4R wide.
CrownMetrics measure_crown(const std::vector<CrownTip>& tips, double quadrat_size = 8.0, double crowding_radius = 4.0);

// The living tips of a dichotomy tree, optionally of one group only (-1: all). A tip's bough starts at its
// ancestor `bough_generations` back (or at the first fork, if the tip is younger than that).
std::vector<CrownTip> crown_tips(const DichotomyTree& tree, int group = -1, int bough_generations = 10);

}  // namespace heliostand
