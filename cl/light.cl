// The light field of seed 000 on OpenCL: one work item per receiving leaf ball.
// balls: (x, y, z, radius) relative to a stand origin chosen by the host (keeps float precision).
// patches: (N(h,v), S(h,v)); b0: B0 per patch. Output per receiver: (light vector, light).
// Seed 000's shading of one receiving leaf ball, shared by the exact and the culled light kernels.
// Compile-time constants (build options): SKY_BANDS (V), SKY_SECTORS (H), AXIS_STRIDE (below), FAR_ROW
// (far_field.cl), SCAN_BATCHES (shade_by_tile_candidates), and
// BALANCED_LIGHT_FRACTION, made by the host from light_sum.hpp's balanced_light_fraction (the one copy: both
// backends use the same threshold).
// Per patch the kernel keeps log(B / B0): each occluding ball adds log(t), the far field adds -(1-t) tau.
#include "rounding.clh"
#include "voxel_grid.clh"

#define PATCH_COUNT (SKY_BANDS * SKY_SECTORS)
#define PI_F 3.14159265358979f
#define BAND_WIDTH (PI_F / SKY_BANDS)
#define SECTOR_WIDTH (2.0f * PI_F / SKY_SECTORS)
// The window of candidate patches is widened by this angle (rad), far above float round-off, so that the
// exact ray test below, not the window, decides every hit.
#define WINDOW_MARGIN 1e-3f
#define WINDOW_MARGIN_COS 0.9999995f  // cos(WINDOW_MARGIN)
#define WINDOW_MARGIN_SIN 9.9999983e-4f  // sin(WINDOW_MARGIN)

// Patch centre directions by axis, for eight patches at a time: x of every patch, then y, then z, AXIS_STRIDE
// apart (a build option: the host lays the array out). Each axis and every receiver's log_b carry at least seven
// padding entries, so that eight patches read from any patch of the sky stay inside the arrays.
#if AXIS_STRIDE < PATCH_COUNT + 7
#error "AXIS_STRIDE leaves no room for a run of eight patches from the last one"
#endif
#if SCAN_BATCHES < 1
#error "SCAN_BATCHES: the tile scan windows at least one batch at a time"
#endif
#if FAR_ROW > AXIS_STRIDE || FAR_ROW % 8 != 0
#error "far_field_attenuate writes whole runs of eight patches of a FAR_ROW into log_b"
#endif

// The ray test of the reference solver (half-line from the receiver along n hits the ball at offset d: in front,
// and |d x n|^2 <= r^2) for the eight patches p .. p + 7. Without contraction into fused multiply-adds the eight lanes
// decide each hit exactly as the scalar test they replace did (same tables, docs/performance.md).
__attribute__((always_inline)) inline int8 run_hits(__global const float* axes, int p, float3 d, float r2) {
#pragma OPENCL FP_CONTRACT OFF
  const float8 nx = vload8(0, axes + p), ny = vload8(0, axes + AXIS_STRIDE + p);
  const float8 nz = vload8(0, axes + 2 * AXIS_STRIDE + p);
  const float8 along = nx * d.x + ny * d.y + nz * d.z;
  const float8 cx = d.y * nz - d.z * ny, cy = d.z * nx - d.x * nz, cz = d.x * ny - d.y * nx;
  return along > 0.0f && cx * cx + cy * cy + cz * cz <= r2;
}

// The same for the patches first .. last of one band, eight at a time: log(t) is added to each patch hit and 0 to
// the others (a lane past `last` adds 0 to whatever it reads), so every patch sums the same terms in the same order
// as a patch-by-patch loop would.
inline int8 patch_run_hits(__global const float* axes, int p, int last, float3 d, float r2) {
  return run_hits(axes, p, d, r2) && p + (int8)(0, 1, 2, 3, 4, 5, 6, 7) <= last;
}

inline void shade_patch_run(float* log_b, __global const float* axes, int first, int last, float3 d, float r2,
                            float log_t) {
  for (int p = first; p <= last; p += 8)
    vstore8(vload8(0, log_b + p) + select((float8)(0.0f), (float8)(log_t), patch_run_hits(axes, p, last, d, r2)), 0,
            log_b + p);
}

// The same run shading two skies at once (light_culled_and_alone: the tree alone's and the stand's).
inline void shade_patch_run_twice(float* log_b, float* other_log_b, __global const float* axes, int first, int last,
                                  float3 d, float r2, float log_t) {
  for (int p = first; p <= last; p += 8) {
    const float8 added = select((float8)(0.0f), (float8)(log_t), patch_run_hits(axes, p, last, d, r2));
    vstore8(vload8(0, log_b + p) + added, 0, log_b + p);
    vstore8(vload8(0, other_log_b + p) + added, 0, other_log_b + p);
  }
}

