// The far field's optical-depth table swept on the device, layer by layer against the light: the same sweep as
// FarField::sweep (src/light/far_field.cpp), in float. One launch per layer step; work item (x + y * nx, patch).
// Table layout [patch][z][y][x], density [z][y][x] (sigma, 1/m).
#include "voxel_grid.clh"

// Midpoint rule along `direction` from `start`, at least one sample per cell length, stopping outside the grid
// or once the patch is dark (`saturated` hits); as FarField::march.
inline float far_field_march(__global const float* density, float3 start, float3 direction, float length,
                             float3 origin, float3 cell, int4 dims, int periodic, float saturated) {
  const float step_limit = min(cell.x, min(cell.y, cell.z));
  const int samples = max(1, (int)ceil(length / step_limit - 1e-6f));
  const float step = length / samples;
  float tau = 0.0f;
  for (int k = 0; k < samples && tau < saturated; ++k) {
    const float3 at = start + (k + 0.5f) * step * direction;
    if (grid_outside(at, origin, cell, dims, periodic)) break;
    tau += grid_sample(density, at, origin, cell, dims, periodic) * step;
  }
  return tau;
}

__kernel void far_field_layer(__global const float* density, __global float* depth, __global const float4* patches,
                              const float4 grid_origin, const float4 grid_cell, const int4 grid_dims,
                              const int periodic, const int layer_step, const float max_path, const float saturated) {
  const int column = get_global_id(0);
  const int patch = get_global_id(1);
  if (column >= grid_dims.x * grid_dims.y) return;
  const float3 origin = grid_origin.xyz, cell = grid_cell.xyz;
  const float3 direction = patches[patch].xyz;
  const int x = column % grid_dims.x, y = column / grid_dims.x;
  const int step_z = direction.z > 0.0f ? 1 : -1;  // band centres never lie on the horizon (even V)
  const int z = direction.z > 0.0f ? grid_dims.z - 1 - layer_step : layer_step;
  const size_t cells = (size_t)grid_dims.x * grid_dims.y * grid_dims.z;
  __global float* table = depth + (size_t)patch * cells;
  const float3 start = origin + ((float3)((float)x, (float)y, (float)z) + 0.5f) * cell;
  const int next = z + step_z;
  float tau;
  if (next < 0 || next >= grid_dims.z) {
    tau = far_field_march(density, start, direction, max_path, origin, cell, grid_dims, periodic, saturated);
  } else {
    const float reach = cell.z / fabs(direction.z);  // path to the next layer's mid-plane
    tau = far_field_march(density, start, direction, reach, origin, cell, grid_dims, periodic, saturated);
    const float3 landing = start + reach * direction;
    tau += grid_sample_layer(table, landing, origin, cell, grid_dims, periodic, next);
  }
  table[((size_t)z * grid_dims.y + y) * grid_dims.x + x] = tau;
}
