// The command-line tests start heliostand through one command line, which HELIOSTAND_TEST_EXECUTABLE can replace
// (a GPU machine's bundle runs its own packed heliostand: validation/bench/gpu/checks.sh).
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "cli/cli_runner.hpp"
#include "scoped_environment.hpp"

namespace heliostand::testing {
namespace {

// HELIOSTAND_TEST_EXECUTABLE set (or, given nothing, unset) for one test, and put back as it was.
class TestExecutable : public ScopedEnvironment {
 public:
  explicit TestExecutable(const std::optional<std::string>& command)
      : ScopedEnvironment("HELIOSTAND_TEST_EXECUTABLE", command) {}
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
