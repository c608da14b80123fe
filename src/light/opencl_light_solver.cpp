#include "light/opencl_light_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

#include <glm/common.hpp>

#include "compute/kernel_options.hpp"
#include "compute/kernel_sources.hpp"
#include "compute/opencl_kept_buffer.hpp"
#include "compute/opencl_context.hpp"
#include "core/seconds_since.hpp"
#include "light/celestial_sphere.hpp"
#include "light/far_field.hpp"
#include "light/far_field_buffers.hpp"
#include "light/far_field_margin.hpp"
#include "light/light_sum.hpp"
#include "light/near_field.hpp"
#include "light/occluders.hpp"

namespace heliostand {
namespace {

using Clock = std::chrono::steady_clock;

// Receivers per culled kernel launch (the candidate lists are per tile and go to the device once).
constexpr std::size_t culled_chunk = std::size_t(1) << 18;

template <typename T>
cl::Buffer read_only(const cl::Context& context, std::span<const T> data) {
  // a zero-sized buffer is invalid in OpenCL; one element of padding keeps empty inputs legal
  if (data.empty()) {
    T padding{};
    return cl::Buffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(T), &padding);
  }
  return cl::Buffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, data.size() * sizeof(T),
                    const_cast<T*>(data.data()));
}

template <typename T>
cl::Buffer read_only(const cl::Context& context, const std::vector<T>& data) {
  return read_only(context, std::span<const T>(data));
}

using compute::kept_at_least;
using compute::KeptBuffer;
using compute::MappedForWriting;

// The near-field search's tile lists, the occluders' written by the search straight into `kept` (mapped), the buffer
// the tile scan reads them from, kept from one solve to the next: not laid out on the host, nor copied to the device,
// nor written to fresh pages once the buffer has room. At 10^6 balls that was 144 MB of fresh host pages cleared and
// 144 MB more copied into a fresh buffer each solve (docs/performance.md "The tile lists written where the device reads
// them"). `kept` holds at least one entry after this, whatever the lists hold.
TileCandidates tile_lists_on_device(compute::OpenCLContext& device, const NearFieldSearch& search,
                                    std::span<const std::uint32_t> receivers, double tile_m, KeptBuffer& kept) {
  std::optional<MappedForWriting> mapped;
  const TileListPlace place = [&](std::size_t entries) {
    const std::size_t bytes = std::max<std::size_t>(entries, 1) * sizeof(std::uint32_t);
    mapped.emplace(device.queue, kept_at_least(device, kept, bytes), bytes);
    return std::span<std::uint32_t>(static_cast<std::uint32_t*>(mapped->data()), entries);
  };
  TileCandidates near = search.tile_candidates(receivers, tile_m, place);
  if (mapped)
    mapped->unmap();
  else  // no lists, so no room asked: still a buffer to hand the kernel
    kept_at_least(device, kept, sizeof(std::uint32_t));
  return near;
}

// Which cells of the far field's table by cell the culled kernels will read, one byte a cell (cl/far_field.cl,
// far_field_mark_read): the corners around each receiver. A first 10^5 solve reads 43 % of the cells, a 10^6 one 58 %
// (docs/performance.md "Candidate lists and the k-d tree from one year to the next, and a first 10⁵ far field in its
// parts"); only those are laid out.
const cl::Buffer& mark_cells_read(compute::OpenCLContext& device, cl::Kernel& k, const cl::Buffer& balls,
                                  std::span<const std::uint32_t> receivers, const cl_float4& origin,
                                  const cl_float4& cell, const cl_int4& dims, bool periodic, KeptBuffer& read_kept) {
  const std::size_t cells = std::size_t(dims.s[0]) * dims.s[1] * dims.s[2];
  const cl::Buffer& read = kept_at_least(device, read_kept, cells);
  device.queue.enqueueFillBuffer(read, cl_uchar(0), 0, cells);
  // The indices go as they are (unsigned, read as int: solve_culled has checked that the balls are fewer than 2^31).
  const cl::Buffer receiver_buffer = read_only(device.context, receivers);
  int arg = 0;
  k.setArg(arg++, balls);
  k.setArg(arg++, receiver_buffer);
  k.setArg(arg++, cl_int(receivers.size()));
  k.setArg(arg++, origin);
  k.setArg(arg++, cell);
  k.setArg(arg++, dims);
  k.setArg(arg++, cl_int(periodic ? 1 : 0));
  k.setArg(arg++, read);
  compute::launch(device, k, receivers.size());
  return read;
}

// The rows of the table by cell that `read` marks (mark_cells_read) made resident before the layout writes them
// (compute::make_resident; the caller asks only where makes_pages_resident, which spares a GPU the marks' read-back),
// each run of consecutive cells read in one call; the other rows stay unbacked.
void make_rows_read_resident(compute::OpenCLContext& device, const cl::Buffer& table, const cl::Buffer& read,
                             std::size_t cells, std::size_t row_bytes) {
  std::vector<std::uint8_t> marks(cells);
  device.queue.enqueueReadBuffer(read, CL_TRUE, 0, cells, marks.data());
  std::vector<compute::ByteRange> rows;
  for (const CellRun& run : runs_of_cells_read(marks)) rows.push_back({run.first * row_bytes, run.end * row_bytes});
  compute::make_resident(device, table, rows);
}

