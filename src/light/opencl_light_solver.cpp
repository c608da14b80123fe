#include "light/opencl_light_solver.hpp"

#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>

#include <glm/common.hpp>

#include "compute/kernel_options.hpp"
#include "compute/kernel_sources.hpp"
#include "compute/opencl_context.hpp"
#include "light/celestial_sphere.hpp"
#include "light/far_field.hpp"
#include "light/light_sum.hpp"
#include "light/near_field.hpp"
#include "light/occluders.hpp"

namespace heliostand {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Each work item keeps V x H floats of private state; PoCL places a whole work-group's private arrays on
// one thread's stack, so a large automatic local size overflows it (seen at 16k receivers). Small explicit
// groups keep that at 64 x 2 KB.
constexpr std::size_t group_size = 64;

void launch(cl::CommandQueue& queue, cl::Kernel& kernel, const cl::Device& device, std::size_t items) {
  const std::size_t local =
      std::min<std::size_t>(group_size, kernel.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(device));
  const std::size_t global = (items + local - 1) / local * local;  // the kernels ignore the extra items
  queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(global), cl::NDRange(local));
}

// Receivers per culled kernel launch: bounds the memory of the candidate lists (~ chunk x candidates x 4 B).
constexpr std::size_t culled_chunk = 16384;

template <typename T>
cl::Buffer read_only(const cl::Context& context, const std::vector<T>& data) {
  // a zero-sized buffer is invalid in OpenCL; one element of padding keeps empty inputs legal
  if (data.empty()) {
    T padding{};
    return cl::Buffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(T), &padding);
  }
  return cl::Buffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, data.size() * sizeof(T),
                    const_cast<T*>(data.data()));
}

}  // namespace

struct OpenCLLightSolver::Device {
  compute::OpenCLContext cl;
  cl::Program program;
  cl::Kernel exact;
  cl::Kernel culled;
};

OpenCLLightSolver::OpenCLLightSolver(const LightParameters& parameters, const compute::OpenCLContext& device)
    : parameters_(parameters) {
  validate(parameters_);
  device_ = std::make_unique<Device>();
  device_->cl = device;
  const auto options = compute::KernelOptions()
                           .define("SKY_BANDS", parameters_.sky_bands)
                           .define("SKY_SECTORS", parameters_.sky_sectors)
                           .define("BALANCED_LIGHT_FRACTION", balanced_light_fraction);
  device_->program = compute::build_program(device_->cl, compute::kernel_source("light.cl"), options.text());
  device_->exact = cl::Kernel(device_->program, "light_exact");
  device_->culled = cl::Kernel(device_->program, "light_culled");
}

OpenCLLightSolver::~OpenCLLightSolver() = default;

std::string OpenCLLightSolver::name() const { return "opencl:" + device_->cl.description; }

