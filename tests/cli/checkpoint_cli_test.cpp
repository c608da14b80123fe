// `heliostand grow --checkpoint-every N` and `--resume`, end to end: a run killed with SIGKILL after its second
// checkpoint and resumed writes byte for byte what the uninterrupted run writes (run.json's timing fields aside),
// also when it has to fall back to the older checkpoint; damaged, cut-off and foreign checkpoints are refused.
#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <map>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli/cli_runner.hpp"
#include "cli/resumable_run.hpp"

extern char** environ;

namespace heliostand::testing {
namespace {
namespace fs = std::filesystem;

// Starts the grow command, waits for `checkpoint` to appear and then for `table` to grow past what it held then
// (the next year has begun writing rows the checkpoint does not count), and kills the run with SIGKILL.
void grow_and_kill(const std::string& grow_arguments, const fs::path& checkpoint, const fs::path& table) {
  const std::string command = "exec " + heliostand_command() + " " + grow_arguments + " -q";
  const char* argv[] = {"sh", "-c", command.c_str(), nullptr};
  pid_t pid = 0;
  ASSERT_EQ(::posix_spawn(&pid, "/bin/sh", nullptr, nullptr, const_cast<char**>(argv), environ), 0);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(2);
  while (!fs::exists(checkpoint) && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  std::error_code ignored;
  const auto counted = fs::file_size(table, ignored);
  while (fs::file_size(table, ignored) == counted && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
      << "the run ended on its own before it could be killed after " << checkpoint;
}

std::vector<fs::path> checkpoint_files(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder))
    if (entry.path().extension() == ".hsck") files.push_back(entry.path());
  return files;
}

void flip_a_byte(const fs::path& file) {
  std::string bytes = read_text(file);
  bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x01);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

TEST(CheckpointCli, AKilledRunResumesToTheUninterruptedOutputsAndBadCheckpointsAreRefused) {
  const fs::path folder = scratch_folder("checkpoint_cli");
  const std::string scenario = write_resumable_scenario(folder / "stand").string();
  const fs::path out = folder / "out";
  // Same command line for every run (run.json records it): the uninterrupted run is moved aside afterwards.
  const std::string grow = "grow " + scenario + " --out " + out.string() + " --checkpoint-every 2 --device reference";

  const auto uninterrupted = run_cli(grow + " -q");
  ASSERT_EQ(uninterrupted.status, 0) << uninterrupted.output;
  EXPECT_TRUE(checkpoint_files(out).empty()) << "a finished run keeps no checkpoints";
  const auto finished = run_cli(grow + " --resume -q");
  EXPECT_NE(finished.status, 0);
  EXPECT_NE(finished.output.find("has finished (it has its run.json)"), std::string::npos) << finished.output;
  fs::rename(out, folder / "uninterrupted");

  grow_and_kill(grow, out / "checkpoint_year_0004.hsck", out / ".stand_table.csv.tmp");
  ASSERT_FALSE(fs::exists(out / "run.json"));
  ASSERT_EQ(checkpoint_files(out).size(), 2u);
  for (const char* copy : {"damaged", "truncated", "fallback", "foreign", "short-table"})
    fs::copy(out, folder / copy, fs::copy_options::recursive);

  const auto resumed = run_cli(grow + " --resume -q");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  expect_same_outputs(folder / "uninterrupted", out);

  // The newest checkpoint damaged: refused by name, the one before it used, the outputs still the same.
  const fs::path fallback = folder / "fallback";
  flip_a_byte(fallback / "checkpoint_year_0004.hsck");
  fs::rename(out, folder / "resumed");
  fs::rename(fallback, out);
  const auto fell_back = run_cli(grow + " --resume");
  ASSERT_EQ(fell_back.status, 0) << fell_back.output;
  EXPECT_NE(fell_back.output.find("checkpoint_year_0004.hsck refused: it is damaged"), std::string::npos)
      << fell_back.output;
  EXPECT_NE(fell_back.output.find("resuming from " + (out / "checkpoint_year_0002.hsck").string()), std::string::npos)
      << fell_back.output;
  expect_same_outputs(folder / "uninterrupted", out);

  // Both damaged, both cut short, or another run's: refused with file and reason, nothing finished.
  const auto refused = [&](const fs::path& copy, const std::string& extra, const std::string& reason) {
    fs::remove_all(out);
    fs::rename(copy, out);
    const auto run = run_cli(grow + extra + " --resume -q");
    EXPECT_NE(run.status, 0) << run.output;
    for (const char* file : {"checkpoint_year_0004.hsck", "checkpoint_year_0002.hsck"})
      EXPECT_NE(run.output.find((out / file).string() + ": " + reason), std::string::npos)
          << reason << " not reported for " << file << ":\n" << run.output;
    EXPECT_NE(run.output.find("start it over with --force"), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(out / "run.json"));
  };
  for (const auto& file : checkpoint_files(folder / "damaged")) flip_a_byte(file);
  refused(folder / "damaged", "", "it is damaged");
  for (const auto& file : checkpoint_files(folder / "truncated")) fs::resize_file(file, fs::file_size(file) / 2);
  refused(folder / "truncated", "", "it is truncated");
  refused(folder / "foreign", " --seed 8", "it belongs to another run (foreign): its seed is 7, this run's is 8");
  // A table shorter than the checkpoints count (lost in a crash of the machine): refused, no table cut back.
  const fs::path short_table = folder / "short-table";
  fs::resize_file(short_table / ".trees.csv.tmp", 10);
  const auto stand_table_bytes = fs::file_size(short_table / ".stand_table.csv.tmp");
  refused(short_table, "", "cannot resume " + (out / ".trees.csv.tmp").string() + ": the checkpoint counts");
  EXPECT_EQ(fs::file_size(out / ".stand_table.csv.tmp"), stand_table_bytes);
}

}  // namespace
}  // namespace heliostand::testing
