#pragma once
// What the tests of interrupted runs share (checkpoint_cli_test, batch_resume_cli_test): a small stand that grows
// a few years with roots, and a byte-for-byte comparison of two output folders without run.json's timings.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/cli_runner.hpp"
#include "tiny_stand_scenario.hpp"

namespace heliostand::testing {
namespace fs = std::filesystem;

// The tiny stand (8 trees, a thinning at age 23) with roots and soil on, 6 years under a coarse sky: ~1 s a year.
inline fs::path write_resumable_scenario(const fs::path& folder) {
  return write_tiny_stand_scenario(folder,
                                   "[run]\nyears = 6\nseed = 7\noutput_interval = 1\n"
                                   "[light]\nsky_bands = 4\nsky_sectors = 8\n"
                                   "[soil]\nnutrient = 0.5\n"
                                   "[[thinning]]\nage = 23\nmethod = \"ids\"\nids = [\"4\"]\n"
                                   "reason = \"test removal\"\n");
}

// Every file under `folder` (hidden ones too), by relative path, with its bytes; run.json without its timings and
// the machine that finished the run (a resumed run may finish on another).
inline std::map<std::string, std::string> outputs_of(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (!entry.is_regular_file()) continue;
    const std::string name = fs::relative(entry.path(), folder).generic_string();
    std::string bytes = read_text(entry.path());
    if (name == "run.json") {
      auto manifest = nlohmann::json::parse(bytes);
      for (const char* timing : {"started_utc", "finished_utc", "finished_on", "wall_seconds", "stage_seconds"}) {
        EXPECT_TRUE(manifest.contains(timing)) << timing;
        manifest.erase(timing);
      }
      bytes = manifest.dump(2);
    }
    files[name] = bytes;
  }
  return files;
}

// `at_least`: how many files the uninterrupted run must have written (a run with VTK writes more than 10).
inline void expect_same_outputs(const fs::path& expected, const fs::path& actual, std::size_t at_least = 10) {
  const auto want = outputs_of(expected), got = outputs_of(actual);
  EXPECT_GT(want.size(), at_least);
  for (const auto& [name, bytes] : want) {
    const auto found = got.find(name);
    if (found == got.end()) {
      ADD_FAILURE() << actual / name << " is missing";
      continue;
    }
    EXPECT_TRUE(found->second == bytes) << actual / name << " differs from " << expected / name;
  }
  for (const auto& [name, bytes] : got)
    EXPECT_TRUE(want.count(name)) << actual / name << " is not in the uninterrupted run";
}

}  // namespace heliostand::testing