// The far field's optical-depth table, swept on the device from the density of `far` (cl/far_field.cl) and laid
// out by cell where `read` marks a cell; it stays there for the culled kernel.
cl::Buffer sweep_far_field(compute::OpenCLContext& device, cl::Kernel& k, cl::Kernel& by_cell, const FarField& far,
                           std::span<const SkyPatch> sky_patches, const cl::Buffer& patches, const cl_float4& cell,
                           const cl_int4& dims, bool periodic, const cl::Buffer& read, KeptBuffer& swept_kept,
                           KeptBuffer& table_kept, std::size_t table_cap_bytes) {
  const auto& context = device.context;
  const std::size_t patch_count = sky_patches.size();
  const int margin = sweep_margin_cells(far, sky_patches);
  std::vector<float> density = density_with_margin(far, margin);
  density.resize(density.size() + sweep_overread_floats, 0.0f);
  const cl::Buffer density_buffer = read_only(context, density);
  const std::size_t cells = far.grid().cell_count();
  // Both of the table's layouts are kept from one solve to the next, each replaced only when the table outgrows it:
  // the sweep writes every entry of its chunk again and the layout by cell every entry of its own (below), and
  // what a lookup reads past a row's end goes only into lanes left unused. On a CPU device a fresh buffer's pages
  // are each touched for the first time by the kernel that writes them: a seventh of the far field's time at 10^5
  // balls (docs/performance.md "Both layouts of the far field kept"). The room kept_at_least spares (within the
  // cap) spares a growing canopy a new buffer every year.
  const std::size_t row = far_row(patch_count);
  const std::size_t chunk = sweep_chunk(patch_count);
  const std::size_t table_bytes = cells * row * sizeof(float);
  const cl::Buffer& depth = kept_at_least(device, swept_kept, swept_layout_bytes(table_bytes, patch_count),
                                          swept_layout_bytes(table_cap_bytes, patch_count));
  // The layout by cell into a fresh buffer took three to four times as long as into a used one (docs/performance.md
  // "The far-field table kept from one solve to the next"). Only the rows of the cells a receiver reads are made
  // resident, since the layout writes no others (42-57 % of the cells are read by none at 10^6 and 10^5 balls). Once a
  // buffer, and again as the table grows: a solve of the same table found its rows resident, and its far field paid
  // up to 0.08 s at 10^5 balls to be told so.
  const cl::Buffer& table =
      kept_at_least(device, table_kept, table_bytes, table_cap_bytes, compute::Residency::parts_by_the_caller);
  if (compute::makes_pages_resident(device) && table_bytes > table_kept.resident_bytes) {
    make_rows_read_resident(device, table, read, cells, row * sizeof(float));
    table_kept.resident_bytes = table_bytes;
  }
  const std::size_t runs = (std::size_t(far.grid().dims.x) + 7) / 8;  // eight columns of a row a work item
  const std::size_t column_items = runs * far.grid().dims.y;
  int arg = 0;
  k.setArg(arg++, density_buffer);
  k.setArg(arg++, cl_int(margin));
  k.setArg(arg++, depth);
  k.setArg(arg++, patches);
  k.setArg(arg++, cell);
  k.setArg(arg++, dims);
  k.setArg(arg++, cl_int(periodic ? 1 : 0));
  const int layer_arg = arg++;
  k.setArg(arg++, float(far.max_path_m()));
  k.setArg(arg++, float(far.saturated_hits()));
  k.setArg(arg++, float(far.start_distance()));
  const int first_patch_arg = arg++;
  by_cell.setArg(0, depth);
  by_cell.setArg(1, read);
  by_cell.setArg(2, table);
  by_cell.setArg(3, cl_int(cells));
  // A chunk of patches at a time, swept and laid out before the next, so the sweep's own layout holds one chunk (its
  // first touch is what a first solve pays: docs/performance.md "The far field swept a chunk of patches at a time").
  for (std::size_t first = 0; first < row; first += chunk) {
    const std::size_t swept = std::min(chunk, patch_count - first);  // the rest of the row is padding
    k.setArg(first_patch_arg, cl_int(first));
    // Each layer reads the one swept before it: one launch per layer, in order on the in-order queue.
    for (int layer = 0; layer < far.grid().dims.z; ++layer) {
      k.setArg(layer_arg, cl_int(layer));
      compute::launch(device, k, column_items, swept);
    }
    by_cell.setArg(4, cl_int(first));
    compute::launch(device, by_cell, (cells + 7) / 8, std::min(chunk, row - first) / 8);
  }
  device.queue.finish();
  return table;
}

