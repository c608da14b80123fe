#include "scenario/toml_file.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

#include "core/input_error.hpp"

namespace heliostand {

toml::table read_toml_file(const std::filesystem::path& file, const std::string& label, std::string_view what) {
  std::error_code ec;
  const bool folder = std::filesystem::is_directory(file, ec);
  errno = 0;
  std::ifstream probe(file);
  if (folder || !probe) {
    const std::string reason = folder ? "it is a directory" : std::strerror(errno);
    throw InputError({{label, 0, "", fmt::format("cannot read the {}: {}", what, reason)}}, "key");
  }
  try {
    return toml::parse_file(file.string());
  } catch (const toml::parse_error& error) {
    throw InputError({{label, static_cast<int>(error.source().begin.line), "",
                       fmt::format("not valid TOML: {}", error.description())}},
                     "key");
  }
}

}  // namespace heliostand
