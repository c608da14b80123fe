#pragma once
// An OpenCL device ready to run kernels: context, in-order queue, and program building with the build log
// in the error. Included only by opencl_*.cpp files and, in OpenCL builds, compute_backend.cpp (the OpenCL
// backend is optional at build time). A copy shares the same context and queue (OpenCL handles are counted).
#include <optional>
#include <string>

#include <CL/opencl.hpp>

#include "compute/device_memory.hpp"

namespace heliostand::compute {

struct OpenCLContext {
  cl::Device device;
  cl::Context context;
  cl::CommandQueue queue;
  std::string description;  // "Portable Computing Language / pthread-..." for logs and solver names
  // CL_DEVICE_TYPE_CPU, _GPU, ... of `device`: where a kernel's cost differs between the two, a solver chooses by it
  // (OpenCLLightSolver::solve_with_each_alone).
  cl_device_type type = 0;
  int index = 0;
  DeviceMemory memory;  // the largest buffer and all of them, as the device reports them
};

// Device `index` (heliostand devices numbering; nullopt = the default, default_opencl_device: the first GPU, else
// device 0). Returns nullopt when there is no OpenCL platform or no device at all; throws std::runtime_error when a
// given index does not exist.
std::optional<OpenCLContext> open_opencl_device(std::optional<int> index);

// Builds `source` for the context's device; throws std::runtime_error with the build log on failure.
cl::Program build_program(const OpenCLContext& context, const std::string& source, const std::string& options);

// The work-group size every kernel of this program is launched with on `device`: fixed per kernel and device,
// never left to the OpenCL implementation (see opencl_context.cpp for why).
std::size_t work_group_size(const cl::Kernel& kernel, const cl::Device& device);

// Launches `kernel` over `items` work items in groups of work_group_size, the global size rounded up to whole
// groups: every kernel ignores the items at or past its own count. `rows` > 1 adds a second dimension of that
// many rows (groups one row high).
void launch(const OpenCLContext& context, cl::Kernel& kernel, std::size_t items, std::size_t rows = 1);

}  // namespace heliostand::compute