// Float keeps ~7 digits: coordinates go to the device relative to the middle of their stand (or group), so
// offsets between balls lose little.
glm::dvec3 float_origin(std::span<const glm::dvec3> centres) {
  glm::dvec3 low = centres[0], high = centres[0];
  for (const auto& c : centres) low = glm::min(low, c), high = glm::max(high, c);
  return glm::floor(0.5 * (low + high));
}

cl_float4 relative_ball(const glm::dvec3& centre, double radius, const glm::dvec3& origin) {
  const glm::dvec3 c = centre - origin;
  return {{float(c.x), float(c.y), float(c.z), float(radius)}};
}

// Each ball relative to the middle of its own group, the group it belongs to, and where each group starts: how
// light_each_alone and light_culled_and_alone read a tree, as if it were a stand of its own.
struct GroupFrames {
  std::vector<cl_float4> balls;
  std::vector<cl_int> group;
  std::vector<cl_int> group_start;
};

GroupFrames group_frames(std::span<const LeafBall> balls, std::span<const std::size_t> group_start) {
  GroupFrames frames{std::vector<cl_float4>(balls.size()), std::vector<cl_int>(balls.size()),
                     std::vector<cl_int>(group_start.begin(), group_start.end())};
  std::vector<glm::dvec3> centres;
  for (std::size_t g = 0; g + 1 < group_start.size(); ++g) {
    if (group_start[g] == group_start[g + 1]) continue;
    centres.clear();
    for (auto k = group_start[g]; k < group_start[g + 1]; ++k) centres.push_back(balls[k].centre);
    const glm::dvec3 origin = float_origin(centres);
    for (auto k = group_start[g]; k < group_start[g + 1]; ++k) {
      frames.balls[k] = relative_ball(balls[k].centre, balls[k].radius, origin);
      frames.group[k] = cl_int(g);
    }
  }
  return frames;
}

// A receiver's result as the kernels write it, (light vector, light), read back.
LightSample sample_of(const cl_float4& result) {
  LightSample sample;
  sample.light = result.s[3];
  sample.vector = glm::dvec3(result.s[0], result.s[1], result.s[2]);
  return sample;
}

// The first `count` results of a kernel's output buffer, read back (blocking) as samples in the same order.
std::vector<LightSample> read_samples(const cl::CommandQueue& queue, const cl::Buffer& out, std::size_t count) {
  std::vector<cl_float4> result(count);
  queue.enqueueReadBuffer(out, CL_TRUE, 0, count * sizeof(cl_float4), result.data());
  std::vector<LightSample> samples(count);
  for (std::size_t k = 0; k < count; ++k) samples[k] = sample_of(result[k]);
  return samples;
}

// Entries per axis in SkyData::axes: every patch and eight zeros, since the kernels test runs of eight patches
// (float8, cl/light.cl) from any patch. The kernels get it as the build option AXIS_STRIDE.
std::size_t axis_stride(std::size_t patch_count) { return patch_count + 8; }

// The sky as the kernels read it: (N, S) per patch, N again by axis (x of every patch, then y, then z,
// axis_stride apart) and B0 per patch.
struct SkyData {
  std::vector<cl_float4> patches;
  std::vector<float> axes;
  std::vector<float> b0;
};

SkyData sky_data_of(const CelestialSphere& sky) {
  SkyData data;
  for (const auto& patch : sky.patches()) {
    data.patches.push_back({{float(patch.direction.x), float(patch.direction.y), float(patch.direction.z),
                             float(patch.solid_angle)}});
    data.b0.push_back(float(patch.initial_intensity));
  }
  const std::size_t stride = axis_stride(data.patches.size());
  data.axes.assign(3 * stride, 0.0f);
  for (std::size_t p = 0; p < data.patches.size(); ++p)
    for (std::size_t axis = 0; axis < 3; ++axis) data.axes[axis * stride + p] = data.patches[p].s[axis];
  return data;
}

// Batches of eight near-field occluders whose windows the tile scan finds together (cl/light.cl,
// shade_by_tile_candidates). Two on a CPU, where the second batch's square roots and divisions run while the first's
// wait on theirs (docs/performance.md "Two batches' windows at a time, and the own tree read in lanes"); one on a GPU,
// whose work items would hold the second batch in scarce private memory, and where two were never measured.
int scan_batches(const compute::OpenCLContext& device) { return (device.type & CL_DEVICE_TYPE_CPU) ? 2 : 1; }

}  // namespace

struct OpenCLLightSolver::Device {
  compute::OpenCLContext cl;
  cl::Program program;
  cl::Kernel exact;
  cl::Kernel culled;
  cl::Kernel far_field_layer;
  cl::Kernel far_field_mark_read;
  cl::Kernel far_field_by_cell;
  cl::Kernel each_alone;
  cl::Kernel culled_and_alone;
  cl::Kernel tile_entries;
  KeptBuffer far_field_swept;  // sweep_far_field's own layout, [patch][cell]
  KeptBuffer far_field_table;  // sweep_far_field's, laid out by cell
  KeptBuffer far_field_read;   // mark_cells_read's, a byte a cell of the table
  KeptBuffer tile_entries_by_axis, tile_entry_tags;  // the tile lists as the culled kernels scan them
  KeptBuffer tile_lists;  // the tiles' occluders as the search lays them out (tile_lists_on_device)
};

