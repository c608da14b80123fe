#pragma once
// A fresh, empty folder under the build tree for one test, removed afterwards.
#include <filesystem>
#include <string>

namespace heliostand::testing {

class TempFolder {
 public:
  explicit TempFolder(const std::string& name)
      : path_(std::filesystem::path(HELIOSTAND_BINARY_DIR) / "test-output" / name) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace heliostand::testing
