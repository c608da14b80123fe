// The command-line tests start heliostand through one command line, which HELIOSTAND_TEST_EXECUTABLE can replace
// (a GPU machine's bundle runs its own packed heliostand: validation/bench/gpu/checks.sh).
#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

#include "cli/cli_runner.hpp"

namespace heliostand::testing {
namespace {

// Sets (or, given nothing, unsets) HELIOSTAND_TEST_EXECUTABLE for one test and puts back what was there.
class TestExecutable {
 public:
  explicit TestExecutable(const std::optional<std::string>& command) {
    if (const char* before = std::getenv(name)) before_ = before;
    if (command)
      ::setenv(name, command->c_str(), 1);
    else
      ::unsetenv(name);
  }
  ~TestExecutable() {
    if (before_)
      ::setenv(name, before_->c_str(), 1);
    else
      ::unsetenv(name);
  }
  TestExecutable(const TestExecutable&) = delete;
  TestExecutable& operator=(const TestExecutable&) = delete;

 private:
  static constexpr const char* name = "HELIOSTAND_TEST_EXECUTABLE";
  std::optional<std::string> before_;
};

TEST(CliRunner, RunsThisBuildsHeliostandWhenNoOtherIsNamed) {
  const TestExecutable none(std::nullopt);
  EXPECT_EQ(heliostand_command(), HELIOSTAND_EXECUTABLE);
  const TestExecutable empty(std::string{});
  EXPECT_EQ(heliostand_command(), HELIOSTAND_EXECUTABLE);
}

TEST(CliRunner, RunsTheCommandTheEnvironmentNames) {
  // A command line with a quoted word, as checks.sh names a bundle's loader wrapper and the program it starts.
  const TestExecutable echo(std::string("'echo' from-the-environment"));
  const CliResult result = run_cli("--version");
  EXPECT_EQ(result.status, 0);
  EXPECT_EQ(result.output, "from-the-environment --version\n");
}

}  // namespace
}  // namespace heliostand::testing