// What the fused pass (light_culled_and_alone) adds to a culled solve: each receiver's group lit alone as `solver`
// (the exact open-plot one) would light it.
struct OpenCLLightSolver::AloneLight {
  const OpenCLLightSolver& solver;
  std::span<const std::size_t> group_start;
  std::vector<LightSample> samples;
};

OpenCLLightSolver::OpenCLLightSolver(const LightParameters& parameters, const compute::OpenCLContext& device)
    : parameters_(parameters) {
  validate(parameters_);
  // Before the kernels' build: a cap the device cannot hold is said now, not at the first solve's clCreateBuffer.
  if (auto reason = far_field_beyond_device(parameters_, device.memory, "opencl:" + device.description))
    throw FarFieldBeyondDevice(*reason);
  device_ = std::make_unique<Device>();
  device_->cl = device;
  const auto options = compute::KernelOptions()
                           .define("SKY_BANDS", parameters_.sky_bands)
                           .define("SKY_SECTORS", parameters_.sky_sectors)
                           .define("AXIS_STRIDE", int(axis_stride(parameters_.sky_bands * parameters_.sky_sectors)))
                           .define("FAR_ROW", int(far_row(parameters_.sky_bands * parameters_.sky_sectors)))
                           .define("SCAN_BATCHES", scan_batches(device))
                           .define("BALANCED_LIGHT_FRACTION", balanced_light_fraction);
  const std::string source = compute::kernel_source("far_field.cl") + compute::kernel_source("light.cl");
  device_->program = compute::build_program(device_->cl, source, options.text());
  device_->exact = cl::Kernel(device_->program, "light_exact");
  device_->culled = cl::Kernel(device_->program, "light_culled");
  device_->far_field_layer = cl::Kernel(device_->program, "far_field_layer");
  device_->far_field_mark_read = cl::Kernel(device_->program, "far_field_mark_read");
  device_->far_field_by_cell = cl::Kernel(device_->program, "far_field_by_cell");
  device_->each_alone = cl::Kernel(device_->program, "light_each_alone");
  device_->culled_and_alone = cl::Kernel(device_->program, "light_culled_and_alone");
  device_->tile_entries = cl::Kernel(device_->program, "tile_entries");
}

OpenCLLightSolver::~OpenCLLightSolver() = default;

std::vector<LightSample> OpenCLLightSolver::solve_each_alone(std::span<const LeafBall> balls,
                                                             std::span<const std::size_t> group_start) {
  if (!parameters_.exact || parameters_.periodic) return LightSolver::solve_each_alone(balls, group_start);
  check_groups(balls, group_start);
  statistics_ = {};
  if (balls.empty()) return {};
  const auto start = Clock::now();
  const GroupFrames frames = group_frames(balls, group_start);
  const CelestialSphere sky(parameters_);
  const SkyData sky_data = sky_data_of(sky);
  const auto& context = device_->cl.context;
  const cl::Buffer balls_buffer = read_only(context, frames.balls);
  const cl::Buffer groups_buffer = read_only(context, frames.group);
  const cl::Buffer starts_buffer = read_only(context, frames.group_start);
  const cl::Buffer patches_buffer = read_only(context, sky_data.patches);
  const cl::Buffer axes_buffer = read_only(context, sky_data.axes);
  const cl::Buffer b0_buffer = read_only(context, sky_data.b0);
  cl::Buffer out(context, CL_MEM_WRITE_ONLY, balls.size() * sizeof(cl_float4));
  auto& k = device_->each_alone;
  int arg = 0;
  k.setArg(arg++, balls_buffer);
  k.setArg(arg++, groups_buffer);
  k.setArg(arg++, starts_buffer);
  k.setArg(arg++, cl_int(balls.size()));
  k.setArg(arg++, patches_buffer);
  k.setArg(arg++, axes_buffer);
  k.setArg(arg++, b0_buffer);
  k.setArg(arg++, float(std::log(parameters_.transmittance)));
  k.setArg(arg++, out);
  compute::launch(device_->cl, k, balls.size());
  std::vector<LightSample> samples = read_samples(device_->cl.queue, out, balls.size());
  statistics_.evaluate_seconds = seconds_since(start);
  return samples;
}


std::string OpenCLLightSolver::name() const { return "opencl:" + device_->cl.description; }

std::vector<LightSample> OpenCLLightSolver::solve_for(std::span<const LeafBall> balls,
                                                      std::span<const std::uint32_t> receivers) {
  return solve_receivers(balls, receivers, nullptr);
}

