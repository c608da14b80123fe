#pragma once
// Runs the heliostand executable the way a user does, capturing exit status and stderr.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>

#include "read_text.hpp"

namespace heliostand::testing {

struct CliResult {
  int status = -1;
  std::string output;  // stdout and stderr together
};

// The shell reports a signal as exit 128 + its number (a crash: 134, 139, ...).
inline CliResult run_command(const std::string& command_line) {
  const std::string command = command_line + " 2>&1";
  CliResult result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) result.output += buffer;
  const int raw = ::pclose(pipe);
  result.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return result;
}

// The command line that starts heliostand: this build's, or the one HELIOSTAND_TEST_EXECUTABLE names, so that the
// command-line tests can run another copy of it (validation/bench/gpu/checks.sh runs a GPU machine's bundle's
// heliostand through its packed loader: "'/path/bundle/run' heliostand"). A shell command, quoted as the shell
// reads it.
inline std::string heliostand_command() {
  const char* chosen = std::getenv("HELIOSTAND_TEST_EXECUTABLE");
  return chosen != nullptr && *chosen != '\0' ? std::string(chosen) : std::string(HELIOSTAND_EXECUTABLE);
}

inline CliResult run_cli(const std::string& arguments) { return run_command(heliostand_command() + " " + arguments); }

inline std::filesystem::path source_path(const std::string& relative) {
  return std::filesystem::path(HELIOSTAND_SOURCE_DIR) / relative;
}

// The eight trees of stands/tiny at age 20 with roots and a coarse 8 x 16 sky, without the stand's thinning:
// validation/bench/stands/tiny.toml, the bench tests' stand.
inline const std::filesystem::path tiny_bench_stand = source_path("validation/bench/stands/tiny.toml");

// A light benchmark that takes a moment: 300 random leaf balls, the plain C++ solvers only (no OpenCL device, no
// culled reference). The bench tests append -q, -o and what else they check.
inline const std::string quick_reference_light_bench =
    "bench light --balls 300 --subsample 20 --device none --reference-culled-max 0";

// A fresh, empty folder under the build tree for one test's output.
inline std::filesystem::path scratch_folder(const std::string& name) {
  const auto path = std::filesystem::path(HELIOSTAND_BINARY_DIR) / "test-output" / name;
  std::filesystem::remove_all(path);
  std::filesystem::create_directories(path.parent_path());
  return path;
}

// The names of what a folder holds (files and folders, hidden ones too), not recursing.
inline std::set<std::string> names_in(const std::filesystem::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
}

}  // namespace heliostand::testing
