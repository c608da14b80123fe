// The far field's optical-depth table swept on the device, layer by layer against the light: the same sweep as
// FarField::sweep (src/light/far_field.cpp), in float. One launch per layer step and chunk; work item (a run of eight
// columns of one row, patch), the columns in SIMD lanes (voxel_grid.clh): every column computes what it would
// alone. The host sweeps a chunk of patches at a time (src/light/far_field_buffers.hpp, sweep_chunk): table layout
// [patch of the chunk][z][y][x], from `first_patch` on; the density (sigma, 1/m) [z][y][x] with `margin` cells around
// the x and y sides (src/light/far_field_margin.hpp). far_field_by_cell then lays each chunk out by cell for the
// culled light kernel: [z][y][x][FAR_ROW], a row of every patch per cell (FAR_ROW, a build option made by the host,
// is the patch count rounded up to eight; the padding holds zeros), only for the cells a receiver reads.
#include "voxel_grid.clh"

// Midpoint rule along `direction` from `start` metres beyond each lane's cell centre, at least one sample per cell
// length, as FarField::march: a lane stops once its patch is dark (`saturated` hits); all stop where the ray
// leaves the grid through its top or bottom (z never wraps; beyond the grid's sides a lookup gives 0, and a
// straight ray never comes back).
__attribute__((always_inline)) inline float8 far_field_march8(__global const float* density, int margin, int x0,
                                                              int y, int lanes, int z, float3 direction, float start,
                                                              float length, float3 cell, int4 dims, int periodic,
                                                              float saturated) {
  const float step_limit = min(cell.x, min(cell.y, cell.z));
  const int samples = max(1, (int)round_up(length / step_limit - 1e-6f));
  const float step = length / samples;
  const float3 per_metre = direction / cell;  // cells moved per metre along the ray
  int8 active = (int8)(0, 1, 2, 3, 4, 5, 6, 7) < lanes;
  float8 tau = 0.0f;
  for (int k = 0; k < samples; ++k) {
    active = active && tau < saturated;
    if (!any(active)) break;
    const float3 shift = (start + (k + 0.5f) * step) * per_metre;
    const float uz = (float)z + shift.z;
    if (uz < -0.5f || uz > dims.z - 0.5f) break;
    const float8 sigma = grid_sample_shifted8(density, margin, x0, y, lanes, z, shift, dims, periodic, -1);
    tau = select(tau, tau + sigma * step, active);
  }
  return tau;
}

__kernel void far_field_layer(__global const float* density, const int margin, __global float* depth,
                              __global const float4* patches, const float4 grid_cell, const int4 grid_dims,
                              const int periodic, const int layer_step, const float max_path, const float saturated,
                              const float start, const int first_patch) {
  const int runs = (grid_dims.x + 7) / 8;  // runs of eight columns a row
  const int y = get_global_id(0) / runs;
  if (y >= grid_dims.y) return;
  const int x0 = (get_global_id(0) - y * runs) * 8;
  const int lanes = min(8, grid_dims.x - x0);
  const int patch = first_patch + get_global_id(1);
  const float3 cell = grid_cell.xyz;
  const float3 direction = patches[patch].xyz;
  const int step_z = direction.z > 0.0f ? 1 : -1;  // band centres never lie on the horizon (even V)
  const int z = direction.z > 0.0f ? grid_dims.z - 1 - layer_step : layer_step;
  const size_t cells = (size_t)grid_dims.x * grid_dims.y * grid_dims.z;
  __global float* table = depth + (size_t)get_global_id(1) * cells;  // the patch's place in this chunk
  // the cell's own part of the path begins `start` metres out (FarField::start_distance)
  const int next = z + step_z;
  float8 tau;
  if (next < 0 || next >= grid_dims.z) {
    tau = far_field_march8(density, margin, x0, y, lanes, z, direction, start, max_path, cell, grid_dims, periodic,
                           saturated);
  } else {
    const float reach = cell.z / fabs(direction.z);  // path to the next layer's mid-plane
    tau = far_field_march8(density, margin, x0, y, lanes, z, direction, start, reach, cell, grid_dims, periodic,
                           saturated);
    tau += grid_sample_shifted8(table, 0, x0, y, lanes, z, reach * direction / cell, grid_dims, periodic, next);
  }
  __global float* out = table + grid_at(x0, y, z, grid_dims, 0);
  if (lanes == 8) {
    vstore8(tau, 0, out);
  } else {
    float lane_tau[8];
    vstore8(tau, 0, lane_tau);
    for (int l = 0; l < lanes; ++l) out[l] = lane_tau[l];
  }
}

// Marks, one byte a cell, the cells of the table by cell that the culled kernels read: the eight corners around
// each receiver's centre (light.cl, far_field_attenuate), and the next ones along an axis where the centre lies
// within READ_MARGIN cells of a plane of cell centres (where the corners change), so that no rounding of the
// readers' own arithmetic can reach a cell left unmarked. A receiver beyond the grid marks its clamped or wrapped
// corners, which the readers do not read.
#define READ_MARGIN 1e-3f
__kernel void far_field_mark_read(__global const float4* balls, __global const int* receivers,
                                  const int receiver_count, const float4 grid_origin, const float4 grid_cell,
                                  const int4 grid_dims, const int periodic, __global uchar* read) {
  const int slot = get_global_id(0);
  if (slot >= receiver_count) return;
  const float3 u = (balls[receivers[slot]].xyz - grid_origin.xyz) / grid_cell.xyz - 0.5f;
  const int3 low = convert_int3(round_down(u - READ_MARGIN));
  const int3 high = convert_int3(round_down(u + READ_MARGIN)) + 1;
  for (int z = low.z; z <= high.z; ++z)
    for (int y = low.y; y <= high.y; ++y)
      for (int x = low.x; x <= high.x; ++x) {
        const int cz = clamp(z, 0, grid_dims.z - 1);
        const int cy = periodic ? wrap_cell(y, grid_dims.y) : clamp(y, 0, grid_dims.y - 1);
        const int cx = periodic ? wrap_cell(x, grid_dims.x) : clamp(x, 0, grid_dims.x - 1);
        read[((size_t)cz * grid_dims.y + cy) * grid_dims.x + cx] = 1;
      }
}

// A chunk of the swept table, [patch - chunk_first_patch][cell], laid out by cell, [cell][FAR_ROW], for the cells
// marked read (far_field_mark_read); the others keep whatever they held: work item (eight cells from
// 8 * get_global_id(0), eight patches from chunk_first_patch + 8 * get_global_id(1)).
__kernel void far_field_by_cell(__global const float* depth, __global const uchar* read, __global float* by_cell,
                                const int cells, const int chunk_first_patch) {
  const int first_cell = get_global_id(0) * 8, first_patch = chunk_first_patch + get_global_id(1) * 8;
  for (int c = first_cell; c < min(first_cell + 8, cells); ++c) {
    if (!read[c]) continue;
    for (int p = first_patch; p < first_patch + 8; ++p)
      by_cell[(size_t)c * FAR_ROW + p] =
          p < SKY_BANDS * SKY_SECTORS ? depth[(size_t)(p - chunk_first_patch) * cells + c] : 0.0f;
  }
}
