// The light field of seed 000 on OpenCL: one work item per receiving leaf ball.
// balls: (x, y, z, radius) relative to a stand origin chosen by the host (keeps float precision).
// patches: (N(h,v), S(h,v)); b0: B0 per patch. Output per receiver: (light vector, light).
// Seed 000's shading of one receiving leaf ball, shared by the exact and the culled light kernels.
// Compile-time constants (build options): SKY_BANDS (V), SKY_SECTORS (H), and BALANCED_LIGHT_FRACTION, made by the
// host from light_sum.hpp's balanced_light_fraction (the one copy: both backends use the same threshold).
// Per patch the kernel keeps log(B / B0): each occluding ball adds log(t), the far field adds -(1-t) tau.
#define PATCH_COUNT (SKY_BANDS * SKY_SECTORS)
#define PI_F 3.14159265358979f
#define BAND_WIDTH (PI_F / SKY_BANDS)
#define SECTOR_WIDTH (2.0f * PI_F / SKY_SECTORS)
// The window of candidate patches is widened by this angle (rad), far above float round-off, so that the
// exact ray test below, not the window, decides every hit.
#define WINDOW_MARGIN 1e-3f

// The ray test of the reference solver: half-line from the receiver along n vs a ball at offset d, radius r.
inline bool ray_hits(float3 d, float r, float3 n) {
  if (dot(n, d) <= 0.0f) return false;
  const float3 c = cross(d, n);
  return dot(c, c) <= r * r;
}

// Adds log(t) to every patch whose centre ray hits the ball at offset d. Only the patches whose centre can
// lie in the ball's angular disc (half-angle asin(r/|d|)) are tested, so the cost per ball is O(1) + hits.
inline void shade_by_ball(float* log_b, __global const float4* patches, float3 d, float r, float log_t) {
  const float dist2 = dot(d, d);
  if (dist2 <= r * r) {  // the receiver sits inside this ball: shaded in every direction
    for (int p = 0; p < PATCH_COUNT; ++p) log_b[p] += log_t;
    return;
  }
  const float dist = sqrt(dist2);
  const float half_angle = asin(r / dist) + WINDOW_MARGIN;
  const float polar = acos(clamp(d.z / dist, -1.0f, 1.0f));
  // bands whose centre polar angle (v + 0.5) * BAND_WIDTH lies within the disc's polar range
  const int v_lo = max(0, (int)ceil((polar - half_angle) / BAND_WIDTH - 0.5f));
  const int v_hi = min(SKY_BANDS - 1, (int)floor((polar + half_angle) / BAND_WIDTH - 0.5f));
  if (v_lo > v_hi) return;
  int h_lo = 0, h_hi = SKY_SECTORS - 1;
  const float horizontal = sqrt(d.x * d.x + d.y * d.y);
  const bool holds_pole = polar - half_angle <= 0.0f || polar + half_angle >= PI_F;
  if (!holds_pole) {
    // a disc clear of the poles spans at most asin(sin(half angle) / sin(polar)) in azimuth
    const float spread = asin(min(1.0f, sin(half_angle) * dist / horizontal)) + WINDOW_MARGIN;
    float azimuth = atan2(d.y, d.x);
    if (azimuth < 0.0f) azimuth += 2.0f * PI_F;
    h_lo = (int)ceil((azimuth - spread) / SECTOR_WIDTH - 0.5f);
    h_hi = (int)floor((azimuth + spread) / SECTOR_WIDTH - 0.5f);
    if (h_hi - h_lo >= SKY_SECTORS) { h_lo = 0; h_hi = SKY_SECTORS - 1; }
  }
  for (int v = v_lo; v <= v_hi; ++v)
    for (int h = h_lo; h <= h_hi; ++h) {
      const int sector = (h % SKY_SECTORS + SKY_SECTORS) % SKY_SECTORS;
      const int p = v * SKY_SECTORS + sector;
      if (ray_hits(d, r, patches[p].xyz)) log_b[p] += log_t;
    }
}

// light = Σ B S / Σ B0 S and vector = normalize(Σ N B S), packed as (vector, light).
inline float4 light_sample(const float* log_b, __global const float4* patches, __global const float* b0) {
  float received = 0.0f, unshaded = 0.0f;
  float3 flux = (float3)(0.0f);
  for (int p = 0; p < PATCH_COUNT; ++p) {
    const float b0s = b0[p] * patches[p].w;
    const float bs = b0s * exp(log_b[p]);
    unshaded += b0s;
    received += bs;
    flux += patches[p].xyz * bs;
  }
  const float len = length(flux);
  const float3 v = len > BALANCED_LIGHT_FRACTION * unshaded ? flux / len : (float3)(0.0f);
  return (float4)(v, received / unshaded);
}