bool OpenCLLightSolver::groups_clear_of_own_images(std::span<const LeafBall> balls,
                                                   std::span<const std::size_t> group_start) const {
  const PlotTorus torus = PlotTorus::from(parameters_);
  if (!torus.periodic) return true;
  // An image lies a plot width (depth) from its ball: it stays beyond the cut-off of every ball of its group when
  // the group's centres span less than the plot less the cut-off (1 cm spare for the kernel's float test).
  const glm::dvec2 reach = torus.size - parameters_.cutoff_m - 0.01;
  for (std::size_t g = 0; g + 1 < group_start.size(); ++g) {
    if (group_start[g] == group_start[g + 1]) continue;
    glm::dvec2 low(balls[group_start[g]].centre), high = low;
    for (auto k = group_start[g]; k < group_start[g + 1]; ++k)
      low = glm::min(low, glm::dvec2(balls[k].centre)), high = glm::max(high, glm::dvec2(balls[k].centre));
    if (high.x - low.x >= reach.x || high.y - low.y >= reach.y) return false;
  }
  return true;
}

std::optional<LightSolver::StandAndAlone> OpenCLLightSolver::solve_with_each_alone(
    std::span<const LeafBall> balls, std::span<const std::size_t> group_start, const LightSolver& alone) {
  // Only on a CPU device: there the one pass saves projecting each tree's own balls twice (the hectare's light 0.92
  // of two passes on PoCL), while on a GPU its two skies per work item cost more than the second launch (an H100:
  // 1.14x two passes' light in both of two pairs, docs/performance.md "The one pass on a GPU").
  if (!(device_->cl.type & CL_DEVICE_TYPE_CPU)) return std::nullopt;
  const auto* open = dynamic_cast<const OpenCLLightSolver*>(&alone);
  if (open == nullptr || parameters_.exact || !open->parameters_.exact || open->parameters_.periodic) return std::nullopt;
  const LightParameters& q = open->parameters_;
  const bool same_sky = q.sky_bands == parameters_.sky_bands && q.sky_sectors == parameters_.sky_sectors &&
                        q.transmittance == parameters_.transmittance;
  if (!same_sky || open->device_->cl.context() != device_->cl.context()) return std::nullopt;
  check_groups(balls, group_start);
  if (!groups_clear_of_own_images(balls, group_start)) return std::nullopt;
  AloneLight light{*open, group_start, std::vector<LightSample>(balls.size())};
  std::vector<std::uint32_t> everyone(balls.size());
  std::iota(everyone.begin(), everyone.end(), 0u);
  StandAndAlone both;
  both.stand = solve_receivers(balls, everyone, &light);
  both.alone = std::move(light.samples);
  return both;
}

// One solve's stand on the device: the balls (and, culled on a periodic plot, their images within the cut-off of an
// edge) relative to `origin`, and the sky, as every light kernel reads them.
struct OpenCLLightSolver::DeviceStand {
  std::chrono::steady_clock::time_point setup_start;
  CelestialSphere sky;
  PlotTorus torus;
  OccluderSet set;
  glm::dvec3 origin;
  cl::Buffer balls, patches, axes, b0;
  float log_t;
};

// One solve's far-field table on the device, laid out by cell, and where its grid lies relative to the stand's
// origin. Without a far field: one cell of zeros and no attenuation.
struct OpenCLLightSolver::FarFieldTable {
  cl::Buffer table;
  cl_float4 grid_origin, grid_cell;
  cl_int4 grid_dims;
  float attenuation;
  double cell_m;  // LightSolveStatistics::far_field_cell_m
};

// What the fused pass (light_culled_and_alone) reads besides the stand: each group in its own frame, the group of
// every occluder entry (an image's is its ball's), where each group starts, and the open-grown solver's B0.
struct OpenCLLightSolver::FusedPass {
  cl::Buffer group_balls, entry_group, group_start, alone_b0;
};

// The tile lists as the culled kernels scan them (cl/light.cl, tile_entries), and which part of which list each
// receiver scans, in the tiles' order of receivers.
struct OpenCLLightSolver::TileScan {
  const cl::Buffer& entries;
  const cl::Buffer& tags;
  std::size_t entry_stride;
  std::vector<cl_int> receiver_balls;
  std::vector<cl_int2> receiver_scan;  // first and end of the part of its tile's list each receiver scans
};

// The culled kernel's results, in the tiles' order of receivers: the stand's light and, in the fused pass, each
// receiver's group alone.
struct OpenCLLightSolver::CulledLight {
  std::vector<cl_float4> stand, alone;
};

std::vector<LightSample> OpenCLLightSolver::solve_receivers(std::span<const LeafBall> balls,
                                                            std::span<const std::uint32_t> receivers,
                                                            AloneLight* alone) {
  check_receivers(balls, receivers);
  statistics_ = {};
  if (receivers.empty()) return {};
  const DeviceStand stand = stand_on_device(balls);
  return parameters_.exact ? solve_exact(stand, receivers) : solve_culled(stand, balls, receivers, alone);
}

