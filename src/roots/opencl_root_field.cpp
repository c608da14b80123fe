#include "roots/opencl_root_field.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include <CL/opencl.hpp>
#include <glm/geometric.hpp>

#include "compute/kernel_options.hpp"
#include "compute/kernel_sources.hpp"
#include "compute/opencl_kept_buffer.hpp"
#include "compute/opencl_context.hpp"
#include "core/parallel_for.hpp"
#include "roots/segment_grid.hpp"

namespace heliostand::roots {

using compute::kept_at_least;
using compute::KeptBuffer;
using compute::MappedForWriting;

struct OpenCLRootFieldSolver::State {
  compute::OpenCLContext cl;
  cl::Program program;
  cl::Kernel kernel;
  // The year's field (begin_year): the grid's geometry (its index arrays live only on the device), the frame.
  bool has_year = false;
  SegmentGrid grid;
  glm::dvec3 frame{0.0};
  bool has_soil = false;
  // Every buffer is kept from one year to the next and written again (compute/opencl_kept_buffer.hpp): a hectare's
  // segments fill some 200 MB of them a year, which made anew were as many fresh pages each year.
  KeptBuffer middle, start, end, segment_id, cell_start, moisture;
  // One query's apices, probes and answers, reused by the next query.
  KeptBuffer tips, excluded, probes, contact_out, moisture_out;
};

namespace {

cl_float4 to_float4(const glm::dvec3& v, double w = 0.0) {
  return {{static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), static_cast<float>(w)}};
}

// `data` into `kept` (grown when too small; OpenCL forbids zero-sized buffers, so it holds at least one element).
template <class T>
void kept_holding(compute::OpenCLContext& cl, KeptBuffer& kept, const std::vector<T>& data) {
  const cl::Buffer& buffer = kept_at_least(cl, kept, sizeof(T) * std::max<std::size_t>(data.size(), 1));
  if (!data.empty()) cl.queue.enqueueWriteBuffer(buffer, CL_TRUE, 0, sizeof(T) * data.size(), data.data());
}

// Segments this many at a time are mapped for the host to write (on a GPU a mapping may be a host copy, so the host
// never holds a float copy of the whole stand beside the device's).
constexpr std::size_t segments_per_upload = std::size_t{1} << 16;
// A worker thread's share of the host's conversions (segments of an upload, apices of a query).
constexpr std::size_t items_per_block = std::size_t{1} << 12;

// The year's segments in the grid's cell order (the kernel walks a cell's segments contiguously), each with its
// midpoint and half length for a cheap first test, relative to `frame`, written into the kept `middle`, `start` and
// `end`.
void segments_on_device(compute::OpenCLContext& cl, const SegmentList& segments, const SegmentGrid& grid,
                        const glm::dvec3& frame, KeptBuffer& middle, KeptBuffer& start, KeptBuffer& end) {
  const std::size_t bytes = sizeof(cl_float4) * std::max<std::size_t>(segments.size(), 1);
  const cl::Buffer& middles = kept_at_least(cl, middle, bytes);
  const cl::Buffer& starts = kept_at_least(cl, start, bytes);
  const cl::Buffer& ends = kept_at_least(cl, end, bytes);
  for (std::size_t first = 0; first < segments.size(); first += segments_per_upload) {
    const std::size_t count_here = std::min(segments.size() - first, segments_per_upload);
    const std::size_t offset = sizeof(cl_float4) * first, length = sizeof(cl_float4) * count_here;
    MappedForWriting middles_here(cl.queue, middles, length, offset), starts_here(cl.queue, starts, length, offset),
        ends_here(cl.queue, ends, length, offset);
    auto* const middle_data = static_cast<cl_float4*>(middles_here.data());
    auto* const start_data = static_cast<cl_float4*>(starts_here.data());
    auto* const end_data = static_cast<cl_float4*>(ends_here.data());
    // Entries convert independently (a gather from the trees' lists in cell order): blocks of them go to the worker
    // threads, since this host work is not shortened by a faster device.
    parallel_for_blocks(count_here, items_per_block, [&](std::size_t from, std::size_t to) {
      for (std::size_t k = from; k < to; ++k) {
        const RootSegmentLine segment = segments[static_cast<std::size_t>(grid.cell_segments[first + k])];
        middle_data[k] =
            to_float4(0.5 * (segment.start + segment.end) - frame, 0.5 * glm::length(segment.end - segment.start));
        start_data[k] = to_float4(segment.start - frame);
        end_data[k] = to_float4(segment.end - frame);
      }
    });
    middles_here.unmap();
    starts_here.unmap();
    ends_here.unmap();
  }
}

// The soil's moisture at its vertices and where they lie relative to `frame`; without soil, one unused value (the
// kernel is told there is none).
struct SoilOnDevice {
  cl_int4 vertices{{2, 2, 2, 0}};
  cl_float4 origin{{0, 0, 0, 0}};
  float spacing = 1.0f;
};

SoilOnDevice soil_on_device(compute::OpenCLContext& cl, const SoilGrid* soil, const glm::dvec3& frame,
                            KeptBuffer& kept) {
  SoilOnDevice on_device;
  std::vector<float> moisture;
  if (soil != nullptr) {
    const std::vector<double>& values = soil->values(SoilField::moisture);
    moisture.assign(values.begin(), values.end());
    const glm::ivec3 n = soil->vertex_counts();
    on_device.vertices = {{n.x, n.y, n.z, 0}};
    on_device.origin = to_float4(soil->min_corner() - frame);
    on_device.spacing = static_cast<float>(soil->geometry().spacing_m);
  }
  kept_holding(cl, kept, moisture);
  return on_device;
}

}  // namespace

