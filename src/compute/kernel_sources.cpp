#include "compute/kernel_sources.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace heliostand::compute {
namespace {

std::optional<std::string> read_override(std::string_view file_name) {
  const char* dir = std::getenv("HELIOSTAND_KERNEL_DIR");
  if (dir == nullptr || *dir == '\0') return std::nullopt;
  const std::filesystem::path path = std::filesystem::path(dir) / std::string(file_name);
  std::ifstream in(path);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string raw_source(std::string_view file_name) {
  if (auto text = read_override(file_name)) return *text;
  for (const auto& kernel : embedded_kernels())
    if (kernel.name == file_name) return std::string(kernel.source);
  throw std::runtime_error("no OpenCL kernel file '" + std::string(file_name) + "' in cl/");
}

}  // namespace

std::string kernel_source(std::string_view file_name) {
  std::istringstream in(raw_source(file_name));
  std::string out, line;
  constexpr std::string_view directive = "#include \"";
  while (std::getline(in, line)) {
    const auto at = line.find(directive);
    if (at != std::string::npos && line.find_first_not_of(" \t") == at) {
      const auto begin = at + directive.size();
      const auto end = line.find('"', begin);
      out += kernel_source(line.substr(begin, end - begin));
    } else {
      out += line;
    }
    out += '\n';
  }
  return out;
}

}  // namespace heliostand::compute
