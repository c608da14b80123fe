#pragma once
// A fresh, empty folder under the build tree for one test, removed afterwards. The folder name carries
// the running test's name, so tests sharing a fixture can run in parallel (ctest -j) without racing, and the
// process's id, so the same test run by two programs at once (the sanitizer tree's input tests and its unit-suite
// shards, tests/scripts/no_opencl.cmake) does not race either.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace heliostand::testing {

class TempFolder {
 public:
  explicit TempFolder(const std::string& name)
      : path_(std::filesystem::path(HELIOSTAND_BINARY_DIR) / "test-output" /
              (name + "." + running_test() + "." + std::to_string(::getpid()))) {
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
