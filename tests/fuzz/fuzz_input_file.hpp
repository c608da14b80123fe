#pragma once
// The fuzzed readers take a file path (as a user's input reaches them): each input is written to one scratch
// file per fuzzing process, in a folder of its own beside which a harness may place fixed companions.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace heliostand::fuzz {

// The folder of one fuzzing process, deleted with what it holds when the process exits: libFuzzer ends a timed run
// with exit(0), which runs the destructors of statics, so no run leaves its inputs in the temporary folder. A run
// that crashes leaves it (the input that crashed is saved as an artifact anyway).
class ScratchFolder {
 public:
  ScratchFolder()
      : path_(std::filesystem::temp_directory_path() / ("heliostand-fuzz-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ignored;  // best effort at exit: never throw from a destructor
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline const std::filesystem::path& scratch_folder() {
  static const ScratchFolder folder;
  return folder.path();
}

inline std::filesystem::path write_input(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const auto path = scratch_folder() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

}  // namespace heliostand::fuzz
