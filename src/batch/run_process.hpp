#pragma once
// One batch run as its own `heliostand grow` process. A process per run (not an in-process call) keeps runs
// apart: a run that crashes, aborts or exhausts memory takes only itself down, the memory of a finished run is
// returned to the system, and the logger and OpenCL/OpenMP state of one run never meet another's.
#include <filesystem>
#include <string>
#include <vector>

namespace heliostand {

struct ProcessOutcome {
  int exit_status = 0;   // the process's exit status; 128 + N when killed by signal N (as a shell reports it)
  std::string error;     // empty on success; else the run's "error:" lines, or the signal that killed it
  double seconds = 0;
};

// Runs `arguments` (arguments[0] is what the program sees as its name) of the executable `program` in the
// folder `working_folder`, its stdout and stderr written to `log_file` (replacing an older one), and waits for
// it. Never throws for a failing child; a child that cannot be started is reported as exit status 127.
ProcessOutcome run_process(const std::filesystem::path& program, const std::vector<std::string>& arguments,
                           const std::filesystem::path& working_folder, const std::filesystem::path& log_file);

// Why a run that ended with `exit_status` (as ProcessOutcome's) failed: the signal that killed it, or its
// "error:" lines from `log_file` joined by "; ". Empty for status 0.
std::string failure_reason(int exit_status, const std::filesystem::path& log_file);

// This executable's own path (/proc/self/exe), to start runs with the same build.
std::filesystem::path own_executable();

}  // namespace heliostand
