#pragma once
// The whole text of a file, for tests that read back what the program wrote.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace heliostand::testing {

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace heliostand::testing
