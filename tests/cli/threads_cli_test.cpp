// `--threads` (core/parallel_for.hpp): the per-tree work — crowns growing, their light response, the leaf balls
// gathered for the solver, the root buds and their moisture probes, new root segments, each tree's crown–root
// balance — runs on several threads, and the answers must not depend on how many. The tiny stand with roots, grown
// two years by one thread and by three, must write the same bytes in every file but run.json (which records the
// command line and the clock).
#include <gtest/gtest.h>

#include <map>

#include "cli/cli_runner.hpp"
#include "tiny_stand_scenario.hpp"

namespace heliostand::testing {
namespace {

namespace fs = std::filesystem;

fs::path tiny_with_roots_file(const fs::path& folder) {
  return write_tiny_stand_scenario(folder,
                                   "[run]\nyears = 2\nseed = 7\ndetail = \"full\"\noutput_interval = 1\n"
                                   "[light]\nsky_bands = 8\nsky_sectors = 16\n"
                                   "[roots]\nenabled = true\n");
}

// Every file of a run folder but run.json, by its path relative to the folder.
std::map<std::string, std::string> files_of(const fs::path& run) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(run))
    if (entry.is_regular_file() && entry.path().filename() != "run.json")
      files[fs::relative(entry.path(), run).string()] = read_text(entry.path());
  return files;
}

}  // namespace

TEST(ThreadsCli, AnswersDoNotDependOnTheThreads) {
  const fs::path folder = scratch_folder("threads");
  const fs::path scenario = tiny_with_roots_file(folder);
  for (const char* threads : {"1", "3"}) {
    const CliResult run = run_cli(std::string("--threads ") + threads + " grow " + scenario.string() + " --out " +
                                  (folder / threads).string() + " --device reference -q");
    ASSERT_EQ(run.status, 0) << run.output;
  }
  const auto one = files_of(folder / "1");
  const auto three = files_of(folder / "3");
  ASSERT_GT(one.size(), 5u);  // the tables and a VTK series with roots, not an empty folder
  ASSERT_TRUE(one.count("trees.csv") && one.count("stand_table.csv"));
  EXPECT_EQ(one.size(), three.size());
  for (const auto& [name, bytes] : one) {
    const auto other = three.find(name);
    ASSERT_NE(other, three.end()) << name << " written by one thread only";
    EXPECT_TRUE(bytes == other->second) << name << " differs between 1 and 3 threads";
  }
}

TEST(ThreadsCli, RefusesZeroThreads) {
  const CliResult run = run_cli("--threads 0 check " + source_path("stands/tiny/scenario.toml").string());
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("--threads"), std::string::npos) << run.output;
}

}  // namespace heliostand::testing
