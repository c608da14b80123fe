#pragma once
// The clumping index of the foliage in each far-field cell (Nilson 1971; Chen & Black 1992): the far field
// treats the balls of a cell as randomly placed (Poisson), so a patch keeps exp(-(1 - t) sigma L) of its light
// across a cell of edge L. Real foliage is clumped: balls overlap in projection and leave gaps, so more light
// gets through. The clumping index Omega = ln P_actual / ln P_random compares the two, where P_actual is the
// cell's mean transmission computed from the shadows of its actual balls (each ball a disc of its radius,
// rasterised on a fine grid of the cell's face, t per ball over a pixel) along the three axes. Multiplying the
// cell's density by Omega gives the random medium that lets through as much light as the real one.
#include <vector>

#include "light/far_field.hpp"
#include "light/occluders.hpp"

namespace heliostand {

// Omega per cell of `grid` (1 where a cell casts no shadow, or t = 1).
std::vector<double> cell_clumping_index(const OccluderSet& occluders, const VoxelGrid& grid, double transmittance);

}  // namespace heliostand