OpenCLLightSolver::DeviceStand OpenCLLightSolver::stand_on_device(std::span<const LeafBall> balls) const {
  const auto setup_start = Clock::now();
  const CelestialSphere sky(parameters_);
  const PlotTorus torus = PlotTorus::from(parameters_);
  OccluderSet set = make_occluder_set(balls, torus, parameters_.exact ? 0.0 : parameters_.cutoff_m);
  const glm::dvec3 origin = float_origin(set.centres);
  std::vector<cl_float4> ball_data(set.centres.size());
  for (std::size_t k = 0; k < set.centres.size(); ++k) ball_data[k] = relative_ball(set.centres[k], set.radii[k], origin);
  const SkyData sky_data = sky_data_of(sky);
  const auto& context = device_->cl.context;
  return DeviceStand{setup_start,
                     sky,
                     torus,
                     std::move(set),
                     origin,
                     read_only(context, ball_data),
                     read_only(context, sky_data.patches),
                     read_only(context, sky_data.axes),
                     read_only(context, sky_data.b0),
                     float(std::log(parameters_.transmittance))};
}

std::vector<LightSample> OpenCLLightSolver::solve_exact(const DeviceStand& stand,
                                                        std::span<const std::uint32_t> receivers) {
  statistics_.setup_seconds = 0;
  const double ball_count = double(stand.set.ball_count);
  statistics_.mean_candidates = stand.torus.periodic ? 9.0 * ball_count - 1 : ball_count - 1;
  const auto start = Clock::now();
  const auto& context = device_->cl.context;
  std::vector<cl_int> receiver_data(receivers.begin(), receivers.end());
  const cl::Buffer receivers_buffer = read_only(context, receiver_data);
  cl::Buffer out(context, CL_MEM_WRITE_ONLY, receivers.size() * sizeof(cl_float4));
  auto& k = device_->exact;
  int arg = 0;
  k.setArg(arg++, stand.balls);
  k.setArg(arg++, cl_int(stand.set.ball_count));
  k.setArg(arg++, receivers_buffer);
  k.setArg(arg++, cl_int(receivers.size()));
  k.setArg(arg++, stand.patches);
  k.setArg(arg++, stand.axes);
  k.setArg(arg++, stand.b0);
  k.setArg(arg++, stand.log_t);
  k.setArg(arg++, cl_int(stand.torus.periodic ? 1 : 0));
  k.setArg(arg++, float(stand.torus.size.x));
  k.setArg(arg++, float(stand.torus.size.y));
  k.setArg(arg++, out);
  compute::launch(device_->cl, k, receivers.size());
  std::vector<LightSample> samples = read_samples(device_->cl.queue, out, receivers.size());
  statistics_.evaluate_seconds = seconds_since(start);
  return samples;
}

std::vector<LightSample> OpenCLLightSolver::solve_culled(const DeviceStand& stand, std::span<const LeafBall> balls,
                                                         std::span<const std::uint32_t> receivers,
                                                         AloneLight* alone) {
  // The kernels index the balls, and read the receivers' and occluders' indices, as int.
  if (stand.set.centres.size() > std::size_t(std::numeric_limits<cl_int>::max()))
    throw std::runtime_error("the light's stand holds " + std::to_string(stand.set.centres.size()) +
                             " leaf balls with their periodic images, more than the OpenCL kernels can index");
  auto part_start = Clock::now();
  const NearFieldSearch search(stand.set, parameters_.cutoff_m);
  statistics_.search_seconds = seconds_since(part_start);
  part_start = Clock::now();
  const FarFieldTable far = far_field_on_device(stand, receivers);
  statistics_.far_field_cell_m = far.cell_m;
  statistics_.far_field_seconds = seconds_since(part_start);
  statistics_.setup_seconds = seconds_since(stand.setup_start);

  // Near-field candidates, one list per tile of receivers (light/near_field.hpp), laid out for the scan.
  part_start = Clock::now();
  const TileCandidates near = tile_lists_on_device(device_->cl, search, receivers, tile_edge_for(parameters_.cutoff_m),
                                                   device_->tile_lists);
  double search_seconds = seconds_since(part_start);
  const std::optional<FusedPass> fused =
      alone != nullptr ? std::optional<FusedPass>(fused_pass_on_device(stand, balls, *alone)) : std::nullopt;
  part_start = Clock::now();
  const TileScan scan = tile_scan_on_device(stand, near, receivers, fused ? &*fused : nullptr);
  search_seconds += seconds_since(part_start);

  const auto start = Clock::now();
  const CulledLight light = shade_culled(stand, far, scan, fused ? &*fused : nullptr);
  std::vector<LightSample> samples(receivers.size());
  std::size_t candidate_total = 0;
  for (std::size_t k = 0; k < receivers.size(); ++k) {
    samples[near.slots[k]] = sample_of(light.stand[k]);
    if (alone != nullptr) alone->samples[receivers[near.slots[k]]] = sample_of(light.alone[k]);
    candidate_total += std::size_t(scan.receiver_scan[k].s[1] - scan.receiver_scan[k].s[0]);
  }
  statistics_.evaluate_seconds = seconds_since(start);
  statistics_.setup_seconds += search_seconds;
  statistics_.search_seconds += search_seconds;
  // The kernel discards the tile's occluders beyond each receiver's cut-off without counting them, so only the
  // scanned length is known here (the reference solver reports both).
  statistics_.mean_tile_candidates = double(candidate_total) / receivers.size();
  return samples;
}

