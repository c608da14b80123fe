#include "light/far_field.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/parallel_for.hpp"
#include "geometry/angles.hpp"
#include "light/foliage_clumping.hpp"

namespace heliostand {
namespace {

// Once exp(-(1-t) tau) < exp(-14) ~ 1e-6 the patch is dark for any purpose; stopping there keeps
// near-horizontal rays in a dense (or periodic) stand from marching on for nothing.
constexpr double saturated_attenuation = 14.0;

int wrap_index(int i, int n) {
  i %= n;
  return i < 0 ? i + n : i;
}

VoxelGrid grid_around(const OccluderSet& occluders, const LightParameters& p, std::size_t patch_count) {
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
  // two cells of margin: the cloud-in-cell deposit reaches one cell beyond a ball's own, and the outermost
  // cells must stay empty because interpolation holds their value out to the grid's faces
  low -= occluders.max_radius + 2 * p.far_field_cell_m;
  high += occluders.max_radius + 2 * p.far_field_cell_m;
  if (p.periodic) {
    low.x = p.plot_x_min, high.x = p.plot_x_max;
    low.y = p.plot_y_min, high.y = p.plot_y_max;
  }
  const glm::dvec3 extent = high - low;
  // The table holds 4 bytes per cell and patch; a stand too big for the budget gets coarser cells.
  const double budget_cells = far_field_table_budget_cells(p, patch_count);
  double cell_m = p.far_field_cell_m;
  const double volume = (extent.x + cell_m) * (extent.y + cell_m) * (extent.z + cell_m);
  // Said once per run by whoever runs the solves (LightSolveStatistics::far_field_cell_m), not once per solve.
  if (volume / (cell_m * cell_m * cell_m) > budget_cells) cell_m = std::cbrt(volume / budget_cells) * 1.05;
  for (int axis = 0; axis < 3; ++axis) {
    grid.dims[axis] = std::max(1, static_cast<int>(std::ceil(extent[axis] / cell_m - 1e-9)));
    // periodic x/y: whole cells per plot; otherwise cells of the asked size (the box grows to fit)
    grid.cell[axis] = (p.periodic && axis < 2) ? extent[axis] / grid.dims[axis] : cell_m;
  }
  grid.origin = low;
  return grid;
}

// The near/far hand-over. The near field ray-tests every ball whose centre lies within the cut-off; the far
// field holds every ball, smoothed: the cloud-in-cell deposit puts a ball on the cell centres within one cell of
// it and the lookup interpolates between cell centres, so a ball reaches the table up to two cells away. Read
// right at the cut-off, the table still holds much of the near balls just inside it, which the ray test has
// already counted; at a canopy's top and bottom, where a receiver's rays leave the foliage, nothing beyond
// makes up for it, and the light comes out too dark. The bias correction starts further out
// (LightParameters::far_field_hand_over_cells, one cell by default): that drops most of the double count and
// misses about as much of the balls just beyond the cut-off (docs/light.md). Off, the table starts at the cut-off.
double far_field_start(const VoxelGrid& grid, const LightParameters& p) {
  if (!p.far_field_bias_correction) return p.cutoff_m;
  return p.cutoff_m + p.far_field_hand_over_cells * std::max({grid.cell.x, grid.cell.y, grid.cell.z});
}

}  // namespace

bool VoxelGrid::outside(const glm::dvec3& point) const {
  const glm::dvec3 far_corner = origin + glm::dvec3(dims) * cell;
  if (point.z < origin.z || point.z > far_corner.z) return true;
  if (periodic) return false;
  return point.x < origin.x || point.x > far_corner.x || point.y < origin.y || point.y > far_corner.y;
}

FarField::FarField(const OccluderSet& occluders, const LightParameters& p, const CelestialSphere& sky,
                   bool with_table)
    : grid_(grid_around(occluders, p, sky.patches().size())),
      transmittance_(p.transmittance),
      bias_corrected_(p.far_field_bias_correction),
      start_m_(far_field_start(grid_, p)) {
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
  if (bias_corrected_) apply_clumping_index(occluders);
  if (!with_table) return;
  // The optical-depth table: patches are independent, so split them over the cores (at most four: each holds one
  // patch's depths over the whole grid in double). Share w takes every workers-th patch from w; a share whose thread
  // cannot start (a process at its limit of threads) is swept by one that did, so the table never depends on the
  // threads.
  const auto& patches = sky.patches();
  depth_.assign(patches.size() * grid_.cell_count(), 0.0f);
  const std::size_t workers = std::max(1u, std::min(4u, std::thread::hardware_concurrency()));
  parallel_for_on(workers, workers, [&](std::size_t w) {
    std::vector<double> depth(grid_.cell_count());  // swept in double, stored in float (read by both solvers)
    for (std::size_t q = w; q < patches.size(); q += workers) {
      sweep(patches[q].direction, depth);
      std::copy(depth.begin(), depth.end(), depth_.begin() + q * grid_.cell_count());
    }
  });
}

// Layer by layer against the light: tau at a cell centre c = the integral of sigma from c + s N to
// c + (s + reach) N, where c + reach N lies on the next layer's mid-plane, plus tau already known there
// (bilinear in that layer), which by definition starts at c + (reach + s) N. Each cell costs ~1/|N.z| samples
// instead of a march to the edge of the canopy. z never wraps, so this holds for periodic plots too.
// (Band centres never lie on the horizon for even V, so N.z != 0.) s = start_distance().
void FarField::sweep(const glm::dvec3& direction, std::span<double> depth) const {
  const int step_z = direction.z > 0 ? 1 : -1;
  const int first = direction.z > 0 ? grid_.dims.z - 1 : 0;
  const double reach = grid_.cell.z / std::abs(direction.z);  // path to the next layer's mid-plane
  for (int z = first; z >= 0 && z < grid_.dims.z; z -= step_z)
    for (int y = 0; y < grid_.dims.y; ++y)
      for (int x = 0; x < grid_.dims.x; ++x) {
        const glm::dvec3 start = grid_.centre(x, y, z);
        const glm::dvec3 far_start = start + start_m_ * direction;
        const int next = z + step_z;
        double tau;
        if (next < 0 || next >= grid_.dims.z) {
          tau = march(far_start, direction);  // last layer: at most half a layer to the grid face
        } else {
          tau = march(far_start, direction, reach);
          const glm::dvec3 landing = start + reach * direction;
          tau += grid_.outside(landing) ? 0.0 : grid_.sample_layer(std::span<const double>(depth), landing, next);
        }
        depth[grid_.index(x, y, z)] = tau;
      }
}

double FarField::saturated_hits() const {
  return saturated_attenuation / std::max(1e-6, 1.0 - transmittance_);
}

double FarField::march(const glm::dvec3& point, const glm::dvec3& direction, double length) const {
  // midpoint rule, at least one sample per cell length: sigma is itself trilinear between cell centres
  const double cell = std::min({grid_.cell.x, grid_.cell.y, grid_.cell.z});
  const double saturated = saturated_hits();
  length = std::min(length, max_path_m_);
  const int samples = static_cast<int>(std::ceil(length / cell - 1e-9));
  const double step = length / samples;
  double tau = 0;
  for (int k = 0; k < samples && tau < saturated; ++k) {
    const glm::dvec3 at = point + (k + 0.5) * step * direction;
    if (grid_.outside(at)) break;
    tau += grid_.sample(std::span<const double>(density_), at) * step;
  }
  return tau;
}

// Clumped foliage lets more light through than the same density placed at random: scale each cell's density by
// its clumping index (light/foliage_clumping.hpp), computed from the balls' actual shadows.
void FarField::apply_clumping_index(const OccluderSet& occluders) {
  const std::vector<double> omega = cell_clumping_index(occluders, grid_, transmittance_);
  for (std::size_t c = 0; c < density_.size(); ++c) density_[c] *= omega[c];
}

double FarField::optical_depth(const glm::dvec3& receiver, int patch) const {
  const std::span<const float> table(depth_.data() + std::size_t(patch) * grid_.cell_count(), grid_.cell_count());
  return grid_.sample(table, receiver);
}

}  // namespace heliostand
