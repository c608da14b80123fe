#include "roots/opencl_root_field.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include <CL/opencl.hpp>
#include <glm/geometric.hpp>

#include "compute/kernel_options.hpp"
#include "compute/kernel_sources.hpp"
#include "compute/opencl_context.hpp"
#include "roots/segment_grid.hpp"

namespace heliostand::roots {

struct OpenCLRootFieldSolver::State {
  compute::OpenCLContext cl;
  cl::Program program;
  cl::Kernel kernel;
};

namespace {

cl_float4 to_float4(const glm::dvec3& v, double w = 0.0) {
  return {{static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), static_cast<float>(w)}};
}

// OpenCL forbids zero-sized buffers: empty inputs get one unused element.
template <class T>
cl::Buffer read_only_buffer(const cl::Context& context, std::vector<T>& data) {
  if (data.empty()) data.emplace_back();
  return cl::Buffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(T) * data.size(), data.data());
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

std::vector<RootFieldSample> OpenCLRootFieldSolver::solve(const RootFieldInput& input) {
  std::vector<RootFieldSample> samples(input.tips.size());
  if (input.tips.empty()) return samples;
  State& s = *state_;

  double widest_sphere = 0.0;
  for (const RootTipQuery& tip : input.tips) widest_sphere = std::max(widest_sphere, tip.perception_radius_m);
  double longest_half = 0.0;
  for (const RootSegmentLine& segment : input.segments)
    longest_half = std::max(longest_half, 0.5 * glm::length(segment.end - segment.start));
  // Cells half the widest reach: a query visits at most 5³ cells and skips those wholly outside its reach,
  // which hugs the sphere more tightly than 3³ cells of a whole reach.
  const SegmentGrid grid = SegmentGrid::build(input.segments, 0.5 * (widest_sphere + longest_half));

  // One frame origin for everything on the device keeps float positions small (sub-micrometre over 100 m).
  const glm::dvec3 frame = input.soil != nullptr ? input.soil->min_corner() : grid.origin;
  // Segments in cell order (the kernel walks a cell's segments contiguously), each with its midpoint and
  // half length for a cheap first test, and its index in the caller's list for the exclusions.
  std::vector<cl_float4> middles, starts, ends, tips, probes;
  std::vector<cl_int2> excluded;
  middles.reserve(input.segments.size());
  starts.reserve(input.segments.size());
  ends.reserve(input.segments.size());
  for (int s : grid.cell_segments) {
    const RootSegmentLine& segment = input.segments[s];
    middles.push_back(to_float4(0.5 * (segment.start + segment.end) - frame, 0.5 * glm::length(segment.end - segment.start)));
    starts.push_back(to_float4(segment.start - frame));
    ends.push_back(to_float4(segment.end - frame));
  }
  // Apices in cell order too: neighbouring work-items then walk the same cells (SIMD lanes and caches agree).
  std::vector<std::size_t> order(input.tips.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::vector<std::size_t> tip_cell(input.tips.size());
  for (std::size_t t = 0; t < input.tips.size(); ++t) tip_cell[t] = grid.cell_index(grid.cell_of(input.tips[t].position));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return tip_cell[a] < tip_cell[b]; });
  const int probes_per_tip = input.soil != nullptr ? std::max(input.probes_per_tip, 0) : 0;
  for (std::size_t t : order) {
    const RootTipQuery& tip = input.tips[t];
    tips.push_back(to_float4(tip.position - frame, tip.perception_radius_m));
    excluded.push_back({{tip.excluded[0], tip.excluded[1]}});
    for (int p = 0; p < probes_per_tip; ++p) probes.push_back(to_float4(input.probes[t * probes_per_tip + p]));
  }
  std::vector<float> moisture;
  cl_int4 soil_vertices{{2, 2, 2, 0}};
  cl_float4 soil_origin{{0, 0, 0, 0}};
  float soil_spacing = 1.0f;
  if (input.soil != nullptr) {
    const std::vector<double>& values = input.soil->values(SoilField::moisture);
    moisture.assign(values.begin(), values.end());
    const glm::ivec3 n = input.soil->vertex_counts();
    soil_vertices = {{n.x, n.y, n.z, 0}};
    soil_origin = to_float4(input.soil->min_corner() - frame);
    soil_spacing = static_cast<float>(input.soil->geometry().spacing_m);
  }
  std::vector<int> cell_start = grid.cell_start, segment_ids = grid.cell_segments;

