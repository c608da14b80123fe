// The far field's optical-depth table swept on the device, layer by layer against the light: the same sweep as
// FarField::sweep (src/light/far_field.cpp), in float. One launch per layer step; work item (eight columns from
// 8 * get_global_id(0), patch), the columns in SIMD lanes (voxel_grid.clh): every column computes what it would
// alone. Table layout [patch][z][y][x], density [z][y][x] (sigma, 1/m). far_field_by_cell then lays the table out
// by cell for the culled light kernel: [z][y][x][FAR_ROW], a row of every patch per cell (FAR_ROW, a build option
// made by the host, is the patch count rounded up to eight; the padding holds zeros).
#include "voxel_grid.clh"

// Midpoint rule along `direction` from each lane's start, at least one sample per cell length; a lane stops
// outside the grid or once its patch is dark (`saturated` hits), as FarField::march.
inline float8 far_field_march8(__global const float* density, float8 sx, float8 sy, float8 sz, float3 direction,
                               float length, float3 origin, float3 cell, int4 dims, int periodic, float saturated,
                               int8 active) {
  const float step_limit = min(cell.x, min(cell.y, cell.z));
  const int samples = max(1, (int)ceil(length / step_limit - 1e-6f));
  const float step = length / samples;
  float8 tau = 0.0f;
  for (int k = 0; k < samples; ++k) {
    active = active && tau < saturated;
    if (!any(active)) break;
    const float along = (k + 0.5f) * step;
    const float8 ax = sx + along * direction.x, ay = sy + along * direction.y, az = sz + along * direction.z;
    active = active && !grid_outside8(ax, ay, az, origin, cell, dims, periodic);
    const float8 sigma = grid_sample8(density, ax, ay, az, origin, cell, dims, periodic);
    tau = select(tau, tau + sigma * step, active);
  }
  return tau;
}

__kernel void far_field_layer(__global const float* density, __global float* depth, __global const float4* patches,
                              const float4 grid_origin, const float4 grid_cell, const int4 grid_dims,
                              const int periodic, const int layer_step, const float max_path, const float saturated,
                              const float start) {
  const int columns = grid_dims.x * grid_dims.y;
  const int first = get_global_id(0) * 8;
  const int patch = get_global_id(1);
  if (first >= columns) return;
  const float3 origin = grid_origin.xyz, cell = grid_cell.xyz;
  const float3 direction = patches[patch].xyz;
  const int8 column = first + (int8)(0, 1, 2, 3, 4, 5, 6, 7);
  const int8 valid = column < columns;
  const int8 x = select((int8)(0), column % grid_dims.x, valid), y = select((int8)(0), column / grid_dims.x, valid);
  const int step_z = direction.z > 0.0f ? 1 : -1;  // band centres never lie on the horizon (even V)
  const int z = direction.z > 0.0f ? grid_dims.z - 1 - layer_step : layer_step;
  const size_t cells = (size_t)grid_dims.x * grid_dims.y * grid_dims.z;
  __global float* table = depth + (size_t)patch * cells;
  const float8 sx = origin.x + (convert_float8(x) + 0.5f) * cell.x;
  const float8 sy = origin.y + (convert_float8(y) + 0.5f) * cell.y;
  const float8 sz = origin.z + ((float)z + 0.5f) * cell.z;
  // the cell's own part of the path begins `start` metres out (FarField::start_distance)
  const float8 fx = sx + start * direction.x, fy = sy + start * direction.y, fz = sz + start * direction.z;
  const int next = z + step_z;
  float8 tau;
  if (next < 0 || next >= grid_dims.z) {
    tau = far_field_march8(density, fx, fy, fz, direction, max_path, origin, cell, grid_dims, periodic, saturated,
                           valid);
  } else {
    const float reach = cell.z / fabs(direction.z);  // path to the next layer's mid-plane
    tau = far_field_march8(density, fx, fy, fz, direction, reach, origin, cell, grid_dims, periodic, saturated, valid);
    tau += grid_sample_layer8(table, sx + reach * direction.x, sy + reach * direction.y,
                              sz + reach * direction.z, origin, cell, grid_dims, periodic, next);
  }
  float lane_tau[8];
  vstore8(tau, 0, lane_tau);
  for (int l = 0; l < 8 && first + l < columns; ++l) table[(size_t)z * columns + first + l] = lane_tau[l];
}

// The swept table [patch][cell] laid out by cell, [cell][FAR_ROW]: work item (eight cells from
// 8 * get_global_id(0), eight patches from 8 * get_global_id(1)).
__kernel void far_field_by_cell(__global const float* depth, __global float* by_cell, const int cells) {
  const int first_cell = get_global_id(0) * 8, first_patch = get_global_id(1) * 8;
  for (int c = first_cell; c < min(first_cell + 8, cells); ++c)
    for (int p = first_patch; p < first_patch + 8; ++p)
      by_cell[(size_t)c * FAR_ROW + p] = p < SKY_BANDS * SKY_SECTORS ? depth[(size_t)p * cells + c] : 0.0f;
}
