#pragma once
// Which compute backend runs the light and root-contact fields: the --device option (run.device in a scenario).
// compute/compute_backend.hpp opens the chosen one.
//   auto       the default OpenCL device (default_opencl_device: the first GPU, else the first device); no OpenCL
//              platform -> warn once, use the reference solver
//   reference  the plain C++ oracle
//   opencl     the default OpenCL device; none -> error
//   opencl:N   OpenCL device N in `heliostand devices` numbering; missing -> error
#include <optional>
#include <string>
#include <vector>

#include "compute/device_memory.hpp"

namespace heliostand::compute {

struct DeviceChoice {
  enum class Kind { automatic, reference, opencl };
  Kind kind = Kind::automatic;
  std::optional<int> opencl_index;  // only with Kind::opencl

  // Throws std::invalid_argument ("device 'x': expected auto, reference, opencl or opencl:N").
  static DeviceChoice parse(const std::string& text);
  std::string text() const;  // back to "auto", "reference", "opencl", "opencl:N"
  bool operator==(const DeviceChoice&) const = default;
};

struct OpenCLDeviceInfo {
  int index = 0;            // across all platforms, in enumeration order
  std::string platform;
  std::string name;
  std::string type;         // "CPU", "GPU", "accelerator", ...
  std::string version;      // OpenCL version string of the device
  unsigned compute_units = 0;
  DeviceMemory memory;      // the largest buffer and all of them (the far field's cap must fit: docs/light.md)
  bool is_default = false;  // the one `auto` and `opencl` pick
};

// The device `auto` and `opencl` pick among devices of these types (OpenCLDeviceInfo::type, in enumeration order):
// the first GPU, else the first device; none when there is no device. A machine may carry both a CPU runtime (PoCL,
// which the set-up installs) and a GPU's driver, enumerated in either order, and a user with a GPU expects the run on
// it: the hectare's 60 years take ~2.5 min on an H100 and ~20 min on PoCL on two cores (docs/performance.md).
std::optional<int> default_opencl_device(const std::vector<std::string>& types);

// Every OpenCL device of every platform; empty when there is no OpenCL platform (clGetPlatformIDs -> -1001)
// or when the build has no OpenCL.
std::vector<OpenCLDeviceInfo> list_opencl_devices();

// True when `auto` would pick an OpenCL device. The one reason an OpenCL test may skip is that this is false.
bool opencl_device_exists();

// Whether this build has the OpenCL backend (CMake option HELIOSTAND_OPENCL).
#ifdef HELIOSTAND_HAVE_OPENCL
inline constexpr bool opencl_backend_built = true;
#else
inline constexpr bool opencl_backend_built = false;
#endif

}  // namespace heliostand::compute