// The far field: density on the host (O(balls)), optical-depth table swept on the device, where it stays.
// Without a far field the kernel gets a one-cell table of zeros and a zero attenuation factor.
OpenCLLightSolver::FarFieldTable OpenCLLightSolver::far_field_on_device(const DeviceStand& stand,
                                                                        std::span<const std::uint32_t> receivers) {
  const std::size_t patch_count = stand.sky.patches().size();
  const std::optional<FarField> far =
      parameters_.far_field ? std::optional<FarField>(std::in_place, stand.set, parameters_, stand.sky, false)
                            : std::nullopt;
  const VoxelGrid grid = far ? far->grid() : VoxelGrid{};
  const glm::dvec3 grid_origin = grid.origin - stand.origin;
  FarFieldTable on_device{cl::Buffer(),
                          {{float(grid_origin.x), float(grid_origin.y), float(grid_origin.z), 0.0f}},
                          {{float(grid.cell.x), float(grid.cell.y), float(grid.cell.z), 0.0f}},
                          {{grid.dims.x, grid.dims.y, grid.dims.z, 0}},
                          far ? float(1.0 - parameters_.transmittance) : 0.0f,
                          far ? grid.cell.z : 0.0};  // z is never stretched to fit a periodic plot
  if (!far) {
    on_device.table = read_only(device_->cl.context, std::vector<float>(far_row(patch_count), 0.0f));  // one empty cell
    return on_device;
  }
  const cl::Buffer& read = mark_cells_read(device_->cl, device_->far_field_mark_read, stand.balls, receivers,
                                           on_device.grid_origin, on_device.grid_cell, on_device.grid_dims,
                                           stand.torus.periodic, device_->far_field_read);
  on_device.table = sweep_far_field(device_->cl, device_->far_field_layer, device_->far_field_by_cell, *far,
                                    stand.sky.patches(), stand.patches, on_device.grid_cell, on_device.grid_dims,
                                    stand.torus.periodic, read, device_->far_field_swept, device_->far_field_table,
                                    far_table_cap_bytes(parameters_, patch_count));
  return on_device;
}

// The fused pass's inputs. B0 is the open-grown solver's (a different sky_scale rounds differently); the patches are
// the stand's, since solve_with_each_alone fuses only with the same bands and sectors.
OpenCLLightSolver::FusedPass OpenCLLightSolver::fused_pass_on_device(const DeviceStand& stand,
                                                                     std::span<const LeafBall> balls,
                                                                     const AloneLight& alone) const {
  const GroupFrames frames = group_frames(balls, alone.group_start);
  std::vector<cl_int> entry_group(stand.set.centres.size());
  for (std::size_t k = 0; k < entry_group.size(); ++k) entry_group[k] = frames.group[stand.set.source[k]];
  const auto& context = device_->cl.context;
  return FusedPass{read_only(context, frames.balls), read_only(context, entry_group),
                   read_only(context, frames.group_start),
                   read_only(context, sky_data_of(CelestialSphere(alone.solver.parameters_)).b0)};
}

