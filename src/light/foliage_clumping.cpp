#include "light/foliage_clumping.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/parallel_for.hpp"

namespace heliostand {
namespace {

int slab_of(double coordinate, double origin, double cell, int count, bool wraps) {
  const int i = static_cast<int>(std::floor((coordinate - origin) / cell));
  return wraps ? wrap_cell(i, count) : std::clamp(i, 0, count - 1);
}

// Balls cast their shadow along `axis` onto the face of their own slab of cells; per cell of the slab, adds
// -ln(mean transmission) to `log_gap` and the mean number of shadows over a pixel to `hits`.
void add_shadows_along(int axis, const OccluderSet& occluders, const VoxelGrid& grid, double t, int pixels_per_cell,
                       std::vector<double>& log_gap, std::vector<double>& hits) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const int P = pixels_per_cell;
  const int nu = grid.dims[u] * P, nv = grid.dims[v] * P;
  const double pu = grid.cell[u] / P, pv = grid.cell[v] / P;
  const bool wraps_u = grid.periodic && u < 2, wraps_v = grid.periodic && v < 2;
  std::vector<std::vector<std::uint32_t>> slabs(grid.dims[axis]);
  for (std::size_t k = 0; k < occluders.ball_count; ++k)
    slabs[slab_of(occluders.centres[k][axis], grid.origin[axis], grid.cell[axis], grid.dims[axis],
                  grid.periodic && axis < 2)]
        .push_back(static_cast<std::uint32_t>(k));
  std::vector<double> kept(256);  // t^n
  for (int n = 0; n < 256; ++n) kept[n] = std::pow(t, n);
  // A slab writes only its own cells: blocks of slabs are rasterised on the worker threads, each block on a raster
  // of its own, and every cell gets the same sums as in one loop over the slabs in order. Four blocks a thread,
  // fewer where that many rasters would pass 256 MB.
  const std::size_t slab_count = std::size_t(grid.dims[axis]);
  const std::size_t raster_bytes = std::max<std::size_t>(1, std::size_t(nu) * nv);
  const std::size_t blocks = std::clamp<std::size_t>((std::size_t(256) << 20) / raster_bytes, 1,
                                                     4 * std::size_t(worker_threads()));
  const std::size_t block = (slab_count + blocks - 1) / blocks;
  parallel_for_blocks(slab_count, block, [&](std::size_t first, std::size_t last) {
    std::vector<std::uint8_t> shadows(std::size_t(nu) * nv);
    for (int s = int(first); s < int(last); ++s) {
      if (slabs[s].empty()) continue;
      std::fill(shadows.begin(), shadows.end(), 0);
      for (const auto k : slabs[s]) {
        const double cu = (occluders.centres[k][u] - grid.origin[u]) / pu - 0.5;  // in pixel-centre units
        const double cv = (occluders.centres[k][v] - grid.origin[v]) / pv - 0.5;
        const double r = occluders.radii[k];
        for (int j = static_cast<int>(std::ceil(cv - r / pv)); j <= static_cast<int>(std::floor(cv + r / pv)); ++j)
          for (int i = static_cast<int>(std::ceil(cu - r / pu)); i <= static_cast<int>(std::floor(cu + r / pu)); ++i) {
            const double du = (i - cu) * pu, dv = (j - cv) * pv;
            if (du * du + dv * dv > r * r) continue;
            const int iu = wraps_u ? wrap_cell(i, nu) : i, iv = wraps_v ? wrap_cell(j, nv) : j;
            if (iu < 0 || iu >= nu || iv < 0 || iv >= nv) continue;
            auto& n = shadows[std::size_t(iv) * nu + iu];
            if (n < 255) ++n;
          }
      }
      for (int b = 0; b < grid.dims[v]; ++b)
        for (int a = 0; a < grid.dims[u]; ++a) {
          double gap = 0, count = 0;
          for (int j = b * P; j < (b + 1) * P; ++j)
            for (int i = a * P; i < (a + 1) * P; ++i) {
              const int n = shadows[std::size_t(j) * nu + i];
              gap += kept[n];
              count += n;
            }
          if (count == 0) continue;
          int at[3];
          at[axis] = s, at[u] = a, at[v] = b;
          const std::size_t cell = grid.index(at[0], at[1], at[2]);
          log_gap[cell] -= std::log(gap / (P * P));
          hits[cell] += count / (P * P);
        }
    }
  });
}

}  // namespace

std::vector<double> cell_clumping_index(const OccluderSet& occluders, const VoxelGrid& grid, double t) {
  std::vector<double> omega(grid.cell_count(), 1.0);
  if (t >= 1.0 || occluders.ball_count == 0) return omega;
  double mean_radius = 0;
  for (std::size_t k = 0; k < occluders.ball_count; ++k) mean_radius += occluders.radii[k] / occluders.ball_count;
  if (mean_radius <= 0) return omega;
  // pixels of about a third of a ball radius, so a disc's rasterised area is within a few % of pi r^2; at most
  // 2^26 pixels (64 MB) on the largest face of the grid
  const double cell = std::min({grid.cell.x, grid.cell.y, grid.cell.z});
  const double largest_face =
      std::max({double(grid.dims.x) * grid.dims.y, double(grid.dims.y) * grid.dims.z, double(grid.dims.z) * grid.dims.x});
  const double fine = std::ceil(3.0 * cell / mean_radius);
  const double affordable = std::floor(std::sqrt(double(1 << 26) / largest_face));
  const int pixels_per_cell = static_cast<int>(std::clamp(std::min(fine, affordable), 4.0, 32.0));
  std::vector<double> log_gap(grid.cell_count(), 0.0), hits(grid.cell_count(), 0.0);
  for (int axis = 0; axis < 3; ++axis) add_shadows_along(axis, occluders, grid, t, pixels_per_cell, log_gap, hits);
  for (std::size_t c = 0; c < omega.size(); ++c)
    if (hits[c] > 0) omega[c] = log_gap[c] / ((1.0 - t) * hits[c]);
  return omega;
}

}  // namespace heliostand
