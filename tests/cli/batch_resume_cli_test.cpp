// `heliostand batch --checkpoint-every N`: a batch killed with SIGKILL (with its runs) and started again resumes
// each unfinished run from its checkpoint (grow --resume) instead of growing it anew, and ends with the outputs
// of the batch that was never interrupted (run.json's timing fields aside).
#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "cli/cli_runner.hpp"
#include "cli/resumable_run.hpp"

extern char** environ;

namespace heliostand::testing {
namespace {
namespace fs = std::filesystem;

// One run of the checkpoint tests' stand (cli/resumable_run.hpp), tables only.
fs::path write_manifest(const fs::path& folder) {
  write_resumable_scenario(folder);
  std::ofstream(folder / "manifest.toml") << "out = \"out\"\nseeds = [7]\nvtk = false\ndevice = \"reference\"\n"
                                             "[[stand]]\nname = \"tiny\"\nscenario = \"scenario.toml\"\n"
                                             "[[scenario]]\nname = \"as-is\"\n";
  return folder / "manifest.toml";
}

const fs::path run_folder = fs::path("runs") / "tiny" / "as-is" / "seed-7";

// Starts the batch in a process group of its own, waits for the run's second checkpoint, and kills the batch and
// its grow process with SIGKILL.
void batch_and_kill(const std::string& arguments, const fs::path& checkpoint) {
  const std::string command = "exec " + heliostand_command() + " " + arguments;
  const char* argv[] = {"sh", "-c", command.c_str(), nullptr};
  posix_spawnattr_t attributes;
  ::posix_spawnattr_init(&attributes);
  ::posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  ::posix_spawnattr_setpgroup(&attributes, 0);
  pid_t pid = 0;
  ASSERT_EQ(::posix_spawn(&pid, "/bin/sh", nullptr, &attributes, const_cast<char**>(argv), environ), 0);
  ::posix_spawnattr_destroy(&attributes);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(2);
  while (!fs::exists(checkpoint) && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ::kill(-pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
      << "the batch ended on its own before it could be killed after " << checkpoint;
}

TEST(BatchResumeCli, AKilledBatchResumesItsRunFromTheCheckpointAndEndsAsTheUninterruptedOne) {
  const fs::path folder = scratch_folder("batch_resume_cli");
  const std::string manifest = write_manifest(folder / "inputs").string();
  // Both batches run at one root (run.json records the scenario's absolute path); the first is moved aside.
  const fs::path resumed = folder / "root", uninterrupted = folder / "uninterrupted";

  const auto whole = run_cli("batch " + manifest + " --out " + resumed.string() + " --checkpoint-every 2 -j 1");
  ASSERT_EQ(whole.status, 0) << whole.output;
  fs::rename(resumed, uninterrupted);

  batch_and_kill("batch " + manifest + " --out " + resumed.string() + " --checkpoint-every 2 -j 1",
                 resumed / run_folder / "checkpoint_year_0004.hsck");
  ASSERT_FALSE(fs::exists(resumed / run_folder / "run.json")) << "the run was killed before it finished";
  // A file of no run's: growing the run anew (--force) clears the folder, resuming it leaves the file alone.
  std::ofstream(resumed / run_folder / "left-by-the-kill.txt") << "resumed runs keep this\n";

  const auto again = run_cli("batch " + manifest + " --out " + resumed.string() + " --checkpoint-every 2 -j 1");
  ASSERT_EQ(again.status, 0) << again.output;
  EXPECT_TRUE(fs::exists(resumed / run_folder / "left-by-the-kill.txt"))
      << "the unfinished run was grown anew instead of resumed from its checkpoint";
  fs::remove(resumed / run_folder / "left-by-the-kill.txt");
  expect_same_outputs(uninterrupted / run_folder, resumed / run_folder, 3);  // tables only: 3 CSV, run.json, the marker
}

}  // namespace
}  // namespace heliostand::testing