// The sectors h_lo .. h_hi of band v, where -SKY_SECTORS <= h_lo and h_hi < 2 SKY_SECTORS: up to three runs of
// contiguous patches (the part before sector 0, the band itself, the part past its last sector, each wrapped).
inline void shade_band(float* log_b, __global const float* axes, int v, int h_lo, int h_hi, float3 d, float r2,
                       float log_t) {
  const int row = v * SKY_SECTORS;
  shade_patch_run(log_b, axes, row + h_lo + SKY_SECTORS, row + min(h_hi, -1) + SKY_SECTORS, d, r2, log_t);
  shade_patch_run(log_b, axes, row + max(h_lo, 0), row + min(h_hi, SKY_SECTORS - 1), d, r2, log_t);
  shade_patch_run(log_b, axes, row + max(h_lo, SKY_SECTORS) - SKY_SECTORS, row + h_hi - SKY_SECTORS, d, r2, log_t);
}

inline void shade_band_twice(float* log_b, float* other_log_b, __global const float* axes, int v, int h_lo, int h_hi,
                             float3 d, float r2, float log_t) {
  const int row = v * SKY_SECTORS;
  shade_patch_run_twice(log_b, other_log_b, axes, row + h_lo + SKY_SECTORS, row + min(h_hi, -1) + SKY_SECTORS, d, r2,
                        log_t);
  shade_patch_run_twice(log_b, other_log_b, axes, row + max(h_lo, 0), row + min(h_hi, SKY_SECTORS - 1), d, r2, log_t);
  shade_patch_run_twice(log_b, other_log_b, axes, row + max(h_lo, SKY_SECTORS) - SKY_SECTORS, row + h_hi - SKY_SECTORS,
                        d, r2, log_t);
}

// A ball whose window spans at most eight sectors (most of a grown canopy's near field): one run of eight patches a
// band, or two where the window wraps past sector 0 (sectors 0..7 and the last eight, apart while SKY_SECTORS >= 16).
// No lane needs a mask: each run lies inside its band's row, and a patch of it outside the ball's window is one
// the exact test does not hit (the window holds every patch the ball can hit), so it adds 0 as a masked lane would.
// Shades `other_log_b` too when it is not null. Returns 0, shading nothing, for a wider window. Inlined by force:
// a call per band (shade_band) cost more than its run (docs/performance.md "Narrow windows in one run a band, and
// the tile lists read in order").
__attribute__((always_inline)) inline int shade_narrow(float* log_b, float* other_log_b, __global const float* axes,
                                                       int v_lo, int v_hi, int h_lo, int h_hi, float3 d, float r2,
                                                       float log_t) {
#if SKY_SECTORS >= 16
  if (h_hi - h_lo >= 8) return 0;
  const int wraps = h_lo < 0 || h_hi >= SKY_SECTORS;
  const int first = wraps ? 0 : min(h_lo, SKY_SECTORS - 8);
  const int last = wraps ? SKY_SECTORS - 8 : first;
  for (int v = v_lo; v <= v_hi; ++v) {
    const int row = v * SKY_SECTORS;
    for (int p = row + first; p <= row + last; p += SKY_SECTORS - 8) {
      const float8 added = select((float8)(0.0f), (float8)(log_t), run_hits(axes, p, d, r2));
      vstore8(vload8(0, log_b + p) + added, 0, log_b + p);
      if (other_log_b) vstore8(vload8(0, other_log_b + p) + added, 0, other_log_b + p);
    }
  }
  return 1;
#else
  return 0;
#endif
}

// Inverse trigonometry for the patch window only. Polynomials of Abramowitz & Stegun (1964), 4.4.45 (acos,
// |error| <= 6.8e-5 rad in float) and 4.4.49 (atan on [0, 1], |error| <= 1.2e-5 rad): more than ten times
// under WINDOW_MARGIN, so the window still holds every patch the ball can hit and the exact ray test below
// decides; they cost a few multiply-adds where the library functions cost tens of instructions each.
// Eight lanes at a time (see OccluderBatch).
inline float8 acos_window(float8 x) {
  const float8 a = fabs(x);
  const float8 r = sqrt(fmax(0.0f, 1.0f - a)) * (1.5707288f + a * (-0.2121144f + a * (0.0742610f - 0.0187293f * a)));
  return select(r, PI_F - r, x < 0.0f);
}
inline float8 asin_window(float8 x) { return 0.5f * PI_F - acos_window(x); }
inline float8 atan2_window(float8 y, float8 x) {  // in (-pi, pi], like atan2
  const float8 ax = fabs(x), ay = fabs(y);
  const float8 hi = fmax(ax, ay);
  const float8 z = select((float8)(0.0f), fmin(ax, ay) / hi, hi > 0.0f);
  const float8 z2 = z * z;
  float8 a = z * (0.9998660f + z2 * (-0.3302995f + z2 * (0.1801410f + z2 * (-0.0851330f + z2 * 0.0208351f))));
  a = select(a, 0.5f * PI_F - a, ay > ax);
  a = select(a, PI_F - a, x < 0.0f);
  return select(a, -a, y < 0.0f);
}

