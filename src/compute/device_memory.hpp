#pragma once
// What an OpenCL device lets a program hold: one buffer at most CL_DEVICE_MAX_MEM_ALLOC_SIZE, all of them at most
// CL_DEVICE_GLOBAL_MEM_SIZE, as the device reports them. A buffer larger than the first fails at clCreateBuffer
// (CL_INVALID_BUFFER_SIZE). The light solver checks its far-field table's cap against both when it is made
// (light/far_field_buffers.hpp), and `heliostand devices` lists them. No OpenCL headers: a build without the OpenCL
// backend names it too.
#include <cmath>
#include <cstdint>

namespace heliostand::compute {

struct DeviceMemory {
  std::uint64_t buffer_bytes = 0;  // the largest single buffer
  std::uint64_t total_bytes = 0;   // all buffers together
};

// A device's figure in whole MB (10^6 bytes, far_field_table_mb's unit), rounded down, so that a cap of that many MB
// never exceeds it: what `heliostand devices` and `heliostand check` list.
inline double whole_megabytes(std::uint64_t bytes) { return std::floor(double(bytes) / 1e6); }

}  // namespace heliostand::compute
