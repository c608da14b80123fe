#include "light/far_field.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "geometry/angles.hpp"

namespace heliostand {
namespace {

// Along a ray the attenuation exp(-(1-t) tau) is below 1e-9 long before this many expected hits; stopping
// there keeps horizontal rays through a periodic stand from marching forever.
constexpr double saturated_hits = 40.0;

int wrap_index(int i, int n) {
  i %= n;
  return i < 0 ? i + n : i;
}

VoxelGrid grid_around(const OccluderSet& occluders, const LightParameters& p) {
  VoxelGrid grid;
  grid.periodic = p.periodic;
  glm::dvec3 low(0.0), high(0.0);
  if (occluders.ball_count > 0) {
    low = high = occluders.centres[0];
    for (std::size_t k = 0; k < occluders.ball_count; ++k) {
      low = glm::min(low, occluders.centres[k]);
      high = glm::max(high, occluders.centres[k]);
    }
  }
  // one empty cell of margin, so that density deposited near the hull is not clamped away
  low -= occluders.max_radius + p.far_field_cell_m;
  high += occluders.max_radius + p.far_field_cell_m;
  if (p.periodic) {
    low.x = p.plot_x_min, high.x = p.plot_x_max;
    low.y = p.plot_y_min, high.y = p.plot_y_max;
  }
  const glm::dvec3 extent = high - low;
  for (int axis = 0; axis < 3; ++axis) {
    grid.dims[axis] = std::max(1, static_cast<int>(std::ceil(extent[axis] / p.far_field_cell_m - 1e-9)));
    // periodic x/y: whole cells per plot; otherwise cells of the asked size (the box grows to fit)
    grid.cell[axis] = (p.periodic && axis < 2) ? extent[axis] / grid.dims[axis] : p.far_field_cell_m;
  }
  grid.origin = low;
  return grid;
}

}  // namespace

bool VoxelGrid::outside(const glm::dvec3& point) const {
  const glm::dvec3 far_corner = origin + glm::dvec3(dims) * cell;
  if (point.z < origin.z || point.z > far_corner.z) return true;
  if (periodic) return false;
  return point.x < origin.x || point.x > far_corner.x || point.y < origin.y || point.y > far_corner.y;
}

double VoxelGrid::sample(std::span<const double> values, const glm::dvec3& point) const {
  if (outside(point)) return 0.0;
  int lo[3], hi[3];
  double f[3];
  for (int axis = 0; axis < 3; ++axis) {
    const double u = (point[axis] - origin[axis]) / cell[axis] - 0.5;
    const double base = std::floor(u);
    f[axis] = u - base;
    const int i = static_cast<int>(base);
    if (periodic && axis < 2) {
      lo[axis] = wrap_index(i, dims[axis]);
      hi[axis] = wrap_index(i + 1, dims[axis]);
    } else {
      lo[axis] = std::clamp(i, 0, dims[axis] - 1);
      hi[axis] = std::clamp(i + 1, 0, dims[axis] - 1);
    }
  }
  const auto v = [&](int x, int y, int z) { return values[index(x, y, z)]; };
  const double c00 = v(lo[0], lo[1], lo[2]) * (1 - f[0]) + v(hi[0], lo[1], lo[2]) * f[0];
  const double c10 = v(lo[0], hi[1], lo[2]) * (1 - f[0]) + v(hi[0], hi[1], lo[2]) * f[0];
  const double c01 = v(lo[0], lo[1], hi[2]) * (1 - f[0]) + v(hi[0], lo[1], hi[2]) * f[0];
  const double c11 = v(lo[0], hi[1], hi[2]) * (1 - f[0]) + v(hi[0], hi[1], hi[2]) * f[0];
  const double c0 = c00 * (1 - f[1]) + c10 * f[1];
  const double c1 = c01 * (1 - f[1]) + c11 * f[1];
  return c0 * (1 - f[2]) + c1 * f[2];
}

FarField::FarField(const OccluderSet& occluders, const LightParameters& p, const CelestialSphere& sky)
    : grid_(grid_around(occluders, p)) {
  // Longest useful path: horizontal rays in a periodic stand would circle the torus forever.
  max_path_m_ = 4.0 * glm::length(glm::dvec3(grid_.dims) * grid_.cell) + 1.0;
  density_.assign(grid_.cell_count(), 0.0);
  const double cell_volume = grid_.cell.x * grid_.cell.y * grid_.cell.z;
  // Cloud-in-cell deposit of each ball's cross-section, so the density varies smoothly between cells.
  for (std::size_t k = 0; k < occluders.ball_count; ++k) {
    const double cross_section = pi * occluders.radii[k] * occluders.radii[k];
    int lo[3];
    double f[3];
    for (int axis = 0; axis < 3; ++axis) {
      const double u = (occluders.centres[k][axis] - grid_.origin[axis]) / grid_.cell[axis] - 0.5;
      lo[axis] = static_cast<int>(std::floor(u));
      f[axis] = u - lo[axis];
    }
    for (int corner = 0; corner < 8; ++corner) {
      int at[3];
      double weight = cross_section / cell_volume;
      for (int axis = 0; axis < 3; ++axis) {
        const bool upper = (corner >> axis) & 1;
        at[axis] = lo[axis] + (upper ? 1 : 0);
        weight *= upper ? f[axis] : 1 - f[axis];
        at[axis] = (grid_.periodic && axis < 2) ? wrap_index(at[axis], grid_.dims[axis])
                                                : std::clamp(at[axis], 0, grid_.dims[axis] - 1);
      }
      density_[grid_.index(at[0], at[1], at[2])] += weight;
    }
  }
  // The optical-depth table: patches are independent, so split them over the cores.
  const auto& patches = sky.patches();
  depth_.assign(patches.size() * grid_.cell_count(), 0.0);
  const unsigned workers = std::max(1u, std::min(4u, std::thread::hardware_concurrency()));
  std::vector<std::jthread> pool;
  for (unsigned w = 0; w < workers; ++w)
    pool.emplace_back([&, w] {
      for (std::size_t q = w; q < patches.size(); q += workers)
        for (int z = 0; z < grid_.dims.z; ++z)
          for (int y = 0; y < grid_.dims.y; ++y)
            for (int x = 0; x < grid_.dims.x; ++x)
              depth_[q * grid_.cell_count() + grid_.index(x, y, z)] =
                  march(grid_.centre(x, y, z), patches[q].direction);
    });
}

double FarField::march(const glm::dvec3& point, const glm::dvec3& direction) const {
  const double step = 0.5 * std::min({grid_.cell.x, grid_.cell.y, grid_.cell.z});
  double tau = 0;
  for (double s = 0.5 * step; s < max_path_m_ && tau < saturated_hits; s += step) {
    const glm::dvec3 at = point + s * direction;
    if (grid_.outside(at)) break;
    tau += grid_.sample(density_, at) * step;
  }
  return tau;
}

double FarField::optical_depth(const glm::dvec3& point, int patch) const {
  const std::span<const double> table(depth_.data() + std::size_t(patch) * grid_.cell_count(), grid_.cell_count());
  return grid_.sample(table, point);
}

}  // namespace heliostand