// The occluders of one receiver, eight at a time. Finding which patches a ball can cover (its window, below) is
// most of the near field's work: three square roots, three polynomials and four roundings per ball, with no
// branch that depends on the data. Collected into a batch of eight, it runs in the SIMD lanes of a CPU (float8: a
// real canopy's solve in 0.6 of its time on PoCL, docs/performance.md); a GPU runs the same code as eight scalar
// computations. The balls' patches are then tested ball after ball in the order the balls were added (each
// band in runs of eight patches, shade_band), so every patch sums the same terms in the same order as one ball at a
// time would.
typedef struct {
  float x[8], y[8], z[8], r[8];  // offset from the receiver and radius of each ball in the batch
  int count;
} OccluderBatch;

inline void batch_clear(OccluderBatch* batch) {
  for (int l = 0; l < 8; ++l) batch->x[l] = batch->y[l] = batch->z[l] = batch->r[l] = 1.0f;  // lanes never filled stay finite
  batch->count = 0;
}

// The patches each ball of a batch can cover: the sectors h_lo .. h_hi of the bands v_lo .. v_hi, or every patch
// when the receiver sits inside the ball. Only the patches whose centre can lie in a ball's angular disc
// (half-angle asin(r/|d|)) are tested (seed 000 "scan-converts" each ball onto the receiver's sky the same way), so
// the cost per ball is O(1) + the patches it covers.
typedef struct {
  int v_lo[8], v_hi[8], h_lo[8], h_hi[8], inside[8];
} BatchWindows;

// The windows of eight balls at offsets (dx, dy, dz) with radii r, one in each lane.
inline void lane_windows(float8 dx, float8 dy, float8 dz, float8 r, BatchWindows* window) {
  const float8 dist2 = dx * dx + dy * dy + dz * dz;
  const float8 inverse_dist = rsqrt(dist2);
  const float8 sin_disc = r * inverse_dist;  // sine of the disc's half-angle
  const float8 half_angle = asin_window(sin_disc) + WINDOW_MARGIN;
  const float8 polar = acos_window(clamp(dz * inverse_dist, -1.0f, 1.0f));
  // bands whose centre polar angle (v + 0.5) * BAND_WIDTH lies within the disc's polar range
  const int8 v_lo = max(0, convert_int8(round_up((polar - half_angle) / BAND_WIDTH - 0.5f)));
  const int8 v_hi = min(SKY_BANDS - 1, convert_int8(round_down((polar + half_angle) / BAND_WIDTH - 0.5f)));
  // a disc clear of the poles spans at most asin(sin(half angle) / sin(polar)) in azimuth;
  // sin(asin(sin_disc) + margin) by the angle-sum rule
  const float8 horizontal = sqrt(dx * dx + dy * dy);
  const float8 sin_half = sin_disc * WINDOW_MARGIN_COS + sqrt(fmax(0.0f, 1.0f - sin_disc * sin_disc)) * WINDOW_MARGIN_SIN;
  const float8 spread = asin_window(fmin(1.0f, sin_half / (horizontal * inverse_dist))) + WINDOW_MARGIN;
  float8 azimuth = atan2_window(dy, dx);
  azimuth = select(azimuth, azimuth + 2.0f * PI_F, azimuth < 0.0f);
  int8 h_lo = convert_int8(round_up((azimuth - spread) / SECTOR_WIDTH - 0.5f));
  int8 h_hi = convert_int8(round_down((azimuth + spread) / SECTOR_WIDTH - 0.5f));
  const int8 all_sectors = polar - half_angle <= 0.0f || polar + half_angle >= PI_F || h_hi - h_lo >= SKY_SECTORS;
  h_lo = select(h_lo, (int8)(0), all_sectors);
  h_hi = select(h_hi, (int8)(SKY_SECTORS - 1), all_sectors);
  const int8 inside = dist2 <= r * r;  // the receiver sits inside this ball: shaded in every direction
  vstore8(v_lo, 0, window->v_lo), vstore8(v_hi, 0, window->v_hi);
  vstore8(h_lo, 0, window->h_lo), vstore8(h_hi, 0, window->h_hi);
  vstore8(inside, 0, window->inside);
}

inline void batch_windows(const OccluderBatch* batch, BatchWindows* window) {
  lane_windows(vload8(0, batch->x), vload8(0, batch->y), vload8(0, batch->z), vload8(0, batch->r), window);
}

