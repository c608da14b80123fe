#include "compute/opencl_context.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "compute/device_choice.hpp"

namespace heliostand::compute {
namespace {

struct PlatformDevice {
  cl::Platform platform;
  cl::Device device;
};

// All devices of all platforms, in a stable order. No platform (ICD loader returns
// CL_PLATFORM_NOT_FOUND_KHR = -1001) or a platform without devices simply contributes nothing.
std::vector<PlatformDevice> enumerate() {
  std::vector<PlatformDevice> all;
  std::vector<cl::Platform> platforms;
  try {
    cl::Platform::get(&platforms);
  } catch (const cl::Error&) {
    return all;
  }
  for (auto& platform : platforms) {
    std::vector<cl::Device> devices;
    try {
      platform.getDevices(CL_DEVICE_TYPE_ALL, &devices);
    } catch (const cl::Error&) {
      continue;  // CL_DEVICE_NOT_FOUND
    }
    for (auto& device : devices) all.push_back({platform, device});
  }
  return all;
}

// Work items per group on a CPU device (PoCL). Each light work item keeps V x H floats of private state, and
// PoCL places a whole group's private arrays on one thread's stack, so a large automatic size overflows it (seen
// at 16k receivers): 64 keeps that at 64 x 2 KB. And PoCL compiles a kernel anew (LLVM, ~0.25 s for the roots on a
// 2-core machine) for every work-group size it meets: an automatic size follows the item count, which for the
// roots changes with every query, so each year paid for new compiles (docs/performance.md).
constexpr std::size_t cpu_group_size = 64;

std::string type_name(cl_device_type type) {
  if (type & CL_DEVICE_TYPE_GPU) return "GPU";
  if (type & CL_DEVICE_TYPE_CPU) return "CPU";
  if (type & CL_DEVICE_TYPE_ACCELERATOR) return "accelerator";
  return "other";
}

DeviceMemory memory_of(const cl::Device& device) {
  return {device.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>(), device.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>()};
}

// The default among the enumerated devices (default_opencl_device over their types): the one `heliostand devices`
// marks and the one opened when no index is given.
std::optional<int> default_of(const std::vector<PlatformDevice>& all) {
  std::vector<std::string> types;
  for (const auto& [platform, device] : all) types.push_back(type_name(device.getInfo<CL_DEVICE_TYPE>()));
  return default_opencl_device(types);
}

}  // namespace

std::vector<OpenCLDeviceInfo> list_opencl_devices() {
  const auto all = enumerate();
  const std::optional<int> chosen = default_of(all);
  std::vector<OpenCLDeviceInfo> infos;
  int index = 0;
  for (const auto& [platform, device] : all) {
    OpenCLDeviceInfo info;
    info.index = index;
    info.platform = platform.getInfo<CL_PLATFORM_NAME>();
    info.name = device.getInfo<CL_DEVICE_NAME>();
    info.type = type_name(device.getInfo<CL_DEVICE_TYPE>());
    info.version = device.getInfo<CL_DEVICE_VERSION>();
    info.compute_units = device.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>();
    info.memory = memory_of(device);
    info.is_default = index == chosen;
    infos.push_back(info);
    ++index;
  }
  return infos;
}

std::optional<OpenCLContext> open_opencl_device(std::optional<int> index) {
  auto all = enumerate();
  if (all.empty()) return std::nullopt;
  const int chosen = index ? *index : default_of(all).value_or(0);
  if (chosen < 0 || chosen >= static_cast<int>(all.size()))
    throw std::runtime_error("OpenCL device " + std::to_string(chosen) + " does not exist (" +
                             std::to_string(all.size()) + " found; see `heliostand devices`)");
  OpenCLContext context;
  context.index = chosen;
  context.device = all[chosen].device;
  context.type = context.device.getInfo<CL_DEVICE_TYPE>();
  context.memory = memory_of(context.device);
  context.context = cl::Context(context.device);
  context.queue = cl::CommandQueue(context.context, context.device);
  context.description = all[chosen].platform.getInfo<CL_PLATFORM_NAME>() + " / " +
                        context.device.getInfo<CL_DEVICE_NAME>();
  return context;
}

cl::Program build_program(const OpenCLContext& context, const std::string& source, const std::string& options) {
  cl::Program program(context.context, source);
  try {
    program.build({context.device}, options.c_str());
  } catch (const cl::BuildError& error) {
    std::string log;
    for (const auto& [device, text] : error.getBuildLog()) log += text;
    throw std::runtime_error("OpenCL kernel build failed: " + log);
  } catch (const cl::Error& error) {
    throw std::runtime_error(std::string("OpenCL kernel build failed: ") + error.what() + " (" +
                             std::to_string(error.err()) + "): " +
                             program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(context.device));
  }
  return program;
}

// A GPU gets its preferred multiple (a warp or wavefront): private arrays spill to its cache either way, and small
// groups keep more of them resident.
std::size_t work_group_size(const cl::Kernel& kernel, const cl::Device& device) {
  const std::size_t most = kernel.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(device);
  if (device.getInfo<CL_DEVICE_TYPE>() & CL_DEVICE_TYPE_CPU) return std::min(cpu_group_size, most);
  return std::min(kernel.getWorkGroupInfo<CL_KERNEL_PREFERRED_WORK_GROUP_SIZE_MULTIPLE>(device), most);
}

void launch(const OpenCLContext& context, cl::Kernel& kernel, std::size_t items, std::size_t rows) {
  const std::size_t local = work_group_size(kernel, context.device);
  const std::size_t global = (items + local - 1) / local * local;
  if (rows == 1)
    context.queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(global), cl::NDRange(local));
  else
    context.queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(global, rows), cl::NDRange(local, 1));
}

}  // namespace heliostand::compute
