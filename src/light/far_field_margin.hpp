#pragma once
// The far field's density as the device sweep reads it (cl/far_field.cl): the grid with a margin of cells around
// its x and y sides that hold what a lookup there gives by VoxelGrid's rules. A lookup whose eight columns reach
// past a side then reads two runs of eight floats per corner row like any other, instead of going lane by lane
// with a wrap or clamp per lane: at 10^5 synthetic balls a sixth of the sweep's lookups reached past a side or
// across a row's end, and those took about a quarter of the sweep (docs/performance.md, "The sweep's lookups in
// rows, past the grid's sides").
//
// The margin holds wrapped copies on a periodic grid. On an open grid it holds zeros, which equal VoxelGrid's
// rules (clamped to the outermost cell within half a cell of a side, 0 beyond it) only where the outermost cells
// are empty; the grid's two cells of margin see to that unless a stand too big for the table's budget got cells
// coarser than that margin (FarField's grid_around). Such a grid gets no margin and the lane-by-lane lookups.
#include <span>
#include <vector>

#include "light/celestial_sphere.hpp"
#include "light/far_field.hpp"

namespace heliostand {

// Cells of margin on each side that every lookup of the sweep of `far` toward `patches` lands within; 0 where
// an open grid's outermost cells hold foliage (see above). Capped at sweep_margin_cap.
int sweep_margin_cells(const FarField& far, std::span<const SkyPatch> patches);
inline constexpr int sweep_margin_cap = 64;

// far.density() in float, laid out [z][y + margin][x + margin] with rows of dims.x + 2 margin cells and layers of
// dims.y + 2 margin rows (cl/voxel_grid.clh, grid_at).
std::vector<float> density_with_margin(const FarField& far, int margin);

}  // namespace heliostand