// Adds log(t) to every patch of `log_b` whose centre ray hits the ball at offset d, radius r, whose window is v_lo ..
// v_hi, h_lo .. h_hi (`inside`: the receiver sits in it), and to the same patches of `other_log_b` unless it is 0
// (light_culled_and_alone: a ball of the receiver's own tree within the cut-off shades the tree alone's sky and the
// stand's).
__attribute__((always_inline)) inline void shade_by_windowed_ball(float* log_b, float* other_log_b,
                                                                 __global const float* axes, float3 d, float r,
                                                                 int inside, int v_lo, int v_hi, int h_lo, int h_hi,
                                                                 float log_t) {
  if (inside) {
    for (int p = 0; p < PATCH_COUNT; ++p) log_b[p] += log_t;
    if (other_log_b)
      for (int p = 0; p < PATCH_COUNT; ++p) other_log_b[p] += log_t;
    return;
  }
  const float r2 = r * r;
  if (shade_narrow(log_b, other_log_b, axes, v_lo, v_hi, h_lo, h_hi, d, r2, log_t)) return;
  for (int v = v_lo; v <= v_hi; ++v) {
    if (other_log_b)
      shade_band_twice(log_b, other_log_b, axes, v, h_lo, h_hi, d, r2, log_t);
    else
      shade_band(log_b, axes, v, h_lo, h_hi, d, r2, log_t);
  }
}

// Adds log(t) to every patch whose centre ray hits a ball of the batch, its windows found (batch_windows).
inline void shade_by_windows(float* log_b, __global const float* axes, const OccluderBatch* batch,
                             const BatchWindows* window, float log_t) {
  for (int l = 0; l < batch->count; ++l)
    shade_by_windowed_ball(log_b, 0, axes, (float3)(batch->x[l], batch->y[l], batch->z[l]), batch->r[l],
                           window->inside[l], window->v_lo[l], window->v_hi[l], window->h_lo[l], window->h_hi[l],
                           log_t);
}

// Adds log(t) to every patch whose centre ray hits a ball of the batch.
inline void shade_by_batch(float* log_b, __global const float* axes, const OccluderBatch* batch, float log_t) {
  BatchWindows window;
  batch_windows(batch, &window);
  shade_by_windows(log_b, axes, batch, &window, log_t);
}

// Shades the receiver by the balls in the batch, if any, and empties it.
inline void batch_finish(OccluderBatch* batch, float* log_b, __global const float* axes, float log_t) {
  if (batch->count > 0) shade_by_batch(log_b, axes, batch, log_t);
  batch->count = 0;
}

// The first `count` entries of the tile lists at places `held` (laid out by axis, `entry_stride` apart) into the
// batch, as offsets from the receiver at `centre`.
inline void batch_fill(OccluderBatch* batch, __global const float* entries, int entry_stride, const int* held,
                       int count, float3 centre) {
  for (int l = 0; l < count; ++l) {
    const int e = held[l];
    batch->x[l] = entries[e] - centre.x, batch->y[l] = entries[entry_stride + e] - centre.y;
    batch->z[l] = entries[2 * entry_stride + e] - centre.z, batch->r[l] = entries[3 * entry_stride + e];
  }
  batch->count = count;
}

// Puts the ball at offset d into the batch, shading the receiver once eight are in; batch_finish shades the rest.
inline void shade_by_ball(OccluderBatch* batch, float* log_b, __global const float* axes, float3 d, float r,
                          float log_t) {
  const int l = batch->count++;
  batch->x[l] = d.x, batch->y[l] = d.y, batch->z[l] = d.z, batch->r[l] = r;
  if (batch->count == 8) batch_finish(batch, log_b, axes, log_t);
}

// light = Σ B S / Σ B0 S and vector = normalize(Σ N B S), packed as (vector, light). The transmitted fractions
// exp(log B / B0) are taken eight patches at a time (the exponential was a fifth of a receiver's work when taken
// one patch at a time on a CPU); the sums still add the patches one by one, in order.
inline float4 light_sample(const float* log_b, __global const float4* patches, __global const float* b0) {
  float received = 0.0f, unshaded = 0.0f;
  float3 flux = (float3)(0.0f);
  for (int run = 0; run < PATCH_COUNT; run += 8) {
    float transmitted[8];
    vstore8(exp(vload8(0, log_b + run)), 0, transmitted);
    for (int l = 0; l < 8 && run + l < PATCH_COUNT; ++l) {
      const int p = run + l;
      const float b0s = b0[p] * patches[p].w;
      const float bs = b0s * transmitted[l];
      unshaded += b0s;
      received += bs;
      flux += patches[p].xyz * bs;
    }
  }
  const float len = length(flux);
  const float3 v = len > BALANCED_LIGHT_FRACTION * unshaded ? flux / len : (float3)(0.0f);
  return (float4)(v, received / unshaded);
}

