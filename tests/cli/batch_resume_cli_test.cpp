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
#include <map>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli/cli_runner.hpp"

extern char** environ;

namespace heliostand::testing {
namespace {
namespace fs = std::filesystem;

// One run: the tiny stand (8 trees) with roots, 6 years under a coarse sky (~1 s a year), tables only.
fs::path write_manifest(const fs::path& folder) {
  fs::create_directories(folder);
  fs::copy_file(source_path("stands/tiny/survey.csv"), folder / "survey.csv");
  std::ofstream(folder / "scenario.toml")
      << "[stand]\nsurvey = \"survey.csv\"\nage_at_survey = 20\nx_min = 0.0\ny_min = 0.0\nx_max = 10.0\ny_max = 10.0\n"
         "[run]\nyears = 6\nseed = 7\noutput_interval = 1\n"
         "[light]\nsky_bands = 4\nsky_sectors = 8\n"
         "[soil]\nnutrient = 0.5\n";
  std::ofstream(folder / "manifest.toml") << "out = \"out\"\nseeds = [7]\nvtk = false\ndevice = \"reference\"\n"
                                             "[[stand]]\nname = \"tiny\"\nscenario = \"scenario.toml\"\n"
                                             "[[scenario]]\nname = \"as-is\"\n";
  return folder / "manifest.toml";
}

const fs::path run_folder = fs::path("runs") / "tiny" / "as-is" / "seed-7";

std::map<std::string, std::string> outputs_of(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (!entry.is_regular_file()) continue;
    const std::string name = fs::relative(entry.path(), folder).generic_string();
    std::string bytes = read_text(entry.path());
    if (name == "run.json") {
      auto manifest = nlohmann::json::parse(bytes);
      for (const char* timing : {"started_utc", "finished_utc", "wall_seconds", "stage_seconds"}) manifest.erase(timing);
      bytes = manifest.dump(2);
    }
    files[name] = bytes;
  }
  return files;
}

// Starts the batch in a process group of its own, waits for the run's second checkpoint, and kills the batch and
// its grow process with SIGKILL.
void batch_and_kill(const std::string& arguments, const fs::path& checkpoint) {
  const std::string command = "exec " + std::string(HELIOSTAND_EXECUTABLE) + " " + arguments;
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
  const auto want = outputs_of(uninterrupted / run_folder), got = outputs_of(resumed / run_folder);
  EXPECT_GT(want.size(), 3u);
  for (const auto& [name, bytes] : want) {
    const auto found = got.find(name);
    if (found == got.end()) {
      ADD_FAILURE() << name << " is missing in the resumed run";
      continue;
    }
    EXPECT_TRUE(found->second == bytes) << name << " differs from the uninterrupted run's";
  }
  EXPECT_EQ(got.size(), want.size());
}

}  // namespace
}  // namespace heliostand::testing
