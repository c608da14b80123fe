#pragma once
// A fresh, empty folder under the build tree for one test, removed afterwards. The folder name carries
// the running test's name, so tests sharing a fixture can run in parallel (ctest -j) without racing.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace heliostand::testing {

class TempFolder {
 public:
  explicit TempFolder(const std::string& name)
      : path_(std::filesystem::path(HELIOSTAND_BINARY_DIR) / "test-output" / (name + "." + running_test())) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  static std::string running_test() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    return info == nullptr ? "suite" : std::string(info->test_suite_name()) + "." + info->name();
  }
  std::filesystem::path path_;
};

}  // namespace heliostand::testing