// Exact: every other ball of the stand; periodic: also each ball's images in the 8 neighbouring plots.
__kernel void light_exact(__global const float4* balls, const int ball_count,
                          __global const int* receivers, const int receiver_count,
                          __global const float4* patches, __global const float* axes, __global const float* b0,
                          const float log_t, const int periodic, const float plot_width, const float plot_depth,
                          __global float4* out) {
  const int slot = get_global_id(0);
  if (slot >= receiver_count) return;
  const int i = receivers[slot];
  const float3 centre = balls[i].xyz;
  float log_b[AXIS_STRIDE];
  for (int p = 0; p < AXIS_STRIDE; ++p) log_b[p] = 0.0f;
  OccluderBatch batch;
  batch_clear(&batch);
  const int reach = periodic ? 1 : 0;
  for (int j = 0; j < ball_count; ++j) {
    const float4 ball = balls[j];
    for (int sx = -reach; sx <= reach; ++sx)
      for (int sy = -reach; sy <= reach; ++sy) {
        if (j == i && sx == 0 && sy == 0) continue;
        const float3 d = (float3)(ball.x + sx * plot_width - centre.x, ball.y + sy * plot_depth - centre.y,
                                  ball.z - centre.z);
        shade_by_ball(&batch, log_b, axes, d, ball.w, log_t);
      }
  }
  batch_finish(&batch, log_b, axes, log_t);
  out[slot] = light_sample(log_b, patches, b0);
}

// Each group alone (the open-grown light of every tree at once): ball i is shaded by the other balls of its own
// group, balls[group_start[g] .. group_start[g + 1]), in the order light_exact visits them. Coordinates are
// relative to each group's own origin, as when the group is solved as a stand by itself.
__kernel void light_each_alone(__global const float4* balls, __global const int* ball_group,
                               __global const int* group_start, const int ball_count,
                               __global const float4* patches, __global const float* axes,
                               __global const float* b0, const float log_t, __global float4* out) {
  const int i = get_global_id(0);
  if (i >= ball_count) return;
  const int g = ball_group[i];
  const float3 centre = balls[i].xyz;
  float log_b[AXIS_STRIDE];
  for (int p = 0; p < AXIS_STRIDE; ++p) log_b[p] = 0.0f;
  OccluderBatch batch;
  batch_clear(&batch);
  for (int j = group_start[g]; j < group_start[g + 1]; ++j) {
    if (j == i) continue;
    const float4 ball = balls[j];
    shade_by_ball(&batch, log_b, axes, ball.xyz - centre, ball.w, log_t);
  }
  batch_finish(&batch, log_b, axes, log_t);
  out[i] = light_sample(log_b, patches, b0);
}

// The far field of a receiver at `at`: log(B) -= (1 - t) tau for every patch, tau interpolated in the table laid
// out by cell (far_field_by_cell), which holds each cell's optical depth from FarField::start_distance outward.
// Every patch is read at the receiver's own position, so one set of trilinear weights and eight corner rows serve
// them all, eight patches at a time; the corners and the arithmetic are those of grid_sample_shifted8.
inline void far_field_attenuate(float* log_b, __global const float* by_cell, float3 at, float3 origin, float3 cell,
                                int4 dims, int periodic, float one_minus_t) {
  if (any(grid_outside8((float8)(at.x), (float8)(at.y), (float8)(at.z), origin, cell, dims, periodic))) return;
  const float3 u = (at - origin) / cell - 0.5f;
  const float3 base = round_down(u);
  const float3 f = u - base;
  int lox = (int)base.x, hix = lox + 1, loy = (int)base.y, hiy = loy + 1;
  int loz = clamp((int)base.z, 0, dims.z - 1), hiz = clamp((int)base.z + 1, 0, dims.z - 1);
  if (periodic) {
    lox = wrap_cell(lox, dims.x), hix = wrap_cell(hix, dims.x), loy = wrap_cell(loy, dims.y), hiy = wrap_cell(hiy, dims.y);
  } else {
    lox = clamp(lox, 0, dims.x - 1), hix = clamp(hix, 0, dims.x - 1);
    loy = clamp(loy, 0, dims.y - 1), hiy = clamp(hiy, 0, dims.y - 1);
  }
  const size_t row00 = ((size_t)loz * dims.y + loy) * dims.x, row10 = ((size_t)loz * dims.y + hiy) * dims.x;
  const size_t row01 = ((size_t)hiz * dims.y + loy) * dims.x, row11 = ((size_t)hiz * dims.y + hiy) * dims.x;
  __global const float* v0 = by_cell + (row00 + lox) * FAR_ROW;
  __global const float* v1 = by_cell + (row00 + hix) * FAR_ROW;
  __global const float* v2 = by_cell + (row10 + lox) * FAR_ROW;
  __global const float* v3 = by_cell + (row10 + hix) * FAR_ROW;
  __global const float* v4 = by_cell + (row01 + lox) * FAR_ROW;
  __global const float* v5 = by_cell + (row01 + hix) * FAR_ROW;
  __global const float* v6 = by_cell + (row11 + lox) * FAR_ROW;
  __global const float* v7 = by_cell + (row11 + hix) * FAR_ROW;
  for (int p = 0; p < FAR_ROW; p += 8) {
    const float8 c00 = mix(vload8(0, v0 + p), vload8(0, v1 + p), f.x);
    const float8 c10 = mix(vload8(0, v2 + p), vload8(0, v3 + p), f.x);
    const float8 c01 = mix(vload8(0, v4 + p), vload8(0, v5 + p), f.x);
    const float8 c11 = mix(vload8(0, v6 + p), vload8(0, v7 + p), f.x);
    const float8 tau = mix(mix(c00, c10, f.y), mix(c01, c11, f.y), f.z);
    vstore8(vload8(0, log_b + p) - one_minus_t * tau, 0, log_b + p);  // padding lanes: past the last patch, unused
  }
}

