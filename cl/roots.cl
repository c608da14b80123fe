// The root-contact field of seed 003 (Ohshida, Muraoka, Chiba), one work-item per growing root apex:
//   contact avoidance  Vt = −Σ unit(apex → nearest point of each other segment inside the perception sphere)
//   moisture pull      Vw =  Σ unit(probe_k) · moisture(apex + R probe_k)
// Same meaning as roots::ReferenceRootFieldSolver (the oracle). Candidate segments come from a uniform
// grid over segment midpoints (roots::SegmentGrid, CSR: segments sorted by cell, cell_start); a midpoint can only
// matter within R + the longest half segment ("reach"), and cells wholly beyond the reach are skipped. All positions are relative to one frame origin (float precision).
// Build option TOUCHING_DISTANCE: roots::touching_distance_m, made by the host (segments nearer than this to the
// apex give no direction and are not counted, on both backends alike).
#include "rounding.clh"

// Soil moisture at a point: trilinear interpolation of vertex values, points outside the grid read the
// nearest boundary value (the same rule as roots::SoilGrid::value). Coordinates relative to the frame origin.
float soil_moisture(global const float* moisture, int4 vertices, float3 soil_origin, float spacing, float3 p) {
  const int3 n = vertices.xyz;
  const float3 cells = convert_float3(n - 1);
  const float3 g = clamp((p - soil_origin) / spacing, (float3)(0.0f), cells);
  const int3 base = min(convert_int3(round_down(g)), n - 2);
  const float3 f = g - convert_float3(base);
  float sum = 0.0f;
  for (int c = 0; c < 8; ++c) {
    const int di = c & 1, dj = (c >> 1) & 1, dk = (c >> 2) & 1;
    const float w = (di ? f.x : 1.0f - f.x) * (dj ? f.y : 1.0f - f.y) * (dk ? f.z : 1.0f - f.z);
    const int index = (base.x + di) + n.x * ((base.y + dj) + n.y * (base.z + dk));
    sum += w * moisture[index];
  }
  return sum;
}

int3 grid_cell(float3 p, float3 grid_origin, float cell_size, int3 dims) {
  return clamp(convert_int3(round_down((p - grid_origin) / cell_size)), (int3)(0), dims - 1);
}

kernel void root_contact_field(global const float4* segment_middle,  // xyz midpoint, w half length
                               global const float4* segment_start, global const float4* segment_end,
                               global const int* segment_id,  // the caller's index, for the exclusions
                               global const int* cell_start,
                               const int4 grid_dims, const float4 grid_origin, const float cell_size,
                               const float longest_half,
                               global const float4* tips,  // xyz apex, w perception radius R
                               global const int2* excluded, const int tip_count,
                               global const float4* probes, const int probes_per_tip,
                               global const float* moisture, const int4 soil_vertices, const float4 soil_origin,
                               const float soil_spacing, const int has_soil,
                               global float4* contact_out,   // xyz Vt, w number of contacts
                               global float4* moisture_out)  // xyz Vw
{
  const int t = get_global_id(0);
  if (t >= tip_count) return;
  const float3 apex = tips[t].xyz;
  const float radius = tips[t].w;
  const int2 skip = excluded[t];

  float3 avoid = (float3)(0.0f);
  int contacts = 0;
  if (cell_start[grid_dims.x * grid_dims.y * grid_dims.z] > 0) {
    // A small margin so float rounding of the query box never drops a cell the double grid used.
    const float reach = radius + longest_half + 1e-4f;
    const int3 dims = grid_dims.xyz;
    const int3 low = grid_cell(apex - reach, grid_origin.xyz, cell_size, dims);
    const int3 high = grid_cell(apex + reach, grid_origin.xyz, cell_size, dims);
    for (int z = low.z; z <= high.z; ++z)
      for (int y = low.y; y <= high.y; ++y)
        for (int x = low.x; x <= high.x; ++x) {
          // Skip cells whose box lies wholly outside the reach (cells are about reach/2 wide).
          const float3 box_low = grid_origin.xyz + cell_size * (float3)((float)x, (float)y, (float)z);
          const float3 gap = max(max(box_low - apex, apex - (box_low + cell_size)), (float3)(0.0f));
          if (dot(gap, gap) > reach * reach) continue;
          const int cell = x + dims.x * (y + dims.y * z);
          // Segments are stored in cell order, so a cell's segments are contiguous in memory.
          for (int i = cell_start[cell]; i < cell_start[cell + 1]; ++i) {
            // Cheap rejection first: the nearest point lies within half a length of the midpoint.
            const float4 middle = segment_middle[i];
            const float3 offset = middle.xyz - apex;
            const float bound = radius + middle.w + 1e-4f;
            if (dot(offset, offset) > bound * bound) continue;
            const int s = segment_id[i];
            if (s == skip.x || s == skip.y) continue;
            const float3 a = segment_start[i].xyz;
            const float3 axis = segment_end[i].xyz - a;
            const float length2 = dot(axis, axis);
            const float u = length2 > 0.0f ? clamp(dot(apex - a, axis) / length2, 0.0f, 1.0f) : 0.0f;
            const float3 toward = a + u * axis - apex;
            const float distance = length(toward);
            if (distance >= radius || distance < TOUCHING_DISTANCE) continue;
            avoid -= toward / distance;
            ++contacts;
          }
        }
  }
  contact_out[t] = (float4)(avoid, (float)contacts);

  float3 pull = (float3)(0.0f);
  if (has_soil) {
    for (int k = 0; k < probes_per_tip; ++k) {
      const float3 probe = probes[t * probes_per_tip + k].xyz;
      const float probe_length = length(probe);
      if (probe_length <= 0.0f) continue;
      pull += (probe / probe_length) *
              soil_moisture(moisture, soil_vertices, soil_origin.xyz, soil_spacing, apex + radius * probe);
    }
  }
  moisture_out[t] = (float4)(pull, 0.0f);
}
