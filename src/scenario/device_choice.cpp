#include "scenario/device_choice.hpp"

#include <charconv>

namespace heliostand {

std::string DeviceChoice::text() const {
  switch (kind) {
    case Kind::automatic: return "auto";
    case Kind::reference: return "reference";
    case Kind::opencl: return opencl_index ? "opencl:" + std::to_string(*opencl_index) : "opencl";
  }
  return "auto";
}

std::optional<DeviceChoice> parse_device_choice(std::string_view text) {
  if (text == "auto") return DeviceChoice{};
  if (text == "reference") return DeviceChoice{DeviceChoice::Kind::reference, std::nullopt};
  if (text == "opencl") return DeviceChoice{DeviceChoice::Kind::opencl, std::nullopt};
  constexpr std::string_view prefix = "opencl:";
  if (text.substr(0, prefix.size()) != prefix) return std::nullopt;
  const std::string_view digits = text.substr(prefix.size());
  int index = -1;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
  if (digits.empty() || error != std::errc{} || end != digits.data() + digits.size() || index < 0) return std::nullopt;
  return DeviceChoice{DeviceChoice::Kind::opencl, index};
}

}  // namespace heliostand
