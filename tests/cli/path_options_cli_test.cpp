// The options that name a file or a folder to write refuse an empty name (src/cli/path_checks.hpp): exit 2 and the
// option named, before anything runs. An empty name (most often a script's unset variable, `-o "$OUT"`) passed as
// "not given" before: no JSON file and no word of it, no tables kept, a report in the default folder.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli/cli_runner.hpp"
#include "cli/path_checks.hpp"

namespace heliostand::testing {
namespace {

namespace fs = std::filesystem;

std::string refusal_of(const CLI::Validator& validator, std::string value) { return validator(value); }

}  // namespace

TEST(PathChecks, AnEmptyNameIsRefusedAndAnyOtherPassesToTheCommand) {
  EXPECT_EQ(refusal_of(path_check("file"), ""), "a file name is expected, got an empty one");
  EXPECT_EQ(refusal_of(path_check("folder"), ""), "a folder name is expected, got an empty one");
  EXPECT_EQ(refusal_of(path_check("file"), "out/light.json"), "");
  EXPECT_EQ(refusal_of(path_check("folder"), " "), "") << "a name of one blank is a name; the command judges it";
}

TEST(PathOptionsCli, EachOptionThatNamesAFileOrFolderToWriteRefusesAnEmptyName) {
  const fs::path scratch = scratch_folder("path-options");
  fs::create_directories(scratch);
  const std::string tiny = source_path("stands/tiny/scenario.toml").string();
  const std::string bench_stand = "bench stand " + tiny_bench_stand.string() + " --years 1 --device reference";
  const std::string file = "a file name is expected, got an empty one";
  const std::string folder = "a folder name is expected, got an empty one";
  struct Case {
    std::string arguments, refusal;
  };
  const std::vector<Case> cases = {
      {"grow " + tiny + " --out ''", "--out: " + folder},
      {"kanamaru " + source_path("stands/kanamaru-ci/scenario.toml").string() + " --out ''", "--out: " + folder},
      {"report " + scratch.string() + " -o ''", "--out: " + folder},
      {"batch manifest.toml -o ''", "--out: " + folder},
      {bench_stand + " --tables ''", "--tables: " + folder},
      {bench_stand + " -o ''", "--output: " + file},
      {quick_reference_light_bench + " -o ''", "--output: " + file},
  };
  for (const Case& c : cases) {
    const CliResult run = run_cli(c.arguments);
    EXPECT_EQ(run.status, 2) << c.arguments << "\n" << run.output;
    EXPECT_NE(run.output.find(c.refusal), std::string::npos) << c.arguments << "\n" << run.output;
    EXPECT_EQ(run.output.find("\"benchmark\""), std::string::npos) << "nothing ran: " << c.arguments;
  }
  EXPECT_TRUE(fs::is_empty(scratch)) << "no report written into the run folder";
}

}  // namespace heliostand::testing
