// `heliostand kanamaru` (a seed-000 experiment) takes its output folder as `grow` does, and never leaves a file
// half-written under its name.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "cli/cli_runner.hpp"

namespace heliostand::testing {
namespace {

namespace fs = std::filesystem;

// The Table 1 tree to generation 12, drawn at generations 0, 6 and 12 (0.2 s).
const std::string kanamaru_ci = source_path("stands/kanamaru-ci/scenario.toml").string();

CliResult kanamaru(const fs::path& folder, const std::string& extra = "") {
  return run_cli("kanamaru " + kanamaru_ci + " --out " + folder.string() + " " + extra);
}

TEST(KanamaruCli, WritesItsSeriesIntoANewFolderAndReplacesItOnlyWithForce) {
  const auto folder = scratch_folder("kanamaru_ci");
  const auto first = kanamaru(folder);
  ASSERT_EQ(first.status, 0) << first.output;
  const std::set<std::string> expected{".heliostand-output", "crown.pvd",       "crown_gen_0000.vtp",
                                       "crown_gen_0006.vtp", "crown_gen_0012.vtp", "generations.csv",
                                       "tips.csv"};
  EXPECT_EQ(names_in(folder), expected);
  const std::string tips = read_text(folder / "tips.csv");

  const auto again = kanamaru(folder);
  EXPECT_EQ(again.status, 2) << again.output;
  EXPECT_NE(again.output.find("--force"), std::string::npos) << again.output;
  EXPECT_EQ(read_text(folder / "tips.csv"), tips);

  const auto forced = kanamaru(folder, "--force");
  EXPECT_EQ(forced.status, 0) << forced.output;
  EXPECT_EQ(names_in(folder), expected);
  EXPECT_EQ(read_text(folder / "tips.csv"), tips) << "the same seed grows the same tree";
}

TEST(KanamaruCli, AFolderHoldingSomethingElseIsRefusedEvenWithForceAndLeftAlone) {
  const auto folder = scratch_folder("kanamaru_not_ours");
  fs::create_directories(folder);
  std::ofstream(folder / "tips.csv") << "my own tips\n";
  for (const std::string extra : {"", "--force"}) {
    const auto run = kanamaru(folder, extra);
    EXPECT_EQ(run.status, 2) << extra << ": " << run.output;
    EXPECT_EQ(read_text(folder / "tips.csv"), "my own tips\n");
    EXPECT_EQ(names_in(folder), std::set<std::string>{"tips.csv"});
  }
}

// Files may not grow past 1 024 bytes (the shell's `ulimit -f 1`, its SIGXFSZ ignored), as on a full disk: the
// first crown (3.4 kB) cannot be written. VTK's writer says so only in its error code.
TEST(KanamaruCli, ACrownThatCannotBeWrittenIsAnErrorAndNothingIsLeftHalfWritten) {
  const auto folder = scratch_folder("kanamaru_full_disk");
  const auto run = run_command("bash -c \"trap '' XFSZ; ulimit -f 1; exec " + heliostand_command() +
                               " kanamaru " + kanamaru_ci + " --out " + folder.string() + "\"");
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("error: cannot write " + (folder / "crown_gen_0000.vtp").string() + ": "),
            std::string::npos)
      << run.output;
  EXPECT_EQ(names_in(folder), std::set<std::string>{".heliostand-output"}) << "no crown, no temporary";
}

// A scenario path that is a folder, missing or not TOML is refused as the stand scenario is, naming the file and the
// reason; nothing is written. (toml++ alone read the folder as an empty table: "expected a [model] table".)
TEST(KanamaruCli, AScenarioThatCannotBeReadIsRefusedWithTheReason) {
  const auto folder = scratch_folder("kanamaru_unreadable_scenario");
  const fs::path not_toml = scratch_folder("kanamaru_not_toml") / "scenario.toml";
  fs::create_directories(not_toml.parent_path());
  std::ofstream(not_toml) << "[model\n";
  const std::string source = source_path("stands").string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {source, source + ": cannot read the scenario: it is a directory"},
      {"/nonexistent/heliostand/scenario.toml",
       "/nonexistent/heliostand/scenario.toml: cannot read the scenario: No such file or directory"},
      {not_toml.string(), not_toml.string() + ":1: not valid TOML: "},
  };
  for (const auto& [scenario, refusal] : cases) {
    const CliResult run = run_cli("kanamaru " + scenario + " --out " + folder.string());
    EXPECT_EQ(run.status, 2) << run.output;
    EXPECT_NE(run.output.find("error: " + refusal), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(folder)) << scenario;
  }
}

}  // namespace
}  // namespace heliostand::testing
