#pragma once
// The planting rows of a stand, found from its stem positions (for row thinning, stand/row_thinning.hpp).
//
// Method (docs/model.md "Planting rows"):
//   1. Direction. Given (row_azimuth_deg), or found: every stem's vector to its nearest neighbour, folded to a
//      direction in [0°, 180°), averaged on the doubled angle (so 1° and 179° agree). Trees are planted closer
//      within a row than between rows, so the nearest neighbours point along the rows. When the directions do not
//      agree (mean resultant length below 0.5, as in a square planting where half point along the rows and half
//      across), no direction is found and the scenario must give one.
//   2. Rows. Each stem's offset across that direction; sorted, the offsets are cut into bands: a band starts at
//      its smallest offset and takes every offset within `tolerance_m` of it. A found direction is then refined
//      to the common direction of the rows (principal axis of the within-row scatter, pooled over rows) and the
//      bands cut again, twice.
//   3. Check. There is a row structure when there are at least two bands and each is separated from the next by
//      a gap of at least `tolerance_m`; otherwise the stems are not in rows and row thinning is refused.
// Rows are numbered from 0: from the south when they run within 45° of east–west (azimuth counter-clockwise from
// east), else from the west.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

namespace heliostand {

struct PlantingRows {
  double azimuth_deg = 0;   // direction the rows run, counter-clockwise from east (+x), in [0, 180)
  std::vector<int> row_of;  // per position, its row
  int count = 0;
};

struct PlantingRowsFound {
  std::optional<PlantingRows> rows;
  std::string problem;  // why there are none: a sentence for the user
};

PlantingRowsFound find_planting_rows(std::span<const glm::dvec2> positions, std::optional<double> azimuth_deg,
                                     double tolerance_m);

}  // namespace heliostand
