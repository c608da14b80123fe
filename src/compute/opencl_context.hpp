#pragma once
// An OpenCL device ready to run kernels: context, in-order queue, and program building with the build log
// in the error. Included only by opencl_*.cpp files and, in OpenCL builds, compute_backend.cpp (the OpenCL
// backend is optional at build time). A copy shares the same context and queue (OpenCL handles are counted).
#include <optional>
#include <string>

#include <CL/opencl.hpp>

namespace heliostand::compute {

struct OpenCLContext {
  cl::Device device;
  cl::Context context;
  cl::CommandQueue queue;
  std::string description;  // "Portable Computing Language / pthread-..." for logs and solver names
  int index = 0;
};

// Device `index` (heliostand devices numbering; nullopt = the default, device 0). Returns nullopt when there
// is no OpenCL platform or no device at all; throws std::runtime_error when a given index does not exist.
std::optional<OpenCLContext> open_opencl_device(std::optional<int> index);

// Builds `source` for the context's device; throws std::runtime_error with the build log on failure.
cl::Program build_program(const OpenCLContext& context, const std::string& source, const std::string& options);

}  // namespace heliostand::compute