  cl::Buffer middle_buffer = read_only_buffer(s.cl.context, middles);
  cl::Buffer start_buffer = read_only_buffer(s.cl.context, starts);
  cl::Buffer end_buffer = read_only_buffer(s.cl.context, ends);
  cl::Buffer segment_id_buffer = read_only_buffer(s.cl.context, segment_ids);
  cl::Buffer cell_start_buffer = read_only_buffer(s.cl.context, cell_start);
  cl::Buffer tip_buffer = read_only_buffer(s.cl.context, tips);
  cl::Buffer excluded_buffer = read_only_buffer(s.cl.context, excluded);
  cl::Buffer probe_buffer = read_only_buffer(s.cl.context, probes);
  cl::Buffer moisture_buffer = read_only_buffer(s.cl.context, moisture);
  const std::size_t tip_count = input.tips.size();
  cl::Buffer contact_out(s.cl.context, CL_MEM_WRITE_ONLY, sizeof(cl_float4) * tip_count);
  cl::Buffer moisture_out(s.cl.context, CL_MEM_WRITE_ONLY, sizeof(cl_float4) * tip_count);

  int arg = 0;
  s.kernel.setArg(arg++, middle_buffer);
  s.kernel.setArg(arg++, start_buffer);
  s.kernel.setArg(arg++, end_buffer);
  s.kernel.setArg(arg++, segment_id_buffer);
  s.kernel.setArg(arg++, cell_start_buffer);
  s.kernel.setArg(arg++, cl_int4{{grid.dims.x, grid.dims.y, grid.dims.z, 0}});
  s.kernel.setArg(arg++, to_float4(grid.origin - frame));
  s.kernel.setArg(arg++, static_cast<float>(grid.cell_size_m));
  s.kernel.setArg(arg++, static_cast<float>(grid.longest_half_m));
  s.kernel.setArg(arg++, tip_buffer);
  s.kernel.setArg(arg++, excluded_buffer);
  s.kernel.setArg(arg++, static_cast<cl_int>(tip_count));
  s.kernel.setArg(arg++, probe_buffer);
  s.kernel.setArg(arg++, static_cast<cl_int>(probes_per_tip));
  s.kernel.setArg(arg++, moisture_buffer);
  s.kernel.setArg(arg++, soil_vertices);
  s.kernel.setArg(arg++, soil_origin);
  s.kernel.setArg(arg++, soil_spacing);
  s.kernel.setArg(arg++, static_cast<cl_int>(input.soil != nullptr ? 1 : 0));
  s.kernel.setArg(arg++, contact_out);
  s.kernel.setArg(arg++, moisture_out);
  s.cl.queue.enqueueNDRangeKernel(s.kernel, cl::NullRange, cl::NDRange(tip_count), cl::NullRange);

  std::vector<cl_float4> contacts(tip_count), pulls(tip_count);
  s.cl.queue.enqueueReadBuffer(contact_out, CL_FALSE, 0, sizeof(cl_float4) * tip_count, contacts.data());
  s.cl.queue.enqueueReadBuffer(moisture_out, CL_TRUE, 0, sizeof(cl_float4) * tip_count, pulls.data());
  for (std::size_t i = 0; i < tip_count; ++i) {
    RootFieldSample& sample = samples[order[i]];
    sample.contact_avoidance = {contacts[i].s[0], contacts[i].s[1], contacts[i].s[2]};
    sample.contacts = static_cast<int>(contacts[i].s[3]);
    sample.moisture_pull = {pulls[i].s[0], pulls[i].s[1], pulls[i].s[2]};
  }
  return samples;
}

}  // namespace heliostand::roots
