#pragma once
// A text as a JSON string literal, for the JSON the benchmarks write with fmt: quotes, backslashes and control
// characters escaped (a stand's name is a path; a processor's name is whatever the kernel reports).
#include <string>

#include <fmt/format.h>

namespace heliostand {

inline std::string json_string(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\')
      quoted += {'\\', c};
    else if (static_cast<unsigned char>(c) < 0x20)
      quoted += fmt::format("\\u{:04x}", int(c));
    else
      quoted += c;
  }
  return quoted + "\"";
}

}  // namespace heliostand