std::vector<LightSample> OpenCLLightSolver::solve_for(std::span<const LeafBall> balls,
                                                      std::span<const std::uint32_t> receivers) {
  check_receivers(balls, receivers);
  statistics_ = {};
  std::vector<LightSample> samples(receivers.size());
  if (receivers.empty()) return samples;
  const auto setup_start = Clock::now();
  const CelestialSphere sky(parameters_);
  const PlotTorus torus = PlotTorus::from(parameters_);
  const OccluderSet set = make_occluder_set(balls, torus, parameters_.exact ? 0.0 : parameters_.cutoff_m);

  // Float keeps ~7 digits: centre the coordinates on the stand so offsets between balls lose little.
  glm::dvec3 low = set.centres[0], high = set.centres[0];
  for (const auto& c : set.centres) low = glm::min(low, c), high = glm::max(high, c);
  const glm::dvec3 origin = glm::floor(0.5 * (low + high));

  std::vector<cl_float4> ball_data(set.centres.size());
  for (std::size_t k = 0; k < set.centres.size(); ++k) {
    const glm::dvec3 c = set.centres[k] - origin;
    ball_data[k] = {{float(c.x), float(c.y), float(c.z), float(set.radii[k])}};
  }
  std::vector<cl_float4> patch_data;
  std::vector<float> b0;
  for (const auto& patch : sky.patches()) {
    patch_data.push_back({{float(patch.direction.x), float(patch.direction.y), float(patch.direction.z),
                           float(patch.solid_angle)}});
    b0.push_back(float(patch.initial_intensity));
  }
  const auto& context = device_->cl.context;
  auto& queue = device_->cl.queue;
  const cl::Buffer balls_buffer = read_only(context, ball_data);
  const cl::Buffer patches_buffer = read_only(context, patch_data);
  const cl::Buffer b0_buffer = read_only(context, b0);
  const float log_t = float(std::log(parameters_.transmittance));

  auto collect = [&](const cl::Buffer& out, std::size_t first_slot, std::size_t count) {
    std::vector<cl_float4> result(count);
    queue.enqueueReadBuffer(out, CL_TRUE, 0, count * sizeof(cl_float4), result.data());
    for (std::size_t k = 0; k < count; ++k) {
      const auto& r = result[k].s;
      samples[first_slot + k].light = r[3];
      samples[first_slot + k].vector = glm::dvec3(r[0], r[1], r[2]);
    }
  };

  if (parameters_.exact) {
    statistics_.setup_seconds = 0;
    statistics_.mean_candidates = torus.periodic ? 9.0 * balls.size() - 1 : double(balls.size()) - 1;
    const auto start = Clock::now();
    std::vector<cl_int> receiver_data(receivers.begin(), receivers.end());
    const cl::Buffer receivers_buffer = read_only(context, receiver_data);
    cl::Buffer out(context, CL_MEM_WRITE_ONLY, receivers.size() * sizeof(cl_float4));
    auto& k = device_->exact;
    int arg = 0;
    k.setArg(arg++, balls_buffer);
    k.setArg(arg++, cl_int(set.ball_count));
    k.setArg(arg++, receivers_buffer);
    k.setArg(arg++, cl_int(receivers.size()));
    k.setArg(arg++, patches_buffer);
    k.setArg(arg++, b0_buffer);
    k.setArg(arg++, log_t);
    k.setArg(arg++, cl_int(torus.periodic ? 1 : 0));
    k.setArg(arg++, float(torus.size.x));
    k.setArg(arg++, float(torus.size.y));
    k.setArg(arg++, out);
    launch(queue, k, device_->cl.device, receivers.size());
    collect(out, 0, receivers.size());
    statistics_.evaluate_seconds = seconds_since(start);
    return samples;
  }

  const NearFieldSearch search(set, parameters_.cutoff_m);
  // Without a far field the kernel gets a one-cell table of zeros and a zero attenuation factor.
  const std::optional<FarField> far =
      parameters_.far_field ? std::optional<FarField>(std::in_place, set, parameters_, sky) : std::nullopt;
  const VoxelGrid grid = far ? far->grid() : VoxelGrid{};
  const std::vector<float> no_table(far ? 0 : sky.patches().size(), 0.0f);  // one empty cell
  const cl::Buffer depth_buffer = read_only(context, far ? far->optical_depth() : no_table);
  const glm::dvec3 grid_origin = grid.origin - origin;
  const cl_float4 grid_origin_arg = {{float(grid_origin.x), float(grid_origin.y), float(grid_origin.z), 0.0f}};
  const cl_float4 grid_cell_arg = {{float(grid.cell.x), float(grid.cell.y), float(grid.cell.z), 0.0f}};
  const cl_int4 grid_dims_arg = {{grid.dims.x, grid.dims.y, grid.dims.z, 0}};
  const float far_attenuation = far ? float(1.0 - parameters_.transmittance) : 0.0f;
  statistics_.setup_seconds = seconds_since(setup_start);

  // Candidate search (host) of one chunk overlaps nothing yet; its time is counted as setup.
  std::size_t candidate_total = 0;
  double search_seconds = 0;
  const auto start = Clock::now();
  for (std::size_t first = 0; first < receivers.size(); first += culled_chunk) {
    const auto chunk = receivers.subspan(first, std::min(culled_chunk, receivers.size() - first));
    const auto search_start = Clock::now();
    const CandidateLists near = search.candidates(chunk);
    search_seconds += seconds_since(search_start);
    candidate_total += near.occluders.size();
    std::vector<cl_int> chunk_receivers(chunk.begin(), chunk.end());
    std::vector<cl_int> starts(near.start.begin(), near.start.end());
    std::vector<cl_int> candidates(near.occluders.begin(), near.occluders.end());
    const cl::Buffer receivers_buffer = read_only(context, chunk_receivers);
    const cl::Buffer starts_buffer = read_only(context, starts);
    const cl::Buffer candidates_buffer = read_only(context, candidates);
    cl::Buffer out(context, CL_MEM_WRITE_ONLY, chunk.size() * sizeof(cl_float4));
    auto& k = device_->culled;
    int arg = 0;
    k.setArg(arg++, balls_buffer);
    k.setArg(arg++, receivers_buffer);
    k.setArg(arg++, cl_int(chunk.size()));
    k.setArg(arg++, starts_buffer);
    k.setArg(arg++, candidates_buffer);
    k.setArg(arg++, patches_buffer);
    k.setArg(arg++, b0_buffer);
    k.setArg(arg++, log_t);
    k.setArg(arg++, depth_buffer);
    k.setArg(arg++, grid_origin_arg);
    k.setArg(arg++, grid_cell_arg);
    k.setArg(arg++, grid_dims_arg);
    k.setArg(arg++, cl_int(torus.periodic ? 1 : 0));
    k.setArg(arg++, float(parameters_.cutoff_m));
    k.setArg(arg++, far_attenuation);
    k.setArg(arg++, out);
    launch(queue, k, device_->cl.device, chunk.size());
    collect(out, first, chunk.size());
  }
  statistics_.evaluate_seconds = seconds_since(start) - search_seconds;
  statistics_.setup_seconds += search_seconds;
  statistics_.mean_candidates = double(candidate_total) / receivers.size();
  return samples;
}

}  // namespace heliostand