// The tile lists laid out on the device for the scan (cl/light.cl, tile_entries): each entry's ball copied in, by
// axis, and its tag (its group, given the `fused` pass), read in order eight at a time by the culled
// kernels. That scan costs less than reading the balls through the lists' indices did (docs/performance.md "Narrow
// windows in one run a band, and the tile lists read in order"), for 20 bytes an entry on the device where the index
// took 4; the buffers are kept from one solve to the next, as the far field's table is.
OpenCLLightSolver::TileScan OpenCLLightSolver::tile_scan_on_device(const DeviceStand& stand,
                                                                   const TileCandidates& near,
                                                                   std::span<const std::uint32_t> receivers,
                                                                   const FusedPass* fused) {
  std::vector<cl_int> receiver_balls(receivers.size());
  std::vector<cl_int2> receiver_scan(receivers.size());
  for (std::size_t tile = 0; tile < near.tile_count(); ++tile)
    for (auto k = near.slot_start[tile]; k < near.slot_start[tile + 1]; ++k) {
      receiver_balls[k] = cl_int(receivers[near.slots[k]]);
      receiver_scan[k] = {{cl_int(near.start[tile]), cl_int(near.scan_end[k])}};
    }
  const std::size_t entry_stride = near.entry_count() + 8;  // room for a run of eight from the last entry
  if (4 * entry_stride > std::size_t(std::numeric_limits<cl_int>::max()))  // the kernels index them with int
    throw std::runtime_error("the light's near-field tile lists hold " + std::to_string(near.entry_count()) +
                             " entries, more than the OpenCL kernels can index; use a shorter [light] cutoff_m");
  const cl::Buffer& entries =
      kept_at_least(device_->cl, device_->tile_entries_by_axis, 4 * entry_stride * sizeof(float));
  const cl::Buffer& tags = kept_at_least(device_->cl, device_->tile_entry_tags, entry_stride * sizeof(cl_int));
  // The indices as the search wrote them (unsigned, read as int by the kernel: the balls are fewer than 2^31, checked
  // by solve_culled), in the buffer tile_lists_on_device wrote them to.
  const cl::Buffer& occluders = device_->tile_lists.buffer;
  auto& k = device_->tile_entries;
  int arg = 0;
  k.setArg(arg++, stand.balls);
  k.setArg(arg++, occluders);
  k.setArg(arg++, cl_int(near.entry_count()));
  k.setArg(arg++, fused != nullptr ? fused->entry_group : occluders);  // read only when tagged by group
  k.setArg(arg++, cl_int(fused != nullptr ? 1 : 0));
  k.setArg(arg++, cl_int(entry_stride));
  k.setArg(arg++, entries);
  k.setArg(arg++, tags);
  compute::launch(device_->cl, k, entry_stride);
  device_->cl.queue.finish();  // the index list goes here; the layout's time is the search's
  return TileScan{entries, tags, entry_stride, std::move(receiver_balls), std::move(receiver_scan)};
}

// The culled kernel (light_culled, or light_culled_and_alone given `fused`) over every receiver of `scan`, in
// launches of at most `culled_chunk` receivers, which keep one launch's run time and output buffer bounded.
OpenCLLightSolver::CulledLight OpenCLLightSolver::shade_culled(const DeviceStand& stand, const FarFieldTable& far,
                                                               const TileScan& scan, const FusedPass* fused) {
  const auto& context = device_->cl.context;
  auto& queue = device_->cl.queue;
  const std::size_t receiver_count = scan.receiver_balls.size();
  CulledLight light{std::vector<cl_float4>(receiver_count),
                    std::vector<cl_float4>(fused != nullptr ? receiver_count : 0)};
  for (std::size_t first = 0; first < receiver_count; first += culled_chunk) {
    const std::size_t count = std::min(culled_chunk, receiver_count - first);
    const cl::Buffer receivers_buffer = read_only(context, std::span(scan.receiver_balls).subspan(first, count));
    const cl::Buffer scan_buffer = read_only(context, std::span(scan.receiver_scan).subspan(first, count));
    cl::Buffer out(context, CL_MEM_WRITE_ONLY, count * sizeof(cl_float4));
    const std::optional<cl::Buffer> alone_out =
        fused != nullptr ? std::optional<cl::Buffer>(std::in_place, context, CL_MEM_WRITE_ONLY, count * sizeof(cl_float4))
                         : std::nullopt;
    auto& k = fused != nullptr ? device_->culled_and_alone : device_->culled;
    int arg = 0;
    k.setArg(arg++, stand.balls);
    k.setArg(arg++, receivers_buffer);
    k.setArg(arg++, scan_buffer);
    k.setArg(arg++, cl_int(count));
    k.setArg(arg++, scan.entries);
    k.setArg(arg++, cl_int(scan.entry_stride));
    k.setArg(arg++, scan.tags);
    if (fused != nullptr) {
      k.setArg(arg++, fused->entry_group);
      k.setArg(arg++, fused->group_balls);
      k.setArg(arg++, fused->group_start);
    }
    k.setArg(arg++, stand.patches);
    k.setArg(arg++, stand.axes);
    k.setArg(arg++, stand.b0);
    if (fused != nullptr) k.setArg(arg++, fused->alone_b0);
    k.setArg(arg++, stand.log_t);
    k.setArg(arg++, far.table);
    k.setArg(arg++, far.grid_origin);
    k.setArg(arg++, far.grid_cell);
    k.setArg(arg++, far.grid_dims);
    k.setArg(arg++, cl_int(stand.torus.periodic ? 1 : 0));
    k.setArg(arg++, float(parameters_.cutoff_m));
    k.setArg(arg++, far.attenuation);
    k.setArg(arg++, out);
    if (fused != nullptr) k.setArg(arg++, *alone_out);
    compute::launch(device_->cl, k, count);
    queue.enqueueReadBuffer(out, CL_TRUE, 0, count * sizeof(cl_float4), light.stand.data() + first);
    if (fused != nullptr)
      queue.enqueueReadBuffer(*alone_out, CL_TRUE, 0, count * sizeof(cl_float4), light.alone.data() + first);
  }
  return light;
}

}  // namespace heliostand
