#pragma once
// Which compute device runs the light (and root-field) solvers: scenario key run.device and the CLI's
// --device. "auto" = first OpenCL device, falling back to the reference solver when there is none.
#include <optional>
#include <string>
#include <string_view>

namespace heliostand {

struct DeviceChoice {
  enum class Kind { automatic, reference, opencl };
  Kind kind = Kind::automatic;
  std::optional<int> opencl_index;  // "opencl:N": the N-th device (0-based) over all platforms

  std::string text() const;  // back to "auto", "reference", "opencl", "opencl:N"
  bool operator==(const DeviceChoice&) const = default;
};

// "auto" | "reference" | "opencl" | "opencl:N" (N >= 0); nothing for anything else.
std::optional<DeviceChoice> parse_device_choice(std::string_view text);

}  // namespace heliostand
