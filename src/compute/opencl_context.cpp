#include "compute/opencl_context.hpp"

#include <stdexcept>
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

std::string type_name(cl_device_type type) {
  if (type & CL_DEVICE_TYPE_GPU) return "GPU";
  if (type & CL_DEVICE_TYPE_CPU) return "CPU";
  if (type & CL_DEVICE_TYPE_ACCELERATOR) return "accelerator";
  return "other";
}

}  // namespace

std::vector<OpenCLDeviceInfo> list_opencl_devices() {
  std::vector<OpenCLDeviceInfo> infos;
  int index = 0;
  for (const auto& [platform, device] : enumerate()) {
    OpenCLDeviceInfo info;
    info.index = index;
    info.platform = platform.getInfo<CL_PLATFORM_NAME>();
    info.name = device.getInfo<CL_DEVICE_NAME>();
    info.type = type_name(device.getInfo<CL_DEVICE_TYPE>());
    info.version = device.getInfo<CL_DEVICE_VERSION>();
    info.compute_units = device.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>();
    info.is_default = index == 0;
    infos.push_back(info);
    ++index;
  }
  return infos;
}

std::optional<OpenCLContext> open_opencl_device(std::optional<int> index) {
  auto all = enumerate();
  if (all.empty()) return std::nullopt;
  const int chosen = index.value_or(0);
  if (chosen < 0 || chosen >= static_cast<int>(all.size()))
    throw std::runtime_error("OpenCL device " + std::to_string(chosen) + " does not exist (" +
                             std::to_string(all.size()) + " found; see `heliostand devices`)");
  OpenCLContext context;
  context.index = chosen;
  context.device = all[chosen].device;
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

}  // namespace heliostand::compute