OpenCLRootFieldSolver::OpenCLRootFieldSolver(const compute::OpenCLContext& device) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.cl = device;
  const auto options = compute::KernelOptions().flag("-cl-std=CL1.2").define("TOUCHING_DISTANCE", touching_distance_m);
  s.program = compute::build_program(s.cl, compute::kernel_source("roots.cl"), options.text());
  s.kernel = cl::Kernel(s.program, "root_contact_field");
}

OpenCLRootFieldSolver::~OpenCLRootFieldSolver() = default;

std::string OpenCLRootFieldSolver::name() const { return "opencl:" + state_->cl.description; }

void OpenCLRootFieldSolver::begin_year(const RootFieldYear& year) {
  State& s = *state_;
  s.grid = SegmentGrid::build(year.segments, year.widest_perception_radius_m);
  // One frame origin for everything on the device keeps float positions small (sub-micrometre over 100 m).
  s.frame = year.soil != nullptr ? year.soil->min_corner() : s.grid.origin;
  segments_on_device(s.cl, year.segments, s.grid, s.frame, s.middle, s.start, s.end);
  // Each segment's index in the year's list, for the exclusions, and where each cell's segments start.
  kept_holding(s.cl, s.segment_id, s.grid.cell_segments);
  kept_holding(s.cl, s.cell_start, s.grid.cell_start);
  // The device has the grid's index arrays now; the host keeps only its geometry (to sort apices by cell).
  std::vector<int>().swap(s.grid.cell_segments);
  std::vector<int>().swap(s.grid.cell_start);
  const SoilOnDevice soil = soil_on_device(s.cl, year.soil, s.frame, s.moisture);
  s.has_soil = year.soil != nullptr;

  s.kernel.setArg(0, s.middle.buffer);
  s.kernel.setArg(1, s.start.buffer);
  s.kernel.setArg(2, s.end.buffer);
  s.kernel.setArg(3, s.segment_id.buffer);
  s.kernel.setArg(4, s.cell_start.buffer);
  s.kernel.setArg(5, cl_int4{{s.grid.dims.x, s.grid.dims.y, s.grid.dims.z, 0}});
  s.kernel.setArg(6, to_float4(s.grid.origin - s.frame));
  s.kernel.setArg(7, static_cast<float>(s.grid.cell_size_m));
  s.kernel.setArg(8, static_cast<float>(s.grid.longest_half_m));
  s.kernel.setArg(14, s.moisture.buffer);
  s.kernel.setArg(15, soil.vertices);
  s.kernel.setArg(16, soil.origin);
  s.kernel.setArg(17, soil.spacing);
  s.kernel.setArg(18, static_cast<cl_int>(s.has_soil ? 1 : 0));
  s.has_year = true;
}

// The buffers stay for the next year's field (written anew in begin_year); only the year is over.
void OpenCLRootFieldSolver::end_year() { state_->has_year = false; }