// The tile lists laid out for the scan below: entry k of the lists (occluder occluders[k]) gets a copy of its ball,
// by axis (x of every entry, then y, z and radius, entry_stride apart), and its tag: the occluder's tree
// (occluder_group) where tag_by_group is set (the one pass), else its index. Entries entry_count .. entry_stride - 1
// are padding, so that a run of eight from any entry stays inside the buffers; they carry tag -1 and a zero ball.
__kernel void tile_entries(__global const float4* balls, __global const int* occluders, const int entry_count,
                           __global const int* occluder_group, const int tag_by_group, const int entry_stride,
                           __global float* entries, __global int* entry_tag) {
  const int k = get_global_id(0);
  if (k >= entry_stride) return;
  const int j = k < entry_count ? occluders[k] : -1;
  const float4 ball = j >= 0 ? balls[j] : (float4)(0.0f);
  entries[k] = ball.x, entries[entry_stride + k] = ball.y;
  entries[2 * entry_stride + k] = ball.z, entries[3 * entry_stride + k] = ball.w;
  entry_tag[k] = j < 0 ? -1 : tag_by_group ? occluder_group[j] : j;
}

// The near field from the receiver's tile list, entries scan.x .. scan.y - 1 of the lists laid out by axis: the x of
// every entry, then y, z and radius, `entry_stride` apart (each a copy of its occluder's ball: the list is read in
// order, eight entries at a time, instead of through an index into the stand's balls; docs/performance.md "Narrow
// windows in one run a band, and the tile lists read in order"). The entries within the cut-off (squared: cutoff2) of
// the receiver at `centre` whose tag differs from `excluded_tag` (light_culled: the occluder index and the receiver's
// own; the one pass: the tree of each entry and the receiver's tree) shade log_b, eight at a time, in the order of the
// list.
// Without a branch on the distance: each of the eight entries' places is written into the next free slot of `held`,
// and only those kept claim theirs; once SCAN_BATCHES batches of eight are held, their windows are found one batch
// after the other and then their patches shaded. On a CPU two batches at a time (the host's choice) let the square
// roots and divisions of the second batch's windows run while the first's wait on theirs, where one batch's windows
// stalled the core (docs/performance.md "Two batches' windows at a time, and the own tree read in lanes"). Every hit
// adds the same log t, so neither this order nor the shells' changes a patch's sum.
inline void shade_by_tile_candidates(float* log_b, __global const float* entries, int entry_stride,
                                     __global const int* entry_tag, int excluded_tag, int2 scan, float3 centre,
                                     float cutoff2, __global const float* axes, float log_t) {
#pragma OPENCL FP_CONTRACT OFF
  const int8 lane = (int8)(0, 1, 2, 3, 4, 5, 6, 7);
  int held[8 * SCAN_BATCHES + 8];
  int count = 0;
  OccluderBatch batches[SCAN_BATCHES];
  BatchWindows windows[SCAN_BATCHES];
  for (int b = 0; b < SCAN_BATCHES; ++b) batch_clear(&batches[b]);
  for (int k = scan.x; k < scan.y; k += 8) {
    const float8 dx = vload8(0, entries + k) - centre.x;
    const float8 dy = vload8(0, entries + entry_stride + k) - centre.y;
    const float8 dz = vload8(0, entries + 2 * entry_stride + k) - centre.z;
    // each square rounded, then summed, without fused multiply-adds: the test dot(d, d) <= cutoff2 made before the
    // lists were laid out by axis, bit for bit (and so the same tables)
    const int8 keep = vload8(0, entry_tag + k) != excluded_tag && dx * dx + dy * dy + dz * dz <= cutoff2 &&
                      k + lane < scan.y;  // -1 in each lane kept
    int kept[8];
    vstore8(keep, 0, kept);
    for (int l = 0; l < 8; ++l) held[count] = k + l, count -= kept[l];
    if (count >= 8 * SCAN_BATCHES) {
      for (int b = 0; b < SCAN_BATCHES; ++b) batch_fill(&batches[b], entries, entry_stride, held + 8 * b, 8, centre);
      for (int b = 0; b < SCAN_BATCHES; ++b) batch_windows(&batches[b], &windows[b]);
      for (int b = 0; b < SCAN_BATCHES; ++b) shade_by_windows(log_b, axes, &batches[b], &windows[b], log_t);
      count -= 8 * SCAN_BATCHES;
      for (int l = 0; l < count; ++l) held[l] = held[8 * SCAN_BATCHES + l];
    }
  }
  for (int first = 0; first < count; first += 8) {
    batch_fill(&batches[0], entries, entry_stride, held + first, min(count - first, 8), centre);
    batch_finish(&batches[0], log_b, axes, log_t);
  }
}

