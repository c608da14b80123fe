#pragma once
// The fuzzed readers take a file path (as a user's input reaches them): each input is written to one scratch
// file per fuzzing process, in a folder of its own beside which a harness may place fixed companions.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "../folders_removed_at_exit.hpp"

namespace heliostand::fuzz {

// The folder of one fuzzing process, deleted when the process exits (no run leaves its inputs in the temporary
// folder; one that crashes leaves them, and the input that crashed is saved as an artifact anyway).
inline const std::filesystem::path& scratch_folder() {
  static const std::filesystem::path folder = [] {
    auto path = std::filesystem::temp_directory_path() / ("heliostand-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
    testing::folders_removed_at_exit().add(path);
    return path;
  }();
  return folder;
}

inline std::filesystem::path write_input(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const auto path = scratch_folder() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

}  // namespace heliostand::fuzz
