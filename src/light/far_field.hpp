#pragma once
// The far field: occluders beyond the near-field cut-off, seen as a smooth density of leaf-ball
// cross-section on a coarse voxel grid. Each cell holds sigma = sum(pi r^2) / cell volume (1/m): the expected
// number of balls a ray hits per metre. For every cell centre and every sky patch, a table holds the optical
// depth tau = integral of sigma along the patch's direction outward from start_distance() beyond that point
// (the expected number of ball hits past the near field). A receiver's patch then gets the factor
// exp(-(1 - t) tau): the mean of t^K over Poisson-placed balls with mean K = tau. With
// LightParameters::far_field_bias_correction (on by default), each cell's density is scaled by its clumping
// index (light/foliage_clumping.hpp) and the table starts one cell beyond the cut-off; off, at the cut-off, with
// the plain density. Both solvers read the same table (double on the host, float on the device).
//
// Why the table is indexed by the receiver, not by the point where its ray leaves the near field: every patch of
// a receiver is then read at the receiver's own position, so one set of interpolation weights and the same eight
// corner cells serve all V x H patches (the OpenCL kernel reads them as eight contiguous rows, one per corner).
// Read at the start point instead, each patch fell in other cells of its own table: V x H scattered lookups per
// receiver, a third of the culled solve at 10^6 balls (docs/performance.md "The far field read where the
// receiver is").
#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "light/celestial_sphere.hpp"
#include "light/light_parameters.hpp"
#include "light/occluders.hpp"

namespace heliostand {

struct VoxelGrid {
  glm::dvec3 origin{0.0};   // corner of cell (0,0,0), m
  glm::dvec3 cell{1.0};     // cell edge per axis, m (x/y adjusted so a periodic plot holds whole cells)
  glm::ivec3 dims{1};
  bool periodic = false;    // x and y wrap (torus); z never wraps
  std::size_t cell_count() const { return std::size_t(dims.x) * dims.y * dims.z; }
  std::size_t index(int x, int y, int z) const { return (std::size_t(z) * dims.y + y) * dims.x + x; }
  glm::dvec3 centre(int x, int y, int z) const { return origin + (glm::dvec3(x, y, z) + 0.5) * cell; }
  bool outside(const glm::dvec3& point) const;  // beyond the grid: no more leaf balls along a ray
  // Trilinear interpolation between cell-centre values (clamped at the faces, wrapped in x/y when periodic);
  // 0 outside the grid.
  // fixed_layer >= 0: bilinear in x/y within that z layer (the point's z is ignored).
  template <typename T>
  double sample(std::span<const T> values, const glm::dvec3& point, int fixed_layer = -1) const;
  template <typename T>
  double sample_layer(std::span<const T> values, const glm::dvec3& point, int layer) const;
};

class FarField {
 public:
  // `with_table` = false computes the grid and the density only: the OpenCL solver sweeps the optical-depth
  // table on its device (cl/far_field.cl) from the same density, so the table never exists on the host.
  FarField(const OccluderSet& occluders, const LightParameters& parameters, const CelestialSphere& sky,
           bool with_table = true);

  const VoxelGrid& grid() const { return grid_; }
  const std::vector<double>& density() const { return density_; }  // sigma (corrected: Omega * sigma) per cell, 1/m
  const std::vector<float>& optical_depth() const { return depth_; }      // [patch][cell]
  // Expected number of ball hits along patch `patch`'s direction beyond start_distance() from `receiver`
  // (interpolated between the cell centres around the receiver).
  double optical_depth(const glm::dvec3& receiver, int patch) const;
  // Distance from a receiver, along each patch direction, at which the far field begins: the near-field
  // cut-off, or with the bias correction one cell beyond it, where the smoothed density of the near-field balls
  // (already ray-tested) has faded.
  double start_distance() const { return start_m_; }
  // tau integrated directly from the density (what the table approximates); used by the table and by tests.
  // (The table itself is built layer by layer, see sweep().) Marches at most `length` metres.
  double march(const glm::dvec3& point, const glm::dvec3& direction, double length = 1e300) const;
  // Longest march (m): horizontal rays in a periodic stand would circle the torus forever.
  double max_path_m() const { return max_path_m_; }
  // Expected hits after which a patch counts as dark: the march stops there (see far_field.cpp).
  double saturated_hits() const;

 private:
  void apply_clumping_index(const OccluderSet& occluders);
  void sweep(const glm::dvec3& direction, std::span<double> depth) const;

  VoxelGrid grid_;
  double transmittance_;
  bool bias_corrected_;
  double start_m_;
  double max_path_m_;
  std::vector<double> density_;
  std::vector<float> depth_;
};

// The most cells the optical-depth table may have: far_field_table_mb at 4 bytes a cell and patch. A stand that
// would need more gets coarser cells (FarField's grid); the OpenCL solver keeps its table's buffer within it.
inline double far_field_table_budget_cells(const LightParameters& p, std::size_t patch_count) {
  return p.far_field_table_mb * 1e6 / (4.0 * patch_count);
}

inline int wrap_cell(int i, int n) {
  i %= n;
  return i < 0 ? i + n : i;
}

template <typename T>
inline double VoxelGrid::sample_layer(std::span<const T> values, const glm::dvec3& point, int layer) const {
  return sample(values, point, layer);
}

template <typename T>
inline double VoxelGrid::sample(std::span<const T> values, const glm::dvec3& point, int fixed_layer) const {
  if (outside(point)) return 0.0;
  int lo[3], hi[3];
  double f[3];
  for (int axis = 0; axis < 3; ++axis) {
    const double u = (point[axis] - origin[axis]) / cell[axis] - 0.5;
    const double base = std::floor(u);
    f[axis] = u - base;
    const int i = static_cast<int>(base);
    if (periodic && axis < 2) {
      lo[axis] = wrap_cell(i, dims[axis]);
      hi[axis] = wrap_cell(i + 1, dims[axis]);
    } else {
      lo[axis] = std::clamp(i, 0, dims[axis] - 1);
      hi[axis] = std::clamp(i + 1, 0, dims[axis] - 1);
    }
  }
  const auto v = [&](int x, int y, int z) { return values[index(x, y, z)]; };
  if (fixed_layer >= 0) lo[2] = hi[2] = fixed_layer;
  const double c00 = v(lo[0], lo[1], lo[2]) * (1 - f[0]) + v(hi[0], lo[1], lo[2]) * f[0];
  const double c10 = v(lo[0], hi[1], lo[2]) * (1 - f[0]) + v(hi[0], hi[1], lo[2]) * f[0];
  const double c01 = v(lo[0], lo[1], hi[2]) * (1 - f[0]) + v(hi[0], lo[1], hi[2]) * f[0];
  const double c11 = v(lo[0], hi[1], hi[2]) * (1 - f[0]) + v(hi[0], hi[1], hi[2]) * f[0];
  const double c0 = c00 * (1 - f[1]) + c10 * f[1];
  const double c1 = c01 * (1 - f[1]) + c11 * f[1];
  return c0 * (1 - f[2]) + c1 * f[2];
}

}  // namespace heliostand