// Culled: receivers come in tile order; each reads the part of its tile's candidate list (CSR) that can hold its
// near field, scan = (first, end) (light/near_field.hpp: the list in shells of distance from the tile's centre),
// keeps the occluders whose centre lies within the cut-off of its own (the reference solver's test, in float),
// then adds the far-field optical depth (far_field_attenuate), attenuating by exp(-(1 - t) tau); with
// LightParameters::far_field_bias_correction the clumping index is already in the table's density.
__kernel void light_culled(__global const float4* balls, __global const int* receivers,
                           __global const int2* receiver_scan, const int receiver_count,
                           __global const float* entries, const int entry_stride, __global const int* entry_tag,
                           __global const float4* patches, __global const float* axes, __global const float* b0,
                           const float log_t, __global const float* far_by_cell, const float4 grid_origin,
                           const float4 grid_cell, const int4 grid_dims, const int periodic, const float cutoff,
                           const float one_minus_t, __global float4* out) {
  const int slot = get_global_id(0);
  if (slot >= receiver_count) return;
  const int self = receivers[slot];
  const int2 scan = receiver_scan[slot];
  const float3 centre = balls[self].xyz;
  const float cutoff2 = cutoff * cutoff;
  float log_b[AXIS_STRIDE];
  for (int p = 0; p < AXIS_STRIDE; ++p) log_b[p] = 0.0f;
  shade_by_tile_candidates(log_b, entries, entry_stride, entry_tag, self, scan, centre, cutoff2, axes, log_t);
  far_field_attenuate(log_b, far_by_cell, centre, grid_origin.xyz, grid_cell.xyz, grid_dims, periodic, one_minus_t);
  out[slot] = light_sample(log_b, patches, b0);
}

// A run of eight balls of the receiver's own tree, each as its offset from the receiver in the tree's frame, whether
// to shade it (not shaded by an earlier run, in the tree, not the receiver itself), whether it lies within the
// cut-off, and its window.
typedef struct {
  float x[8], y[8], z[8], r[8];
  int shaded[8], within[8];
  BatchWindows window;
} OwnRun;

// The run of group_balls[j0 .. j0 + 8), read in lanes straight from the buffer (from `first`, ball by ball, for a
// tree of fewer than eight balls, whose lanes past its end are left out). Balls before `done` are left out too.
__attribute__((always_inline)) inline void own_run(OwnRun* run, __global const float4* group_balls, int j0, int first,
                                                   int end, int done, int self, float3 own_centre, float cutoff2) {
#pragma OPENCL FP_CONTRACT OFF
  float8 bx, by, bz, br;
  if (end - first >= 8) {
    const float16 a = vload16(0, (__global const float*)(group_balls + j0));
    const float16 b = vload16(0, (__global const float*)(group_balls + j0 + 4));
    bx = (float8)(a.s048c, b.s048c), by = (float8)(a.s159d, b.s159d);
    bz = (float8)(a.s26ae, b.s26ae), br = (float8)(a.s37bf, b.s37bf);
  } else {
    for (int l = 0; l < 8; ++l) {
      const float4 ball = first + l < end ? group_balls[first + l] : (float4)(own_centre, 1.0f);
      run->x[l] = ball.x, run->y[l] = ball.y, run->z[l] = ball.z, run->r[l] = ball.w;
    }
    bx = vload8(0, run->x), by = vload8(0, run->y), bz = vload8(0, run->z), br = vload8(0, run->r);
  }
  const int8 j = j0 + (int8)(0, 1, 2, 3, 4, 5, 6, 7);
  const int8 shaded = j >= done && j < end && j != self;
  const float8 dx = select((float8)(1.0f), bx - own_centre.x, shaded);  // lanes left out stay finite
  const float8 dy = select((float8)(1.0f), by - own_centre.y, shaded);
  const float8 dz = select((float8)(1.0f), bz - own_centre.z, shaded);
  // each square rounded, then summed: dot(d, d) <= cutoff2 as the ball-by-ball loop before it decided (same tables)
  const int8 within = dx * dx + dy * dy + dz * dz <= cutoff2;
  lane_windows(dx, dy, dz, br, &run->window);
  vstore8(dx, 0, run->x), vstore8(dy, 0, run->y), vstore8(dz, 0, run->z), vstore8(br, 0, run->r);
  vstore8(shaded, 0, run->shaded), vstore8(within, 0, run->within);
}