// Exact: every other ball of the stand; periodic: also each ball's images in the 8 neighbouring plots.
__kernel void light_exact(__global const float4* balls, const int ball_count,
                          __global const int* receivers, const int receiver_count,
                          __global const float4* patches, __global const float* b0, const float log_t,
                          const int periodic, const float plot_width, const float plot_depth,
                          __global float4* out) {
  const int slot = get_global_id(0);
  if (slot >= receiver_count) return;
  const int i = receivers[slot];
  const float3 centre = balls[i].xyz;
  float log_b[PATCH_COUNT];
  for (int p = 0; p < PATCH_COUNT; ++p) log_b[p] = 0.0f;
  const int reach = periodic ? 1 : 0;
  for (int j = 0; j < ball_count; ++j) {
    const float4 ball = balls[j];
    for (int sx = -reach; sx <= reach; ++sx)
      for (int sy = -reach; sy <= reach; ++sy) {
        if (j == i && sx == 0 && sy == 0) continue;
        const float3 d = (float3)(ball.x + sx * plot_width - centre.x, ball.y + sy * plot_depth - centre.y,
                                  ball.z - centre.z);
        shade_by_ball(log_b, patches, d, ball.w, log_t);
      }
  }
  out[slot] = light_sample(log_b, patches, b0);
}

// Trilinear interpolation of cell-centre values (layout [z][y][x]); same rules as VoxelGrid::sample.
inline float grid_sample(__global const float* values, float3 p, float3 origin, float3 cell, int4 dims,
                         int periodic) {
  const float3 far_corner = origin + convert_float3(dims.xyz) * cell;
  if (p.z < origin.z || p.z > far_corner.z) return 0.0f;
  if (!periodic && (p.x < origin.x || p.x > far_corner.x || p.y < origin.y || p.y > far_corner.y)) return 0.0f;
  const float3 u = (p - origin) / cell - 0.5f;
  const float3 base = floor(u);
  const float3 f = u - base;
  int3 lo = convert_int3(base), hi = lo + 1;
  if (periodic) {
    lo.x = (lo.x % dims.x + dims.x) % dims.x; hi.x = (hi.x % dims.x + dims.x) % dims.x;
    lo.y = (lo.y % dims.y + dims.y) % dims.y; hi.y = (hi.y % dims.y + dims.y) % dims.y;
  } else {
    lo.x = clamp(lo.x, 0, dims.x - 1); hi.x = clamp(hi.x, 0, dims.x - 1);
    lo.y = clamp(lo.y, 0, dims.y - 1); hi.y = clamp(hi.y, 0, dims.y - 1);
  }
  lo.z = clamp(lo.z, 0, dims.z - 1); hi.z = clamp(hi.z, 0, dims.z - 1);
#define V(ix, iy, iz) values[((iz) * dims.y + (iy)) * dims.x + (ix)]
  const float c00 = mix(V(lo.x, lo.y, lo.z), V(hi.x, lo.y, lo.z), f.x);
  const float c10 = mix(V(lo.x, hi.y, lo.z), V(hi.x, hi.y, lo.z), f.x);
  const float c01 = mix(V(lo.x, lo.y, hi.z), V(hi.x, lo.y, hi.z), f.x);
  const float c11 = mix(V(lo.x, hi.y, hi.z), V(hi.x, hi.y, hi.z), f.x);
#undef V
  return mix(mix(c00, c10, f.y), mix(c01, c11, f.y), f.z);
}

// Culled: the near-field candidates of each receiver (CSR), then the far-field optical depth from the
// cut-off outward (table [patch][cell]), attenuating by exp(-(1 - t) tau).
__kernel void light_culled(__global const float4* balls, __global const int* receivers, const int receiver_count,
                           __global const int* candidate_start, __global const int* candidates,
                           __global const float4* patches, __global const float* b0, const float log_t,
                           __global const float* far_depth, const float4 grid_origin, const float4 grid_cell,
                           const int4 grid_dims, const int periodic, const float cutoff, const float one_minus_t,
                           __global float4* out) {
  const int slot = get_global_id(0);
  if (slot >= receiver_count) return;
  const float3 centre = balls[receivers[slot]].xyz;
  float log_b[PATCH_COUNT];
  for (int p = 0; p < PATCH_COUNT; ++p) log_b[p] = 0.0f;
  for (int k = candidate_start[slot]; k < candidate_start[slot + 1]; ++k) {
    const float4 ball = balls[candidates[k]];
    shade_by_ball(log_b, patches, ball.xyz - centre, ball.w, log_t);
  }
  const int cells = grid_dims.x * grid_dims.y * grid_dims.z;
  for (int p = 0; p < PATCH_COUNT; ++p) {
    const float3 beyond_cutoff = centre + cutoff * patches[p].xyz;
    const float tau = grid_sample(far_depth + (size_t)p * cells, beyond_cutoff, grid_origin.xyz, grid_cell.xyz,
                                  grid_dims, periodic);
    log_b[p] -= one_minus_t * tau;
  }
  out[slot] = light_sample(log_b, patches, b0);
}