std::vector<RootFieldSample> OpenCLRootFieldSolver::query(std::span<const RootTipQuery> tips,
                                                          std::span<const glm::dvec3> probes, int probes_per_tip) {
  State& s = *state_;
  if (!s.has_year) throw std::logic_error("OpenCLRootFieldSolver::query before begin_year");
  std::vector<RootFieldSample> samples(tips.size());
  if (tips.empty()) return samples;

  // Apices in cell order: neighbouring work-items then walk the same cells (SIMD lanes and caches agree).
  std::vector<std::size_t> order(tips.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::vector<std::size_t> tip_cell(tips.size());
  parallel_for_blocks(tips.size(), items_per_block, [&](std::size_t from, std::size_t to) {
    for (std::size_t t = from; t < to; ++t) tip_cell[t] = s.grid.cell_index(s.grid.cell_of(tips[t].position));
  });
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return tip_cell[a] < tip_cell[b]; });
  const auto per_tip = static_cast<std::size_t>(s.has_soil ? std::max(probes_per_tip, 0) : 0);
  const std::size_t tip_count = tips.size(), probe_count = std::max<std::size_t>(tip_count * per_tip, 1);
  const cl::Buffer& tip_buffer = kept_at_least(s.cl, s.tips, sizeof(cl_float4) * tip_count);
  const cl::Buffer& excluded_buffer = kept_at_least(s.cl, s.excluded, sizeof(cl_int2) * tip_count);
  const cl::Buffer& probe_buffer = kept_at_least(s.cl, s.probes, sizeof(cl_float4) * probe_count);
  {
    // The apices and probes written where the kernel reads them (mapped), in cell order.
    MappedForWriting tips_here(s.cl.queue, tip_buffer, sizeof(cl_float4) * tip_count),
        excluded_here(s.cl.queue, excluded_buffer, sizeof(cl_int2) * tip_count),
        probes_here(s.cl.queue, probe_buffer, sizeof(cl_float4) * probe_count);
    auto* const tip_data = static_cast<cl_float4*>(tips_here.data());
    auto* const excluded_data = static_cast<cl_int2*>(excluded_here.data());
    auto* const probe_data = static_cast<cl_float4*>(probes_here.data());
    parallel_for_blocks(tip_count, items_per_block, [&](std::size_t from, std::size_t to) {
      for (std::size_t i = from; i < to; ++i) {
        const RootTipQuery& tip = tips[order[i]];
        tip_data[i] = to_float4(tip.position - s.frame, tip.perception_radius_m);
        excluded_data[i] = {{tip.excluded[0], tip.excluded[1]}};
        for (std::size_t p = 0; p < per_tip; ++p) probe_data[i * per_tip + p] = to_float4(probes[order[i] * per_tip + p]);
      }
    });
    tips_here.unmap();
    excluded_here.unmap();
    probes_here.unmap();
  }

  s.kernel.setArg(9, tip_buffer);
  s.kernel.setArg(10, excluded_buffer);
  s.kernel.setArg(11, static_cast<cl_int>(tip_count));
  s.kernel.setArg(12, probe_buffer);
  s.kernel.setArg(13, static_cast<cl_int>(per_tip));
  s.kernel.setArg(19, kept_at_least(s.cl, s.contact_out, sizeof(cl_float4) * tip_count));
  s.kernel.setArg(20, kept_at_least(s.cl, s.moisture_out, sizeof(cl_float4) * tip_count));
  compute::launch(s.cl, s.kernel, tip_count);

  std::vector<cl_float4> contacts(tip_count), pulls(tip_count);
  s.cl.queue.enqueueReadBuffer(s.contact_out.buffer, CL_FALSE, 0, sizeof(cl_float4) * tip_count, contacts.data());
  s.cl.queue.enqueueReadBuffer(s.moisture_out.buffer, CL_TRUE, 0, sizeof(cl_float4) * tip_count, pulls.data());
  for (std::size_t i = 0; i < tip_count; ++i) {
    RootFieldSample& sample = samples[order[i]];
    sample.contact_avoidance = {contacts[i].s[0], contacts[i].s[1], contacts[i].s[2]};
    sample.contacts = static_cast<int>(contacts[i].s[3]);
    sample.moisture_pull = {pulls[i].s[0], pulls[i].s[1], pulls[i].s[2]};
  }
  return samples;
}

}  // namespace heliostand::roots
