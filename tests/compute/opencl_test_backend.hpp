#pragma once
// The OpenCL backend for a test, or nullopt when this machine (or this build) has no OpenCL device: the one
// reason an OpenCL test may skip. Anything else — a device that fails to open, a kernel that does not build —
// throws, and the test fails.
#include <optional>

#include "compute/compute_backend.hpp"

namespace heliostand::compute {

inline std::optional<ComputeBackend> opencl_backend_for_test() {
  if (!opencl_device_exists()) return std::nullopt;
  return ComputeBackend::open({DeviceChoice::Kind::opencl});
}

}  // namespace heliostand::compute