// Shades both skies by the balls of a run: the tree alone's by each, the stand's by those within the cut-off.
__attribute__((always_inline)) inline void shade_by_own_run(float* alone_log_b, float* stand_log_b,
                                                           __global const float* axes, const OwnRun* run,
                                                           float log_t) {
  for (int l = 0; l < 8; ++l) {
    if (!run->shaded[l]) continue;
    shade_by_windowed_ball(alone_log_b, run->within[l] ? stand_log_b : 0, axes,
                           (float3)(run->x[l], run->y[l], run->z[l]), run->r[l], run->window.inside[l],
                           run->window.v_lo[l], run->window.v_hi[l], run->window.h_lo[l], run->window.h_hi[l], log_t);
  }
}

// The receiver's own tree, group_balls[first .. end) but the receiver `self`, in runs of eight read in lanes, two runs
// at a time while sixteen balls remain (their windows' square roots and divisions overlap, as the tile scan's two
// batches do). A tree of eight balls or more ends with a run of its last eight, its lanes already shaded left out.
// Every ball is windowed once, in lanes, and shades the skies it belongs to: before, each was copied ball by ball
// into a batch of near and one of far balls, whose windows then read the copies back as vectors, stalling on the
// copies (docs/performance.md "Two batches' windows at a time, and the own tree read in lanes"). Every hit adds the
// same log t, so the order does not change a patch's sum.
inline void shade_by_own_tree(float* alone_log_b, float* stand_log_b, __global const float4* group_balls, int first,
                              int end, int self, float cutoff2, __global const float* axes, float log_t) {
  const float3 own_centre = group_balls[self].xyz;
  OwnRun run, next;
  int done = first;
  for (; end - done >= 16; done += 16) {
    own_run(&run, group_balls, done, first, end, done, self, own_centre, cutoff2);
    own_run(&next, group_balls, done + 8, first, end, done, self, own_centre, cutoff2);
    shade_by_own_run(alone_log_b, stand_log_b, axes, &run, log_t);
    shade_by_own_run(alone_log_b, stand_log_b, axes, &next, log_t);
  }
  while (done < end) {
    const int j0 = end - first >= 8 ? min(done, end - 8) : first;
    own_run(&run, group_balls, j0, first, end, done, self, own_centre, cutoff2);
    shade_by_own_run(alone_log_b, stand_log_b, axes, &run, log_t);
    done = j0 + 8;
  }
}

// light_culled and light_each_alone in one pass (the stand's light and the open-grown light of its trees): the
// receiver's own tree, balls[group_start[g] .. group_start[g + 1]), is projected once, in the tree's own frame
// (`group_balls`, as light_each_alone reads them), and each hit shades both skies: the tree alone's always, the stand's
// when the ball lies within the cut-off. The stand's candidate scan then skips every entry of the tree (`entry_tag`:
// the tree of each list entry, images included; `entry_group`: of each occluder). The host fuses only where no image of
// a tree's ball can come within the cut-off of another of its balls, so the stand's near field holds the same balls as
// light_culled's; their offsets differ only by float round-off (the tree's frame is nearer). The tree-alone sky is
// light_each_alone's, bit for bit: the same offsets, windows and hit tests, and every hit adds the same log t.
__kernel void light_culled_and_alone(__global const float4* balls, __global const int* receivers,
                                     __global const int2* receiver_scan, const int receiver_count,
                                     __global const float* entries, const int entry_stride,
                                     __global const int* entry_tag, __global const int* entry_group,
                                     __global const float4* group_balls, __global const int* group_start,
                                     __global const float4* patches, __global const float* axes,
                                     __global const float* b0, __global const float* b0_alone, const float log_t,
                                     __global const float* far_by_cell, const float4 grid_origin,
                                     const float4 grid_cell, const int4 grid_dims, const int periodic,
                                     const float cutoff, const float one_minus_t, __global float4* out,
                                     __global float4* out_alone) {
  const int slot = get_global_id(0);
  if (slot >= receiver_count) return;
  const int self = receivers[slot];
  const int g = entry_group[self];
  const float cutoff2 = cutoff * cutoff;
  float log_b[AXIS_STRIDE], alone_log_b[AXIS_STRIDE];
  for (int p = 0; p < AXIS_STRIDE; ++p) log_b[p] = alone_log_b[p] = 0.0f;
  shade_by_own_tree(alone_log_b, log_b, group_balls, group_start[g], group_start[g + 1], self, cutoff2, axes, log_t);
  out_alone[slot] = light_sample(alone_log_b, patches, b0_alone);
  // The other trees, as light_culled scans them.
  const int2 scan = receiver_scan[slot];
  const float3 centre = balls[self].xyz;
  shade_by_tile_candidates(log_b, entries, entry_stride, entry_tag, g, scan, centre, cutoff2, axes, log_t);
  far_field_attenuate(log_b, far_by_cell, centre, grid_origin.xyz, grid_cell.xyz, grid_dims, periodic, one_minus_t);
  out[slot] = light_sample(log_b, patches, b0);
}
