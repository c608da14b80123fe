#pragma once
// An environment variable set (or unset) for one scope and put back as it was when the scope ends: a test that
// points HELIOSTAND_KERNEL_DIR, TMPDIR or HELIOSTAND_TEST_EXECUTABLE somewhere must not leave it so for the tests
// that run after it in the same process, nor erase a value the caller gave the whole run (a GPU bundle's
// HELIOSTAND_TEST_EXECUTABLE, a CI machine's TMPDIR).
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>

namespace heliostand::testing {

class ScopedEnvironment {
 public:
  // Sets `name` to `value`, or unsets it when `value` is empty (std::nullopt).
  ScopedEnvironment(std::string name, const std::optional<std::string>& value) : name_(std::move(name)) {
    if (const char* before = std::getenv(name_.c_str())) before_ = before;
    assign(value);
  }
  ~ScopedEnvironment() { assign(before_); }
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

 private:
  void assign(const std::optional<std::string>& value) const {
    if (value)
      ::setenv(name_.c_str(), value->c_str(), 1);
    else
      ::unsetenv(name_.c_str());
  }

  std::string name_;
  std::optional<std::string> before_;
};

}  // namespace heliostand::testing
