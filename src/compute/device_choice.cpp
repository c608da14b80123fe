#include "compute/device_choice.hpp"

#include <algorithm>
#include <charconv>
#include <stdexcept>

namespace heliostand::compute {

DeviceChoice DeviceChoice::parse(const std::string& text) {
  DeviceChoice choice;
  if (text == "auto" || text.empty()) return choice;
  if (text == "reference") {
    choice.kind = Kind::reference;
    return choice;
  }
  if (text == "opencl") {
    choice.kind = Kind::opencl;
    return choice;
  }
  const std::string prefix = "opencl:";
  if (text.rfind(prefix, 0) == 0) {
    int index = -1;
    const char* first = text.data() + prefix.size();
    const char* last = text.data() + text.size();
    const auto [end, error] = std::from_chars(first, last, index);
    if (error == std::errc() && end == last && first != last && index >= 0) {
      choice.kind = Kind::opencl;
      choice.opencl_index = index;
      return choice;
    }
  }
  throw std::invalid_argument("device '" + text + "': expected auto, reference, opencl or opencl:N (N >= 0)");
}

std::string DeviceChoice::text() const {
  switch (kind) {
    case Kind::automatic: return "auto";
    case Kind::reference: return "reference";
    case Kind::opencl: return opencl_index ? "opencl:" + std::to_string(*opencl_index) : "opencl";
  }
  return "auto";
}

std::optional<int> default_opencl_device(const std::vector<std::string>& types) {
  if (types.empty()) return std::nullopt;
  const auto gpu = std::find(types.begin(), types.end(), "GPU");
  return gpu != types.end() ? static_cast<int>(gpu - types.begin()) : 0;
}

bool opencl_device_exists() { return !list_opencl_devices().empty(); }

#ifndef HELIOSTAND_HAVE_OPENCL
std::vector<OpenCLDeviceInfo> list_opencl_devices() { return {}; }
#endif

}  // namespace heliostand::compute
